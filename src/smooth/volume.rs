//! The volume constraint: after each step, rescale about the initial centre of mass so that the
//! enclosed volume stays what it was (trimesh's formula, divergence theorem over the faces).
//!
//! The sums are taken about a reference point `about`. For a closed mesh the volume and centre
//! do not depend on it, but the rounding does: about the origin, a mesh at distance D from it
//! sums terms of size D^2 L (L its size) to a result of size L^3 and loses the centre entirely
//! once D / L passes about 1e4. Measured about a point inside the mesh, the terms stay of size
//! L^3. For an open mesh the "volume" (that of the cone from `about` over the faces) depends
//! on the point: the clean behaviour uses the vertices' mean, which moves with the mesh, so the
//! result commutes with rigid motions. trimesh measures about the origin, and so does its preset.

use crate::parallel::deterministic_sum;
use crate::real::{Real, Vec3};

/// Signed volume enclosed by the faces, measured about `about` (meaningful for closed,
/// consistently oriented meshes).
pub fn volume<T: Real>(x: &[Vec3<T>], faces: &[[u32; 3]], about: [f64; 3]) -> f64 {
    deterministic_sum(faces.len(), |f| {
        let [a, b, c] = corners(x, faces[f], about);
        let nx = (b[1] - a[1]) * (c[2] - a[2]) - (b[2] - a[2]) * (c[1] - a[1]);
        nx * (a[0] + b[0] + c[0])
    }) / 6.0
}

/// Centre of mass of the solid the faces enclose, given its volume, with the sums taken about
/// `about`.
pub fn center_of_mass<T: Real>(x: &[Vec3<T>], faces: &[[u32; 3]], vol: f64, about: [f64; 3]) -> [f64; 3] {
    let mut c = [0.0; 3];
    for (k, ck) in c.iter_mut().enumerate() {
        *ck = about[k]
            + deterministic_sum(faces.len(), |f| {
                let [a, b, cc] = corners(x, faces[f], about);
                let u = [b[0] - a[0], b[1] - a[1], b[2] - a[2]];
                let v = [cc[0] - a[0], cc[1] - a[1], cc[2] - a[2]];
                let n = [u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]];
                n[k] * (a[k] * a[k] + b[k] * b[k] + a[k] * b[k] + cc[k] * (a[k] + b[k] + cc[k]))
            }) / (24.0 * vol);
    }
    c
}

/// The mean of the positions (in a fixed summation order, so the same bits for any thread count).
pub fn mean<T: Real>(x: &[Vec3<T>]) -> [f64; 3] {
    let n = x.len().max(1) as f64;
    std::array::from_fn(|k| deterministic_sum(x.len(), |i| x[i][k].to_f64()) / n)
}

/// A face's corners relative to `about` (exactly the corners when `about` is the origin).
#[inline]
fn corners<T: Real>(x: &[Vec3<T>], f: [u32; 3], about: [f64; 3]) -> [[f64; 3]; 3] {
    f.map(|i| {
        let p = crate::real::to_f64(x[i as usize]);
        [p[0] - about[0], p[1] - about[1], p[2] - about[2]]
    })
}

/// The initial state the constraint restores.
#[derive(Debug, Clone, Copy)]
pub struct VolumeConstraint {
    pub volume: f64,
    pub center: [f64; 3],
    /// The point volumes are measured about.
    pub about: [f64; 3],
}

impl VolumeConstraint {
    /// None when the mesh encloses no volume (an open or flat mesh): rescaling would divide by
    /// zero, so the constraint is skipped rather than producing inf or NaN.
    ///
    /// With `closed_only`, a mesh whose volume depends on the point it is measured from (an open
    /// or inconsistently oriented one, where "enclosed volume" and its centre mean nothing) is
    /// skipped too: the volume is measured again about a point one diagonal away, and the two
    /// must agree to 1e-6.
    pub fn new<T: Real>(
        x: &[Vec3<T>],
        faces: &[[u32; 3]],
        about: [f64; 3],
        closed_only: bool,
    ) -> Option<VolumeConstraint> {
        let volume = volume(x, faces, about);
        let scale = crate::mesh::Bounds::of(x).diagonal();
        let enclosed = volume.is_finite() && volume.abs() > 1e-12 * scale * scale * scale;
        if !enclosed {
            return None;
        }
        if closed_only {
            let elsewhere = self::volume(x, faces, about.map(|c| c + scale));
            if !((elsewhere - volume).abs() <= 1e-6 * volume.abs()) {
                return None;
            }
        }
        Some(VolumeConstraint { volume, center: center_of_mass(x, faces, volume, about), about })
    }

    /// The factor to scale by, or None if the current volume is unusable.
    pub fn factor<T: Real>(&self, x: &[Vec3<T>], faces: &[[u32; 3]]) -> Option<f64> {
        let now = volume(x, faces, self.about);
        let ratio = self.volume / now;
        (ratio.is_finite() && ratio > 0.0).then(|| ratio.cbrt())
    }
}

//! The volume constraint: after each step, rescale about the initial centre of mass so that the
//! enclosed volume stays what it was.
//!
//! Two rules. trimesh's (its preset): the divergence theorem with the x component only, summed
//! about the origin, applied to any mesh whose result is not nearly zero. The clean rule: only a
//! mesh that encloses a volume (its faces' vector area vanishes: closed and consistently
//! oriented) is constrained, and volumes are those of the cones from the vertices' mean over
//! the faces. For a closed mesh both give the same volume about any point; the clean rule keeps
//! it so once smoothing opens a crack, and it moves with the mesh, so the result commutes with
//! rigid motions. Summing about a point inside the mesh also keeps the rounding small: about
//! the origin, a mesh at distance D sums terms of size D^2 L (L its size) into a result of size
//! L^3, and loses its centre entirely once D / L passes about 1e4.

use crate::parallel::deterministic_sum;
use crate::real::{Real, Vec3};

/// Which volume the constraint keeps.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Rule {
    /// trimesh's: x-component divergence about the origin, any mesh.
    Trimesh,
    /// Cones from the vertices' mean, closed meshes only.
    Enclosed,
}

/// trimesh's signed volume: the divergence theorem with the x component, about `about`
/// (the volume enclosed by closed, consistently oriented faces).
pub fn volume<T: Real>(x: &[Vec3<T>], faces: &[[u32; 3]], about: [f64; 3]) -> f64 {
    deterministic_sum(faces.len(), |f| {
        let [a, b, c] = corners(x, faces[f], about);
        let nx = (b[1] - a[1]) * (c[2] - a[2]) - (b[2] - a[2]) * (c[1] - a[1]);
        nx * (a[0] + b[0] + c[0])
    }) / 6.0
}

/// The signed volume of the cones from `about` over the faces: the enclosed volume for closed,
/// consistently oriented faces, and a quantity that does not depend on the axes for any faces.
pub fn cone_volume<T: Real>(x: &[Vec3<T>], faces: &[[u32; 3]], about: [f64; 3]) -> f64 {
    deterministic_sum(faces.len(), |f| {
        let [a, b, c] = corners(x, faces[f], about);
        a[0] * (b[1] * c[2] - b[2] * c[1])
            + a[1] * (b[2] * c[0] - b[0] * c[2])
            + a[2] * (b[0] * c[1] - b[1] * c[0])
    }) / 6.0
}

/// Whether the faces' vector area vanishes (to `CLOSED_TOLERANCE` times the dtype's epsilon
/// of their total area): true of closed, consistently oriented meshes, whose enclosed volume
/// does not depend on where it is measured. The tolerance lies well above the rounding of the
/// coordinates (a collinear face rounded to float32 opens about 1e-8 of the area).
pub fn encloses<T: Real>(x: &[Vec3<T>], faces: &[[u32; 3]]) -> bool {
    let cross = |f: usize| {
        let [a, b, c] = corners(x, faces[f], [0.0; 3]);
        let (u, v) = ([b[0] - a[0], b[1] - a[1], b[2] - a[2]], [c[0] - a[0], c[1] - a[1], c[2] - a[2]]);
        [u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]]
    };
    let total = deterministic_sum(faces.len(), |f| crate::real::norm(cross(f)));
    let vector: [f64; 3] = std::array::from_fn(|k| deterministic_sum(faces.len(), |f| cross(f)[k]));
    crate::real::norm(vector) <= CLOSED_TOLERANCE * T::EPS * total
}

/// See `encloses`.
pub const CLOSED_TOLERANCE: f64 = 1e3;

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
    pub rule: Rule,
}

impl VolumeConstraint {
    /// None when the mesh encloses no volume (a flat mesh, or under the clean rule an open
    /// one): rescaling would divide by zero or mean nothing, so the constraint is skipped.
    pub fn new<T: Real>(x: &[Vec3<T>], faces: &[[u32; 3]], rule: Rule) -> Option<VolumeConstraint> {
        let about = match rule {
            Rule::Trimesh => [0.0; 3],
            Rule::Enclosed => mean(x),
        };
        if rule == Rule::Enclosed && !encloses(x, faces) {
            return None;
        }
        let vc = VolumeConstraint { volume: 0.0, center: [0.0; 3], about, rule };
        let volume = vc.measure(x, faces);
        let scale = crate::mesh::Bounds::of(x).diagonal();
        let enclosed = volume.is_finite() && volume.abs() > 1e-12 * scale * scale * scale;
        if !enclosed {
            return None;
        }
        Some(VolumeConstraint { volume, center: center_of_mass(x, faces, volume, about), ..vc })
    }

    fn measure<T: Real>(&self, x: &[Vec3<T>], faces: &[[u32; 3]]) -> f64 {
        match self.rule {
            Rule::Trimesh => volume(x, faces, self.about),
            Rule::Enclosed => cone_volume(x, faces, self.about),
        }
    }

    /// The factor to scale by, or None if the current volume is unusable.
    pub fn factor<T: Real>(&self, x: &[Vec3<T>], faces: &[[u32; 3]]) -> Option<f64> {
        let ratio = self.volume / self.measure(x, faces);
        (ratio.is_finite() && ratio > 0.0).then(|| ratio.cbrt())
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn both_rules_agree_on_a_closed_mesh_and_the_clean_one_skips_open_ones() {
        let (v, f) = crate::mesh::shapes::icosphere(2, 0.1, 1).unwrap();
        let shifted: Vec<[f64; 3]> = v.iter().map(|p| [p[0] + 100.0, p[1], p[2]]).collect();
        let (a, b) = (volume(&v, &f, [0.0; 3]), cone_volume(&v, &f, mean(&v)));
        assert!(
            (a - b).abs() < 1e-12 * a && (cone_volume(&shifted, &f, mean(&shifted)) - a).abs() < 1e-12 * a
        );
        assert!(VolumeConstraint::new(&v, &f, Rule::Enclosed).is_some());
        assert!(VolumeConstraint::new(&v, &f[1..], Rule::Enclosed).is_none());
        assert!(VolumeConstraint::new(&v, &f[1..], Rule::Trimesh).is_some());
    }
}

//! The truth the shadow map is measured against: for each pixel, the nearest surface along the
//! camera ray, then whether a ray from there toward the light meets any surface (or the surface
//! faces away from the light). Brute force over the triangles, rows in parallel: for tests and
//! the benchmark's accuracy table, on scenes of a few thousand triangles.

use glam::{DMat4, DVec3, DVec4};
use rayon::prelude::*;

use crate::real::{Real, Vec3};

/// `shadow_truth` of a mesh in world space (`faces` checked against `positions`), with
/// `view_proj` given as its 16 values row by row.
pub fn mesh_shadow_truth<T: Real>(
    positions: &[Vec3<T>],
    faces: &[[u32; 3]],
    view_proj: &[f64],
    (width, height): (usize, usize),
    toward_light: [f64; 3],
) -> Vec<f32> {
    let p: Vec<DVec3> = positions.iter().map(|q| DVec3::from_array(q.map(Real::to_f64))).collect();
    let tris = Triangles::new(faces.iter().map(|t| t.map(|i| p[i as usize])).collect());
    let toward = DVec3::from_array(toward_light).normalize();
    shadow_truth(&tris, DMat4::from_cols_slice(view_proj).transpose(), width, height, toward)
}

/// A triangle soup in world space.
pub struct Triangles {
    pub corners: Vec<[DVec3; 3]>,
    lo: DVec3,
    hi: DVec3,
}

impl Triangles {
    pub fn new(corners: Vec<[DVec3; 3]>) -> Self {
        let mut lo = DVec3::splat(f64::INFINITY);
        let mut hi = DVec3::splat(f64::NEG_INFINITY);
        for c in corners.iter().flatten() {
            lo = lo.min(*c);
            hi = hi.max(*c);
        }
        Triangles { corners, lo, hi }
    }

    fn diagonal(&self) -> f64 {
        (self.hi - self.lo).length()
    }

    /// The nearest hit beyond `t_min` along `o + t d`: distance and triangle.
    fn nearest(&self, o: DVec3, d: DVec3, t_min: f64) -> Option<(f64, usize)> {
        let mut best: Option<(f64, usize)> = None;
        for (i, tri) in self.corners.iter().enumerate() {
            if let Some(t) = intersect(o, d, tri) {
                if t > t_min && best.is_none_or(|(b, _)| t < b) {
                    best = Some((t, i));
                }
            }
        }
        best
    }

    fn any(&self, o: DVec3, d: DVec3, t_min: f64) -> bool {
        self.corners.iter().any(|tri| intersect(o, d, tri).is_some_and(|t| t > t_min))
    }
}

/// Möller-Trumbore: the ray parameter of the hit, if any (both sides).
fn intersect(o: DVec3, d: DVec3, [a, b, c]: &[DVec3; 3]) -> Option<f64> {
    let e1 = *b - *a;
    let e2 = *c - *a;
    let p = d.cross(e2);
    let det = e1.dot(p);
    if det.abs() < 1e-300 {
        return None;
    }
    let inv = 1.0 / det;
    let s = o - *a;
    let u = s.dot(p) * inv;
    if !(0.0..=1.0).contains(&u) {
        return None;
    }
    let q = s.cross(e1);
    let v = d.dot(q) * inv;
    if v < 0.0 || u + v > 1.0 {
        return None;
    }
    Some(e2.dot(q) * inv)
}

/// The light's visibility at each pixel of a `width` x `height` image seen through `view_proj`
/// (world -> clip): 1 lit (or no surface), 0 shadowed or facing away from the light, which
/// lies along `toward_light` (a unit vector, world space). Row-major, top row first.
pub fn shadow_truth(
    tris: &Triangles,
    view_proj: DMat4,
    width: usize,
    height: usize,
    toward_light: DVec3,
) -> Vec<f32> {
    let inv = view_proj.inverse();
    let eps = 1e-9 * tris.diagonal();
    let mut out = vec![1.0f32; width * height];
    out.par_chunks_mut(width).enumerate().for_each(|(y, row)| {
        for (x, px) in row.iter_mut().enumerate() {
            let ndc_x = (x as f64 + 0.5) / width as f64 * 2.0 - 1.0;
            let ndc_y = 1.0 - (y as f64 + 0.5) / height as f64 * 2.0;
            let unproject = |z: f64| {
                let p = inv * DVec4::new(ndc_x, ndc_y, z, 1.0);
                p.truncate() / p.w
            };
            let (near, far) = (unproject(0.0), unproject(1.0));
            let d = far - near;
            let Some((t, i)) = tris.nearest(near, d, 0.0) else { continue };
            let hit = near + d * t;
            let [a, b, c] = tris.corners[i];
            let mut n = (b - a).cross(c - a).normalize();
            if n.dot(d) > 0.0 {
                n = -n; // the side the camera sees
            }
            let facing = n.dot(toward_light) > 0.0;
            *px = if facing && !tris.any(hit + n * eps, toward_light, eps) { 1.0 } else { 0.0 };
        }
    });
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_square_over_a_floor_shadows_the_floor_below_it() {
        let sq = |z: f64, h: f64| {
            let p = [DVec3::new(-h, -h, z), DVec3::new(h, -h, z), DVec3::new(h, h, z), DVec3::new(-h, h, z)];
            vec![[p[0], p[1], p[2]], [p[0], p[2], p[3]]]
        };
        let mut corners = sq(0.0, 2.0);
        corners.extend(sq(1.0, 0.5));
        let tris = Triangles::new(corners);
        // looking straight down from z = 5 with an orthographic box of half-size 2
        let view = DMat4::from_translation(DVec3::new(0.0, 0.0, -5.0));
        let proj = crate::render::scene::camera::orthographic(2.0, 2.0, 0.1, 10.0);
        let vis = shadow_truth(&tris, proj * view, 8, 8, DVec3::Z);
        // the top square (lit) covers the centre 2x2 pixels; everything else is floor, lit
        assert!(vis.iter().all(|&v| v == 1.0));
        // light from the side at 45 degrees: the floor next to the square's shadow side darkens
        let vis = shadow_truth(&tris, proj * view, 8, 8, DVec3::new(1.0, 0.0, 1.0).normalize());
        let shadowed = vis.iter().filter(|&&v| v == 0.0).count();
        assert_eq!(shadowed, 4, "{vis:?}");
    }
}

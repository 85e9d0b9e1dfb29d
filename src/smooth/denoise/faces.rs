//! Per-face quantities of the current positions: unit normal (zero for a degenerate face),
//! area and centroid, in f64.

use rayon::prelude::*;

use crate::mesh::normals::face_normal;

#[derive(Debug, Clone, Copy, Default)]
pub struct FaceData {
    pub normal: [f64; 3],
    pub area: f64,
    pub centroid: [f64; 3],
}

pub fn face_data(x: &[[f64; 3]], faces: &[[u32; 3]], out: &mut Vec<FaceData>) {
    out.resize(faces.len(), FaceData::default());
    out.par_iter_mut().with_min_len(4096).zip(faces.par_iter()).for_each(|(o, f)| {
        let [a, b, c] = f.map(|i| x[i as usize]);
        let centroid = std::array::from_fn(|k| (a[k] + b[k] + c[k]) / 3.0);
        let e1: [f64; 3] = std::array::from_fn(|k| b[k] - a[k]);
        let e2: [f64; 3] = std::array::from_fn(|k| c[k] - a[k]);
        let n = cross(e1, e2);
        let area = 0.5 * norm(n);
        // The shared rule decides which faces are too thin to have a normal.
        let normal = face_normal(x, *f).unwrap_or([0.0; 3]);
        *o = FaceData { normal, area: if normal == [0.0; 3] { 0.0 } else { area }, centroid };
    });
}

#[inline]
pub fn cross(a: [f64; 3], b: [f64; 3]) -> [f64; 3] {
    [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]]
}

#[inline]
pub fn dot(a: [f64; 3], b: [f64; 3]) -> f64 {
    a[0] * b[0] + a[1] * b[1] + a[2] * b[2]
}

#[inline]
pub fn norm(a: [f64; 3]) -> f64 {
    dot(a, a).sqrt()
}

#[inline]
pub fn dist2(a: [f64; 3], b: [f64; 3]) -> f64 {
    let d: [f64; 3] = std::array::from_fn(|k| a[k] - b[k]);
    dot(d, d)
}

/// `v / |v|`, or zero when `v` is zero (or not finite).
#[inline]
pub fn unit_or_zero(v: [f64; 3]) -> [f64; 3] {
    let l = norm(v);
    if l > 0.0 && l.is_finite() {
        v.map(|c| c / l)
    } else {
        [0.0; 3]
    }
}

//! Per-vertex normals for shading.

use crate::real::{cross, sub, to_f64, Real, Vec3};

/// Area-weighted vertex normals: each vertex gets the normalised sum of the (unnormalised)
/// cross products of the faces around it, so large faces count more than slivers.
/// A vertex with no non-degenerate face gets `[0, 0, 0]`.
pub fn vertex_normals<T: Real>(positions: &[Vec3<T>], faces: &[[u32; 3]]) -> Vec<[f64; 3]> {
    let mut acc = vec![[0.0f64; 3]; positions.len()];
    for f in faces {
        let a = to_f64(positions[f[0] as usize]);
        let b = to_f64(positions[f[1] as usize]);
        let c = to_f64(positions[f[2] as usize]);
        let n = cross(sub(b, a), sub(c, a));
        for &k in f {
            let s = &mut acc[k as usize];
            s[0] += n[0];
            s[1] += n[1];
            s[2] += n[2];
        }
    }
    acc.into_iter().map(unit_or_zero).collect()
}

/// The unit normal of one triangle, or `[0, 0, 0]` when it has no area.
pub fn triangle_unit_normal<T: Real>(a: Vec3<T>, b: Vec3<T>, c: Vec3<T>) -> [f64; 3] {
    let (a, b, c) = (to_f64(a), to_f64(b), to_f64(c));
    unit_or_zero(cross(sub(b, a), sub(c, a)))
}

fn unit_or_zero(n: [f64; 3]) -> [f64; 3] {
    let l = (n[0] * n[0] + n[1] * n[1] + n[2] * n[2]).sqrt();
    if l > 0.0 && l.is_finite() {
        [n[0] / l, n[1] / l, n[2] / l]
    } else {
        [0.0; 3]
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn larger_face_dominates_and_isolated_vertex_is_zero() {
        // two faces sharing vertex 0: a big one in the xy-plane, a small one in the xz-plane
        let p = [[0.0, 0.0, 0.0], [2.0, 0.0, 0.0], [0.0, 2.0, 0.0], [0.0, 0.0, -0.1], [9.0, 9.0, 9.0]];
        let n = vertex_normals(&p, &[[0, 1, 2], [0, 3, 1]]);
        assert!(n[0][2] > 0.99);
        assert_eq!(n[4], [0.0; 3]);
        assert_eq!(triangle_unit_normal([0.0f32; 3], [1.0, 0.0, 0.0], [0.0, 1.0, 0.0]), [0.0, 0.0, 1.0]);
    }
}

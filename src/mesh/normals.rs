//! Unit face normals, with an explicit rule for faces that have none, and area-weighted vertex
//! normals for shading.
//!
//! The normal of face (a, b, c) is (b - a) x (c - a), normalised: counter-clockwise faces seen
//! from the front face the viewer. It is computed in f64 whatever the input precision, so the
//! rule below does not depend on the dtype's rounding.
//!
//! A face is *degenerate* (no defined normal) when it repeats a vertex index or when
//! |(b - a) x (c - a)| <= DEGENERATE_RELATIVE_AREA * L^2, with L its longest edge: zero-area and
//! collinear faces, scale-invariant. Degenerate faces get the zero vector.
//!
//! |n|^2 grows as the fourth power of the face's size, so in f64 it overflows for faces larger
//! than about 1e77 and underflows below about 1e-77. A face whose longest edge squared is
//! outside [2^-400, 2^400] (or not finite, when corners near f64::MAX have opposite signs) is
//! recomputed from its edges scaled by a power of two, so the rule and the normal are the same
//! at every scale from the smallest subnormal to f64::MAX.

use rayon::prelude::*;

use crate::error::{Error, Result};
use crate::real::{cross, sub, to_f64, Real, Vec3};

/// Twice the area of a face, relative to its longest edge squared, below which it has no normal.
/// A needle with relative area 1e-12 has a normal whose direction is still meaningful in f64
/// (rounding moves it by about 1e-4 rad at worst); below that it is noise.
pub const DEGENERATE_RELATIVE_AREA: f64 = 1e-12;

/// Unit normal of one face in f64, or None when the face is degenerate.
#[inline]
pub fn face_normal<T: Real>(positions: &[Vec3<T>], face: [u32; 3]) -> Option<[f64; 3]> {
    let [a, b, c] = face;
    if a == b || b == c || a == c {
        return None;
    }
    let p = |i: u32| {
        let q = positions[i as usize];
        [q[0].to_f64(), q[1].to_f64(), q[2].to_f64()]
    };
    let (pa, pb, pc) = (p(a), p(b), p(c));
    let e1 = [pb[0] - pa[0], pb[1] - pa[1], pb[2] - pa[2]];
    let e2 = [pc[0] - pa[0], pc[1] - pa[1], pc[2] - pa[2]];
    let e3 = [pc[0] - pb[0], pc[1] - pb[1], pc[2] - pb[2]];
    let sq = |e: [f64; 3]| e[0] * e[0] + e[1] * e[1] + e[2] * e[2];
    let longest = sq(e1).max(sq(e2)).max(sq(e3));
    if (SAFE_LOW..=SAFE_HIGH).contains(&longest) {
        unit_normal_of_edges(e1, e2, longest)
    } else {
        rescaled_normal(pa, pb, pc)
    }
}

/// Squared edge lengths inside which |n|^2 (the fourth power) fits in f64.
const SAFE_LOW: f64 = 1.0 / SAFE_HIGH;
const SAFE_HIGH: f64 = 2.5822498780869086e120; // 2^400

/// The unit normal from two edges and the longest edge squared, or None when degenerate.
#[inline]
fn unit_normal_of_edges(e1: [f64; 3], e2: [f64; 3], longest: f64) -> Option<[f64; 3]> {
    let n = [e1[1] * e2[2] - e1[2] * e2[1], e1[2] * e2[0] - e1[0] * e2[2], e1[0] * e2[1] - e1[1] * e2[0]];
    let len = (n[0] * n[0] + n[1] * n[1] + n[2] * n[2]).sqrt();
    // Written negated so that a NaN also counts as degenerate.
    #[allow(clippy::neg_cmp_op_on_partial_ord)]
    if !(len > DEGENERATE_RELATIVE_AREA * longest) {
        return None;
    }
    Some([n[0] / len, n[1] / len, n[2] / len])
}

/// `face_normal` for a face too large or too small for the direct formula: the edges are taken
/// from halved corners (so they cannot overflow) and scaled by a power of two so that their
/// largest component is in [1, 2). Both scalings are exact unless a component underflows, and
/// such a component is below 2^-1000 of the face's size.
#[cold]
fn rescaled_normal(pa: [f64; 3], pb: [f64; 3], pc: [f64; 3]) -> Option<[f64; 3]> {
    let h = |p: [f64; 3]| p.map(|c| c * 0.5);
    let (pa, pb, pc) = (h(pa), h(pb), h(pc));
    let e1 = [pb[0] - pa[0], pb[1] - pa[1], pb[2] - pa[2]];
    let e2 = [pc[0] - pa[0], pc[1] - pa[1], pc[2] - pa[2]];
    let e3 = [pc[0] - pb[0], pc[1] - pb[1], pc[2] - pb[2]];
    let largest = e1.iter().chain(&e2).chain(&e3).fold(0.0f64, |m, c| m.max(c.abs()));
    if largest == 0.0 {
        return None;
    }
    // 2^-e for largest = f 2^e, applied in two steps so that subnormal faces work too.
    let e = largest.log2().floor() as i32;
    let (s1, s2) = (2f64.powi(-e / 2), 2f64.powi(-e - (-e / 2)));
    let s = |v: [f64; 3]| v.map(|c| c * s1 * s2);
    let (e1, e2, e3) = (s(e1), s(e2), s(e3));
    let sq = |e: [f64; 3]| e[0] * e[0] + e[1] * e[1] + e[2] * e[2];
    unit_normal_of_edges(e1, e2, sq(e1).max(sq(e2)).max(sq(e3)))
}

/// Unit normals of all faces (zero for degenerate faces), in f64, computed in parallel.
pub fn face_normals<T: Real>(positions: &[Vec3<T>], faces: &[[u32; 3]]) -> Vec<[f64; 3]> {
    let mut out = vec![[0.0; 3]; faces.len()];
    face_normals_into(positions, faces, &mut out);
    out
}

/// `face_normals` into a caller's buffer of `faces.len()` normals.
pub fn face_normals_into<T: Real>(positions: &[Vec3<T>], faces: &[[u32; 3]], out: &mut [[f64; 3]]) {
    out.par_chunks_mut(4096).zip(faces.par_chunks(4096)).for_each(|(o, f)| {
        for (n, &face) in o.iter_mut().zip(f) {
            *n = face_normal(positions, face).unwrap_or([0.0; 3]);
        }
    });
}

/// Whether a normal returned by `face_normals` is defined (not the zero of a degenerate face).
#[inline]
pub fn is_defined(n: [f64; 3]) -> bool {
    n[0] != 0.0 || n[1] != 0.0 || n[2] != 0.0
}

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

/// `n` normalised, or `[0, 0, 0]` when it has no length (or an infinite one).
pub fn unit_or_zero(n: [f64; 3]) -> [f64; 3] {
    let l = (n[0] * n[0] + n[1] * n[1] + n[2] * n[2]).sqrt();
    if l > 0.0 && l.is_finite() {
        [n[0] / l, n[1] / l, n[2] / l]
    } else {
        [0.0; 3]
    }
}

/// A mesh's own vertex normals (a file's), checked as the argument `arg`: one a vertex of
/// `n_vertices`, finite, none the zero vector; scaled to unit length (without squaring large or
/// tiny components) in f32, as the GPU takes them.
pub fn given_unit_normals<T: Real>(
    arg: &str,
    normals: &[Vec3<T>],
    n_vertices: usize,
) -> Result<Vec<[f32; 3]>> {
    if normals.len() != n_vertices {
        return Err(Error::invalid(
            arg,
            format!("expected one normal a vertex, shape ({n_vertices}, 3), got ({}, 3)", normals.len()),
        ));
    }
    normals
        .iter()
        .enumerate()
        .map(|(i, n)| {
            let n = to_f64(*n);
            if !n.iter().all(|x| x.is_finite()) {
                return Err(Error::invalid(arg, format!("the normal of vertex {i} is not finite: {n:?}")));
            }
            let m = n.iter().fold(0.0f64, |m, x| m.max(x.abs()));
            if m == 0.0 {
                return Err(Error::invalid(
                    arg,
                    format!("the normal of vertex {i} is the zero vector: a normal needs a direction"),
                ));
            }
            let u = unit_or_zero(n.map(|x| x / m));
            Ok(u.map(|x| x as f32))
        })
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn unit_normal_and_degenerates() {
        let v: Vec<[f32; 3]> = vec![[0.0, 0.0, 0.0], [1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [2.0, 0.0, 0.0]];
        let n = face_normals(&v, &[[0, 1, 2], [0, 2, 1], [0, 1, 3], [0, 0, 2]]);
        assert_eq!(n[0], [0.0, 0.0, 1.0]);
        assert_eq!(n[1], [0.0, 0.0, -1.0]);
        assert!(!is_defined(n[2]), "collinear face has no normal");
        assert!(!is_defined(n[3]), "repeated index has no normal");
    }

    #[test]
    fn scale_invariant() {
        for s in [1e-30, 1.0, 1e30] {
            let v = vec![[0.0, 0.0, 0.0], [s, 0.0, 0.0], [0.0, s * 1e-9, 0.0]];
            assert!(face_normal(&v, [0, 1, 2]).is_some(), "thin but valid at scale {s}");
        }
    }

    #[test]
    fn the_same_normal_from_the_smallest_subnormal_to_the_largest_float() {
        let tri = [[0.3, -0.2, 0.1], [1.0, 0.1, -0.4], [-0.2, 0.9, 0.5]];
        let reference = face_normal(&tri, [0, 1, 2]).unwrap();
        for s in [1e-320, 1e-300, 1e-160, 1e-100, 1e100, 1e160, 1e300, 1e307] {
            let v: Vec<[f64; 3]> = tri.iter().map(|p| p.map(|c| c * s)).collect();
            let n = face_normal(&v, [0, 1, 2]).unwrap_or_else(|| panic!("degenerate at {s}"));
            let tol = if s < 1e-300 { 1e-2 } else { 1e-15 }; // subnormal corners keep about 10 bits
            assert!((0..3).all(|k| (n[k] - reference[k]).abs() < tol), "{s}: {n:?}");
        }
        // corners near f64::MAX with opposite signs: their differences overflow unless halved
        let m = f64::MAX / 2.0;
        let v = vec![[-m, -m, 0.0], [m, -m, 0.0], [-m, m, 0.0]];
        assert_eq!(face_normal(&v, [0, 1, 2]), Some([0.0, 0.0, 1.0]));
        // a needle stays degenerate at every scale
        for s in [1e-300, 1.0, 1e300] {
            let v = vec![[0.0, 0.0, 0.0], [s, 0.0, 0.0], [2.0 * s, s * 1e-14, 0.0]];
            assert!(face_normal(&v, [0, 1, 2]).is_none(), "{s}");
        }
    }

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

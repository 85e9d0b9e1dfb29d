//! The operators of the clean behaviour (no preset): distinct neighbours, rows that sum to one,
//! boundaries handled as asked, so nothing drifts toward the origin.
//!
//! Cotangent weights stay finite on any triangle: a corner's cotangent is
//! (u . v) / max(2 area, 1e-4 L^2), with u, v its two sides and L the triangle's longest side, so
//! |cot| <= 1e4 (a triangle with all sides of zero length contributes nothing); an edge's weight
//! (the sum over its faces) is clamped at zero, and a vertex whose weights then sum to zero
//! falls back to uniform weights. Every row is therefore a convex combination of neighbours, and
//! no vertex can leave the bounding box of the input.

use rayon::prelude::*;

use super::operator::{Operator, ROW_CHUNK};
use super::options::{Boundary, Weights};
use crate::mesh::{Adjacency, Bounds};
use crate::real::{self, Real, Vec3};

/// Floor of 2 area / L^2 in a cotangent, which bounds |cot| by its inverse.
pub const COT_FLOOR: f64 = 1e-4;

/// Which vertices never move under the clean rules.
pub fn frozen_vertices(
    adj: &Adjacency,
    boundary: Boundary,
    is_boundary: &[bool],
    pinned: Option<&[bool]>,
) -> Vec<bool> {
    (0..adj.n_vertices())
        .map(|i| {
            adj.slots(i).is_empty()
                || pinned.is_some_and(|p| p[i])
                || (boundary == Boundary::Fixed && is_boundary[i])
        })
        .collect()
}

/// Buffers reused from step to step, so that geometry-dependent weights do not allocate (and
/// page-fault) tens of megabytes per step on large meshes.
#[derive(Default)]
pub struct Scratch {
    face_cot: Vec<f64>,
    self_w: Vec<f64>,
    w: Vec<f64>,
}

impl Scratch {
    /// Takes back the buffers of an operator that is no longer needed.
    pub fn recycle(&mut self, op: Operator) {
        if let Operator::Weighted { self_w, w } = op {
            self.self_w = self_w;
            self.w = w;
        }
    }
}

/// Builds the clean operator for the current positions `x`.
#[allow(clippy::too_many_arguments)]
pub fn operator<T: Real>(
    adj: &Adjacency,
    x: &[Vec3<T>],
    faces: &[[u32; 3]],
    weights: Weights,
    boundary: Boundary,
    frozen: &[bool],
    is_boundary: &[bool],
    scratch: &mut Scratch,
) -> Operator {
    if weights == Weights::Uniform && boundary != Boundary::Slide {
        return Operator::Uniform { frozen: frozen.to_vec() };
    }
    let n = adj.n_vertices();
    let tiny = 1e-12 * Bounds::of(x).diagonal().max(f64::MIN_POSITIVE);
    if weights == Weights::Cotangent {
        // Each corner's cotangent once per face, then gathered per edge.
        face_cotangents_into(x, faces, &mut scratch.face_cot);
    }
    let face_cot = &scratch.face_cot;
    let mut self_w = std::mem::take(&mut scratch.self_w);
    let mut w = std::mem::take(&mut scratch.w);
    self_w.resize(n, 0.0);
    w.resize(adj.nbrs.len(), 0.0);
    // Rows are filled in chunks of vertices; each chunk owns a contiguous run of slots.
    let chunks: Vec<std::ops::Range<usize>> =
        (0..n.div_ceil(ROW_CHUNK)).map(|c| c * ROW_CHUNK..((c + 1) * ROW_CHUNK).min(n)).collect();
    let mut w_chunks = Vec::with_capacity(chunks.len());
    let mut rest: &mut [f64] = &mut w;
    for r in &chunks {
        let len = (adj.offsets[r.end] - adj.offsets[r.start]) as usize;
        let (head, tail) = rest.split_at_mut(len);
        w_chunks.push(head);
        rest = tail;
    }
    self_w.par_chunks_mut(ROW_CHUNK).zip(w_chunks.into_par_iter()).zip(chunks.par_iter()).for_each(
        |((sw_chunk, w_chunk), r)| {
            let base = adj.offsets[r.start] as usize;
            for (k, i) in r.clone().enumerate() {
                let row = &mut w_chunk[adj.offsets[i] as usize - base..adj.offsets[i + 1] as usize - base];
                fill_row(
                    adj,
                    x,
                    face_cot,
                    i,
                    weights,
                    boundary,
                    frozen[i],
                    is_boundary[i],
                    tiny,
                    &mut sw_chunk[k],
                    row,
                );
            }
        },
    );
    Operator::Weighted { self_w, w }
}

#[allow(clippy::too_many_arguments)]
fn fill_row<T: Real>(
    adj: &Adjacency,
    x: &[Vec3<T>],
    face_cot: &[f64],
    i: usize,
    weights: Weights,
    boundary: Boundary,
    frozen: bool,
    on_boundary: bool,
    tiny: f64,
    self_w: &mut f64,
    row: &mut [f64],
) {
    let slots = adj.slots(i);
    if frozen {
        *self_w = 1.0;
        row.fill(0.0);
        return;
    }
    if boundary == Boundary::Slide && on_boundary {
        // Along the boundary curve only: the vertex slides along its border edges.
        for (k, s) in slots.clone().enumerate() {
            row[k] = if adj.edge_faces[s] == 1 { 1.0 } else { 0.0 };
        }
    } else {
        let xi = real::to_f64(x[i]);
        for (k, s) in slots.clone().enumerate() {
            let xj = real::to_f64(x[adj.nbrs[s] as usize]);
            row[k] = match weights {
                Weights::Uniform => 1.0,
                Weights::Distance => 1.0 / real::norm(real::sub(xi, xj)).max(tiny),
                Weights::Cotangent => {
                    let c: f64 = adj.corners_of(s).iter().map(|&k| face_cot[k as usize]).sum();
                    c.max(0.0)
                }
            };
        }
    }
    let mut total: f64 = row.iter().sum();
    if !(total > 0.0 && total.is_finite()) {
        row.fill(1.0);
        total = row.len() as f64;
    }
    for v in row.iter_mut() {
        *v /= total;
    }
    *self_w = 0.0;
}

/// The bounded cotangent of each face's three angles, indexed face * 3 + corner.
pub fn face_cotangents<T: Real>(x: &[Vec3<T>], faces: &[[u32; 3]]) -> Vec<f64> {
    let mut out = Vec::new();
    face_cotangents_into(x, faces, &mut out);
    out
}

fn face_cotangents_into<T: Real>(x: &[Vec3<T>], faces: &[[u32; 3]], out: &mut Vec<f64>) {
    out.resize(faces.len() * 3, 0.0);
    out.par_chunks_mut(3 * ROW_CHUNK).enumerate().for_each(|(c, chunk)| {
        for (k, cots) in chunk.chunks_exact_mut(3).enumerate() {
            let f = faces[c * ROW_CHUNK + k];
            let cot = triangle_cotangents(f.map(|i| real::to_f64(x[i as usize])));
            cots.copy_from_slice(&cot);
        }
    });
}

/// The three bounded cotangents of a triangle, corner by corner. Every corner shares the same
/// twice-area |e1 x e2|, so one square root and one division serve all three.
#[inline]
pub fn triangle_cotangents(p: [[f64; 3]; 3]) -> [f64; 3] {
    // e[k] is the side opposite corner k.
    let e = [real::sub(p[2], p[1]), real::sub(p[0], p[2]), real::sub(p[1], p[0])];
    let longest2 = e.iter().map(|v| real::dot(*v, *v)).fold(0.0, f64::max);
    if longest2 == 0.0 {
        return [0.0; 3];
    }
    let twice_area = real::norm(real::cross(e[0], e[1])).max(COT_FLOOR * longest2);
    let inv = 1.0 / twice_area;
    // At corner k the sides are -e[k+1] and e[k+2]: cot = -(e[k+1] . e[k+2]) / (2 area).
    std::array::from_fn(|k| -real::dot(e[(k + 1) % 3], e[(k + 2) % 3]) * inv)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn cotangents_are_exact_on_a_right_triangle_and_bounded_on_degenerate_ones() {
        let c = triangle_cotangents([[0.0, 0.0, 0.0], [1.0, 0.0, 0.0], [0.0, 2.0, 0.0]]);
        assert!(c[0].abs() < 1e-15);
        assert!((c[1] - 0.5).abs() < 1e-15 && (c[2] - 2.0).abs() < 1e-15);
        let flat = triangle_cotangents([[0.0, 0.0, 0.0], [1.0, 0.0, 0.0], [0.5, 1e-30, 0.0]]);
        assert!(flat.iter().all(|v| v.is_finite() && v.abs() <= 1.0 / COT_FLOOR));
        assert_eq!(triangle_cotangents([[1.0, 2.0, 3.0]; 3]), [0.0; 3]);
        let needle = triangle_cotangents([[0.0, 0.0, 0.0], [1.0, 0.0, 0.0], [1.0, 1e-12, 0.0]]);
        assert!(needle.iter().all(|v| v.is_finite() && v.abs() <= 1.0 / COT_FLOOR));
    }
}

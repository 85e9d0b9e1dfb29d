//! The operators of the clean behaviour (no preset): distinct neighbours, rows that sum to one,
//! boundaries handled as asked, so nothing drifts toward the origin.
//!
//! Cotangent weights stay finite on any triangle: each corner's cotangent is cos/max(sin, 1e-4)
//! (so |cot| <= 1e4), a corner with a zero-length side contributes nothing, an edge's weight
//! (the sum over its faces) is clamped at zero, and a vertex whose weights then sum to zero
//! falls back to uniform weights. Every row is therefore a convex combination of neighbours, and
//! no vertex can leave the bounding box of the input.

use rayon::prelude::*;

use super::operator::{Operator, ROW_CHUNK};
use super::options::{Boundary, Weights};
use crate::mesh::{Adjacency, Bounds};
use crate::real::{self, Real, Vec3};

/// Smallest sine used in a cotangent: angles under about 0.0057 degrees count as that angle.
pub const COT_MIN_SIN: f64 = 1e-4;

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

/// Builds the clean operator for the current positions `x`.
pub fn operator<T: Real>(
    adj: &Adjacency,
    x: &[Vec3<T>],
    faces: &[[u32; 3]],
    weights: Weights,
    boundary: Boundary,
    frozen: &[bool],
    is_boundary: &[bool],
) -> Operator {
    if weights == Weights::Uniform && boundary != Boundary::Slide {
        return Operator::Uniform { frozen: frozen.to_vec() };
    }
    let n = adj.n_vertices();
    let tiny = 1e-12 * Bounds::of(x).diagonal().max(f64::MIN_POSITIVE);
    // Each corner's cotangent once per face, then gathered per edge.
    let face_cot = if weights == Weights::Cotangent { face_cotangents(x, faces) } else { Vec::new() };
    let mut self_w = vec![0.0f64; n];
    let mut w = vec![0.0f64; adj.nbrs.len()];
    // Each vertex owns a contiguous run of slots, so rows can be filled independently.
    let mut w_rows: Vec<&mut [f64]> = Vec::with_capacity(n);
    let mut rest: &mut [f64] = &mut w;
    for i in 0..n {
        let (head, tail) = rest.split_at_mut(adj.slots(i).len());
        w_rows.push(head);
        rest = tail;
    }
    self_w.par_chunks_mut(ROW_CHUNK).zip(w_rows.par_chunks_mut(ROW_CHUNK)).enumerate().for_each(
        |(c, (sw_chunk, w_chunk))| {
            for (k, (sw, row)) in sw_chunk.iter_mut().zip(w_chunk.iter_mut()).enumerate() {
                let i = c * ROW_CHUNK + k;
                fill_row(adj, x, &face_cot, i, weights, boundary, frozen[i], is_boundary[i], tiny, sw, row);
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
    let mut out = vec![0.0; faces.len() * 3];
    out.par_chunks_mut(3 * ROW_CHUNK).enumerate().for_each(|(c, chunk)| {
        for (k, cots) in chunk.chunks_exact_mut(3).enumerate() {
            let f = faces[c * ROW_CHUNK + k];
            let p = f.map(|i| real::to_f64(x[i as usize]));
            for j in 0..3 {
                cots[j] = cotangent(p[(j + 1) % 3], p[(j + 2) % 3], p[j]);
            }
        }
    });
    out
}

/// cot of the angle at `k` in triangle (i, j, k), bounded as the module documents:
/// cos / max(sin, 1e-4) = (u.v) / max(|u x v|, 1e-4 |u| |v|), with one square root.
#[inline]
pub fn cotangent(xi: [f64; 3], xj: [f64; 3], xk: [f64; 3]) -> f64 {
    let u = real::sub(xi, xk);
    let v = real::sub(xj, xk);
    let lengths2 = real::dot(u, u) * real::dot(v, v);
    if lengths2 == 0.0 {
        return 0.0;
    }
    let c = real::cross(u, v);
    let sin2_scaled = real::dot(c, c).max(COT_MIN_SIN * COT_MIN_SIN * lengths2);
    real::dot(u, v) / sin2_scaled.sqrt()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn cotangent_is_bounded() {
        let c = cotangent([0.0, 0.0, 0.0], [1.0, 0.0, 0.0], [0.5, 1e-30, 0.0]);
        assert!(c.is_finite() && c.abs() <= 1.0 / COT_MIN_SIN + 1.0);
        assert_eq!(cotangent([0.0; 3], [1.0, 0.0, 0.0], [0.0; 3]), 0.0);
        let right = cotangent([1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 0.0]);
        assert!(right.abs() < 1e-15);
    }
}

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

use super::operator::{prefetch, refill, weighted_average, Operator, PREFETCH_AHEAD, ROW_CHUNK};
use super::options::{Boundary, Weights};
use crate::mesh::{Adjacency, Bounds};
use crate::real::{self, Real, Vec3};

/// Floor of 2 area / L^2 in a cotangent, which bounds |cot| by its inverse.
pub const COT_FLOOR: f64 = 1e-4;

/// What decides the clean rows apart from the positions: the weights, how boundaries are
/// handled, and which vertices never move.
pub struct Rules {
    pub weights: Weights,
    pub boundary: Boundary,
    /// Vertices that never move: pinned, without neighbours, or on a fixed boundary.
    pub frozen: Vec<bool>,
    pub is_boundary: Vec<bool>,
}

impl Rules {
    pub fn new(adj: &Adjacency, weights: Weights, boundary: Boundary, pinned: Option<&[bool]>) -> Rules {
        let is_boundary = adj.boundary_vertices();
        let frozen = (0..adj.n_vertices())
            .into_par_iter()
            .map(|i| {
                adj.slots(i).is_empty()
                    || pinned.is_some_and(|p| p[i])
                    || (boundary == Boundary::Fixed && is_boundary[i])
            })
            .collect();
        Rules { weights, boundary, frozen, is_boundary }
    }
}

/// Buffers reused from step to step, so that geometry-dependent weights do not allocate (and
/// page-fault) tens of megabytes per step on large meshes.
#[derive(Default)]
pub struct Scratch {
    /// One value per face corner (face * 3 + k): the corners' cotangents.
    pub face_cot: Vec<f64>,
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

    /// The weight buffers of an earlier operator, for a new one to fill.
    pub fn take_weights(&mut self) -> (Vec<f64>, Vec<f64>) {
        (std::mem::take(&mut self.self_w), std::mem::take(&mut self.w))
    }
}

/// The clean rows at positions `x`: what decides each row's weights, with the quantities the
/// whole step shares (each face's cotangents) already computed.
pub struct Rows<'a, T> {
    adj: &'a Adjacency,
    x: &'a [Vec3<T>],
    face_cot: &'a [f64],
    rules: &'a Rules,
    /// Floor of a distance, for inverse-distance weights.
    tiny: f64,
}

impl<'a, T: Real> Rows<'a, T> {
    pub fn new(
        adj: &'a Adjacency,
        x: &'a [Vec3<T>],
        faces: &[[u32; 3]],
        rules: &'a Rules,
        face_cot: &'a mut Vec<f64>,
    ) -> Self {
        // Only inverse-distance weights need a length scale; the box costs a pass over x.
        let tiny = match rules.weights {
            Weights::Distance => 1e-12 * Bounds::of(x).diagonal().max(f64::MIN_POSITIVE),
            _ => 0.0,
        };
        if rules.weights == Weights::Cotangent {
            // Each corner's cotangent once per face, then gathered per edge.
            face_cotangents_into(x, faces, face_cot);
        }
        Rows { adj, x, face_cot, rules, tiny }
    }

    /// Requests what row i will read, a few rows before it is filled: the corners'
    /// cotangents are scattered over the face array, as the neighbours' positions are over x.
    #[inline]
    fn prefetch(&self, i: usize) {
        if self.rules.weights == Weights::Cotangent {
            for &c in self.adj.corners_of_run(self.adj.slots(i)) {
                prefetch(self.face_cot.as_ptr().wrapping_add(c as usize));
            }
        }
    }

    /// Writes row i's neighbour weights and returns its own weight.
    #[inline]
    fn fill(&self, i: usize, row: &mut [f64]) -> f64 {
        let adj = self.adj;
        let slots = adj.slots(i);
        if self.rules.frozen[i] {
            row.fill(0.0);
            return 1.0;
        }
        if self.rules.boundary == Boundary::Slide && self.rules.is_boundary[i] {
            // Along the boundary curve only: the vertex slides along its border edges.
            for (r, &e) in row.iter_mut().zip(adj.edge_faces(i)) {
                *r = if e == 1 { 1.0 } else { 0.0 };
            }
        } else {
            match self.rules.weights {
                Weights::Uniform => row.fill(1.0),
                Weights::Distance => {
                    let xi = real::to_f64(self.x[i]);
                    for (r, &j) in row.iter_mut().zip(&adj.nbrs[slots]) {
                        let xj = real::to_f64(self.x[j as usize]);
                        *r = 1.0 / real::norm(real::sub(xi, xj)).max(self.tiny);
                    }
                }
                Weights::Cotangent if adj.all_fans_closed => {
                    // Every edge has exactly two faces: the corners come in pairs, slot by slot.
                    let corners = adj.corners_of_run(slots.clone());
                    for (r, pair) in row.iter_mut().zip(corners.chunks_exact(2)) {
                        let c: f64 = pair.iter().map(|&k| self.face_cot[k as usize]).sum();
                        *r = c.max(0.0);
                    }
                }
                Weights::Cotangent => {
                    // The row's corners lie together, slot after slot: walk them in step.
                    let mut corners = adj.corners_of_run(slots.clone());
                    for (r, &e) in row.iter_mut().zip(adj.edge_faces(i)) {
                        let (here, next) = corners.split_at(e as usize);
                        corners = next;
                        let c: f64 = here.iter().map(|&k| self.face_cot[k as usize]).sum();
                        *r = c.max(0.0);
                    }
                }
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
        0.0
    }
}

/// Builds the clean operator for the current positions `x`.
pub fn operator<T: Real>(
    adj: &Adjacency,
    x: &[Vec3<T>],
    faces: &[[u32; 3]],
    rules: &Rules,
    scratch: &mut Scratch,
) -> Operator {
    if rules.weights == Weights::Uniform && rules.boundary != Boundary::Slide {
        return Operator::Uniform { frozen: rules.frozen.clone() };
    }
    let n = adj.n_vertices();
    let (self_w, w) = scratch.take_weights();
    let rows = Rows::new(adj, x, faces, rules, &mut scratch.face_cot);
    Operator::from_rows_par(adj, None, self_w, w, |i, row| {
        if i + PREFETCH_AHEAD < n {
            rows.prefetch(i + PREFETCH_AHEAD);
        }
        rows.fill(i, row)
    })
}

/// out[i] = f(i, avg_i) with avg = A x for the clean operator at `x`, each row built and used
/// at once: the same numbers as `operator` then `Operator::row`, without writing the weights
/// out and reading them back.
#[allow(clippy::too_many_arguments)]
pub fn map_averages<T: Real, O: Send>(
    adj: &Adjacency,
    x: &[Vec3<T>],
    faces: &[[u32; 3]],
    rules: &Rules,
    scratch: &mut Scratch,
    out: &mut [O],
    f: impl Fn(usize, [f64; 3]) -> O + Sync,
) {
    let n = out.len();
    let rows = Rows::new(adj, x, faces, rules, &mut scratch.face_cot);
    out.par_chunks_mut(ROW_CHUNK).enumerate().for_each(|(c, chunk)| {
        let base = c * ROW_CHUNK;
        let mut row = Vec::new();
        for (k, o) in chunk.iter_mut().enumerate() {
            let i = base + k;
            if i + PREFETCH_AHEAD < n {
                rows.prefetch(i + PREFETCH_AHEAD);
                for &j in adj.neighbours(i + PREFETCH_AHEAD) {
                    prefetch(x.as_ptr().wrapping_add(j as usize));
                }
            }
            row.clear();
            row.resize(adj.slots(i).len(), 0.0);
            let own = rows.fill(i, &mut row);
            *o = f(i, weighted_average(adj.neighbours(i), x, i, own, &row));
        }
    });
}

/// The bounded cotangent of each face's three angles, indexed face * 3 + corner.
pub fn face_cotangents<T: Real>(x: &[Vec3<T>], faces: &[[u32; 3]]) -> Vec<f64> {
    let mut out = Vec::new();
    face_cotangents_into(x, faces, &mut out);
    out
}

fn face_cotangents_into<T: Real>(x: &[Vec3<T>], faces: &[[u32; 3]], out: &mut Vec<f64>) {
    refill(out, faces.len() * 3);
    out.par_chunks_mut(3 * ROW_CHUNK).zip(faces.par_chunks(ROW_CHUNK)).for_each(|(cots, faces)| {
        #[cfg(target_arch = "x86_64")]
        {
            if std::arch::is_x86_feature_detected!("avx2") {
                // SAFETY: the CPU supports AVX2, checked just above.
                return unsafe { face_chunk_avx2(x, faces, cots) };
            }
        }
        face_chunk(x, faces, cots)
    });
}

/// `face_chunk` compiled for 4-wide f64 vectors. FMA stays off, so every lane rounds exactly
/// as the scalar `triangle_cotangents` does.
#[cfg(target_arch = "x86_64")]
#[target_feature(enable = "avx2")]
unsafe fn face_chunk_avx2<T: Real>(x: &[Vec3<T>], faces: &[[u32; 3]], out: &mut [f64]) {
    face_chunk(x, faces, out)
}

/// Faces computed side by side: enough for two vector registers per quantity.
const LANES: usize = 8;

/// The cotangents of a run of faces, `LANES` at a time with every quantity held per lane (so
/// the compiler can vectorise the square roots and divisions), the rest one by one.
#[inline(always)]
fn face_chunk<T: Real>(x: &[Vec3<T>], faces: &[[u32; 3]], out: &mut [f64]) {
    let mut blocks = faces.chunks_exact(LANES);
    let mut outs = out.chunks_exact_mut(3 * LANES);
    for (block, o) in (&mut blocks).zip(&mut outs) {
        // e[k][axis][lane]: the side opposite corner k, as in `triangle_cotangents`.
        let mut e = [[[0.0f64; LANES]; 3]; 3];
        for (l, f) in block.iter().enumerate() {
            let p = f.map(|i| real::to_f64(x[i as usize]));
            for a in 0..3 {
                e[0][a][l] = p[2][a] - p[1][a];
                e[1][a][l] = p[0][a] - p[2][a];
                e[2][a][l] = p[1][a] - p[0][a];
            }
        }
        let dot = |u: &[[f64; LANES]; 3], v: &[[f64; LANES]; 3], l: usize| {
            u[0][l] * v[0][l] + u[1][l] * v[1][l] + u[2][l] * v[2][l]
        };
        let mut cot = [[0.0f64; LANES]; 3];
        for l in 0..LANES {
            let longest2 =
                0.0f64.max(dot(&e[0], &e[0], l)).max(dot(&e[1], &e[1], l)).max(dot(&e[2], &e[2], l));
            let c = [
                e[0][1][l] * e[1][2][l] - e[0][2][l] * e[1][1][l],
                e[0][2][l] * e[1][0][l] - e[0][0][l] * e[1][2][l],
                e[0][0][l] * e[1][1][l] - e[0][1][l] * e[1][0][l],
            ];
            let twice_area = (c[0] * c[0] + c[1] * c[1] + c[2] * c[2]).sqrt().max(COT_FLOOR * longest2);
            let inv = 1.0 / twice_area;
            for k in 0..3 {
                let v = -dot(&e[(k + 1) % 3], &e[(k + 2) % 3], l) * inv;
                cot[k][l] = if longest2 == 0.0 { 0.0 } else { v };
            }
        }
        for l in 0..LANES {
            for k in 0..3 {
                o[3 * l + k] = cot[k][l];
            }
        }
    }
    for (f, o) in blocks.remainder().iter().zip(outs.into_remainder().chunks_exact_mut(3)) {
        o.copy_from_slice(&triangle_cotangents(f.map(|i| real::to_f64(x[i as usize]))));
    }
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

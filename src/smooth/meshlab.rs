//! Operators that reproduce pymeshlab's (VCG's) coordinate smoothing filters, quirks included.
//!
//! VCG accumulates, per face-edge (a, b) with opposite corner c, a sum S and a weight C at both
//! ends. A "border" face-edge is one whose vertex pair occurs exactly once among all face-edges
//! (so a non-manifold edge is not a border, and a lone self-edge (a, a) of a degenerate face is).
//! With boundary handling on, a vertex on a border edge forgets its interior sums and averages
//! itself with its border neighbours only. The Laplacian moves x to (x + S) / (C + 1), Taubin
//! to x + lambda (S / C - x); a vertex with C <= 0 does not move.

use rayon::prelude::*;

use super::clean::Scratch;
use super::operator::{refill, Operator, ROW_CHUNK};
use crate::mesh::Adjacency;
use crate::real::{self, Real, Vec3};

/// Per-face-edge weight, as VCG computes it: float32 tan(pi/2 - angle at c), or -1 when a side
/// at c has zero length.
#[inline]
fn vcg_cotangent(xa: [f64; 3], xb: [f64; 3], xc: [f64; 3]) -> f64 {
    let u = real::sub(xb, xc);
    let v = real::sub(xa, xc);
    let (lu, lv) = (real::norm(u), real::norm(v));
    if lu == 0.0 || lv == 0.0 {
        return -1.0;
    }
    let angle = (real::dot(u, v) / (lu * lv)).clamp(-1.0, 1.0).acos() as f32;
    (std::f64::consts::FRAC_PI_2 - angle as f64).tan() as f32 as f64
}

/// VCG's weight of every face corner (face * 3 + k), the one both ends of the opposite
/// face-edge use: `vcg_cotangent` is symmetric in the edge's two ends, bit for bit.
fn corner_cotangents<T: Real>(x: &[Vec3<T>], faces: &[[u32; 3]], out: &mut Vec<f64>) {
    refill(out, faces.len() * 3);
    out.par_chunks_mut(3 * ROW_CHUNK).zip(faces.par_chunks(ROW_CHUNK)).for_each(|(cots, faces)| {
        for (o, f) in cots.chunks_exact_mut(3).zip(faces) {
            let p = f.map(|i| real::to_f64(x[i as usize]));
            for k in 0..3 {
                o[k] = vcg_cotangent(p[(k + 1) % 3], p[(k + 2) % 3], p[k]);
            }
        }
    });
}

/// Sums for one vertex: (weight of itself in S, weight per slot, C). `corner_w` holds each
/// corner's cotangent when `cotangent` is on.
fn accumulate(
    adj: &Adjacency,
    corner_w: &[f64],
    i: usize,
    cotangent: bool,
    boundary: bool,
    slot_w: &mut [f64],
) -> (f64, f64) {
    let slots = adj.slots(i);
    let self_border = adj.self_edges[i] == 1;
    let border = boundary && (self_border || adj.edge_faces(i).contains(&1));
    if border {
        // Reset to the vertex itself, then add each border neighbour once; a lone self-edge
        // adds the vertex twice (it is both ends of that border edge).
        let mut c = 1.0;
        let mut own = 1.0;
        for (k, s) in slots.enumerate() {
            slot_w[k] = if adj.edge_faces_at(s) == 1 { 1.0 } else { 0.0 };
            c += slot_w[k];
        }
        if self_border {
            own += 2.0;
            c += 2.0;
        }
        return (own, c);
    }
    let mut c = 0.0;
    if cotangent {
        // The row's corners lie together, slot after slot, in the order of `opposite_of`.
        let mut corners = adj.corners_of_run(slots.clone());
        for (w, &e) in slot_w.iter_mut().zip(adj.edge_faces(i)) {
            let (here, next) = corners.split_at(e as usize);
            corners = next;
            *w = here.iter().map(|&k| corner_w[k as usize]).sum();
            c += *w;
        }
    } else {
        for (w, &e) in slot_w.iter_mut().zip(adj.edge_faces(i)) {
            *w = e as f64;
            c += *w;
        }
    }
    // Self-edges (a, a): the vertex is both ends, so each adds its weight twice.
    let per_self = if cotangent { -1.0 } else { 1.0 };
    let own = 2.0 * per_self * adj.self_edges[i] as f64;
    (own, c + own)
}

/// The operator of `apply_coord_laplacian_smoothing`: x <- (x + S) / (C + 1). With cotangent
/// weights it depends on `x`; `scratch` lends the buffers.
pub fn laplacian<T: Real>(
    adj: &Adjacency,
    x: &[Vec3<T>],
    faces: &[[u32; 3]],
    cotangent: bool,
    boundary: bool,
    pinned: Option<&[bool]>,
    scratch: &mut Scratch,
) -> Operator {
    let mut corner_w = std::mem::take(&mut scratch.face_cot);
    if cotangent {
        corner_cotangents(x, faces, &mut corner_w);
    }
    let op = build(adj, &corner_w, cotangent, boundary, pinned, scratch, |own, c| {
        if c > 0.0 {
            Some(((own + 1.0), c + 1.0))
        } else {
            None
        }
    });
    scratch.face_cot = corner_w;
    op
}

/// The averaging operator of `apply_coord_taubin_smoothing`: S / C (uniform, border rules on).
pub fn taubin_average(adj: &Adjacency, pinned: Option<&[bool]>) -> Operator {
    let rule = |own, c| if c > 0.0 { Some((own, c)) } else { None };
    build(adj, &[], false, true, pinned, &mut Scratch::default(), rule)
}

fn build(
    adj: &Adjacency,
    corner_w: &[f64],
    cotangent: bool,
    boundary: bool,
    pinned: Option<&[bool]>,
    scratch: &mut Scratch,
    // (own weight in S, C) -> Some((self coefficient numerator, denominator)) or None to freeze.
    rule: impl Fn(f64, f64) -> Option<(f64, f64)> + Sync,
) -> Operator {
    let (self_w, w) = scratch.take_weights();
    Operator::from_rows_par(adj, pinned, self_w, w, |i, row| {
        let (own, c) = accumulate(adj, corner_w, i, cotangent, boundary, row);
        match rule(own, c) {
            Some((num, den)) => {
                row.iter_mut().for_each(|v| *v /= den);
                num / den
            }
            None => {
                row.fill(0.0);
                1.0
            }
        }
    })
}

/// The neighbour weights of `apply_coord_hc_laplacian_smoothing`: each face-edge counts once,
/// a border face-edge twice (so on a manifold mesh, a plain mean of all neighbours).
pub fn hc_average(adj: &Adjacency, pinned: Option<&[bool]>) -> Operator {
    Operator::from_rows_par(adj, pinned, Vec::new(), Vec::new(), |i, row| {
        for (r, &e) in row.iter_mut().zip(adj.edge_faces(i)) {
            *r = if e == 1 { 2.0 } else { e as f64 };
        }
        let own = match adj.self_edges[i] {
            0 => 0.0,
            1 => 4.0,
            k => 2.0 * k as f64,
        };
        let total = own + row.iter().sum::<f64>();
        if total > 0.0 {
            row.iter_mut().for_each(|r| *r /= total);
            own / total
        } else {
            1.0
        }
    })
}

/// A corner weight at least this large comes from a corner of 0 or 180 degrees (an exactly
/// collinear face: VCG's tan(pi/2 - angle) is then about 1.6e16). Ordinary weights, even of
/// needles, stay far below it.
const HUGE_WEIGHT: f64 = 1e12;

/// VCG's result, operation for operation, at the interior vertices that a collinear face's
/// huge weights reach: their sums S and C add terms of +-1.6e16 that cancel, so the result
/// depends on the order of the additions, and only VCG's own order (faces in index order, each
/// face's edges in order, x' = (x + S) / (C + 1)) reproduces pymeshlab there. Elsewhere the
/// operator's rows agree with VCG to rounding. Returns (vertex, position) for those vertices.
pub fn exact_at_collinear_faces<T: Real>(
    adj: &Adjacency,
    x: &[Vec3<T>],
    faces: &[[u32; 3]],
    corner_w: &[f64],
    pinned: Option<&[bool]>,
) -> Vec<(u32, [f64; 3])> {
    let n = x.len();
    let mut slot = vec![u32::MAX; 0];
    let mut rows: Vec<u32> = Vec::new();
    for (c, &w) in corner_w.iter().enumerate() {
        if w.abs() < HUGE_WEIGHT {
            continue;
        }
        let f = faces[c / 3];
        for v in [f[(c + 1) % 3], f[(c + 2) % 3]] {
            let i = v as usize;
            // Vertices on a border keep VCG's border rule (uniform weights): nothing huge.
            let border = adj.self_edges[i] == 1 || adj.edge_faces(i).contains(&1);
            if border || pinned.is_some_and(|p| p[i]) {
                continue;
            }
            if slot.is_empty() {
                slot = vec![u32::MAX; n];
            }
            if slot[i] == u32::MAX {
                slot[i] = rows.len() as u32;
                rows.push(v);
            }
        }
    }
    if rows.is_empty() {
        return Vec::new();
    }
    let mut sum = vec![([0.0f64; 3], 0.0f64); rows.len()];
    for (fi, f) in faces.iter().enumerate() {
        for j in 0..3 {
            let (a, b) = (f[j] as usize, f[(j + 1) % 3] as usize);
            let w = corner_w[fi * 3 + (j + 2) % 3];
            for (to, from) in [(a, b), (b, a)] {
                if slot[to] != u32::MAX {
                    let (s, c) = &mut sum[slot[to] as usize];
                    let p = real::to_f64(x[from]);
                    for k in 0..3 {
                        s[k] += p[k] * w;
                    }
                    *c += w;
                }
            }
        }
    }
    rows.iter()
        .zip(sum)
        .filter(|(_, (_, c))| *c > 0.0)
        .map(|(&v, (s, c))| {
            let p = real::to_f64(x[v as usize]);
            (v, std::array::from_fn(|k| (p[k] + s[k]) / (c + 1.0)))
        })
        .collect()
}

//! The averaging operator every smoothing method applies: avg = A x, one row per vertex.
//!
//! Rows live on the adjacency's slots, so no per-method sparse matrix is built. A row that maps
//! a vertex to itself (frozen: pinned, fixed boundary, unreferenced) makes every method leave
//! that vertex exactly where it is.

use rayon::prelude::*;

use crate::mesh::Adjacency;
use crate::real::{Real, Vec3};

/// Rows processed per parallel task: large enough to amortise scheduling, fixed so that the
/// split (and so the result) never depends on the thread count.
pub const ROW_CHUNK: usize = 2048;

#[derive(Debug, Clone)]
pub enum Operator {
    /// The plain mean of the distinct neighbours; `frozen` vertices (and vertices without
    /// neighbours) map to themselves. No weight array, so it is the fastest to apply.
    Uniform { frozen: Vec<bool> },
    /// avg_i = self_w[i] x_i + sum over slots s of i: w[s] x_nbr(s).
    Weighted { self_w: Vec<f64>, w: Vec<f64> },
}

/// 1/k for the valences most vertices have, looked up rather than divided: three divisions
/// per vertex cost as much as the memory traffic of a whole uniform step.
const RECIPROCALS: [f64; 64] = {
    let mut t = [0.0; 64];
    let mut k = 1;
    while k < 64 {
        t[k] = 1.0 / k as f64;
        k += 1;
    }
    t
};

#[inline]
fn reciprocal(k: usize) -> f64 {
    if k < RECIPROCALS.len() {
        RECIPROCALS[k]
    } else {
        1.0 / k as f64
    }
}

impl Operator {
    /// avg_i for one vertex, accumulated in f64.
    #[inline(always)]
    pub fn row<T: Real>(&self, adj: &Adjacency, x: &[Vec3<T>], i: usize) -> [f64; 3] {
        let slots = adj.slots(i);
        match self {
            Operator::Uniform { frozen } => {
                if frozen[i] || slots.is_empty() {
                    return crate::real::to_f64(x[i]);
                }
                let inv = reciprocal(slots.len());
                let mut s = [0.0f64; 3];
                for &j in &adj.nbrs[slots] {
                    let p = x[j as usize];
                    s[0] += p[0].to_f64();
                    s[1] += p[1].to_f64();
                    s[2] += p[2].to_f64();
                }
                [s[0] * inv, s[1] * inv, s[2] * inv]
            }
            Operator::Weighted { self_w, w } => {
                weighted_average(&adj.nbrs[slots.clone()], x, i, self_w[i], &w[slots])
            }
        }
    }
}

/// a x_i + sum over k of w[k] x_nbrs[k]: one weighted row applied, in f64.
#[inline]
pub fn weighted_average<T: Real>(nbrs: &[u32], x: &[Vec3<T>], i: usize, a: f64, w: &[f64]) -> [f64; 3] {
    let own = crate::real::to_f64(x[i]);
    let mut s = [a * own[0], a * own[1], a * own[2]];
    for (&ws, &j) in w.iter().zip(nbrs) {
        if ws != 0.0 {
            let p = x[j as usize];
            s[0] += ws * p[0].to_f64();
            s[1] += ws * p[1].to_f64();
            s[2] += ws * p[2].to_f64();
        }
    }
    s
}

impl Operator {
    /// A weighted operator built row by row: a pinned vertex gets the identity row; for every
    /// other vertex, `fill(i, row)` writes the weights of its slots (zeroed on entry) and returns
    /// the weight of the vertex itself.
    pub fn from_rows(
        adj: &Adjacency,
        pinned: Option<&[bool]>,
        mut fill: impl FnMut(usize, &mut [f64]) -> f64,
    ) -> Operator {
        let n = adj.n_vertices();
        let mut self_w = vec![0.0; n];
        let mut w = vec![0.0; adj.nbrs.len()];
        for i in 0..n {
            self_w[i] = if pinned.is_some_and(|p| p[i]) { 1.0 } else { fill(i, &mut w[adj.slots(i)]) };
        }
        Operator::Weighted { self_w, w }
    }
}

impl Operator {
    /// As `from_rows`, for a `fill` that needs no state of its own: rows are filled in
    /// parallel, in fixed chunks, into `self_w` and `w` (buffers of an earlier operator,
    /// reused; resized here).
    pub fn from_rows_par(
        adj: &Adjacency,
        pinned: Option<&[bool]>,
        mut self_w: Vec<f64>,
        mut w: Vec<f64>,
        fill: impl Fn(usize, &mut [f64]) -> f64 + Sync,
    ) -> Operator {
        let n = adj.n_vertices();
        refill(&mut self_w, n);
        refill(&mut w, adj.nbrs.len());
        // Each chunk of rows owns a contiguous run of slots.
        let mut w_chunks = Vec::with_capacity(n.div_ceil(ROW_CHUNK));
        let mut rest: &mut [f64] = &mut w;
        for c in 0..n.div_ceil(ROW_CHUNK) {
            let r = c * ROW_CHUNK..((c + 1) * ROW_CHUNK).min(n);
            let (head, tail) = rest.split_at_mut((adj.offsets[r.end] - adj.offsets[r.start]) as usize);
            w_chunks.push(head);
            rest = tail;
        }
        self_w.par_chunks_mut(ROW_CHUNK).zip(w_chunks.into_par_iter()).enumerate().for_each(
            |(c, (sw_chunk, w_chunk))| {
                let base = adj.offsets[c * ROW_CHUNK] as usize;
                for (k, sw) in sw_chunk.iter_mut().enumerate() {
                    let i = c * ROW_CHUNK + k;
                    let slots = adj.slots(i);
                    let row = &mut w_chunk[slots.start - base..slots.end - base];
                    row.fill(0.0);
                    *sw = if pinned.is_some_and(|p| p[i]) { 1.0 } else { fill(i, row) };
                }
            },
        );
        Operator::Weighted { self_w, w }
    }
}

/// Makes `v` hold `n` elements, reusing its memory; a first allocation is a huge-page one,
/// since weight buffers are tens of megabytes on large meshes.
pub fn refill(v: &mut Vec<f64>, n: usize) {
    if v.capacity() < n {
        *v = crate::huge_pages::filled_vec(n, 0.0);
    } else {
        v.resize(n, 0.0);
    }
}

/// Rows ahead whose neighbours are prefetched: enough to cover a memory access at the speed one
/// row is computed.
pub const PREFETCH_AHEAD: usize = 16;

/// Fills `out[i] = f(i)` in parallel, in fixed chunks, where `f` gathers `x` over row i's
/// neighbours. The neighbours of row i + PREFETCH_AHEAD are requested while row i is
/// computed: the gathers are scattered enough that the hardware prefetcher cannot guess them,
/// and waiting for them is most of a step's time.
pub fn par_rows_gathering<O: Send, E: Sync>(
    out: &mut [O],
    adj: &Adjacency,
    x: &[E],
    f: impl Fn(usize) -> O + Sync,
) {
    let n = out.len();
    out.par_chunks_mut(ROW_CHUNK).enumerate().for_each(|(c, chunk)| {
        let base = c * ROW_CHUNK;
        for (k, o) in chunk.iter_mut().enumerate() {
            let i = base + k;
            if i + PREFETCH_AHEAD < n {
                for &j in adj.neighbours(i + PREFETCH_AHEAD) {
                    prefetch(x.as_ptr().wrapping_add(j as usize));
                }
            }
            *o = f(i);
        }
    });
}

/// Fills `out[i] = f(i)` in parallel, in fixed chunks, for rows that gather nothing.
pub fn par_rows<O: Send>(out: &mut [O], f: impl Fn(usize) -> O + Sync) {
    out.par_chunks_mut(ROW_CHUNK).enumerate().for_each(|(c, chunk)| {
        let base = c * ROW_CHUNK;
        for (k, o) in chunk.iter_mut().enumerate() {
            *o = f(base + k);
        }
    });
}

#[inline(always)]
pub fn prefetch<E>(p: *const E) {
    #[cfg(target_arch = "x86_64")]
    // SAFETY: a prefetch is only a hint; it never faults, whatever the address.
    unsafe {
        std::arch::x86_64::_mm_prefetch(p as *const i8, std::arch::x86_64::_MM_HINT_T0)
    }
    #[cfg(not(target_arch = "x86_64"))]
    let _ = p;
}

#[inline]
pub fn from_f64<T: Real>(p: [f64; 3]) -> Vec3<T> {
    [T::from_f64(p[0]), T::from_f64(p[1]), T::from_f64(p[2])]
}

impl Operator {
    /// Is row i the identity (a vertex that never moves)?
    pub fn is_identity(&self, adj: &Adjacency, i: usize) -> bool {
        match self {
            Operator::Uniform { frozen } => frozen[i] || adj.slots(i).is_empty(),
            Operator::Weighted { self_w, w } => self_w[i] == 1.0 && w[adj.slots(i)].iter().all(|&v| v == 0.0),
        }
    }

    /// A_ii, the diagonal the solver's preconditioner needs.
    pub fn diagonal(&self, adj: &Adjacency, i: usize) -> f64 {
        match self {
            Operator::Uniform { frozen } => {
                if frozen[i] || adj.slots(i).is_empty() {
                    1.0
                } else {
                    0.0
                }
            }
            Operator::Weighted { self_w, .. } => self_w[i],
        }
    }
}

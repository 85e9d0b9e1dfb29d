//! Every undirected edge of a mesh once, with the faces that use it, derived from the
//! face-edge buckets (`mesh::buckets`).
//!
//! Edges are stored smaller index first and sorted lexicographically, (a, b) before (a, c) when
//! b < c: the order every edge list of `crate::edges` inherits. An edge's face-edges are the
//! (face, direction) pairs whose face walks along it; a collapsed face, one that repeats an
//! index like (a, a, b), is a line and uses no edge. Each vertex's bucket holds the
//! face-edges whose smaller end it is, so sorting the buckets one by one meets every edge once,
//! in order, at a cost of O(faces) that depends neither on face order within a bucket nor on
//! the thread count.

use rayon::prelude::*;

use super::buckets::Buckets;
use crate::error::Result;
use crate::huge_pages::with_capacity;

/// One face walking along an edge: `face` and whether it walks from the larger index to the
/// smaller (`reversed`).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct FaceUse {
    pub face: u32,
    pub reversed: bool,
}

impl FaceUse {
    /// Decodes a face-edge tag, face << 1 | reversed (the low 32 bits of a bucket entry).
    #[inline]
    pub fn unpack(tag: u32) -> FaceUse {
        FaceUse { face: tag >> 1, reversed: tag & 1 == 1 }
    }
}

/// Vertices per parallel task when visiting buckets (fixed, so results never depend on the
/// thread count).
const CHUNK: usize = 8192;
/// How many buckets ahead `visit_edges` hands to its prefetch hook.
const PREFETCH_BUCKETS: usize = 4;

impl Buckets<u64> {
    /// Sorts every face-edge bucket and calls `visit(state, [a, b], entries)` for each distinct
    /// edge, in lexicographic order, with its entries ascending (by face, then direction),
    /// within fixed chunks of vertices that run in parallel; returns each chunk's state, in
    /// order (`init` is told how many face-edges its chunk has). Before a bucket is visited,
    /// `prefetch` sees the (unsorted) entries of a bucket a few vertices ahead, to start
    /// loading what the visitor will need.
    pub fn visit_edges<S: Send>(
        &mut self,
        init: impl Fn(usize) -> S + Sync,
        prefetch: impl Fn(&[u64]) + Sync,
        visit: impl Fn(&mut S, [u32; 2], &[u64]) + Sync,
    ) -> Vec<S> {
        let n_vertices = self.n_vertices();
        let start = &self.start;
        let n_chunks = n_vertices.div_ceil(CHUNK);
        let mut pieces: Vec<&mut [u64]> = Vec::with_capacity(n_chunks);
        let mut rest: &mut [u64] = &mut self.entries;
        for c in 0..n_chunks {
            let hi = ((c + 1) * CHUNK).min(n_vertices);
            let len = (start[hi] - start[c * CHUNK]) as usize;
            let (head, tail) = rest.split_at_mut(len);
            pieces.push(head);
            rest = tail;
        }
        pieces
            .into_par_iter()
            .enumerate()
            .map(|(c, piece)| {
                let v0 = c * CHUNK;
                let v1 = ((c + 1) * CHUNK).min(n_vertices);
                let base = start[v0] as usize;
                let mut state = init(piece.len());
                for a in v0..v1 {
                    let ahead = (a + PREFETCH_BUCKETS).min(v1 - 1);
                    prefetch(&piece[start[ahead] as usize - base..start[ahead + 1] as usize - base]);
                    let bucket = &mut piece[start[a] as usize - base..start[a + 1] as usize - base];
                    bucket.sort_unstable();
                    for run in bucket.chunk_by(|x, y| x >> 32 == y >> 32) {
                        visit(&mut state, [a as u32, (run[0] >> 32) as u32], run);
                    }
                }
                state
            })
            .collect()
    }
}

#[derive(Debug, Clone)]
pub struct EdgeTable {
    /// Unique edges (a, b), a < b, in lexicographic order.
    pub edges: Vec<[u32; 2]>,
    /// `uses[use_offsets[e]..use_offsets[e + 1]]` are edge e's bucket entries (see
    /// `Buckets::face_edges`), ascending by face.
    pub use_offsets: Vec<u32>,
    uses: Vec<u64>,
}

impl EdgeTable {
    pub fn build(n_vertices: usize, faces: &[[u32; 3]]) -> Result<EdgeTable> {
        let buckets = Buckets::face_edges(n_vertices, faces)?;
        Ok(crate::parallel::install(|| EdgeTable::from_buckets(buckets)))
    }

    /// The table from face-edge buckets, whose sorted entries become its face uses.
    pub fn from_buckets(mut buckets: Buckets<u64>) -> EdgeTable {
        // About two face-edges per edge (exactly so on a closed manifold mesh): room for that,
        // so the parts rarely grow.
        let per_chunk = buckets.visit_edges(
            |face_edges| (Vec::with_capacity(face_edges / 2 + 64), Vec::with_capacity(face_edges / 2 + 64)),
            |_| {},
            |(edges, counts): &mut (Vec<[u32; 2]>, Vec<u32>), edge, uses| {
                edges.push(edge);
                counts.push(uses.len() as u32);
            },
        );
        let n_edges: usize = per_chunk.iter().map(|(e, _)| e.len()).sum();
        let mut edges = with_capacity(n_edges);
        let mut use_offsets = with_capacity(n_edges + 1);
        use_offsets.push(0u32);
        let mut acc = 0u32;
        for (e, counts) in per_chunk {
            edges.extend_from_slice(&e);
            for c in counts {
                acc += c;
                use_offsets.push(acc);
            }
        }
        EdgeTable { edges, use_offsets, uses: buckets.entries }
    }

    pub fn len(&self) -> usize {
        self.edges.len()
    }

    pub fn is_empty(&self) -> bool {
        self.edges.is_empty()
    }

    /// How many face-edges lie on edge `e` (1: boundary, 2: manifold, 3+: non-manifold).
    #[inline]
    pub fn face_count(&self, e: usize) -> usize {
        (self.use_offsets[e + 1] - self.use_offsets[e]) as usize
    }

    /// Starts loading `data[f]` for the (first two) faces on edge `e`, if it exists: loops
    /// over edges read per-face data in an order the hardware prefetcher cannot guess, and those
    /// cache misses were the largest single cost of finding creases.
    #[inline(always)]
    pub fn prefetch_faces<T>(&self, e: usize, data: &[T]) {
        if e < self.len() {
            for u in self.uses(e).take(2) {
                prefetch(data, u.face as usize);
            }
        }
    }

    /// The face-edges on edge `e`, by ascending face index.
    #[inline]
    pub fn uses(&self, e: usize) -> impl ExactSizeIterator<Item = FaceUse> + '_ {
        self.uses[self.use_offsets[e] as usize..self.use_offsets[e + 1] as usize]
            .iter()
            .map(|&t| FaceUse::unpack(t as u32))
    }
}

/// Asks the CPU to start loading `data[i]` (any `i`: a prefetch is only a hint and never faults).
#[inline(always)]
pub fn prefetch<T>(data: &[T], i: usize) {
    #[cfg(target_arch = "x86_64")]
    {
        let p = data.as_ptr().wrapping_add(i);
        // SAFETY: prefetching never faults, whatever the address.
        #[allow(unused_unsafe)]
        unsafe {
            std::arch::x86_64::_mm_prefetch::<{ std::arch::x86_64::_MM_HINT_T0 }>(p as *const i8)
        };
    }
    #[cfg(not(target_arch = "x86_64"))]
    let _ = (data, i);
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn square_and_fan() {
        // two triangles sharing 0-2, plus a third face on 0-2 (non-manifold)
        let t = EdgeTable::build(5, &[[0, 1, 2], [0, 2, 3], [2, 0, 4]]).unwrap();
        assert_eq!(t.edges, vec![[0, 1], [0, 2], [0, 3], [0, 4], [1, 2], [2, 3], [2, 4]]);
        assert_eq!(t.face_count(1), 3);
        let u: Vec<FaceUse> = t.uses(1).collect();
        assert_eq!(
            u,
            vec![
                FaceUse { face: 0, reversed: true },
                FaceUse { face: 1, reversed: false },
                FaceUse { face: 2, reversed: true }
            ]
        );
    }

    #[test]
    fn a_collapsed_face_uses_no_edge() {
        // a pole stored as copies of one vertex, welded: (0, 2, 0) walks 0-2 there and back
        let t = EdgeTable::build(4, &[[0, 1, 2], [0, 2, 0], [0, 2, 3]]).unwrap();
        assert_eq!(t.edges, vec![[0, 1], [0, 2], [0, 3], [1, 2], [2, 3]]);
        let u: Vec<FaceUse> = t.uses(1).collect();
        assert_eq!(u, vec![FaceUse { face: 0, reversed: true }, FaceUse { face: 2, reversed: false }]);
    }

    #[test]
    fn matches_a_brute_force_table_on_a_messy_mesh() {
        use std::collections::BTreeMap;
        let n = 40;
        let faces = crate::mesh::shapes::random_faces(5, n, 300);
        let mut expect: BTreeMap<[u32; 2], Vec<FaceUse>> = BTreeMap::new();
        for (fi, f) in faces.iter().enumerate() {
            for j in 0..3 {
                let (a, b) = (f[j], f[(j + 1) % 3]);
                if f[0] != f[1] && f[1] != f[2] && f[0] != f[2] {
                    let u = FaceUse { face: fi as u32, reversed: a > b };
                    expect.entry([a.min(b), a.max(b)]).or_default().push(u);
                }
            }
        }
        for uses in expect.values_mut() {
            uses.sort_by_key(|u| (u.face, u.reversed));
        }
        let t = EdgeTable::build(n, &faces).unwrap();
        let got: BTreeMap<[u32; 2], Vec<FaceUse>> =
            (0..t.len()).map(|e| (t.edges[e], t.uses(e).collect())).collect();
        assert_eq!(got, expect);
        assert!(t.edges.windows(2).all(|w| w[0] < w[1]));
    }
}

//! Every undirected edge of a mesh once, with the faces that use it.
//!
//! Edges are stored smaller index first and sorted lexicographically, (a, b) before (a, c) when
//! b < c: the order every edge list of `crate::edges` inherits. An edge's face-edges are the
//! (face, direction) pairs whose face walks along it; a face that repeats an index, like
//! (a, a, b), uses a-b twice and never has a self-edge a-a. Built with a counting sort on the
//! smaller vertex, so it costs O(faces) and does not depend on face order within a bucket or on
//! the thread count.

use rayon::prelude::*;

use crate::error::{Error, Result};
use crate::huge_pages::{filled_vec, with_capacity};

/// One face walking along an edge: `face` and whether it walks from the larger index to the
/// smaller (`reversed`).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct FaceUse {
    pub face: u32,
    pub reversed: bool,
}

impl FaceUse {
    /// Decodes the low 32 bits of a bucket entry (face << 1 | reversed).
    #[inline]
    pub fn unpack(entry: u64) -> FaceUse {
        let tag = entry as u32;
        FaceUse { face: tag >> 1, reversed: tag & 1 == 1 }
    }
}

/// Face-edges bucketed by their smaller vertex with a counting sort; each entry is
/// larger vertex << 32 | face << 1 | reversed, so sorting a bucket sorts by the other end, then
/// face, then direction.
pub struct Buckets {
    start: Vec<u32>,
    entries: Vec<u64>,
}

/// Vertices per parallel task when visiting buckets (fixed, so results never depend on the
/// thread count).
const CHUNK: usize = 8192;
/// How many buckets ahead `visit` hands to its prefetch hook.
const PREFETCH_BUCKETS: usize = 4;

impl Buckets {
    pub fn build(n_vertices: usize, faces: &[[u32; 3]]) -> Result<Buckets> {
        if faces.len() >= (1usize << 31) / 3 {
            return Err(Error::invalid(
                "faces",
                format!("{} faces is more than toonmesh supports", faces.len()),
            ));
        }
        let mut start = vec![0u32; n_vertices + 1];
        for f in faces {
            for j in 0..3 {
                let (a, b) = (f[j], f[(j + 1) % 3]);
                if a != b {
                    start[a.min(b) as usize + 1] += 1;
                }
            }
        }
        for i in 0..n_vertices {
            start[i + 1] += start[i];
        }
        let total = start[n_vertices] as usize;
        let mut entries = filled_vec(total, 0u64);
        let mut cursor = start.clone();
        for (fi, f) in faces.iter().enumerate() {
            for j in 0..3 {
                let (a, b) = (f[j], f[(j + 1) % 3]);
                if a != b {
                    let (lo, hi, rev) = if a < b { (a, b, 0) } else { (b, a, 1) };
                    let slot = &mut cursor[lo as usize];
                    entries[*slot as usize] = (hi as u64) << 32 | ((fi as u64) << 1 | rev);
                    *slot += 1;
                }
            }
        }
        Ok(Buckets { start, entries })
    }

    /// Sorts every bucket and calls `visit(state, [a, b], entries)` for each distinct edge, in
    /// lexicographic order within fixed chunks of vertices that run in parallel; returns each
    /// chunk's state, in order. Before a bucket is visited, `prefetch` sees the (unsorted)
    /// entries of a bucket a few vertices ahead, to start loading what the visitor will need.
    pub fn visit<S: Send>(
        &mut self,
        init: impl Fn() -> S + Sync,
        prefetch: impl Fn(&[u64]) + Sync,
        visit: impl Fn(&mut S, [u32; 2], &[u64]) + Sync,
    ) -> Vec<S> {
        let n_vertices = self.start.len() - 1;
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
                let mut state = init();
                for a in v0..v1 {
                    let ahead = (a + PREFETCH_BUCKETS).min(v1 - 1);
                    prefetch(&piece[start[ahead] as usize - base..start[ahead + 1] as usize - base]);
                    let bucket = &mut piece[start[a] as usize - base..start[a + 1] as usize - base];
                    bucket.sort_unstable();
                    let mut k = 0;
                    while k < bucket.len() {
                        let b = (bucket[k] >> 32) as u32;
                        let mut e = k + 1;
                        while e < bucket.len() && (bucket[e] >> 32) as u32 == b {
                            e += 1;
                        }
                        visit(&mut state, [a as u32, b], &bucket[k..e]);
                        k = e;
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
    /// `uses[use_offsets[e]..use_offsets[e + 1]]` are edge e's bucket entries (see `Buckets`),
    /// ascending by face.
    pub use_offsets: Vec<u32>,
    uses: Vec<u64>,
}

impl EdgeTable {
    pub fn build(n_vertices: usize, faces: &[[u32; 3]]) -> Result<EdgeTable> {
        let mut buckets = Buckets::build(n_vertices, faces)?;
        let per_chunk = buckets.visit(
            || (Vec::new(), Vec::new()),
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
        Ok(EdgeTable { edges, use_offsets, uses: buckets.entries })
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
            .map(|&t| FaceUse::unpack(t))
    }
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
    fn repeated_index_uses_edge_twice() {
        let t = EdgeTable::build(2, &[[0, 0, 1]]).unwrap();
        assert_eq!(t.edges, vec![[0, 1]]);
        assert_eq!(t.face_count(0), 2);
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

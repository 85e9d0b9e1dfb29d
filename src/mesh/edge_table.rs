//! Every undirected edge of a mesh once, with the faces that use it, derived from the corner
//! table (`mesh::corners`).
//!
//! Edges are stored smaller index first and sorted lexicographically, (a, b) before (a, c) when
//! b < c: the order every edge list of `crate::edges` inherits. An edge's face-edges are the
//! (face, direction) pairs whose face walks along it; a face that repeats an index, like
//! (a, a, b), uses a-b twice and never has a self-edge a-a. The face-edges whose smaller end is
//! a are found among the corners at a (v -> next and prev -> v lead to larger vertices), so a
//! sweep over vertices sorts each vertex's few of them and meets every edge once, in order, at
//! a cost of O(faces) that depends neither on face order nor on the thread count.

use rayon::prelude::*;

use super::corners::{CornerTable, RingCorner};
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
    /// Decodes a face-edge tag, face << 1 | reversed (the low 32 bits of a sweep's sort key).
    #[inline]
    pub fn unpack(tag: u32) -> FaceUse {
        FaceUse { face: tag >> 1, reversed: tag & 1 == 1 }
    }
}

/// Vertices per parallel task in the sweep (fixed, so results never depend on the thread
/// count).
const CHUNK: usize = 8192;
/// How many vertices ahead the sweep hands the faces at a vertex to its prefetch hook.
const PREFETCH_VERTICES: usize = 4;

/// Sweeps the edges of the mesh whose corner table is `table`: calls `visit(state, [a, b],
/// keys)` for each edge in lexicographic order, with a state per chunk from `init(corners in
/// the chunk)`, where `keys` are its face-edges as
/// b << 32 | face << 1 | reversed, ascending (so by face, then direction), within fixed chunks
/// of vertices that run in parallel; returns each chunk's state, in order. Before a vertex is
/// swept, `prefetch(face)` sees the faces at a vertex a few ahead, to start loading what the
/// visitor will need.
pub fn sweep<S: Send>(
    table: &CornerTable<RingCorner>,
    init: impl Fn(usize) -> S + Sync,
    prefetch: impl Fn(u32) + Sync,
    visit: impl Fn(&mut S, [u32; 2], &[u64]) + Sync,
) -> Vec<S> {
    let n = table.n_vertices();
    (0..n.div_ceil(CHUNK))
        .into_par_iter()
        .map(|c| {
            let (v0, v1) = (c * CHUNK, ((c + 1) * CHUNK).min(n));
            let mut state = init((table.start[v1] - table.start[v0]) as usize);
            let mut keys: Vec<u64> = Vec::with_capacity(32);
            for a in v0..v1 {
                for e in table.at((a + PREFETCH_VERTICES).min(v1 - 1)) {
                    prefetch(e[2] / 3);
                }
                upper_face_edges(a as u32, table.at(a), &mut keys);
                keys.sort_unstable();
                for run in keys.chunk_by(|x, y| x >> 32 == y >> 32) {
                    visit(&mut state, [a as u32, (run[0] >> 32) as u32], run);
                }
            }
            state
        })
        .collect()
}

/// The face-edges at a's corners that lead to a larger vertex, as sort keys
/// other << 32 | face << 1 | reversed: a -> next walks up from a, prev -> a walks down to it.
#[inline(always)]
fn upper_face_edges(a: u32, corners: &[RingCorner], keys: &mut Vec<u64>) {
    keys.clear();
    for &[next, prev, id] in corners {
        let tag = (id / 3) << 1;
        if next > a {
            keys.push((next as u64) << 32 | tag as u64);
        }
        if prev > a {
            keys.push((prev as u64) << 32 | (tag | 1) as u64);
        }
    }
}

#[derive(Debug, Clone)]
pub struct EdgeTable {
    /// Unique edges (a, b), a < b, in lexicographic order.
    pub edges: Vec<[u32; 2]>,
    /// `uses[use_offsets[e]..use_offsets[e + 1]]` are edge e's face-edge tags (see `FaceUse`),
    /// ascending by face.
    pub use_offsets: Vec<u32>,
    uses: Vec<u32>,
}

/// One sweep chunk's edges, their face-edge tags and how many tags each has.
struct Part {
    edges: Vec<[u32; 2]>,
    tags: Vec<u32>,
    counts: Vec<u32>,
}

impl EdgeTable {
    pub fn build(n_vertices: usize, faces: &[[u32; 3]]) -> Result<EdgeTable> {
        let table = CornerTable::with_ids(n_vertices, faces)?;
        Ok(crate::parallel::install(|| EdgeTable::from_corners(&table)))
    }

    pub fn from_corners(table: &CornerTable<RingCorner>) -> EdgeTable {
        // A chunk holds about one face-edge per corner and an edge per two (exactly so on a
        // closed manifold mesh): room for that, so the parts rarely grow.
        let room = |corners: usize| Part {
            edges: Vec::with_capacity(corners / 2 + 64),
            tags: Vec::with_capacity(corners + 64),
            counts: Vec::with_capacity(corners / 2 + 64),
        };
        let parts = sweep(
            table,
            room,
            |_| {},
            |p: &mut Part, edge, keys| {
                p.edges.push(edge);
                p.tags.extend(keys.iter().map(|&k| k as u32));
                p.counts.push(keys.len() as u32);
            },
        );
        let mut use_offsets = with_capacity(parts.iter().map(|p| p.counts.len()).sum::<usize>() + 1);
        use_offsets.push(0u32);
        let mut acc = 0u32;
        for c in parts.iter().flat_map(|p| &p.counts) {
            acc += c;
            use_offsets.push(acc);
        }
        let edges = concatenate(parts.iter().map(|p| &p.edges[..]).collect());
        let uses = concatenate(parts.iter().map(|p| &p.tags[..]).collect());
        EdgeTable { edges, use_offsets, uses }
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

/// The pieces one after another, copied by every thread into a huge-page buffer.
fn concatenate<T: Copy + Send + Sync>(pieces: Vec<&[T]>) -> Vec<T> {
    let total = pieces.iter().map(|p| p.len()).sum();
    let mut out: Vec<T> = with_capacity(total);
    let mut rest = &mut out.spare_capacity_mut()[..total];
    let mut targets = Vec::with_capacity(pieces.len());
    for p in &pieces {
        let (head, tail) = rest.split_at_mut(p.len());
        targets.push(head);
        rest = tail;
    }
    targets.into_par_iter().zip(pieces).for_each(|(dst, src)| {
        for (d, &s) in dst.iter_mut().zip(src) {
            d.write(s);
        }
    });
    // SAFETY: the pieces fill 0..total exactly, and each was written above.
    unsafe { out.set_len(total) };
    out
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
    fn repeated_index_uses_edge_twice() {
        let t = EdgeTable::build(2, &[[0, 0, 1]]).unwrap();
        assert_eq!(t.edges, vec![[0, 1]]);
        assert_eq!(t.face_count(0), 2);
        let u: Vec<FaceUse> = t.uses(0).collect();
        assert_eq!(u, vec![FaceUse { face: 0, reversed: false }, FaceUse { face: 0, reversed: true }]);
    }

    #[test]
    fn matches_a_brute_force_table_on_a_messy_mesh() {
        use std::collections::BTreeMap;
        let mut rng = crate::mesh::shapes::SplitMix64::new(5);
        let n = 40;
        let faces: Vec<[u32; 3]> =
            (0..300).map(|_| [0, 1, 2].map(|_| (rng.next_u64() % n as u64) as u32)).collect();
        let mut expect: BTreeMap<[u32; 2], Vec<FaceUse>> = BTreeMap::new();
        for (fi, f) in faces.iter().enumerate() {
            for j in 0..3 {
                let (a, b) = (f[j], f[(j + 1) % 3]);
                if a != b {
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

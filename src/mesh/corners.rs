//! The corner table: every face corner filed under its vertex, the one connectivity structure
//! that smoothing and outlines share.
//!
//! For vertex v, `corners(v)` lists the corners at v in face order, each with the vertex after
//! it and the vertex before it in its face (and, when asked for, the corner's own id,
//! face * 3 + position). The two face-edges at a corner are v -> next and prev -> v, so
//! everything about edges is here: v's one-ring is the union of its corners' next and prev
//! (`Adjacency`), and the face-edges whose smaller end is v are the ones among them that lead to
//! a larger vertex (`EdgeTable`). Both are derived from this table; nothing else buckets faces.
//!
//! Built with one counting sort, in parallel: the faces are split into a few parts in face
//! order, each part counts its corners per vertex, a two-level prefix sum over vertex ranges
//! turns the counts into each part's first slot per vertex, and every part writes its corners
//! there. Parts follow face order, so the table is the same for any thread count. Buffers are
//! advised for huge pages: their first-touch faults cost as much as filling them.

use rayon::prelude::*;

use crate::error::{Error, Result};
use crate::huge_pages;

/// One corner at a vertex: the vertices after and before it in its face.
pub trait Corner: Copy + Send + Sync {
    fn next(&self) -> u32;
    fn prev(&self) -> u32;
}

/// A corner with the vertices after and before it, `[next, prev]`.
pub type Ring = [u32; 2];

/// A corner with the vertices after and before it and its id, `[next, prev, face * 3 + k]`.
pub type RingCorner = [u32; 3];

impl Corner for Ring {
    #[inline(always)]
    fn next(&self) -> u32 {
        self[0]
    }
    #[inline(always)]
    fn prev(&self) -> u32 {
        self[1]
    }
}

impl Corner for RingCorner {
    #[inline(always)]
    fn next(&self) -> u32 {
        self[0]
    }
    #[inline(always)]
    fn prev(&self) -> u32 {
        self[1]
    }
}

/// The corner across the face-edge v -> next from the corner `id` at v (the third corner of
/// its face), and the one across prev -> v.
#[inline(always)]
pub fn across_next(id: u32) -> u32 {
    let k = id % 3;
    id - k + if k == 0 { 2 } else { k - 1 }
}

#[inline(always)]
pub fn across_prev(id: u32) -> u32 {
    let k = id % 3;
    id - k + if k == 2 { 0 } else { k + 1 }
}

/// Larger than any vertex index (`CornerTable` refuses meshes that reach it).
pub const NOT_A_VERTEX: u32 = u32::MAX - 1;

pub struct CornerTable<E> {
    /// `entries[start[v]..start[v + 1]]` are the corners at v, in face order.
    pub start: Vec<u32>,
    pub entries: Vec<E>,
}

impl CornerTable<Ring> {
    /// The table with each corner's next and prev vertex (what one-rings need).
    pub fn rings(n_vertices: usize, faces: &[[u32; 3]]) -> Result<Self> {
        Self::build(n_vertices, faces, |f, j, _| [f[(j + 1) % 3], f[(j + 2) % 3]])
    }
}

impl CornerTable<RingCorner> {
    /// The table with each corner's next and prev vertex and its id (what opposite corners and
    /// the faces on an edge need).
    pub fn with_ids(n_vertices: usize, faces: &[[u32; 3]]) -> Result<Self> {
        Self::build(n_vertices, faces, |f, j, face| [f[(j + 1) % 3], f[(j + 2) % 3], face * 3 + j as u32])
    }
}

impl<E: Copy + Send + Sync> CornerTable<E> {
    pub fn n_vertices(&self) -> usize {
        self.start.len() - 1
    }

    /// The corners at vertex v.
    #[inline(always)]
    pub fn at(&self, v: usize) -> &[E] {
        &self.entries[self.start[v] as usize..self.start[v + 1] as usize]
    }

    /// `entry(face, k, face index)` for every face corner, grouped by the corner's vertex in
    /// face order.
    fn build(
        n: usize,
        faces: &[[u32; 3]],
        entry: impl Fn(&[u32; 3], usize, u32) -> E + Send + Sync,
    ) -> Result<Self> {
        check_size(n, faces)?;
        Ok(crate::parallel::install(|| Self::counting_sort(n, faces, entry)))
    }

    fn counting_sort(
        n: usize,
        faces: &[[u32; 3]],
        entry: impl Fn(&[u32; 3], usize, u32) -> E + Sync,
    ) -> Self {
        let parts = rayon::current_num_threads().clamp(1, 8);
        let per = faces.len().div_ceil(parts).max(1);
        let chunks: Vec<&[[u32; 3]]> = faces.chunks(per).collect();
        let mut cursors: Vec<Vec<u32>> = chunks
            .par_iter()
            .map(|ch| {
                let mut c = huge_pages::filled_vec(n, 0u32);
                for f in ch.iter() {
                    for &v in f {
                        c[v as usize] += 1;
                    }
                }
                c
            })
            .collect();
        // start[v], and (in place of the counts) where each part writes its first corner of v:
        // parts in face order. A two-level prefix sum: totals per vertex range, then each range.
        let ranges = vertex_chunks(n);
        let range_totals: Vec<u32> = ranges
            .par_iter()
            .map(|r| cursors.iter().map(|c| c[r.clone()].iter().sum::<u32>()).sum())
            .collect();
        let mut range_start = Vec::with_capacity(ranges.len());
        let mut acc = 0u32;
        for t in &range_totals {
            range_start.push(acc);
            acc += t;
        }
        let mut start: Vec<u32> = huge_pages::filled_vec(n + 1, 0);
        start[n] = acc;
        {
            let mut per_part: Vec<Vec<&mut [u32]>> =
                cursors.iter_mut().map(|c| split_by(c, &ranges, |r| r.start)).collect();
            let mut by_range: Vec<Vec<&mut [u32]>> = (0..ranges.len()).map(|_| Vec::new()).collect();
            for part in per_part.iter_mut() {
                for (k, piece) in part.drain(..).enumerate() {
                    by_range[k].push(piece);
                }
            }
            split_by(&mut start[..n], &ranges, |r| r.start)
                .into_par_iter()
                .zip(by_range.into_par_iter())
                .zip(range_start.par_iter())
                .for_each(|((st, mut parts), &base)| {
                    let mut acc = base;
                    for (k, s) in st.iter_mut().enumerate() {
                        *s = acc;
                        for c in parts.iter_mut() {
                            let count = c[k];
                            c[k] = acc;
                            acc += count;
                        }
                    }
                });
        }
        let mut entries: Vec<E> = huge_pages::with_capacity(acc as usize);
        let out = SharedSlice(entries.as_mut_ptr());
        chunks.par_iter().zip(cursors.par_iter_mut()).enumerate().for_each(|(p, (ch, cur))| {
            let out = &out;
            for (local, f) in ch.iter().enumerate() {
                let face = (p * per + local) as u32;
                for j in 0..3 {
                    let v = f[j] as usize;
                    // SAFETY: each part writes only inside the index ranges its own cursors
                    // cover, which are disjoint from every other part's, and together they
                    // cover 0..acc exactly once.
                    unsafe { out.write(cur[v] as usize, entry(f, j, face)) };
                    cur[v] += 1;
                }
            }
        });
        // SAFETY: every index in 0..acc was written above.
        unsafe { entries.set_len(acc as usize) };
        CornerTable { start, entries }
    }
}

/// The limits every index type of the table (and of what is derived from it) is sized for:
/// corner ids face * 3 + k, face-edge tags face << 1 | reversed and twice the corners fit in
/// 32 bits, and vertices stay below `NOT_A_VERTEX`.
fn check_size(n_vertices: usize, faces: &[[u32; 3]]) -> Result<()> {
    if faces.len() > (u32::MAX as usize) / 6 {
        return Err(Error::invalid("faces", format!("{} faces is more than toonmesh supports", faces.len())));
    }
    if n_vertices >= NOT_A_VERTEX as usize {
        return Err(Error::invalid(
            "vertices",
            format!("{n_vertices} vertices is more than toonmesh supports"),
        ));
    }
    Ok(())
}

struct SharedSlice<E>(*mut E);
unsafe impl<E: Send> Sync for SharedSlice<E> {}
impl<E> SharedSlice<E> {
    /// # Safety
    /// `i` is in bounds and no other thread writes index `i`.
    unsafe fn write(&self, i: usize, v: E) {
        *self.0.add(i) = v;
    }
}

/// Vertices per parallel task in the passes over the table: fixed, so that no result depends
/// on the thread count.
pub const VERTEX_CHUNK: usize = 4096;

pub fn vertex_chunks(n: usize) -> Vec<std::ops::Range<usize>> {
    (0..n.div_ceil(VERTEX_CHUNK)).map(|c| c * VERTEX_CHUNK..((c + 1) * VERTEX_CHUNK).min(n)).collect()
}

/// Splits `data` into consecutive pieces, one per vertex range, each starting at `at(range)`.
pub fn split_by<'a, T>(
    data: &'a mut [T],
    ranges: &[std::ops::Range<usize>],
    at: impl Fn(&std::ops::Range<usize>) -> usize,
) -> Vec<&'a mut [T]> {
    let mut out = Vec::with_capacity(ranges.len());
    let mut rest = data;
    let mut pos = ranges.first().map(&at).unwrap_or(0);
    for k in 0..ranges.len() {
        let end = ranges.get(k + 1).map(&at).unwrap_or(pos + rest.len());
        let (head, tail) = rest.split_at_mut(end - pos);
        out.push(head);
        rest = tail;
        pos = end;
    }
    out
}

pub fn prefix_sum(counts: &[u32]) -> Vec<u32> {
    let mut out = Vec::with_capacity(counts.len() + 1);
    let mut acc = 0u32;
    out.push(0);
    for c in counts {
        acc += c;
        out.push(acc);
    }
    out
}

/// Sorts 8 values with a fixed network (19 comparators; checked on every 0-1 input by a
/// test), unrolled so that they stay in registers: small rings are sorted branch-free, since
/// which of them hold surprises is unpredictable.
#[inline(always)]
pub fn sort8<T: Ord + Copy>(a: &mut [T; 8]) {
    macro_rules! exchange {
        ($($i:literal $j:literal),*) => {$(
            let (x, y) = (a[$i], a[$j]);
            a[$i] = x.min(y);
            a[$j] = x.max(y);
        )*};
    }
    exchange!(0 2, 1 3, 4 6, 5 7, 0 4, 1 5, 2 6, 3 7, 0 1, 2 3, 4 5, 6 7, 2 4, 3 5, 1 4, 3 6, 1 2, 3 4,
        5 6);
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_sorting_network_sorts_every_zero_one_input() {
        for bits in 0u32..256 {
            let mut a: [u32; 8] = std::array::from_fn(|i| (bits >> i) & 1);
            sort8(&mut a);
            assert!(a.windows(2).all(|w| w[0] <= w[1]), "{bits:b}");
        }
    }

    #[test]
    fn corners_are_filed_under_their_vertex_in_face_order() {
        let faces = [[0, 1, 2], [2, 1, 3], [0, 0, 3]];
        let t = CornerTable::with_ids(5, &faces).unwrap();
        assert_eq!(t.at(0), &[[1, 2, 0], [0, 3, 6], [3, 0, 7]]);
        assert_eq!(t.at(1), &[[2, 0, 1], [3, 2, 4]]);
        assert_eq!(t.at(3), &[[2, 1, 5], [0, 0, 8]]);
        assert!(t.at(4).is_empty());
        let r = CornerTable::rings(5, &faces).unwrap();
        assert_eq!(r.start, t.start);
        assert!(r.entries.iter().zip(&t.entries).all(|(a, b)| a[..] == b[..2]));
    }

    #[test]
    fn the_corners_across_a_corners_two_edges() {
        for face in [0u32, 7] {
            for k in 0..3u32 {
                let id = face * 3 + k;
                // v -> next is the side opposite the corner before v, prev -> v the one after.
                assert_eq!(across_next(id), face * 3 + (k + 2) % 3);
                assert_eq!(across_prev(id), face * 3 + (k + 1) % 3);
            }
        }
    }

    #[test]
    fn the_table_does_not_depend_on_the_thread_count() {
        let (_, faces) = crate::mesh::shapes::icosphere(4, 0.0, 0).unwrap();
        let n = 2562;
        let entry = |f: &[u32; 3], j: usize, face: u32| [f[(j + 1) % 3], f[(j + 2) % 3], face * 3 + j as u32];
        let with = |threads: usize| {
            let pool = rayon::ThreadPoolBuilder::new().num_threads(threads).build().unwrap();
            pool.install(|| CornerTable::counting_sort(n, &faces, entry))
        };
        let (one, five) = (with(1), with(5));
        assert_eq!((one.start, one.entries), (five.start, five.entries));
    }
}

//! Face items bucketed by vertex with one counting sort: the builder behind all connectivity,
//! which smoothing and outlines share.
//!
//! Two fillings of the same structure. *Corner buckets* file every face corner under its
//! vertex, with the vertex after it and the vertex before it in its face (and, when asked for,
//! the corner's id, face * 3 + position); the two face-edges at a corner at v are v -> next and
//! prev -> v, so v's one-ring is the union of its corners' next and prev (`Adjacency`).
//! *Face-edge buckets* file every face-edge under its smaller end, tagged with its other end,
//! its face and its direction, so sorting a bucket meets each edge of that vertex once, with
//! its faces (`EdgeTable`).
//!
//! The counting sort runs in parallel: the faces are split into a few parts in face order (one
//! per thread), each part counts its items per vertex, a two-level prefix sum over vertex ranges turns the counts
//! into each part's first slot per vertex, and every part writes its items there. Parts follow
//! face order, so every bucket lists its items in face order whatever the thread count. Buffers
//! are advised for huge pages: their first-touch faults cost as much as filling them.

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

/// `Ring` and `RingCorner`: the next and previous vertices come first.
impl<const N: usize> Corner for [u32; N] {
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

/// Larger than any vertex index (`Buckets` refuses meshes that reach it).
pub const NOT_A_VERTEX: u32 = u32::MAX - 1;

pub struct Buckets<E> {
    /// `entries[start[v]..start[v + 1]]` is vertex v's bucket, in face order.
    pub start: Vec<u32>,
    pub entries: Vec<E>,
}

impl Buckets<Ring> {
    /// Every corner under its vertex, with its next and prev vertex (what one-rings need).
    pub fn corners(n_vertices: usize, faces: &[[u32; 3]]) -> Result<Self> {
        Self::build(n_vertices, faces, |f, _| {
            std::array::from_fn(|j| Some((f[j], [f[(j + 1) % 3], f[(j + 2) % 3]])))
        })
    }
}

impl Buckets<RingCorner> {
    /// Every face of three distinct corners once, under its smallest corner, with the corners
    /// after and before it and the face's index, `[next, prev, face]`: a face and its back (the
    /// same corners the other way round) land in the same bucket, next and prev swapped.
    pub fn faces_at_smallest(n_vertices: usize, faces: &[[u32; 3]]) -> Result<Self> {
        Self::build(n_vertices, faces, |f, face| {
            let distinct = f[0] != f[1] && f[1] != f[2] && f[0] != f[2];
            let k = if f[0] < f[1] {
                if f[0] < f[2] {
                    0
                } else {
                    2
                }
            } else if f[1] < f[2] {
                1
            } else {
                2
            };
            [distinct.then(|| (f[k], [f[(k + 1) % 3], f[(k + 2) % 3], face])), None, None]
        })
    }

    /// Every corner under its vertex, with its next and prev vertex and its id (what the
    /// opposite corners of an edge need).
    pub fn corners_with_ids(n_vertices: usize, faces: &[[u32; 3]]) -> Result<Self> {
        Self::build(n_vertices, faces, |f, face| {
            std::array::from_fn(|j| Some((f[j], [f[(j + 1) % 3], f[(j + 2) % 3], face * 3 + j as u32])))
        })
    }
}

impl Buckets<u64> {
    /// Every face-edge f[j] -> f[j + 1] under its smaller end, as larger end << 32 | face << 1 |
    /// reversed (walking from the larger end to the smaller): sorting a bucket sorts by the
    /// other end, then face, then direction. A collapsed face (a corner repeated, as at a pole
    /// stored as a row of copies, welded) files none: it is a line walked there and back, and
    /// its two face-edges would make its edge non-manifold (a fan of them inked as a blob).
    pub fn face_edges(n_vertices: usize, faces: &[[u32; 3]]) -> Result<Self> {
        Self::build(n_vertices, faces, |f, face| {
            let collapsed = f[0] == f[1] || f[1] == f[2] || f[0] == f[2];
            std::array::from_fn(|j| {
                let (a, b) = (f[j], f[(j + 1) % 3]);
                let entry = (a.max(b) as u64) << 32 | (face as u64) << 1 | (a > b) as u64;
                (!collapsed).then_some((a.min(b), entry))
            })
        })
    }
}

impl<E: Copy + Send + Sync> Buckets<E> {
    pub fn n_vertices(&self) -> usize {
        self.start.len() - 1
    }

    /// Vertex v's bucket.
    #[inline(always)]
    pub fn at(&self, v: usize) -> &[E] {
        &self.entries[self.start[v] as usize..self.start[v + 1] as usize]
    }

    /// Files the items `items(face, face index)` of every face: up to three (vertex, entry)
    /// pairs, each entry in the bucket of its vertex.
    fn build(
        n: usize,
        faces: &[[u32; 3]],
        items: impl Fn(&[u32; 3], u32) -> [Option<(u32, E)>; 3] + Send + Sync,
    ) -> Result<Self> {
        check_size(n, faces)?;
        Ok(crate::parallel::install(|| {
            Self::counting_sort(n, faces, rayon::current_num_threads().clamp(1, 8), items)
        }))
    }

    /// One part per thread (up to 8); a single part skips the per-part counts. The items are
    /// looped over as Options: `flatten` was measured to make the whole sort 1.5x slower.
    #[allow(clippy::manual_flatten)]
    fn counting_sort(
        n: usize,
        faces: &[[u32; 3]],
        parts: usize,
        items: impl Fn(&[u32; 3], u32) -> [Option<(u32, E)>; 3] + Sync,
    ) -> Self {
        let per = faces.len().div_ceil(parts).max(1);
        let chunks: Vec<&[[u32; 3]]> = faces.chunks(per).collect();
        let count = |c: &mut [u32], ch: &[[u32; 3]]| {
            for f in ch {
                for item in items(f, 0) {
                    if let Some((v, _)) = item {
                        c[v as usize] += 1;
                    }
                }
            }
        };
        // start[v], and per part (in place of its counts) where it writes its first item of v:
        // parts in face order.
        let (start, mut cursors) = if chunks.len() <= 1 {
            let mut start: Vec<u32> = vec![0; n + 1];
            count(&mut start[1..], faces);
            for i in 0..n {
                start[i + 1] += start[i];
            }
            let cursor = start[..n].to_vec();
            (start, vec![cursor])
        } else {
            let mut cursors: Vec<Vec<u32>> = chunks
                .par_iter()
                .map(|ch| {
                    let mut c = huge_pages::filled_vec(n, 0u32);
                    count(&mut c, ch);
                    c
                })
                .collect();
            let start = parallel_offsets(n, &mut cursors);
            (start, cursors)
        };
        let acc = start[n];
        let mut entries: Vec<E> = huge_pages::with_capacity(acc as usize);
        let out = SharedSlice(entries.as_mut_ptr());
        let scatter = |first_face: usize, ch: &[[u32; 3]], cur: &mut [u32]| {
            for (local, f) in ch.iter().enumerate() {
                let items = items(f, (first_face + local) as u32);
                for item in items {
                    if let Some((v, e)) = item {
                        let at = &mut cur[v as usize];
                        // SAFETY: each part writes only inside the index ranges its own
                        // cursors cover, which are disjoint from every other part's, and
                        // together they cover 0..acc exactly once.
                        unsafe { out.write(*at as usize, e) };
                        *at += 1;
                    }
                }
            }
        };
        if let [cur] = &mut cursors[..] {
            scatter(0, faces, cur);
        } else {
            chunks.par_iter().zip(cursors.par_iter_mut()).enumerate().for_each(|(p, (ch, cur))| {
                scatter(p * per, ch, cur);
            });
        }
        // SAFETY: every index in 0..acc was written above.
        unsafe { entries.set_len(acc as usize) };
        Buckets { start, entries }
    }
}

/// From each part's counts per vertex: the start of every vertex's bucket, and (in place of
/// the counts) where each part writes its first item of each vertex, parts in order. A
/// two-level prefix sum: totals per vertex range, then each range, in parallel.
fn parallel_offsets(n: usize, cursors: &mut [Vec<u32>]) -> Vec<u32> {
    let ranges = vertex_chunks(n);
    let range_totals: Vec<u32> =
        ranges.par_iter().map(|r| cursors.iter().map(|c| c[r.clone()].iter().sum::<u32>()).sum()).collect();
    let mut range_start = Vec::with_capacity(ranges.len());
    let mut acc = 0u32;
    for t in &range_totals {
        range_start.push(acc);
        acc += t;
    }
    let mut start: Vec<u32> = huge_pages::filled_vec(n + 1, 0);
    start[n] = acc;
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
    start
}

/// The limits every index type of the buckets (and of what is derived from them) is sized for:
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

/// Vertices per parallel task in the passes over corner buckets: fixed, so that no result
/// depends on the thread count.
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

/// Two arrays of slots, vertex v's `first[v]..first[v + 1]` in each, starting as `start` and
/// filled in parallel over the vertex ranges: `fill` gets a range's pieces of both and a scratch
/// value of its worker's, made by `init`.
pub fn fill_slot_pairs<A: Copy + Send + Sync, B: Copy + Send + Sync, S>(
    first: &[u32],
    ranges: &[std::ops::Range<usize>],
    start: (A, B),
    init: impl Fn() -> S + Send + Sync,
    fill: impl Fn(&mut S, (&mut [A], &mut [B]), &std::ops::Range<usize>) + Send + Sync,
) -> (Vec<A>, Vec<B>) {
    let slots = first.last().map_or(0, |&n| n as usize);
    let mut a = huge_pages::filled_vec(slots, start.0);
    let mut b = huge_pages::filled_vec(slots, start.1);
    let at = |r: &std::ops::Range<usize>| first[r.start] as usize;
    split_by(&mut a, ranges, at)
        .into_par_iter()
        .zip(split_by(&mut b, ranges, at))
        .zip(ranges.par_iter())
        .for_each_init(init, |scratch, (pieces, r)| fill(scratch, pieces, r));
    (a, b)
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
    fn items_are_filed_under_their_vertex_in_face_order() {
        let faces = [[0, 1, 2], [2, 1, 3], [0, 0, 3]];
        let t = Buckets::corners_with_ids(5, &faces).unwrap();
        assert_eq!(t.at(0), &[[1, 2, 0], [0, 3, 6], [3, 0, 7]]);
        assert_eq!(t.at(1), &[[2, 0, 1], [3, 2, 4]]);
        assert_eq!(t.at(3), &[[2, 1, 5], [0, 0, 8]]);
        assert!(t.at(4).is_empty());
        let r = Buckets::corners(5, &faces).unwrap();
        assert_eq!(r.start, t.start);
        assert!(r.entries.iter().zip(&t.entries).all(|(a, b)| a[..] == b[..2]));
        // face-edges under their smaller end; face 2, collapsed (corner 0 twice), files none
        let e = Buckets::face_edges(5, &faces).unwrap();
        let tag = |other: u64, face: u64, reversed: u64| other << 32 | face << 1 | reversed;
        assert_eq!(e.at(0), &[tag(1, 0, 0), tag(2, 0, 1)]);
        assert_eq!(e.at(1), &[tag(2, 0, 0), tag(2, 1, 1), tag(3, 1, 0)]);
        assert_eq!(e.at(2), &[tag(3, 1, 1)]);
        assert!(e.at(3).is_empty() && e.at(4).is_empty());
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
    fn buckets_do_not_depend_on_the_thread_count() {
        let (_, faces) = crate::mesh::shapes::icosphere(4, 0.0, 0).unwrap();
        let n = 2562;
        let with = |threads: usize| {
            let pool = rayon::ThreadPoolBuilder::new().num_threads(threads).build().unwrap();
            // each face's edges under their second end
            let items = |f: &[u32; 3], face: u32| {
                std::array::from_fn(|j| Some((f[(j + 1) % 3], (f[j] as u64) << 32 | face as u64)))
            };
            pool.install(|| Buckets::counting_sort(n, &faces, threads, items))
        };
        let (one, five) = (with(1), with(5));
        assert_eq!((one.start, one.entries), (five.start, five.entries));
    }
}

//! One-ring adjacency in compressed sparse row form, built once per mesh.
//!
//! For vertex `i`, `nbrs[offsets[i]..offsets[i+1]]` are its distinct neighbours in ascending order
//! (never `i` itself). Each such slot `s` also records how many face-edges join the pair
//! (`edge_faces[s]`: 1 on a boundary, 2 on a manifold interior edge, 3+ on a non-manifold edge)
//! and, built on first use, the third vertex of each of those faces (`opposite_of(s)`), which
//! is what cotangent weights need. Faces with a repeated index contribute only their
//! non-degenerate edges; their self-edges (a, a) are only counted, in `self_edges`.

use rayon::prelude::*;

use crate::error::{Error, Result};
use crate::huge_pages;
use crate::parallel;

#[derive(Debug)]
pub struct Adjacency {
    pub offsets: Vec<u32>,
    pub nbrs: Vec<u32>,
    pub edge_faces: Vec<u32>,
    /// Per vertex: how many face-edges (a, a) of degenerate faces start and end at it.
    pub self_edges: Vec<u32>,
    corners: Option<Corners>,
}

/// Opposite corners per slot, in CSR form.
#[derive(Debug)]
struct Corners {
    offsets: Vec<u32>,
    opposite: Vec<u32>,
    /// The same corners as face * 3 + position in the face, for per-face quantities.
    corner: Vec<u32>,
}

impl Adjacency {
    /// Builds the one-rings (neighbours and edge face counts). Opposite corners are added by
    /// `with_corners`, since only cotangent weights need them.
    pub fn build(n_vertices: usize, faces: &[[u32; 3]]) -> Result<Adjacency> {
        if faces.len() > (u32::MAX as usize) / 6 {
            return Err(Error::invalid(
                "faces",
                format!("{} faces is more than toonmesh supports", faces.len()),
            ));
        }
        parallel::install(|| {
            let (start, mut entries, self_edges) = half_edges(n_vertices, faces, |b, _| b);
            // Sort each vertex's neighbour list (so nothing below depends on face order or
            // thread count) and count its distinct neighbours.
            let ranges = vertex_chunks(n_vertices);
            let mut distinct = vec![0u32; n_vertices];
            split_by(&mut entries, &ranges, |r| start[r.start] as usize)
                .into_par_iter()
                .zip(split_by(&mut distinct, &ranges, |r| r.start))
                .zip(ranges.par_iter())
                .for_each(|((ent, dist), r)| {
                    let base = start[r.start] as usize;
                    for (k, i) in r.clone().enumerate() {
                        let e = &mut ent[start[i] as usize - base..start[i + 1] as usize - base];
                        e.sort_unstable();
                        dist[k] = e.chunk_by(|x, y| x == y).count() as u32;
                    }
                });
            let offsets = prefix_sum(&distinct);
            let slots = offsets[n_vertices] as usize;
            let mut nbrs: Vec<u32> = huge_pages::filled_vec(slots, 0);
            let mut edge_faces: Vec<u32> = huge_pages::filled_vec(slots, 0);
            let slot_start = |r: &std::ops::Range<usize>| offsets[r.start] as usize;
            split_by(&mut nbrs, &ranges, slot_start)
                .into_par_iter()
                .zip(split_by(&mut edge_faces, &ranges, slot_start))
                .zip(ranges.par_iter())
                .for_each(|((nb, ef), r)| {
                    let mut s = 0;
                    for i in r.clone() {
                        for run in entries[start[i] as usize..start[i + 1] as usize].chunk_by(|x, y| x == y) {
                            nb[s] = run[0];
                            ef[s] = run.len() as u32;
                            s += 1;
                        }
                    }
                });
            Ok(Adjacency { offsets, nbrs, edge_faces, self_edges, corners: None })
        })
    }

    pub fn n_vertices(&self) -> usize {
        self.offsets.len() - 1
    }

    #[inline]
    pub fn slots(&self, i: usize) -> std::ops::Range<usize> {
        self.offsets[i] as usize..self.offsets[i + 1] as usize
    }

    #[inline]
    pub fn neighbours(&self, i: usize) -> &[u32] {
        &self.nbrs[self.slots(i)]
    }

    /// The third vertex of each face on the edge of `slot`, one per face-edge, in face order.
    /// Needs `with_corners` first (an empty slice otherwise).
    #[inline]
    pub fn opposite_of(&self, slot: usize) -> &[u32] {
        match &self.corners {
            Some(c) => &c.opposite[c.offsets[slot] as usize..c.offsets[slot + 1] as usize],
            None => &[],
        }
    }

    /// The opposite corners of `slot` as face * 3 + k (k: the corner's place in its face).
    #[inline]
    pub fn corners_of(&self, slot: usize) -> &[u32] {
        match &self.corners {
            Some(c) => &c.corner[c.offsets[slot] as usize..c.offsets[slot + 1] as usize],
            None => &[],
        }
    }

    /// The opposite corners of a run of consecutive slots, all together: slot s's own come
    /// next, `edge_faces[s]` of them, so a pass over slots in order walks this without looking
    /// up each slot's offsets. Needs `with_corners` first (an empty slice otherwise).
    #[inline]
    pub fn corners_of_run(&self, slots: std::ops::Range<usize>) -> &[u32] {
        match &self.corners {
            Some(c) => &c.corner[c.offsets[slots.start] as usize..c.offsets[slots.end] as usize],
            None => &[],
        }
    }

    /// Adds the opposite corners of every face-edge (for cotangent weights).
    pub fn with_corners(mut self, faces: &[[u32; 3]]) -> Self {
        if self.corners.is_none() {
            self.corners = Some(self.build_corners(faces));
        }
        self
    }

    fn build_corners(&self, faces: &[[u32; 3]]) -> Corners {
        let n = self.n_vertices();
        parallel::install(|| {
            // Same grouping as the neighbour entries, sorted by (neighbour, corner), so each
            // slot's run has exactly `edge_faces[slot]` entries, in slot order.
            let (start, mut entries, _) =
                half_edges(n, faces, |b, corner| ((b as u64) << 32) | corner as u64);
            let ranges = vertex_chunks(n);
            split_by(&mut entries, &ranges, |r| start[r.start] as usize)
                .into_par_iter()
                .zip(ranges.par_iter())
                .for_each(|(ent, r)| {
                    let base = start[r.start] as usize;
                    for i in r.clone() {
                        ent[start[i] as usize - base..start[i + 1] as usize - base].sort_unstable();
                    }
                });
            let mut offsets = Vec::with_capacity(self.nbrs.len() + 1);
            let mut acc = 0u32;
            for &e in &self.edge_faces {
                offsets.push(acc);
                acc += e;
            }
            offsets.push(acc);
            // Into huge-page buffers, written by every thread: these arrays are as long as the
            // entries, and first-touch faults on them cost as much as filling them.
            let mut corner: Vec<u32> = huge_pages::filled_vec(entries.len(), 0);
            corner.par_iter_mut().zip(entries.par_iter()).for_each(|(c, e)| *c = *e as u32);
            drop(entries);
            let mut opposite: Vec<u32> = huge_pages::filled_vec(corner.len(), 0);
            opposite
                .par_iter_mut()
                .zip(corner.par_iter())
                .for_each(|(o, &c)| *o = faces[c as usize / 3][c as usize % 3]);
            Corners { offsets, opposite, corner }
        })
    }

    /// Per vertex: does it lie on an edge with exactly one face?
    pub fn boundary_vertices(&self) -> Vec<bool> {
        (0..self.n_vertices())
            .into_par_iter()
            .map(|i| self.slots(i).any(|s| self.edge_faces[s] == 1))
            .collect()
    }
}

/// For every face-edge {a, b} (a != b) with opposite corner c, one entry at a and one at b,
/// grouped by vertex: returns (group starts, entries, self-edge counts per vertex).
/// Faces are split into parts filled in parallel; the order inside a group is therefore not
/// fixed, and callers sort each group.
fn half_edges<E: Copy + Default + Send + Sync>(
    n: usize,
    faces: &[[u32; 3]],
    // (the other end b, the opposite corner as face * 3 + k) -> the entry stored at a
    entry: impl Fn(u32, u32) -> E + Sync,
) -> (Vec<u32>, Vec<E>, Vec<u32>) {
    let parts = rayon::current_num_threads().clamp(1, 8);
    let per = faces.len().div_ceil(parts).max(1);
    let chunks: Vec<&[[u32; 3]]> = faces.chunks(per).collect();
    // Per part: how many entries each vertex gets, and its self-edges.
    let counts: Vec<(Vec<u32>, Vec<u32>)> = chunks
        .par_iter()
        .map(|ch| {
            let mut c = vec![0u32; n];
            let mut selfe = vec![0u32; n];
            for f in ch.iter() {
                for j in 0..3 {
                    let (a, b) = (f[j], f[(j + 1) % 3]);
                    if a != b {
                        c[a as usize] += 1;
                        c[b as usize] += 1;
                    } else {
                        selfe[a as usize] += 1;
                    }
                }
            }
            (c, selfe)
        })
        .collect();
    let mut start = Vec::with_capacity(n + 1);
    let mut self_edges = vec![0u32; n];
    // cursors[p][v]: where part p writes its next entry for v.
    let mut cursors: Vec<Vec<u32>> = vec![vec![0u32; n]; counts.len()];
    let mut acc = 0u32;
    for v in 0..n {
        start.push(acc);
        for (p, (c, s)) in counts.iter().enumerate() {
            cursors[p][v] = acc;
            acc += c[v];
            self_edges[v] += s[v];
        }
    }
    start.push(acc);
    drop(counts);
    let mut entries = huge_pages::filled_vec(acc as usize, E::default());
    let out = SharedSlice(entries.as_mut_ptr());
    chunks.par_iter().zip(cursors.par_iter_mut()).enumerate().for_each(|(p, (ch, cur))| {
        let out = &out;
        for (local, f) in ch.iter().enumerate() {
            let face = (p * per + local) as u32;
            for j in 0..3 {
                let (a, b) = (f[j], f[(j + 1) % 3]);
                let corner = face * 3 + ((j + 2) % 3) as u32;
                if a != b {
                    // SAFETY: each part writes only inside the index ranges its own cursors
                    // cover, which are disjoint from every other part's by construction.
                    unsafe {
                        out.write(cur[a as usize] as usize, entry(b, corner));
                        out.write(cur[b as usize] as usize, entry(a, corner));
                    }
                    cur[a as usize] += 1;
                    cur[b as usize] += 1;
                }
            }
        }
    });
    (start, entries, self_edges)
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

fn prefix_sum(counts: &[u32]) -> Vec<u32> {
    let mut out = Vec::with_capacity(counts.len() + 1);
    let mut acc = 0u32;
    out.push(0);
    for c in counts {
        acc += c;
        out.push(acc);
    }
    out
}

/// Vertices per parallel task.
const VERTEX_CHUNK: usize = 4096;

fn vertex_chunks(n: usize) -> Vec<std::ops::Range<usize>> {
    (0..n.div_ceil(VERTEX_CHUNK)).map(|c| c * VERTEX_CHUNK..((c + 1) * VERTEX_CHUNK).min(n)).collect()
}

/// Splits `data` into consecutive pieces, one per vertex range, each starting at `at(range)`.
fn split_by<'a, T>(
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

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn square_of_two_triangles() {
        let faces = [[0, 1, 2], [0, 2, 3]];
        let a = Adjacency::build(5, &faces).unwrap().with_corners(&faces);
        assert_eq!(a.neighbours(0), &[1, 2, 3]);
        assert_eq!(a.neighbours(2), &[0, 1, 3]);
        assert_eq!(a.neighbours(4), &[] as &[u32]);
        // edge 0-2 is shared by both faces; its opposite corners are 1 and 3
        let s = a.slots(0).start + 1;
        assert_eq!(a.edge_faces[s], 2);
        assert_eq!(a.opposite_of(s), &[1, 3]);
        assert_eq!(a.boundary_vertices(), vec![true, true, true, true, false]);
    }

    #[test]
    fn degenerate_face_keeps_only_real_edges() {
        let a = Adjacency::build(3, &[[0, 0, 1]]).unwrap();
        assert_eq!(a.neighbours(0), &[1]);
        assert_eq!(a.edge_faces[a.slots(0).start], 2);
        assert_eq!(a.neighbours(2), &[] as &[u32]);
        assert_eq!(a.self_edges, vec![1, 0, 0]);
    }

    #[test]
    fn matches_a_brute_force_count_on_a_messy_mesh() {
        use std::collections::BTreeMap;
        let mut rng = crate::mesh::shapes::SplitMix64::new(3);
        let n = 50;
        let faces: Vec<[u32; 3]> =
            (0..400).map(|_| [0, 1, 2].map(|_| (rng.next_u64() % n as u64) as u32)).collect();
        let a = Adjacency::build(n, &faces).unwrap().with_corners(&faces);
        let mut expect: BTreeMap<(u32, u32), Vec<u32>> = BTreeMap::new();
        for f in &faces {
            for j in 0..3 {
                let (x, y, c) = (f[j], f[(j + 1) % 3], f[(j + 2) % 3]);
                if x != y {
                    expect.entry((x, y)).or_default().push(c);
                    expect.entry((y, x)).or_default().push(c);
                }
            }
        }
        let mut got = BTreeMap::new();
        for i in 0..n {
            for s in a.slots(i) {
                let mut opp = a.opposite_of(s).to_vec();
                opp.sort_unstable();
                got.insert((i as u32, a.nbrs[s]), opp);
                for (&c, &o) in a.corners_of(s).iter().zip(a.opposite_of(s)) {
                    assert_eq!(faces[c as usize / 3][c as usize % 3], o);
                }
                assert_eq!(a.edge_faces[s] as usize, a.opposite_of(s).len());
            }
        }
        for v in expect.values_mut() {
            v.sort_unstable();
        }
        assert_eq!(got, expect);
    }
}

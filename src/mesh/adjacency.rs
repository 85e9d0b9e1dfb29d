//! One-ring adjacency in compressed sparse row form, derived from the corner buckets
//! (`mesh::buckets`) once per mesh.
//!
//! For vertex `i`, `nbrs[offsets[i]..offsets[i+1]]` are its distinct neighbours in ascending order
//! (never `i` itself). Each such slot `s` also records how many face-edges join the pair
//! (`edge_faces_at(s)`: 1 on a boundary, 2 on a manifold interior edge, 3+ on a non-manifold edge)
//! and, when built with `build_with_corners`, the third vertex of each of those faces
//! (`opposite_of(s)`), which is what cotangent weights need. Faces with a repeated index
//! contribute only their non-degenerate edges; their self-edges (a, a) are only counted, in
//! `self_edges`.

use rayon::prelude::*;

use super::buckets::{
    across_next, across_prev, fill_slot_pairs, prefix_sum, sort8, split_by, vertex_chunks, Buckets, Corner,
    RingCorner, NOT_A_VERTEX,
};
use crate::error::Result;
use crate::huge_pages;
use crate::parallel;

#[derive(Debug)]
pub struct Adjacency {
    pub offsets: Vec<u32>,
    pub nbrs: Vec<u32>,
    /// Face-edges per slot; when every fan is closed they are all 2 and this only holds as
    /// many 2s as the longest row (so a closed mesh needs no array as long as `nbrs`).
    edge_faces: Vec<u32>,
    /// Per vertex: how many face-edges (a, a) of degenerate faces start and end at it.
    pub self_edges: Vec<u32>,
    /// Is every vertex's fan closed and consistently oriented (so no boundary, no non-manifold
    /// edge, no degenerate face and no unreferenced vertex)? Then each vertex's outgoing
    /// half-edges reach exactly its neighbours, once each.
    pub all_fans_closed: bool,
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

impl Corners {
    /// Completes the corners (face * 3 + position) with the vertex at each. Into a huge-page
    /// buffer, written by every thread: it is as long as the corners, and first-touch faults
    /// on it cost as much as filling it.
    fn with_opposites(offsets: Vec<u32>, corner: Vec<u32>, faces: &[[u32; 3]]) -> Corners {
        let mut opposite: Vec<u32> = huge_pages::filled_vec(corner.len(), 0);
        opposite
            .par_iter_mut()
            .zip(corner.par_iter())
            .for_each(|(o, &c)| *o = faces[c as usize / 3][c as usize % 3]);
        Corners { offsets, opposite, corner }
    }
}

impl Adjacency {
    /// Builds the one-rings (neighbours and edge face counts).
    pub fn build(n_vertices: usize, faces: &[[u32; 3]]) -> Result<Adjacency> {
        let mut corners = Buckets::corners(n_vertices, faces)?;
        Ok(parallel::install(|| Adjacency::from_corners(&mut corners)))
    }

    /// Builds the one-rings and the opposite corners of every face-edge (for cotangent
    /// weights), from one filing of the corners that carries each corner's id.
    pub fn build_with_corners(n_vertices: usize, faces: &[[u32; 3]]) -> Result<Adjacency> {
        let mut corners = Buckets::corners_with_ids(n_vertices, faces)?;
        Ok(parallel::install(|| {
            let mut adj = Adjacency::from_corners(&mut corners);
            let opposite = if adj.all_fans_closed {
                adj.closed_fan_corners(&corners.entries, faces)
            } else {
                adj.general_corners(&corners, faces)
            };
            adj.corners = Some(opposite);
            adj
        }))
    }

    /// The one-rings from the corner buckets. Each corner at v contributes the vertex after v and
    /// the vertex before it (the two face-edges at v); v's distinct neighbours are the union of
    /// those, and the number of face-edges joining v to a neighbour is how often it occurs. Most
    /// vertices of a real mesh have a closed fan: the vertices after v are distinct and are the
    /// vertices before v in another order (a closed, consistently oriented fan), so their
    /// neighbours are just the vertices after v, each on two faces, and no general sort and
    /// merge is needed. When every fan is closed the buckets' `start` becomes `offsets` (taken,
    /// not copied).
    fn from_corners<E: Corner>(buckets: &mut Buckets<E>) -> Adjacency {
        let n_vertices = buckets.n_vertices();
        let (start, corners) = (&buckets.start, &buckets.entries);
        let ring = |i: usize| &corners[start[i] as usize..start[i + 1] as usize];
        let ranges = vertex_chunks(n_vertices);
        // Pass 1: classify every fan and count its self-edges. A closed fan has one
        // neighbour per corner, so its sorted neighbours go straight to their final place
        // if every fan turns out closed: the corner lists' offsets.
        let mut self_edges: Vec<u32> = huge_pages::filled_vec(n_vertices, 0);
        let mut closed: Vec<bool> = huge_pages::filled_vec(n_vertices, false);
        let mut nbrs: Vec<u32> = huge_pages::filled_vec(corners.len(), 0);
        let corner_start = |r: &std::ops::Range<usize>| start[r.start] as usize;
        split_by(&mut self_edges, &ranges, |r| r.start)
            .into_par_iter()
            .zip(split_by(&mut closed, &ranges, |r| r.start))
            .zip(split_by(&mut nbrs, &ranges, corner_start))
            .zip(ranges.par_iter())
            .for_each(|(((selfe, closed), nb), r)| {
                let base = start[r.start] as usize;
                for (k, i) in r.clone().enumerate() {
                    let c = ring(i);
                    selfe[k] = c.iter().filter(|e| e.next() == i as u32).count() as u32;
                    let nb = &mut nb[start[i] as usize - base..start[i + 1] as usize - base];
                    closed[k] = closed_fan(i as u32, c, nb);
                }
            });
        let all_fans_closed = closed.par_iter().all(|&s| s);
        if all_fans_closed {
            let longest = (0..n_vertices).into_par_iter().map(|i| ring(i).len()).max().unwrap_or(0);
            let edge_faces = vec![2; longest];
            return Adjacency {
                offsets: std::mem::take(&mut buckets.start),
                nbrs,
                edge_faces,
                self_edges,
                all_fans_closed,
                corners: None,
            };
        }
        drop(nbrs);
        // Otherwise, pass 2: how many distinct neighbours per vertex; pass 3: the sorted
        // neighbours and their face-edge counts.
        let mut distinct: Vec<u32> = huge_pages::filled_vec(n_vertices, 0);
        split_by(&mut distinct, &ranges, |r| r.start).into_par_iter().zip(ranges.par_iter()).for_each_init(
            Vec::new,
            |scratch, (dist, r)| {
                for (k, i) in r.clone().enumerate() {
                    let c = ring(i);
                    dist[k] = if closed[i] {
                        c.len() as u32
                    } else {
                        general_ring(i as u32, c, scratch);
                        runs(scratch).count() as u32
                    };
                }
            },
        );
        let offsets = prefix_sum(&distinct);
        drop(distinct);
        let (nbrs, edge_faces) =
            fill_slot_pairs(&offsets, &ranges, (0u32, 0u32), Vec::new, |scratch, (nb, ef), r| {
                let base = offsets[r.start] as usize;
                for i in r.clone() {
                    let c = ring(i);
                    let at = offsets[i] as usize - base..offsets[i + 1] as usize - base;
                    let (nb, ef) = (&mut nb[at.clone()], &mut ef[at]);
                    if closed[i] {
                        closed_fan(i as u32, c, nb);
                        ef.fill(2);
                    } else {
                        general_ring(i as u32, c, scratch);
                        for (k, (v, count)) in runs(scratch).enumerate() {
                            nb[k] = v;
                            ef[k] = count;
                        }
                    }
                }
            });
        Adjacency { offsets, nbrs, edge_faces, self_edges, all_fans_closed, corners: None }
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

    /// Visits every vertex breadth-first from the lowest index of each connected part, calling
    /// `reach(i, j)` when j is first reached from i.
    pub fn breadth_first(&self, mut reach: impl FnMut(usize, usize)) {
        let n = self.n_vertices();
        let mut seen = vec![false; n];
        let mut queue = std::collections::VecDeque::new();
        for root in 0..n {
            if seen[root] {
                continue;
            }
            seen[root] = true;
            queue.push_back(root);
            while let Some(i) = queue.pop_front() {
                for &j in self.neighbours(i) {
                    let j = j as usize;
                    if !seen[j] {
                        seen[j] = true;
                        reach(i, j);
                        queue.push_back(j);
                    }
                }
            }
        }
    }

    /// How many face-edges join vertex i to each of its neighbours, slot by slot.
    #[inline]
    pub fn edge_faces(&self, i: usize) -> &[u32] {
        let slots = self.slots(i);
        if self.all_fans_closed {
            &self.edge_faces[..slots.len()]
        } else {
            &self.edge_faces[slots]
        }
    }

    /// How many face-edges join the two ends of `slot`.
    #[inline]
    pub fn edge_faces_at(&self, slot: usize) -> u32 {
        if self.all_fans_closed {
            2
        } else {
            self.edge_faces[slot]
        }
    }

    /// The third vertex of each face on the edge of `slot`, one per face-edge, in face order.
    /// Needs `build_with_corners` (an empty slice otherwise).
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
    /// up each slot's offsets. Needs `build_with_corners` (an empty slice otherwise).
    #[inline]
    pub fn corners_of_run(&self, slots: std::ops::Range<usize>) -> &[u32] {
        match &self.corners {
            Some(c) => &c.corner[c.offsets[slots.start] as usize..c.offsets[slots.end] as usize],
            None => &[],
        }
    }

    /// Corners in general: each vertex's face-edges sorted by (neighbour, corner) are its
    /// slots' runs, each of `edge_faces` entries, in slot order. Self-edges (v, v) have no slot.
    fn general_corners(&self, buckets: &Buckets<RingCorner>, faces: &[[u32; 3]]) -> Corners {
        let n = self.n_vertices();
        let mut offsets = Vec::with_capacity(self.nbrs.len() + 1);
        let mut acc = 0u32;
        for &e in (0..n).flat_map(|i| self.edge_faces(i)) {
            offsets.push(acc);
            acc += e;
        }
        offsets.push(acc);
        let mut corner: Vec<u32> = huge_pages::filled_vec(acc as usize, 0);
        let ranges = vertex_chunks(n);
        let corner_at = |i: usize| offsets[self.offsets[i] as usize] as usize;
        split_by(&mut corner, &ranges, |r| corner_at(r.start))
            .into_par_iter()
            .zip(ranges.par_iter())
            .for_each_init(Vec::<u64>::new, |sorted, (out, r)| {
                let base = corner_at(r.start);
                for i in r.clone() {
                    sorted.clear();
                    for &[next, prev, id] in buckets.at(i) {
                        sorted.push((next as u64) << 32 | across_next(id) as u64);
                        sorted.push((prev as u64) << 32 | across_prev(id) as u64);
                    }
                    sorted.retain(|&e| (e >> 32) as usize != i);
                    sorted.sort_unstable();
                    for (o, e) in out[corner_at(i) - base..].iter_mut().zip(sorted.iter()) {
                        *o = *e as u32;
                    }
                }
            });
        Corners::with_opposites(offsets, corner, faces)
    }

    /// Corners when every fan is closed: each slot (v, u) has exactly two, one from the corner
    /// at v whose next vertex is u and one from the corner at v whose previous vertex is u. Both
    /// lists are sorted by that vertex, so their k-th entries belong to slot k.
    /// `entries` are the corner buckets', whose `start` is then `offsets`.
    fn closed_fan_corners(&self, entries: &[RingCorner], faces: &[[u32; 3]]) -> Corners {
        let n = self.n_vertices();
        let start = &self.offsets;
        let slots = self.nbrs.len();
        let mut corner: Vec<u32> = huge_pages::filled_vec(2 * slots, 0);
        let ranges = vertex_chunks(n);
        split_by(&mut corner, &ranges, |r| 2 * self.offsets[r.start] as usize)
            .into_par_iter()
            .zip(ranges.par_iter())
            .for_each(|(out, r)| {
                let base = 2 * self.offsets[r.start] as usize;
                let (mut after, mut before) = (Vec::new(), Vec::new());
                for i in r.clone() {
                    let ring = &entries[start[i] as usize..start[i + 1] as usize];
                    let at = 2 * self.offsets[i] as usize - base;
                    let out = &mut out[at..at + 2 * ring.len()];
                    if ring.len() <= 8 {
                        // Padding sorts last and is never written out.
                        let mut a = [u64::MAX; 8];
                        let mut b = [u64::MAX; 8];
                        for (k, e) in ring.iter().enumerate() {
                            (a[k], b[k]) = across(e);
                        }
                        sort8(&mut a);
                        sort8(&mut b);
                        pair_corners(&a, &b, out);
                    } else {
                        after.clear();
                        before.clear();
                        after.extend(ring.iter().map(|e| across(e).0));
                        before.extend(ring.iter().map(|e| across(e).1));
                        after.sort_unstable();
                        before.sort_unstable();
                        pair_corners(&after, &before, out);
                    }
                }
            });
        let offsets: Vec<u32> = (0..=slots as u32).into_par_iter().map(|s| 2 * s).collect();
        Corners::with_opposites(offsets, corner, faces)
    }

    /// Per vertex: does it lie on an edge with exactly one face?
    pub fn boundary_vertices(&self) -> Vec<bool> {
        if self.all_fans_closed {
            return huge_pages::filled_vec(self.n_vertices(), false);
        }
        (0..self.n_vertices()).into_par_iter().map(|i| self.edge_faces(i).contains(&1)).collect()
    }
}

/// Slot k's two corners, smaller first, from the k-th entries of both sorted corner lists.
#[inline]
fn pair_corners(after: &[u64], before: &[u64], out: &mut [u32]) {
    for (o, (a, b)) in out.chunks_exact_mut(2).zip(after.iter().zip(before)) {
        let (ca, cb) = (*a as u32, *b as u32);
        o[0] = ca.min(cb);
        o[1] = ca.max(cb);
    }
}

/// A corner's two face-edges as sort keys: (next << 32 | the corner across v -> next,
/// prev << 32 | the corner across prev -> v).
#[inline(always)]
fn across(e: &RingCorner) -> (u64, u64) {
    let [next, prev, id] = *e;
    ((next as u64) << 32 | across_next(id) as u64, (prev as u64) << 32 | across_prev(id) as u64)
}

/// If v's fan is closed and consistently oriented (the vertices after v distinct and none of
/// them v, and the same set as the vertices before v), writes those vertices (v's neighbours,
/// each on two faces) sorted into `out` and returns true. Branch-free for up to 8 corners:
/// two sorting networks and a comparison, since which vertices fail is unpredictable.
#[inline]
fn closed_fan<E: Corner>(v: u32, ring: &[E], out: &mut [u32]) -> bool {
    if ring.len() > 8 {
        let sorted = |end: fn(&E) -> u32| {
            let mut s: Vec<u32> = ring.iter().map(end).collect();
            s.sort_unstable();
            s
        };
        let (after, before) = (sorted(E::next), sorted(E::prev));
        let closed = after == before && after.windows(2).all(|w| w[0] != w[1]) && !after.contains(&v);
        if closed {
            out.copy_from_slice(&after);
        }
        return closed;
    }
    let mut after = [NOT_A_VERTEX; 8];
    let mut before = [NOT_A_VERTEX; 8];
    for (k, c) in ring.iter().enumerate() {
        after[k] = c.next();
        before[k] = c.prev();
    }
    sort8(&mut after);
    sort8(&mut before);
    let mut closed = !ring.is_empty() & (after == before);
    for k in 0..8 {
        let inside = k < ring.len();
        closed &= !inside | (after[k] != v);
        if k > 0 {
            closed &= !inside | (after[k - 1] < after[k]);
        }
    }
    if closed {
        // An element loop: a call to memcpy per vertex costs more than the copy.
        for (o, a) in out.iter_mut().zip(after) {
            *o = a;
        }
    }
    closed
}

/// The face-edge ends of v's corners, v itself left out, sorted into `out`.
fn general_ring<E: Corner>(v: u32, ring: &[E], out: &mut Vec<u32>) {
    out.clear();
    for e in ring {
        out.extend([e.next(), e.prev()].into_iter().filter(|&u| u != v));
    }
    out.sort_unstable();
}

/// Each distinct value of a sorted list with how often it occurs.
fn runs(sorted: &[u32]) -> impl Iterator<Item = (u32, u32)> + '_ {
    sorted.chunk_by(|a, b| a == b).map(|r| (r[0], r.len() as u32))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn only_closed_consistent_fans_take_the_shortcut() {
        // A closed fan of 6 around vertex 0: closed.
        let is_closed = |ring: &[[u32; 2]]| closed_fan(0, ring, &mut vec![0; ring.len()]);
        let fan: Vec<[u32; 2]> = (1..=6).map(|k| [k, (k + 4) % 6 + 1]).collect();
        let mut out = vec![0; 6];
        assert!(closed_fan(0, &fan, &mut out));
        assert_eq!(out, [1, 2, 3, 4, 5, 6]);
        // An open fan (a boundary vertex), a repeated face and a degenerate one: not closed.
        assert!(!is_closed(&fan[..5]));
        let mut twice = fan.clone();
        twice[1] = twice[0];
        assert!(!is_closed(&twice));
        assert!(!is_closed(&[[0, 1], [1, 0]]));
        assert!(!is_closed(&[]));
    }

    #[test]
    fn high_valence_fans_and_their_neighbours_are_found() {
        // A closed fan of 40 triangles around vertex 0 (the general path) on a cone with apex 41.
        let mut faces: Vec<[u32; 3]> = (1..=40).map(|k| [0, k, k % 40 + 1]).collect();
        faces.extend((1..=40).map(|k| [41, k % 40 + 1, k]));
        let a = Adjacency::build(42, &faces).unwrap();
        assert_eq!(a.neighbours(0), &(1..=40).collect::<Vec<u32>>()[..]);
        assert!(a.edge_faces(0).iter().all(|&e| e == 2));
        assert_eq!(a.neighbours(5), &[0, 4, 6, 41]);
        assert!(a.all_fans_closed);
        assert!(!Adjacency::build(43, &faces).unwrap().all_fans_closed); // an unreferenced vertex
        assert!(a.boundary_vertices().iter().all(|b| !b));
    }

    #[test]
    fn closed_fan_corners_match_the_general_ones() {
        let (_, faces) = crate::mesh::shapes::icosphere(2, 0.0, 0).unwrap();
        let n = 162;
        let fast = Adjacency::build_with_corners(n, &faces).unwrap();
        assert!(fast.all_fans_closed);
        let general = fast.general_corners(&Buckets::corners_with_ids(n, &faces).unwrap(), &faces);
        let range = |c: &Corners, s: usize| c.offsets[s] as usize..c.offsets[s + 1] as usize;
        for s in 0..fast.nbrs.len() {
            assert_eq!(fast.corners_of(s), &general.corner[range(&general, s)], "slot {s}");
            assert_eq!(fast.opposite_of(s), &general.opposite[range(&general, s)], "slot {s}");
        }
    }

    #[test]
    fn square_of_two_triangles() {
        let faces = [[0, 1, 2], [0, 2, 3]];
        let a = Adjacency::build_with_corners(5, &faces).unwrap();
        assert_eq!(a.neighbours(0), &[1, 2, 3]);
        assert_eq!(a.neighbours(2), &[0, 1, 3]);
        assert_eq!(a.neighbours(4), &[] as &[u32]);
        // edge 0-2 is shared by both faces; its opposite corners are 1 and 3
        let s = a.slots(0).start + 1;
        assert_eq!(a.edge_faces_at(s), 2);
        assert_eq!(a.opposite_of(s), &[1, 3]);
        assert_eq!(a.boundary_vertices(), vec![true, true, true, true, false]);
    }

    #[test]
    fn degenerate_face_keeps_only_real_edges() {
        let a = Adjacency::build(3, &[[0, 0, 1]]).unwrap();
        assert_eq!(a.neighbours(0), &[1]);
        assert_eq!(a.edge_faces_at(a.slots(0).start), 2);
        assert_eq!(a.neighbours(2), &[] as &[u32]);
        assert_eq!(a.self_edges, vec![1, 0, 0]);
    }

    #[test]
    fn matches_a_brute_force_count_on_a_messy_mesh() {
        use std::collections::BTreeMap;
        let n = 50;
        let faces = crate::mesh::shapes::random_faces(3, n, 400);
        let a = Adjacency::build_with_corners(n, &faces).unwrap();
        let plain = Adjacency::build(n, &faces).unwrap();
        assert_eq!((&a.offsets, &a.nbrs, &a.self_edges), (&plain.offsets, &plain.nbrs, &plain.self_edges));
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
                assert_eq!(a.edge_faces_at(s) as usize, a.opposite_of(s).len());
            }
        }
        for v in expect.values_mut() {
            v.sort_unstable();
        }
        assert_eq!(got, expect);
    }
}

//! One-ring adjacency in compressed sparse row form, built once per mesh.
//!
//! For vertex `i`, `nbrs[offsets[i]..offsets[i+1]]` are its distinct neighbours in ascending order
//! (never `i` itself). Each such slot `s` also records how many face-edges join the pair
//! (`edge_faces[s]`: 1 on a boundary, 2 on a manifold interior edge, 3+ on a non-manifold edge)
//! and the third vertex of each of those faces (`opposite[opp_offsets[s]..opp_offsets[s+1]]`),
//! which is what cotangent weights need. Faces with a repeated index contribute only their
//! non-degenerate edges.

use rayon::prelude::*;

use crate::error::{Error, Result};
use crate::parallel;

#[derive(Debug, Clone)]
pub struct Adjacency {
    pub offsets: Vec<u32>,
    pub nbrs: Vec<u32>,
    pub edge_faces: Vec<u32>,
    pub opp_offsets: Vec<u32>,
    pub opposite: Vec<u32>,
}

impl Adjacency {
    pub fn build(n_vertices: usize, faces: &[[u32; 3]]) -> Result<Adjacency> {
        if faces.len() > (u32::MAX as usize) / 6 {
            return Err(Error::invalid("faces", format!("{} faces is more than toonmesh supports", faces.len())));
        }
        // Each face-edge {a, b} with opposite corner c appears once from a and once from b.
        let mut count = vec![0u32; n_vertices + 1];
        for f in faces {
            for j in 0..3 {
                let (a, b) = (f[j], f[(j + 1) % 3]);
                if a != b {
                    count[a as usize] += 1;
                    count[b as usize] += 1;
                }
            }
        }
        let mut start = Vec::with_capacity(n_vertices + 1);
        let mut acc = 0u32;
        for c in count.iter().take(n_vertices) {
            start.push(acc);
            acc += c;
        }
        start.push(acc);
        let mut cursor = start.clone();
        let mut entries = vec![(0u32, 0u32); acc as usize];
        for f in faces {
            for j in 0..3 {
                let (a, b, c) = (f[j], f[(j + 1) % 3], f[(j + 2) % 3]);
                if a != b {
                    entries[cursor[a as usize] as usize] = (b, c);
                    cursor[a as usize] += 1;
                    entries[cursor[b as usize] as usize] = (a, c);
                    cursor[b as usize] += 1;
                }
            }
        }
        drop(cursor);

        // Sort each vertex's entries (by neighbour, then opposite corner) so that everything
        // below is independent of face order and thread count.
        parallel::install(|| {
            let mut rest: &mut [(u32, u32)] = &mut entries;
            let mut chunks = Vec::with_capacity(n_vertices);
            for i in 0..n_vertices {
                let len = (start[i + 1] - start[i]) as usize;
                let (head, tail) = rest.split_at_mut(len);
                chunks.push(head);
                rest = tail;
            }
            chunks.into_par_iter().for_each(|c| c.sort_unstable());
        });

        let mut offsets = Vec::with_capacity(n_vertices + 1);
        let mut nbrs = Vec::new();
        let mut edge_faces = Vec::new();
        let mut opp_offsets = Vec::new();
        offsets.push(0u32);
        for i in 0..n_vertices {
            let (lo, hi) = (start[i] as usize, start[i + 1] as usize);
            let mut k = lo;
            while k < hi {
                let b = entries[k].0;
                let mut e = k;
                while e < hi && entries[e].0 == b {
                    e += 1;
                }
                nbrs.push(b);
                edge_faces.push((e - k) as u32);
                opp_offsets.push(k as u32);
                k = e;
            }
            offsets.push(nbrs.len() as u32);
        }
        opp_offsets.push(entries.len() as u32);
        let opposite = entries.into_iter().map(|(_, c)| c).collect();
        Ok(Adjacency { offsets, nbrs, edge_faces, opp_offsets, opposite })
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

    #[inline]
    pub fn opposite_of(&self, slot: usize) -> &[u32] {
        &self.opposite[self.opp_offsets[slot] as usize..self.opp_offsets[slot + 1] as usize]
    }

    /// Per vertex: does it lie on an edge with exactly one face?
    pub fn boundary_vertices(&self) -> Vec<bool> {
        (0..self.n_vertices()).map(|i| self.slots(i).any(|s| self.edge_faces[s] == 1)).collect()
    }

    /// Per vertex: is it used by any non-degenerate face-edge?
    pub fn referenced(&self) -> Vec<bool> {
        (0..self.n_vertices()).map(|i| self.offsets[i + 1] > self.offsets[i]).collect()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn square_of_two_triangles() {
        let a = Adjacency::build(5, &[[0, 1, 2], [0, 2, 3]]).unwrap();
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
    }
}

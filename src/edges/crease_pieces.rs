//! The pieces creases make: creases joined where they share a vertex (ridges and valleys
//! together), the unit the rules that thin a scan's creases judge and keep or drop whole.

use super::feature::FeatureEdges;
use crate::mesh::union_find::{find, join};

/// Each crease's piece, and the vertices the creases use.
pub struct CreasePieces {
    /// The vertices used by some crease, ascending.
    ids: Vec<u32>,
    /// The piece of each vertex of `ids` (a slot of `ids`, the same for a whole piece).
    root: Vec<u32>,
}

impl CreasePieces {
    pub fn of(crease: &[[u32; 2]]) -> CreasePieces {
        let mut ids: Vec<u32> = crease.iter().flatten().copied().collect();
        ids.sort_unstable();
        ids.dedup();
        let mut parent: Vec<u32> = (0..ids.len() as u32).collect();
        let slot = |v: u32| ids.binary_search(&v).expect("a vertex of a crease");
        for e in crease {
            join(&mut parent, slot(e[0]), slot(e[1]));
        }
        let root = (0..ids.len()).map(|s| find(&mut parent, s)).collect();
        CreasePieces { ids, root }
    }

    /// How many vertices the creases use (slots are 0..this).
    pub fn vertex_count(&self) -> usize {
        self.ids.len()
    }

    /// The slot of crease vertex `v`.
    pub fn slot(&self, v: u32) -> usize {
        self.ids.binary_search(&v).expect("a vertex of a crease")
    }

    /// The vertex in `slot`.
    pub fn vertex(&self, slot: usize) -> u32 {
        self.ids[slot]
    }

    /// The piece of the vertex in `slot`, as an index below `vertex_count()`.
    pub fn piece_of_slot(&self, slot: usize) -> usize {
        self.root[slot] as usize
    }

    /// The piece of crease `e`.
    pub fn piece_of(&self, e: [u32; 2]) -> usize {
        self.piece_of_slot(self.slot(e[0]))
    }
}

/// Keeps the creases of `fe` whose piece `keep` says yes to (indexed as `piece_of`).
pub fn retain_pieces(fe: &mut FeatureEdges, pieces: &CreasePieces, keep: &[bool]) {
    let flags: Vec<bool> = fe.crease.iter().map(|&e| keep[pieces.piece_of(e)]).collect();
    let mut k = flags.iter();
    fe.crease.retain(|_| *k.next().expect("one flag per crease"));
    let mut k = flags.iter();
    fe.crease_angle.retain(|_| *k.next().expect("one flag per crease"));
    let mut k = flags.iter();
    fe.crease_convex.retain(|_| *k.next().expect("one flag per crease"));
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn creases_sharing_a_vertex_are_one_piece() {
        let p = CreasePieces::of(&[[0, 1], [5, 9], [1, 2], [9, 7]]);
        assert_eq!(p.vertex_count(), 6);
        assert_eq!(p.piece_of([0, 1]), p.piece_of([1, 2]));
        assert_eq!(p.piece_of([5, 9]), p.piece_of([9, 7]));
        assert_ne!(p.piece_of([0, 1]), p.piece_of([5, 9]));
        assert_eq!(p.vertex(p.slot(7)), 7);
    }
}

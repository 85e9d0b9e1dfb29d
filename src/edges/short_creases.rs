//! Creases too short to draw: on a scanned surface, noise makes dihedral angles above any
//! useful threshold at scattered edges, and the crease lines come out as dashes. A crease is
//! kept when the connected piece of creases it belongs to (creases sharing vertices, ridges and
//! valleys together) is at least `min_length` long in total: a CAD part's creases run the
//! length of the part, a scan's noise makes short isolated pieces.

/// The shortest crease piece a rendered outline draws when none is given, as a fraction of the
/// mesh's bounding-box diagonal: it keeps a CAD part's creases (fandisk's are one piece 9.2
/// diagonals long) and drops three quarters of the scattered pieces on the Stanford bunny scan.
pub const DEFAULT_MIN_CREASE_LENGTH: f64 = 0.02;

use super::crease_pieces::{retain_pieces, CreasePieces};
use super::crooked_creases::drop_crooked_creases;
use super::feature::FeatureEdges;
use crate::mesh::Bounds;
use crate::real::{norm, sub};

/// Keeps the creases of `fe` that a drawing keeps on scans: pieces at least `min_length` of the
/// bounding-box diagonal of `positions` long in all (this module's rule) that turn by at most
/// `max_turn` degrees on average (`crooked_creases`). The crease lines drawn and the normals
/// split at creases (`NormalMode::Auto`) both follow it.
pub fn keep_drawn_creases(fe: &mut FeatureEdges, positions: &[[f64; 3]], min_length: f64, max_turn: f64) {
    let diagonal = Bounds::of(positions).diagonal();
    drop_short_creases(fe, positions, min_length * diagonal);
    drop_crooked_creases(fe, positions, max_turn);
}

/// Drops the creases of `fe` whose connected piece is shorter than `min_length` (in the units
/// of `positions`). Boundaries and non-manifold edges are kept whatever their length.
pub fn drop_short_creases(fe: &mut FeatureEdges, positions: &[[f64; 3]], min_length: f64) {
    if !(min_length > 0.0) || fe.crease.is_empty() {
        return;
    }
    let pieces = CreasePieces::of(&fe.crease);
    let mut length = vec![0.0f64; pieces.vertex_count()];
    for e in &fe.crease {
        length[pieces.piece_of(*e)] += norm(sub(positions[e[0] as usize], positions[e[1] as usize]));
    }
    let keep: Vec<bool> = length.iter().map(|&l| l >= min_length).collect();
    retain_pieces(fe, &pieces, &keep);
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_short_isolated_crease_goes_and_a_long_chain_stays() {
        let positions: Vec<[f64; 3]> = (0..10).map(|i| [i as f64, 0.0, 0.0]).collect();
        let mut fe = FeatureEdges {
            crease: vec![[0, 1], [1, 2], [2, 3], [3, 4], [7, 8]],
            crease_angle: vec![40.0; 5],
            crease_convex: vec![true, true, false, true, false],
            boundary: vec![[8, 9]],
            ..Default::default()
        };
        drop_short_creases(&mut fe, &positions, 2.0);
        assert_eq!(fe.crease, vec![[0, 1], [1, 2], [2, 3], [3, 4]]);
        assert_eq!(fe.crease_convex, vec![true, true, false, true]);
        assert_eq!(fe.crease_angle.len(), 4);
        assert_eq!(fe.boundary, vec![[8, 9]]);
    }
}

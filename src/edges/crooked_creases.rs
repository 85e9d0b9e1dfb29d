//! Creases that zig-zag: where a scan folds sharply across triangles that do not line up with
//! the fold, alternate edges pass the dihedral test and the crease follows the triangulation in
//! a saw-tooth, turning by 40 to 70 degrees at every vertex. A CAD part's creases run along its
//! edges and barely turn. A crease piece (`crease_pieces`) is kept when the mean turning angle
//! at its vertices where exactly two of its creases meet (the angle between the direction
//! arriving and the direction leaving) is at most `max_turn` degrees. A junction of three or
//! more creases, or a piece's end, has no single way on and is not counted; a piece without a
//! vertex of two creases is kept.

use super::crease_pieces::{retain_pieces, CreasePieces};
use super::feature::FeatureEdges;
use crate::real::{cross, dot, norm, sub};

/// The largest mean turn (degrees) of a crease piece a rendered outline draws when none is
/// given: fandisk's creases turn by 2.3 degrees on average and all stay; the pieces the Stanford
/// bunny scan's noise and ear rims make turn by 13 to 70 (half of them more than 30).
pub const DEFAULT_MAX_CREASE_TURN: f64 = 30.0;

/// Checks a largest mean turn in degrees: in [0, 180] (180 keeps every piece).
pub fn check_max_crease_turn(arg: &str, degrees: f64) -> crate::error::Result<()> {
    if !(0.0..=180.0).contains(&degrees) {
        return Err(crate::error::Error::invalid(arg, format!("must be in [0, 180] degrees, got {degrees}")));
    }
    Ok(())
}

/// The angle in degrees between `a -> b` and `b -> c` (0 for a zero-length step).
fn turn(a: [f64; 3], b: [f64; 3], c: [f64; 3]) -> f64 {
    let (d1, d2) = (sub(b, a), sub(c, b));
    norm(cross(d1, d2)).atan2(dot(d1, d2)).to_degrees()
}

/// Drops the creases of `fe` whose piece turns by more than `max_turn` degrees on average at
/// its vertices of two creases. `max_turn` >= 180 keeps every crease; boundaries and
/// non-manifold edges are never dropped.
pub fn drop_crooked_creases(fe: &mut FeatureEdges, positions: &[[f64; 3]], max_turn: f64) {
    if !(max_turn < 180.0) || fe.crease.is_empty() {
        return;
    }
    let pieces = CreasePieces::of(&fe.crease);
    let n = pieces.vertex_count();
    // each crease vertex's degree and its first two neighbours along creases
    let mut degree = vec![0u32; n];
    let mut ends = vec![[0u32; 2]; n];
    for e in &fe.crease {
        for (v, w) in [(e[0], e[1]), (e[1], e[0])] {
            let s = pieces.slot(v);
            if degree[s] < 2 {
                ends[s][degree[s] as usize] = w;
            }
            degree[s] += 1;
        }
    }
    let (mut turned, mut counted) = (vec![0.0f64; n], vec![0u32; n]);
    for s in (0..n).filter(|&s| degree[s] == 2) {
        let p = |v: u32| positions[v as usize];
        let piece = pieces.piece_of_slot(s);
        turned[piece] += turn(p(ends[s][0]), p(pieces.vertex(s)), p(ends[s][1]));
        counted[piece] += 1;
    }
    let keep: Vec<bool> =
        turned.iter().zip(&counted).map(|(&t, &c)| c == 0 || t <= max_turn * c as f64).collect();
    retain_pieces(fe, &pieces, &keep);
}

#[cfg(test)]
mod tests {
    use super::*;

    fn creases(crease: Vec<[u32; 2]>) -> FeatureEdges {
        let n = crease.len();
        FeatureEdges {
            crease,
            crease_angle: vec![45.0; n],
            crease_convex: vec![true; n],
            boundary: vec![[20, 21]],
            ..Default::default()
        }
    }

    #[test]
    fn a_saw_tooth_goes_and_a_straight_or_gently_bending_crease_stays() {
        // 0..6: a straight line; 10..16: a saw-tooth of equilateral triangles (120 degree turns);
        // 30..36: a gentle arc (10 degrees per vertex)
        let mut p = vec![[0.0; 3]; 40];
        for i in 0..7 {
            let x = i as f64;
            p[i] = [x, 0.0, 0.0];
            p[10 + i] = [0.5 * x, if i % 2 == 1 { 3f64.sqrt() / 2.0 } else { 0.0 }, 5.0];
            let a = (10.0 * x).to_radians();
            p[30 + i] = [a.sin(), 0.0, 10.0 + a.cos()];
        }
        let line = |o: u32| (0..6).map(|i| [o + i, o + i + 1]).collect::<Vec<_>>();
        let mut fe = creases([line(0), line(10), line(30)].concat());
        drop_crooked_creases(&mut fe, &p, 30.0);
        assert_eq!(fe.crease, [line(0), line(30)].concat());
        assert_eq!((fe.crease_angle.len(), fe.crease_convex.len()), (12, 12));
        assert_eq!(fe.boundary, vec![[20, 21]]);
        // the gentle arc turns by 10 degrees: gone at a bound below that
        drop_crooked_creases(&mut fe, &p, 9.0);
        assert_eq!(fe.crease, line(0));
    }

    #[test]
    fn off_at_180_and_junctions_and_ends_are_not_counted() {
        let p = vec![[0.0, 0.0, 0.0], [1.0, 0.0, 0.0], [0.5, 1.0, 0.0], [0.5, -1.0, 0.0]];
        let tooth = vec![[0, 1], [1, 2]];
        let mut fe = creases(tooth.clone());
        drop_crooked_creases(&mut fe, &p, 180.0);
        assert_eq!(fe.crease, tooth, "180 keeps every piece");
        drop_crooked_creases(&mut fe, &p, 100.0);
        assert!(fe.crease.is_empty(), "a turn of about 117 degrees is above 100");
        // a star of three creases at vertex 1: no vertex of exactly two creases, kept
        let star = vec![[0, 1], [1, 2], [1, 3]];
        let mut fe = creases(star.clone());
        drop_crooked_creases(&mut fe, &p, 0.0);
        assert_eq!(fe.crease, star);
        assert!(check_max_crease_turn("max_crease_turn", 181.0).is_err());
        assert!(check_max_crease_turn("max_crease_turn", f64::NAN).is_err());
        assert!(check_max_crease_turn("max_crease_turn", 0.0).is_ok());
    }
}

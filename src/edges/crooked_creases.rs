//! Creases that zig-zag: where a scan folds sharply across triangles that do not line up with
//! the fold, alternate edges pass the dihedral test and the crease follows the triangulation in
//! a saw-tooth, turning one way then the other by 30 to 70 degrees a vertex. A CAD
//! part's creases run along its edges and barely turn, or turn one way round a coarse circle.
//!
//! Rule: a crease piece (`crease_pieces`) is kept when the mean turn at its vertices where
//! exactly two of its creases meet is at most `max_turn` degrees. The turn at such a vertex is
//! the angle between the crease arriving and the crease leaving, except that a vertex whose
//! two neighbours along the piece are such vertices too and turn the same way as it does (both
//! consecutive turns about axes pointing the same way, as round a polygon) turns by 0: an
//! octagon's rim is a smooth curve drawn coarsely, a saw-tooth is not. A junction of three or
//! more creases, or a piece's end, has no single way on and is not counted; a piece without a
//! vertex of two creases is kept.

use super::crease_pieces::{retain_pieces, CreasePieces};
use super::feature::FeatureEdges;
use crate::real::{cross, dot, norm, sub};

/// The largest mean turn (degrees) of a crease piece a rendered outline draws when none is
/// given, the same as the default crease angle: fandisk's creases turn by 0.5 degrees on average
/// and all stay; of the 74 pieces left on the Stanford bunny scan by the shortest-piece rule,
/// 35 turn by more than 30 (up to 166).
pub const DEFAULT_MAX_CREASE_TURN: f64 = 30.0;

/// Checks a largest mean turn in degrees: in [0, 180] (180 keeps every piece).
pub fn check_max_crease_turn(arg: &str, degrees: f64) -> crate::error::Result<()> {
    if !(0.0..=180.0).contains(&degrees) {
        return Err(crate::error::Error::invalid(arg, format!("must be in [0, 180] degrees, got {degrees}")));
    }
    Ok(())
}

/// The axis `a -> b -> c` turns about (length: the sine of the turn times the steps' lengths).
fn axis(a: [f64; 3], b: [f64; 3], c: [f64; 3]) -> [f64; 3] {
    cross(sub(b, a), sub(c, b))
}

/// The angle in degrees between `a -> b` and `b -> c` (0 for a zero-length step).
fn turn(a: [f64; 3], b: [f64; 3], c: [f64; 3]) -> f64 {
    let (d1, d2) = (sub(b, a), sub(c, b));
    norm(cross(d1, d2)).atan2(dot(d1, d2)).to_degrees()
}

/// Drops the creases of `fe` whose piece turns by more than `max_turn` degrees on average at
/// its vertices of two creases (see the module's rule). `max_turn` >= 180 keeps every crease;
/// boundaries and non-manifold edges are never dropped.
pub fn drop_crooked_creases(fe: &mut FeatureEdges, positions: &[[f64; 3]], max_turn: f64) {
    if max_turn >= 180.0 || max_turn.is_nan() || fe.crease.is_empty() {
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
    let p = |v: u32| positions[v as usize];
    let through = |s: usize| degree[s] == 2;
    // the neighbour of `w` (a vertex of two creases) other than `v`
    let beyond = |w: u32, v: u32| {
        let e = ends[pieces.slot(w)];
        if e[0] == v {
            e[1]
        } else {
            e[0]
        }
    };
    let (mut turned, mut counted) = (vec![0.0f64; n], vec![0u32; n]);
    for s in (0..n).filter(|&s| through(s)) {
        let v = pieces.vertex(s);
        let [a, c] = ends[s];
        // v turns as both neighbours do: a coarse curve, not a saw-tooth
        let same_way = [(a, c), (c, a)].iter().all(|&(w, x)| {
            through(pieces.slot(w)) && dot(axis(p(x), p(v), p(w)), axis(p(v), p(w), p(beyond(w, v)))) > 0.0
        });
        let piece = pieces.piece_of_slot(s);
        if !same_way {
            turned[piece] += turn(p(a), p(v), p(c));
        }
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
        // the arc turns one way: its inner vertices count as straight, the two next to its
        // ends (whose neighbour is an end) as 10 degrees, a mean of 4 over its 5 vertices
        drop_crooked_creases(&mut fe, &p, 4.5);
        assert_eq!(fe.crease.len(), 12);
        drop_crooked_creases(&mut fe, &p, 3.5);
        assert_eq!(fe.crease, line(0));
    }

    #[test]
    fn a_coarse_polygon_turning_one_way_stays() {
        // an octagon (45 degrees at each vertex, all the same way) and a zig-zag ring of 16
        // vertices alternately in and out: the same turns, one way and back and forth
        let mut p = Vec::new();
        for i in 0..8 {
            let a = (45.0 * i as f64).to_radians();
            p.push([a.cos(), a.sin(), 0.0]);
        }
        for i in 0..16 {
            let a = (22.5 * i as f64).to_radians();
            let r = if i % 2 == 0 { 1.0 } else { 0.7 };
            p.push([r * a.cos(), r * a.sin(), 5.0]);
        }
        let ring = |o: u32, n: u32| (0..n).map(|i| [o + i, o + (i + 1) % n]).collect::<Vec<_>>();
        let mut fe = creases([ring(0, 8), ring(8, 16)].concat());
        drop_crooked_creases(&mut fe, &p, 30.0);
        assert_eq!(fe.crease, ring(0, 8));
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

//! The zero set of a field given at the vertices, traced through the faces as polylines: the
//! curve where a linearly interpolated value changes sign, cut to where other interpolated
//! fields (the conditions) are positive, and chained across faces. Smooth and suggestive
//! contours are both zero sets.
//!
//! Rules: a vertex value counts as positive when it is > 0 (exact zeros count as negative, so
//! a face has either no crossing or a crossing on exactly two of its edges). The crossing on
//! an edge is interpolated from its smaller-index end, so the two faces of an edge find the
//! same point bit for bit and the pieces chain. Where a condition cuts a piece inside a face,
//! the cut end is a stroke end.

use std::collections::HashMap;

use rayon::prelude::*;

use super::chains::chain_edges;

/// Polylines as one flat point list and the offsets where each starts (CSR): line i is
/// `points[starts[i]..starts[i + 1]]`; a closed line repeats its first point at the end.
/// `strength` holds a number per point (how strongly the line is there, in [0, 1]), or nothing
/// for a zero set without conditions, whose every point is there fully.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Polylines {
    pub points: Vec<[f64; 3]>,
    pub starts: Vec<u32>,
    pub strength: Vec<f64>,
}

impl Polylines {
    pub fn len(&self) -> usize {
        self.starts.len().saturating_sub(1)
    }

    pub fn is_empty(&self) -> bool {
        self.len() == 0
    }

    /// Line i's points.
    pub fn line(&self, i: usize) -> &[[f64; 3]] {
        &self.points[self.starts[i] as usize..self.starts[i + 1] as usize]
    }

    /// Line i's strengths, one per point (none: fully there).
    pub fn line_strength(&self, i: usize) -> &[f64] {
        if self.strength.is_empty() {
            return &[];
        }
        &self.strength[self.starts[i] as usize..self.starts[i + 1] as usize]
    }
}

/// A piece's end: on a mesh edge (key `lo << 32 | hi`), or inside a face (cut by a condition).
#[derive(Clone, Copy)]
struct End {
    key: Option<u64>,
    p: [f64; 3],
    strength: f64,
}

fn lerp(a: [f64; 3], b: [f64; 3], t: f64) -> [f64; 3] {
    [a[0] + t * (b[0] - a[0]), a[1] + t * (b[1] - a[1]), a[2] + t * (b[2] - a[2])]
}

/// The zero set of `value` (a field given per vertex) over `faces` (any number of slices of
/// them), kept where every field of `conditions` is > 0, with `strength` of the conditions
/// interpolated to each point. The fields are read through functions of the vertex, so a
/// caller computes them only for the faces it visits; each must give a vertex the same number
/// whichever face asks.
pub fn zero_set<const K: usize>(
    positions: &[[f64; 3]],
    faces: &[&[[u32; 3]]],
    value: impl Fn(u32) -> f64 + Sync,
    conditions: impl Fn(u32) -> [f64; K] + Sync,
    strength: impl Fn([f64; K]) -> f64 + Sync,
) -> Polylines {
    zero_set_marking(positions, faces, value, conditions, strength, |_| {})
}

/// `zero_set`, calling `mark` with each face that holds a piece of it (from several threads):
/// what a sequence of views remembers of where lines were drawn.
pub fn zero_set_marking<const K: usize>(
    positions: &[[f64; 3]],
    faces: &[&[[u32; 3]]],
    value: impl Fn(u32) -> f64 + Sync,
    conditions: impl Fn(u32) -> [f64; K] + Sync,
    strength: impl Fn([f64; K]) -> f64 + Sync,
    mark: impl Fn(&[u32; 3]) + Sync,
) -> Polylines {
    let fields = Fields { value, conditions, strength };
    let pieces: Vec<[End; 2]> = faces
        .par_iter()
        .flat_map_iter(|chunk| {
            chunk.iter().filter_map(|f| face_piece(positions, f, &fields).inspect(|_| mark(f)))
        })
        .collect();
    chain_pieces(&pieces, K > 0)
}

/// The functions a zero set reads.
struct Fields<V, C, S> {
    value: V,
    conditions: C,
    strength: S,
}

/// The piece of the zero set in one face, if any.
fn face_piece<const K: usize>(
    positions: &[[f64; 3]],
    f: &[u32; 3],
    fields: &Fields<impl Fn(u32) -> f64, impl Fn(u32) -> [f64; K], impl Fn([f64; K]) -> f64>,
) -> Option<[End; 2]> {
    let values = f.map(&fields.value);
    let positive = values.map(|x| x > 0.0);
    if positive[0] == positive[1] && positive[1] == positive[2] {
        return None;
    }
    // the two edges whose ends differ in sign, each from its smaller index: (corner of the
    // smaller end, corner of the larger, t)
    let mut ends = [(0usize, 0usize, 0.0f64); 2];
    let mut n = 0;
    for j in 0..3 {
        let k = (j + 1) % 3;
        if positive[j] != positive[k] {
            let (lo, hi) = if f[j] < f[k] { (j, k) } else { (k, j) };
            let (vl, vh) = (values[lo], values[hi]);
            let t = vl / (vl - vh);
            ends[n] = (lo, hi, if t.is_finite() { t.clamp(0.0, 1.0) } else { 0.5 });
            n += 1;
        }
    }
    debug_assert_eq!(n, 2);
    // the part of the piece (u in [0, 1] from end 0 to end 1) where every condition is > 0
    let (mut u0, mut u1) = (0.0f64, 1.0f64);
    let (mut at0, mut at1) = ([0.0; K], [0.0; K]);
    if K > 0 {
        let c = f.map(&fields.conditions);
        let at = |(lo, hi, t): (usize, usize, f64), k: usize| c[lo][k] + t * (c[hi][k] - c[lo][k]);
        for k in 0..K {
            let (c0, c1) = (at(ends[0], k), at(ends[1], k));
            (at0[k], at1[k]) = (c0, c1);
            match (c0 > 0.0, c1 > 0.0) {
                (true, true) => {}
                (false, false) => return None,
                (true, false) => u1 = u1.min(c0 / (c0 - c1)),
                (false, true) => u0 = u0.max(c0 / (c0 - c1)),
            }
        }
    }
    if !(u1 > u0) {
        return None;
    }
    let strength = |u: f64| (fields.strength)(std::array::from_fn(|k| at0[k] + u * (at1[k] - at0[k])));
    let point =
        |(lo, hi, t): (usize, usize, f64)| lerp(positions[f[lo] as usize], positions[f[hi] as usize], t);
    let (p0, p1) = (point(ends[0]), point(ends[1]));
    let key = |(lo, hi, _): (usize, usize, f64)| (f[lo] as u64) << 32 | f[hi] as u64;
    let a = if u0 > 0.0 {
        End { key: None, p: lerp(p0, p1, u0), strength: strength(u0) }
    } else {
        End { key: Some(key(ends[0])), p: p0, strength: strength(0.0) }
    };
    let b = if u1 < 1.0 {
        End { key: None, p: lerp(p0, p1, u1), strength: strength(u1) }
    } else {
        End { key: Some(key(ends[1])), p: p1, strength: strength(1.0) }
    };
    Some([a, b])
}

/// Chains pieces that share an edge point into polylines (`chains::chain_edges`' rules).
fn chain_pieces(pieces: &[[End; 2]], with_strength: bool) -> Polylines {
    let mut ids: HashMap<u64, u32> = HashMap::with_capacity(pieces.len());
    let mut points: Vec<End> = Vec::with_capacity(pieces.len() + 1);
    let mut id_of = |e: &End, points: &mut Vec<End>| -> u32 {
        match e.key {
            Some(k) => *ids.entry(k).or_insert_with(|| {
                points.push(*e);
                points.len() as u32 - 1
            }),
            None => {
                points.push(*e);
                points.len() as u32 - 1
            }
        }
    };
    let pairs: Vec<[u32; 2]> =
        pieces.iter().map(|[a, b]| [id_of(a, &mut points), id_of(b, &mut points)]).collect();
    let (flat, starts) = chain_edges(&pairs);
    Polylines {
        points: flat.iter().map(|&i| points[i as usize].p).collect(),
        starts,
        strength: match with_strength {
            true => flat.iter().map(|&i| points[i as usize].strength).collect(),
            false => Vec::new(),
        },
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_plane_cut_is_one_line_through_shared_points() {
        // a 3x3 grid of squares, value = x - 1.5: a vertical line at x = 1.5
        let mut positions = Vec::new();
        for y in 0..4 {
            for x in 0..4 {
                positions.push([x as f64, y as f64, 0.0]);
            }
        }
        let mut faces = Vec::new();
        for y in 0..3u32 {
            for x in 0..3u32 {
                let a = y * 4 + x;
                faces.push([a, a + 1, a + 5]);
                faces.push([a, a + 5, a + 4]);
            }
        }
        let value: Vec<f64> = positions.iter().map(|p| p[0] - 1.5).collect();
        let lines = zero_set(&positions, &[&faces], |v| value[v as usize], |_| [], |_| 1.0);
        assert_eq!(lines.len(), 1);
        assert!(lines.points.iter().all(|p| (p[0] - 1.5).abs() < 1e-12));
        // cut to y > 1.2 by a condition
        let cond: Vec<f64> = positions.iter().map(|p| p[1] - 1.2).collect();
        let halves: [&[[u32; 3]]; 2] = [&faces[..4], &faces[4..]];
        let cut = zero_set(&positions, &halves, |v| value[v as usize], |v| [cond[v as usize]], |c| c[0]);
        assert_eq!(cut.len(), 1);
        assert!(cut.points.iter().all(|p| p[1] >= 1.2 - 1e-12));
        assert!(cut.points.iter().any(|p| (p[1] - 1.2).abs() < 1e-12));
        // the strength is the condition interpolated to each point: y - 1.2 on this line
        assert_eq!(cut.strength.len(), cut.points.len());
        assert!(cut.points.iter().zip(&cut.strength).all(|(p, s)| (s - (p[1] - 1.2)).abs() < 1e-12));
        assert!(lines.strength.iter().all(|&s| s == 1.0));
    }
}

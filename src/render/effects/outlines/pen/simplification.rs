//! Simplifying a stroke (Douglas-Peucker): the fewest of its points, found by splitting at the
//! farthest, that keep the polyline within a tolerance of where it was.

use crate::error::{as_many, Error, Result};

/// Indices of the points of `points` that stay within `tolerance` pixels of the polyline; the
/// ends are always kept, and a tolerance of 0 keeps every point. With `widths` (pixels per point)
/// that vary, half the width is a third coordinate, so that the edges of the ink too stay
/// within the tolerance (a taper keeps the points that shape it).
pub fn kept(points: &[[f64; 2]], tolerance: f64, widths: Option<&[f64]>) -> Result<Vec<usize>> {
    if !(tolerance.is_finite() && tolerance >= 0.0) {
        return Err(Error::invalid(
            "simplify",
            format!("must be a finite number of pixels >= 0, got {tolerance}"),
        ));
    }
    let n = points.len();
    if let Some(w) = widths {
        as_many("widths", w.len(), ("one per point", n))?;
    }
    if tolerance == 0.0 || n < 3 {
        return Ok((0..n).collect());
    }
    let varies = |w: &[f64]| w.iter().any(|&x| x != w[0]);
    Ok(match widths {
        Some(w) if varies(w) => {
            let lifted: Vec<[f64; 3]> = points.iter().zip(w).map(|(p, &w)| [p[0], p[1], 0.5 * w]).collect();
            douglas_peucker(&lifted, tolerance, distance_3d)
        }
        _ => douglas_peucker(points, tolerance, distance_2d),
    })
}

/// The kept indices, ascending: each span split at its point farthest from the chord (the first
/// of equally far ones) while that point lies beyond `tolerance`.
fn douglas_peucker<P: Copy>(points: &[P], tolerance: f64, distance: fn(P, P, P) -> f64) -> Vec<usize> {
    let n = points.len();
    let mut keep = vec![false; n];
    keep[0] = true;
    keep[n - 1] = true;
    let mut spans = vec![(0, n - 1)];
    while let Some((a, b)) = spans.pop() {
        if b - a < 2 {
            continue;
        }
        let mut farthest = (a + 1, f64::NEG_INFINITY);
        for i in a + 1..b {
            let d = distance(points[i], points[a], points[b]);
            if d > farthest.1 {
                farthest = (i, d);
            }
        }
        if farthest.1 > tolerance {
            keep[farthest.0] = true;
            spans.push((a, farthest.0));
            spans.push((farthest.0, b));
        }
    }
    (0..n).filter(|&i| keep[i]).collect()
}

/// Distance of `p` from the line through `a` and `b` (from `a` where they coincide).
fn distance_2d(p: [f64; 2], a: [f64; 2], b: [f64; 2]) -> f64 {
    let (rel, seg) = ([p[0] - a[0], p[1] - a[1]], [b[0] - a[0], b[1] - a[1]]);
    let length = seg[0].hypot(seg[1]);
    if length > 0.0 {
        (seg[0] * rel[1] - seg[1] * rel[0]).abs() / length
    } else {
        rel[0].hypot(rel[1])
    }
}

/// `distance_2d` in three dimensions.
fn distance_3d(p: [f64; 3], a: [f64; 3], b: [f64; 3]) -> f64 {
    let rel = [p[0] - a[0], p[1] - a[1], p[2] - a[2]];
    let seg = [b[0] - a[0], b[1] - a[1], b[2] - a[2]];
    let norm = |v: [f64; 3]| (v[0] * v[0] + v[1] * v[1] + v[2] * v[2]).sqrt();
    let length = norm(seg);
    if length > 0.0 {
        let cross = [
            rel[1] * seg[2] - rel[2] * seg[1],
            rel[2] * seg[0] - rel[0] * seg[2],
            rel[0] * seg[1] - rel[1] * seg[0],
        ];
        norm(cross) / length
    } else {
        norm(rel)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn points_within_the_tolerance_go_and_the_ends_and_corners_stay() {
        let line = [[0.0, 0.0], [1.0, 0.1], [2.0, -0.1], [3.0, 0.0], [3.1, 2.0], [3.0, 4.0]];
        assert_eq!(kept(&line, 0.25, None).unwrap(), vec![0, 3, 5]);
        assert_eq!(kept(&line, 0.05, None).unwrap(), vec![0, 1, 2, 3, 4, 5]);
        assert_eq!(kept(&line, 0.0, None).unwrap(), (0..6).collect::<Vec<_>>());
        assert_eq!(kept(&line[..2], 5.0, None).unwrap(), vec![0, 1]);
        // a loop whose ends coincide keeps the point farthest from them
        let ring = [[0.0, 0.0], [2.5, 2.6], [5.0, 5.0], [0.0, 0.0]];
        assert_eq!(kept(&ring, 0.25, None).unwrap(), vec![0, 2, 3]);
    }

    #[test]
    fn a_taper_keeps_the_points_that_shape_it() {
        let line: Vec<[f64; 2]> = (0..5).map(|i| [i as f64, 0.0]).collect();
        let widths = [1.0, 3.0, 5.0, 3.0, 1.0];
        assert_eq!(kept(&line, 0.25, None).unwrap(), vec![0, 4]);
        assert_eq!(kept(&line, 0.25, Some(&widths)).unwrap(), vec![0, 2, 4]);
        assert_eq!(kept(&line, 0.25, Some(&[2.0; 5])).unwrap(), vec![0, 4], "an even width is no taper");
    }

    #[test]
    fn a_bad_tolerance_or_widths_is_refused() {
        let line = [[0.0, 0.0], [1.0, 0.0], [2.0, 0.0]];
        assert!(matches!(kept(&line, -1.0, None), Err(Error::InvalidValue { .. })));
        assert!(matches!(kept(&line, f64::NAN, None), Err(Error::InvalidValue { .. })));
        assert!(
            matches!(kept(&line, 1.0, Some(&[1.0])), Err(Error::InvalidValue { arg, .. }) if arg == "widths")
        );
    }
}

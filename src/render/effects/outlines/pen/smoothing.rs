//! Smoothing a stroke along its length: each point moved to the Gaussian-weighted mean of the
//! polyline within a radius of it, measured along the polyline. The polyline is integrated, not
//! just its points, so unevenly spaced points weigh by the length they stand for and a straight
//! line stays where it is.

use crate::error::{Error, Result};

/// Spacing of the samples that integrate a stroke over the smoothing window, in pixels.
pub const SMOOTH_STEP: f64 = 0.25;
/// Fewest and most samples in a window: enough to shape the Gaussian, few enough that a wide
/// radius costs no more than a fine one.
const FEWEST_SAMPLES: usize = 8;
const MOST_SAMPLES: usize = 1024;
/// The Gaussian's sigma is a third of the window's half width.
const SIGMAS_PER_RADIUS: f64 = 3.0;

/// `points` smoothed over `radius` pixels (sigma a third of the radius). Near the ends of an
/// open polyline the window shrinks to the distance to the end, so the ends stay where they are;
/// a closed one (first point equal to the last) wraps around and stays closed. No point moves
/// more than `radius`: every point averaged lies within that distance along the polyline, so
/// within it in a straight line. A radius of 0 returns the points as they are.
pub fn smoothed(points: &[[f64; 2]], radius: f64) -> Result<Vec<[f64; 2]>> {
    if !(radius.is_finite() && radius >= 0.0) {
        return Err(Error::invalid(
            "smooth",
            format!("must be a finite number of pixels >= 0, got {radius}"),
        ));
    }
    let n = points.len();
    if radius == 0.0 || n < 3 {
        return Ok(points.to_vec());
    }
    let s = arc_lengths(points);
    let total = s[n - 1];
    if !(total > 0.0) {
        return Ok(points.to_vec());
    }
    let closed = points[0] == points[n - 1];
    let reach = if closed { radius.min(total / 2.0) } else { radius };
    let unit = window(reach);
    let weights = gaussian(&unit);
    // closed: the table wraps one point each way, so every arc length mod total falls inside it
    let (table_s, table_p): (Vec<f64>, Vec<[f64; 2]>) = if closed {
        let body = n - 1;
        let s_wrapped = std::iter::once(s[body - 1] - total).chain(s[..body].iter().copied()).chain([total]);
        let p_wrapped =
            std::iter::once(points[body - 1]).chain(points[..body].iter().copied()).chain([points[0]]);
        (s_wrapped.collect(), p_wrapped.collect())
    } else {
        (s.clone(), points.to_vec())
    };
    let mut out: Vec<[f64; 2]> = (0..n)
        .map(|i| {
            let h = if closed { reach } else { reach.min(s[i].min(total - s[i])) };
            let mut sum = [0.0, 0.0];
            for (&t, &w) in unit.iter().zip(&weights) {
                let mut u = s[i] + h * t;
                if closed {
                    u = u.rem_euclid(total);
                }
                let p = interpolated(&table_s, &table_p, u);
                sum[0] += w * p[0];
                sum[1] += w * p[1];
            }
            sum
        })
        .collect();
    if closed {
        out[n - 1] = out[0];
    } else {
        out[0] = points[0];
        out[n - 1] = points[n - 1];
    }
    Ok(out)
}

/// Distance along the polyline from its first point to each point.
fn arc_lengths(points: &[[f64; 2]]) -> Vec<f64> {
    let mut s = Vec::with_capacity(points.len());
    let mut total = 0.0;
    s.push(0.0);
    for w in points.windows(2) {
        total += (w[1][0] - w[0][0]).hypot(w[1][1] - w[0][1]);
        s.push(total);
    }
    s
}

/// The sample offsets across a window of half width `reach`, in half widths from -1 to 1 (the
/// last exactly 1): one every `SMOOTH_STEP` pixels, an odd count so that one falls on the point
/// itself.
fn window(reach: f64) -> Vec<f64> {
    let samples = ((2.0 * reach / SMOOTH_STEP).ceil() as usize).clamp(FEWEST_SAMPLES, MOST_SAMPLES) | 1;
    let step = 2.0 / (samples - 1) as f64;
    (0..samples).map(|i| if i + 1 == samples { 1.0 } else { i as f64 * step - 1.0 }).collect()
}

/// The normalised Gaussian weights of the samples at `unit` (sigma a third of the half width).
fn gaussian(unit: &[f64]) -> Vec<f64> {
    let raw: Vec<f64> = unit
        .iter()
        .map(|&u| {
            let t = SIGMAS_PER_RADIUS * u;
            (-0.5 * t * t).exp()
        })
        .collect();
    let sum: f64 = raw.iter().sum();
    raw.into_iter().map(|w| w / sum).collect()
}

/// The polyline's point at arc length `u` (`s` ascending), held at its ends beyond them.
fn interpolated(s: &[f64], p: &[[f64; 2]], u: f64) -> [f64; 2] {
    let last = s.len() - 1;
    if u <= s[0] {
        return p[0];
    }
    if u >= s[last] {
        return p[last];
    }
    // the last sample at or before u (after a zero-length segment, the later of its two points)
    let j = s.partition_point(|&v| v <= u) - 1;
    if s[j] == u {
        return p[j];
    }
    let t = (u - s[j]) / (s[j + 1] - s[j]);
    [p[j][0] + t * (p[j + 1][0] - p[j][0]), p[j][1] + t * (p[j + 1][1] - p[j][1])]
}

#[cfg(test)]
mod tests {
    use super::*;

    fn moved(a: &[[f64; 2]], b: &[[f64; 2]]) -> Vec<f64> {
        a.iter().zip(b).map(|(p, q)| (p[0] - q[0]).hypot(p[1] - q[1])).collect()
    }

    #[test]
    fn a_straight_line_stays_and_a_zigzag_flattens_with_its_ends_kept() {
        let xs = [0.0, 0.3, 0.4, 2.0, 2.1, 5.0, 5.2, 9.0];
        let line: Vec<[f64; 2]> = xs.iter().map(|&x| [x, 0.5 * x]).collect();
        let out = smoothed(&line, 2.0).unwrap();
        assert!(moved(&line, &out).iter().all(|&d| d < 1e-12), "unevenly spaced points stay on the line");
        let zig: Vec<[f64; 2]> = (0..30).map(|i| [i as f64, 0.4 * (i % 2) as f64]).collect();
        let flat = smoothed(&zig, 2.0).unwrap();
        assert_eq!((flat[0], flat[29]), (zig[0], zig[29]));
        assert!(flat[10..20].iter().all(|p| (p[1] - 0.2).abs() < 0.05), "the teeth, 0.2 px high, shrink");
        assert!(moved(&zig, &flat).iter().all(|&d| d <= 2.0));
        assert_eq!(smoothed(&zig, 0.0).unwrap(), zig);
    }

    #[test]
    fn a_closed_square_rounds_its_corners_and_stays_closed() {
        let corners = [[0.0, 0.0], [20.0, 0.0], [20.0, 20.0], [0.0, 20.0]];
        let mut square = Vec::new();
        for i in 0..4 {
            let (a, b) = (corners[i], corners[(i + 1) % 4]);
            square.extend((0..20).map(|j| {
                let t = j as f64 / 20.0;
                [a[0] + (b[0] - a[0]) * t, a[1] + (b[1] - a[1]) * t]
            }));
        }
        square.push(corners[0]);
        let round = smoothed(&square, 3.0).unwrap();
        assert_eq!(round[0], round[80]);
        let d = moved(&square, &round);
        assert!(d[20] > 0.3 && d[20] <= 3.0, "a corner moves in");
        assert!(d[10] < 1e-9, "the middle of a side stays");
    }

    #[test]
    fn a_radius_that_is_not_a_number_of_pixels_is_refused() {
        let line = [[0.0, 0.0], [1.0, 0.0], [2.0, 0.0]];
        for bad in [-1.0, f64::NAN, f64::INFINITY] {
            assert!(matches!(smoothed(&line, bad), Err(Error::InvalidValue { .. })));
        }
    }
}

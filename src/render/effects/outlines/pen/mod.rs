//! The visible lines as a pen draws them (`RenderResult.strokes`, `RenderResult.svg`):
//! smoothed along their length (`smoothing`), simplified (`simplification`), ordered for a pen
//! plotter (`plotter_order`) and written as SVG (`svg`).

pub mod plotter_order;
pub mod simplification;
pub mod smoothing;
pub mod svg;

use crate::error::{as_many, Error, Result};

/// Checks the points of a stroke (the argument `arg`): each finite.
pub fn check_points(arg: &str, points: &[[f64; 2]]) -> Result<()> {
    match points.iter().position(|q| !(q[0].is_finite() && q[1].is_finite())) {
        Some(i) => Err(Error::invalid(arg, format!("point {i} is not finite: {:?}", points[i]))),
        None => Ok(()),
    }
}

/// Checks the widths of a stroke of `n` points (the argument `arg`): one per point, each finite.
pub fn check_widths(arg: &str, widths: &[f64], n: usize) -> Result<()> {
    as_many(arg, widths.len(), ("one width per point", n))?;
    if widths.iter().any(|v| !v.is_finite()) {
        return Err(Error::invalid(arg, "widths must be finite"));
    }
    Ok(())
}

/// A stroke as the SVG draws it: `points` smoothed over `smooth` pixels, then simplified to
/// within `simplify` pixels, the ink's edges too where `by_width` (`widths`, pixels per point).
/// Returns the points drawn and which of the stroke's points they are (for their widths).
pub fn drawn(
    points: &[[f64; 2]],
    widths: &[f64],
    smooth: f64,
    simplify: f64,
    by_width: bool,
) -> Result<(Vec<[f64; 2]>, Vec<usize>)> {
    let smooth_points = smoothing::smoothed(points, smooth)?;
    let kept = simplification::kept(&smooth_points, simplify, by_width.then_some(widths))?;
    Ok((kept.iter().map(|&i| smooth_points[i]).collect(), kept))
}

/// `drawn` of each stroke, in parallel: its points, and its widths where they shape it (None:
/// simplified by its points alone).
pub fn drawn_all(
    strokes: &[(Vec<[f64; 2]>, Option<Vec<f64>>)],
    smooth: f64,
    simplify: f64,
) -> Result<Vec<(Vec<[f64; 2]>, Vec<usize>)>> {
    use rayon::prelude::*;
    strokes
        .par_iter()
        .map(|(p, w)| drawn(p, w.as_deref().unwrap_or(&[]), smooth, simplify, w.is_some()))
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_drawn_stroke_is_smoothed_then_simplified() {
        let zig: Vec<[f64; 2]> = (0..40).map(|i| [i as f64, 0.4 * (i % 2) as f64]).collect();
        let widths = vec![1.0; 40];
        let (raw, all) = drawn(&zig, &widths, 0.0, 0.0, false).unwrap();
        assert_eq!((raw, all.len()), (zig.clone(), 40));
        let (simple, kept) = drawn(&zig, &widths, 0.0, 0.25, true).unwrap();
        assert_eq!(simple.len(), kept.len());
        assert!(kept.len() > 20, "the zigzag's teeth stand out of a quarter pixel");
        let (smooth, kept) = drawn(&zig, &widths, 3.0, 0.25, false).unwrap();
        assert!(kept.len() < 10, "smoothed flat first, few points are left");
        assert_eq!((smooth[0], *smooth.last().unwrap()), (zig[0], zig[39]));
    }
}

//! How wide a mesh-space line is along its length, as a factor of its kind's width: thinning
//! toward the ends of each chain over `taper` pixels of its projected length (as brush strokes
//! and Freestyle's thickness modifiers do), and, optionally, scaled by depth, nearer lines
//! wider; and a suggestive contour's by its strength (`strength_factor`). The `silhouettes`
//! step gives each line its factors at both ends; the line pass, its
//! CPU reference (`visibility::coverage_image`) and the visible strokes' widths
//! (`visibility::visible_runs`, `RenderResult.line_widths`) interpolate them along the line.

use serde::{Deserialize, Serialize};

/// The thinnest a tapered end gets, as a factor of the width (a round dot, not nothing).
pub const TAPER_FLOOR: f64 = 0.2;
/// Depth scaling never goes beyond these factors (a line at the camera would be infinitely wide).
pub const DEPTH_FACTOR_RANGE: (f64, f64) = (0.25, 4.0);
/// Longest taper, in pixels.
pub const MAX_TAPER: f64 = 4096.0;

/// The width factor of a line of `strength` in [0, 1] (a suggestive contour fading in past its
/// threshold): down to `TAPER_FLOOR`, so a faint line is a thin one, as a brush would draw it.
pub fn strength_factor(strength: f64) -> f64 {
    TAPER_FLOOR + (1.0 - TAPER_FLOOR) * strength.clamp(0.0, 1.0)
}

/// Width along a chain: `taper` pixels at each end over which it thins to `TAPER_FLOOR`
/// (0: no taper), and whether the width scales with reference depth / depth.
#[derive(Clone, Copy, Debug, Default, PartialEq, Serialize, Deserialize)]
pub struct StrokeWidth {
    pub taper: f64,
    pub by_depth: bool,
}

impl StrokeWidth {
    /// Whether every factor is 1.
    pub fn is_constant(&self) -> bool {
        self.taper == 0.0 && !self.by_depth
    }

    /// The factor at each point of a chain, from the points' distances along the chain on
    /// screen (`along`, pixels from its start, non-decreasing) and their depths; `reference`
    /// is the depth at which the factor of depth is 1. A closed chain has no ends to taper.
    pub fn factors(&self, along: &[f64], depths: &[f64], closed: bool, reference: f64) -> Vec<f64> {
        let total = along.last().copied().unwrap_or(0.0);
        along
            .iter()
            .zip(depths)
            .map(|(&s, &z)| {
                let mut f = 1.0;
                if self.taper > 0.0 && !closed {
                    let end = s.min(total - s).max(0.0);
                    f *= (end / self.taper).clamp(TAPER_FLOOR, 1.0);
                }
                if self.by_depth && z > 0.0 && reference > 0.0 {
                    f *= (reference / z).clamp(DEPTH_FACTOR_RANGE.0, DEPTH_FACTOR_RANGE.1);
                }
                f
            })
            .collect()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn ends_thin_and_near_lines_widen() {
        let along = [0.0, 5.0, 10.0, 50.0, 95.0, 100.0];
        let depths = [2.0; 6];
        let taper = StrokeWidth { taper: 10.0, by_depth: false };
        assert_eq!(
            taper.factors(&along, &depths, false, 2.0),
            vec![TAPER_FLOOR, 0.5, 1.0, 1.0, 0.5, TAPER_FLOOR]
        );
        assert!(taper.factors(&along, &depths, true, 2.0).iter().all(|&f| f == 1.0), "a loop has no ends");
        let depth = StrokeWidth { taper: 0.0, by_depth: true };
        assert_eq!(depth.factors(&[0.0, 1.0, 2.0], &[1.0, 2.0, 100.0], false, 2.0), vec![2.0, 1.0, 0.25]);
        assert!(StrokeWidth::default().is_constant());
    }
}

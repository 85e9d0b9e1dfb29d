//! Effects a toon material can add on top of its bands (Borquez and Yepez): cross-hatching,
//! whose stroke density follows the band's tone, and dithering, which blends neighbouring bands
//! with a threshold pattern. Both are shading variants: no extra pass.

use crate::error::{Error, Result};
use crate::render::color::Srgb;

/// Stroke layers of the hatching, added one by one as the tone darkens: at 45, -45, 0 and 90
/// degrees (cross-hatching). Layer k (1-based) shows where the tone is below 1 - k / (LAYERS + 1).
pub const HATCH_LAYERS: usize = 4;
/// Ink of the strokes when none is given (sRGB).
pub const DEFAULT_INK: Srgb = [0.1, 0.1, 0.1];
/// Pixels between strokes of one layer, and their width, when none are given.
pub const DEFAULT_HATCH_SPACING: f64 = 6.0;
pub const DEFAULT_HATCH_WIDTH: f64 = 1.25;
/// How far (in L.n) dithering moves a pixel toward the neighbouring band, when none is given.
pub const DEFAULT_DITHER_AMOUNT: f64 = 0.15;

/// The number of stroke layers drawn at tone `tone` (CPU reference of the shader's rule).
pub fn hatch_layers(tone: f64) -> usize {
    (1..=HATCH_LAYERS).filter(|&k| tone < 1.0 - k as f64 / (HATCH_LAYERS + 1) as f64).count()
}

#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Hatching {
    /// sRGB ink colour.
    pub ink: Srgb,
    /// Pixels between the strokes of one layer (the pattern keeps about this spacing on screen
    /// at any distance, switching between octaves of an object-space pattern).
    pub spacing: f64,
    /// Stroke width in pixels.
    pub width: f64,
}

impl Default for Hatching {
    fn default() -> Self {
        Hatching { ink: DEFAULT_INK, spacing: DEFAULT_HATCH_SPACING, width: DEFAULT_HATCH_WIDTH }
    }
}

impl Hatching {
    pub fn validate(&self, arg: &str) -> Result<()> {
        crate::render::color::check_unit(&format!("{arg}ink"), &self.ink)?;
        if !(self.spacing.is_finite() && (2.0..=256.0).contains(&self.spacing)) {
            return Err(Error::invalid(
                format!("{arg}spacing"),
                format!("must be in [2, 256] pixels, got {}", self.spacing),
            ));
        }
        if !(self.width.is_finite() && self.width > 0.0 && self.width <= self.spacing) {
            return Err(Error::invalid(
                format!("{arg}width"),
                format!("must be in (0, spacing] pixels, got {}", self.width),
            ));
        }
        Ok(())
    }
}

/// The threshold pattern of dithering.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum DitherPattern {
    /// Ordered dithering with a 2x2, 4x4 or 8x8 Bayer matrix.
    Bayer2 = 1,
    Bayer4 = 2,
    Bayer8 = 3,
    /// The R2 low-discrepancy sequence (Roberts): a pattern without the Bayer matrix's grid,
    /// whose spectrum is close to blue noise.
    Blue = 4,
}

impl DitherPattern {
    pub const NAMES: [&'static str; 4] = ["bayer2", "bayer4", "bayer8", "blue"];

    pub fn parse(arg: &str, s: &str) -> Result<Self> {
        match s {
            "bayer2" => Ok(Self::Bayer2),
            "bayer4" => Ok(Self::Bayer4),
            "bayer8" => Ok(Self::Bayer8),
            "blue" => Ok(Self::Blue),
            other => Err(Error::invalid(
                arg,
                format!("must be 'bayer2', 'bayer4', 'bayer8' or 'blue', got {other:?}"),
            )),
        }
    }

    pub fn name(self) -> &'static str {
        Self::NAMES[self as usize - 1]
    }

    /// The threshold in (0, 1) at cell (x, y): the CPU reference of `dither_threshold` in
    /// shade.wgsl.
    pub fn threshold(self, x: u32, y: u32) -> f64 {
        let bits = match self {
            Self::Bayer2 => 1,
            Self::Bayer4 => 2,
            Self::Bayer8 => 3,
            Self::Blue => {
                let v = 0.754_877_666_246_692_7 * x as f64 + 0.569_840_290_998_053_2 * y as f64;
                return v - v.floor();
            }
        };
        let mut v = 0u32;
        for i in 0..bits {
            let (bx, by) = ((x >> i) & 1, (y >> i) & 1);
            v |= ((bx ^ by) << 1 | by) << (2 * (bits - 1 - i));
        }
        (v as f64 + 0.5) / (1u32 << (2 * bits)) as f64
    }
}

/// Where the pattern is anchored.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum DitherSpace {
    /// Pixels, as in the paper: the pattern stays still while the object moves under it.
    Screen,
    /// The object's surface (a planar projection on the axis the normal is closest to, at the
    /// octave whose cells are about `scale` pixels): it moves with the object.
    Object,
}

impl DitherSpace {
    pub fn parse(arg: &str, s: &str) -> Result<Self> {
        match s {
            "screen" => Ok(Self::Screen),
            "object" => Ok(Self::Object),
            other => Err(Error::invalid(arg, format!("must be 'screen' or 'object', got {other:?}"))),
        }
    }

    pub fn name(self) -> &'static str {
        match self {
            Self::Screen => "screen",
            Self::Object => "object",
        }
    }
}

#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Dither {
    pub pattern: DitherPattern,
    pub space: DitherSpace,
    /// How far in L.n a pixel may move toward the neighbouring band: L.n + (t - 1/2) amount is
    /// banded, t the pattern's threshold.
    pub amount: f64,
    /// Pixels a pattern cell covers.
    pub scale: f64,
}

impl Dither {
    pub fn new(pattern: DitherPattern) -> Self {
        Dither { pattern, space: DitherSpace::Screen, amount: DEFAULT_DITHER_AMOUNT, scale: 1.0 }
    }

    pub fn validate(&self, arg: &str) -> Result<()> {
        if !(self.amount.is_finite() && (0.0..=2.0).contains(&self.amount)) {
            return Err(Error::invalid(
                format!("{arg}amount"),
                format!("must be in [0, 2], got {}", self.amount),
            ));
        }
        if !(self.scale.is_finite() && (1.0..=64.0).contains(&self.scale)) {
            return Err(Error::invalid(
                format!("{arg}scale"),
                format!("must be in [1, 64] pixels, got {}", self.scale),
            ));
        }
        Ok(())
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn bayer_matrices_are_the_classic_ones() {
        let m = |p: DitherPattern, n: u32| -> Vec<u32> {
            (0..n * n).map(|i| (p.threshold(i % n, i / n) * (n * n) as f64 - 0.5) as u32).collect()
        };
        assert_eq!(m(DitherPattern::Bayer2, 2), [0, 2, 3, 1]);
        assert_eq!(m(DitherPattern::Bayer4, 4), [0, 8, 2, 10, 12, 4, 14, 6, 3, 11, 1, 9, 15, 7, 13, 5]);
        let mut b8 = m(DitherPattern::Bayer8, 8);
        b8.sort_unstable();
        assert_eq!(b8, (0..64).collect::<Vec<_>>());
    }

    #[test]
    fn layers_darken_step_by_step() {
        assert_eq!([1.0, 0.85, 0.7, 0.5, 0.3, 0.1, 0.0].map(hatch_layers), [0, 0, 1, 2, 3, 4, 4]);
    }
}

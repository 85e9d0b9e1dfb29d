//! Dithering between neighbouring bands (Borquez and Yepez): L.n + (t - 1/2) amount is banded,
//! t a threshold pattern's value at the pixel, so pixels near a band's edge alternate between
//! the two bands. A per-pixel surface effect: `dither.wgsl` moves L.n through the `jitter` hook;
//! `DitherPattern::threshold` is its CPU reference.

use crate::error::field;
use crate::error::{Error, Result};
use crate::render::block::Block;
use crate::render::effects::surface_effect::{Hook, Surface, SurfaceEffect, Variant};
use crate::render::settings::{check_bounds, settings};
use crate::render::stage_part::ANCHORS;
use crate::render::wgsl;

/// The R2 sequence's steps along x and y (Roberts): 1/g and 1/g^2, g the plastic number.
pub const R2_STEPS: [f64; 2] = [0.754_877_666_246_692_7, 0.569_840_290_998_053_2];

crate::named_enum! {
    /// The threshold pattern of dithering.
    pub enum DitherPattern {
        /// Ordered dithering with a 2x2, 4x4 or 8x8 Bayer matrix.
        Bayer2 = "bayer2",
        Bayer4 = "bayer4",
        Bayer8 = "bayer8",
        /// The R2 low-discrepancy sequence (Roberts): a pattern without the Bayer matrix's grid,
        /// whose spectrum is close to blue noise.
        Blue = "blue",
    }
}

impl DitherPattern {
    /// The pattern's id in the shader (`DITHER`; 0 is none).
    pub fn id(self) -> u32 {
        self as u32 + 1
    }

    /// The threshold in (0, 1) at cell (x, y): the CPU reference of `dither_threshold` in
    /// dither.wgsl.
    pub fn threshold(self, x: u32, y: u32) -> f64 {
        let bits = match self {
            Self::Bayer2 => 1,
            Self::Bayer4 => 2,
            Self::Bayer8 => 3,
            Self::Blue => {
                let v = R2_STEPS[0] * x as f64 + R2_STEPS[1] * y as f64;
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

crate::named_enum! {
    /// Where the pattern is anchored.
    pub enum DitherSpace {
        /// Pixels, as in the paper: the pattern stays still while the object moves under it.
        Screen = "screen",
        /// The object's surface (a planar projection on the axis the normal is closest to, at
        /// the octave whose cells are about `scale` pixels): it moves with the object.
        Object = "object",
    }
}

settings! {
    #[derive(Clone, Copy, Debug, PartialEq)]
    pub struct Dither {
        pub pattern: DitherPattern = DitherPattern::Bayer4 => choice(DitherPattern::NAMES), "the threshold pattern";
        pub space: DitherSpace = DitherSpace::Screen => choice(DitherSpace::NAMES),
            "what the pattern is fixed to: the screen's pixels or the surface";
        /// How far in L.n a pixel may move toward the neighbouring band: L.n + (t - 1/2) amount is
        /// banded, t the pattern's threshold.
        pub amount: f64 = 0.15 => float(closed(0.0, 2.0)),
            "how far in L.n a pixel may move toward the neighbouring band, 0 to 2";
        /// Pixels a pattern cell covers.
        pub scale: f64 = 1.0 => float(closed(1.0, 64.0)), "pixels a pattern cell covers, 1 to 64", pixels;
        /// The pattern's turn, counter-clockwise as seen: a print's screen at 45 degrees hides
        /// its grid from the eye.
        pub angle: f64 = 0.0 => float(closed(-90.0, 90.0)),
            "degrees the pattern turns, counter-clockwise as seen, -90 to 90 (45: a print's screen angle)";
    }
    described(positional: 1);
}

impl Dither {
    /// The default settings with `pattern`.
    pub fn new(pattern: DitherPattern) -> Self {
        Dither { pattern, ..Dither::default() }
    }

    /// The cosine and sine of the pattern's turn, as the block carries them.
    fn turn(&self) -> [f32; 2] {
        let a = self.angle.to_radians();
        [a.cos() as f32, a.sin() as f32]
    }

    /// `p` turned by the pattern's angle, counter-clockwise as seen (the pixels' y pointing
    /// down): the CPU reference of `turned` in `dither.wgsl`.
    pub fn turned(&self, p: [f64; 2]) -> [f64; 2] {
        let [c, s] = self.turn().map(f64::from);
        [c * p[0] - s * p[1], s * p[0] + c * p[1]]
    }

    /// Checks the settings; `prefix` names them in errors ("" while they are being made). Its
    /// numbers' bounds are its declaration's.
    pub fn validate(&self, prefix: &str) -> Result<()> {
        check_bounds(self, prefix)
    }
}

crate::uniform_block! {
    /// `draw.dither`: the dithering of one mesh's material.
    pub struct DitherBlock as "DitherBlock" {
        /// In L.n (0 where the material does not dither).
        pub amount: f32,
        /// Pixels a pattern cell covers.
        pub cell: f32,
        /// The cosine and sine of the pattern's turn.
        pub cos_angle: f32,
        pub sin_angle: f32,
    }
}

impl SurfaceEffect for Dither {
    fn wgsl() -> String {
        let mut s = wgsl::constant_u32("DITHER_BLUE", DitherPattern::Blue.id());
        s += &wgsl::constant_f32("R2_STEP_X", R2_STEPS[0]);
        s += &wgsl::constant_f32("R2_STEP_Y", R2_STEPS[1]);
        s + include_str!("dither.wgsl")
    }

    const HOOKS: &'static [Hook] = &[Hook::Jitter];

    fn block() -> crate::render::block::BlockLayout {
        DitherBlock::layout()
    }

    fn validate_with(&self, s: &Surface<'_>, prefix: &str) -> Result<()> {
        if !s.model.is_toon() {
            return Err(Error::invalid(
                "dither",
                format!(
                    "dithers toon bands only (bands, lut, thresholded_phong, hatching), not {}",
                    s.model.name()
                ),
            ));
        }
        if s.per_vertex {
            return Err(Error::invalid("dither", "needs per-pixel shading (per_vertex=False)"));
        }
        self.validate(&field(prefix, "dither"))
    }

    fn block_bytes(dither: Option<&Dither>) -> Vec<u8> {
        let [cos_angle, sin_angle] = dither.map_or([1.0, 0.0], Dither::turn);
        DitherBlock {
            amount: dither.map_or(0.0, |d| d.amount as f32),
            cell: dither.map_or(1.0, |d| d.scale as f32),
            cos_angle,
            sin_angle,
        }
        .bytes()
    }

    fn variant(dither: Option<&Dither>) -> Variant {
        let object = dither.is_some_and(|d| d.space == DitherSpace::Object);
        Variant {
            constants: vec![
                ("DITHER", dither.map_or(0, |d| d.pattern.id()) as f64),
                ("DITHER_OBJECT", object as u32 as f64),
            ],
            parts: if object { vec![&ANCHORS] } else { vec![] },
        }
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
}

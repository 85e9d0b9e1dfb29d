//! Cross-hatching (Borquez and Yepez): strokes of ink over the paper colour, denser where the
//! band's tone is darker. A per-pixel surface effect: `hatching.wgsl` replaces the shaded
//! colour through the `finish` hook; `hatch_layers` is the CPU reference of its tone rule.

use serde::{Deserialize, Serialize};

use crate::error::field;
use crate::error::{Error, Result};
use crate::render::block::{vec4, Block};
use crate::render::color::{check_unit, to_linear, Srgb};
use crate::render::effects::surface_effect::{Hook, Surface, SurfaceEffect, Variant};
use crate::render::scene::model::Model;
use crate::render::wgsl;

/// Stroke layers of the hatching, added one by one as the tone darkens: at 45, -45, 0 and 90
/// degrees (cross-hatching). Layer k (1-based) shows where the tone is below 1 - k / (LAYERS + 1).
pub const HATCH_LAYERS: usize = 4;
/// Ink of the strokes when none is given (sRGB).
pub const DEFAULT_INK: Srgb = [0.1, 0.1, 0.1];
/// Pixels between strokes of one layer, and their width, when none are given.
pub const DEFAULT_HATCH_SPACING: f64 = 6.0;
pub const DEFAULT_HATCH_WIDTH: f64 = 1.25;
/// Rec. 709 luma weights: how the tone of a linear colour is measured.
pub const LUMA: [f64; 3] = [0.2126, 0.7152, 0.0722];

/// The number of stroke layers drawn at tone `tone` (CPU reference of the shader's rule).
pub fn hatch_layers(tone: f64) -> usize {
    (1..=HATCH_LAYERS).filter(|&k| tone < 1.0 - k as f64 / (HATCH_LAYERS + 1) as f64).count()
}

#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
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
    /// Checks the settings; `prefix` names them in errors ("" while they are being made).
    pub fn validate(&self, prefix: &str) -> Result<()> {
        check_unit(&field(prefix, "ink"), &self.ink)?;
        if !(self.spacing.is_finite() && (2.0..=256.0).contains(&self.spacing)) {
            return Err(Error::invalid(
                field(prefix, "spacing"),
                format!("must be in [2, 256] pixels, got {}", self.spacing),
            ));
        }
        if !(self.width.is_finite() && self.width > 0.0 && self.width <= self.spacing) {
            return Err(Error::invalid(
                field(prefix, "width"),
                format!("must be in (0, spacing] pixels, got {}", self.width),
            ));
        }
        Ok(())
    }
}

crate::uniform_block! {
    /// `draw.hatching`: the hatching of one mesh's material.
    pub struct HatchingBlock as "HatchingBlock" {
        /// Linear ink.
        pub ink: [f32; 4],
        /// Pixels between strokes, and their width.
        pub spacing: f32,
        pub width: f32,
        pub _pad0: f32,
        pub _pad1: f32,
    }
}

pub struct HatchingEffect;

pub static EFFECT: HatchingEffect = HatchingEffect;

impl SurfaceEffect for HatchingEffect {
    type Settings = Hatching;

    fn wgsl(&self) -> String {
        let mut s = wgsl::constant_u32("HATCH_LAYERS", HATCH_LAYERS as u32);
        s += &wgsl::constant_vec3("LUMA", LUMA);
        s + include_str!("hatching.wgsl")
    }

    fn block(&self) -> crate::render::block::BlockLayout {
        HatchingBlock::layout()
    }

    fn hooks(&self) -> &'static [Hook] {
        &[Hook::Finish]
    }

    fn validate(&self, hatching: Option<&Hatching>, s: &Surface<'_>, prefix: &str) -> Result<()> {
        let Some(h) = hatching else { return Ok(()) };
        if !matches!(s.model, Model::Bands { .. }) {
            return Err(Error::invalid(field(prefix, "hatching"), "hatches only toon bands"));
        }
        h.validate(prefix)
    }

    fn block_bytes(&self, hatching: Option<&Hatching>) -> Vec<u8> {
        let mut b: HatchingBlock = bytemuck::Zeroable::zeroed();
        if let Some(h) = hatching {
            b.ink = vec4(to_linear(h.ink));
            b.spacing = h.spacing as f32;
            b.width = h.width as f32;
        }
        b.bytes()
    }

    fn variant(&self, hatching: Option<&Hatching>) -> Variant {
        let on = hatching.is_some();
        Variant { constants: vec![("HATCHING", on as u32 as f64)], anchored: on }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn layers_darken_step_by_step() {
        assert_eq!([1.0, 0.85, 0.7, 0.5, 0.3, 0.1, 0.0].map(hatch_layers), [0, 0, 1, 2, 3, 4, 4]);
    }
}

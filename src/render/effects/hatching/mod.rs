//! Cross-hatching (Borquez and Yepez): strokes of ink over the paper colour, denser where the
//! band's tone is darker. A per-pixel surface effect: `hatching.wgsl` replaces the shaded
//! colour through the `finish` hook; `hatch_layers` is the CPU reference of its tone rule and
//! `field_coverage` of its strokes along the form.
//!
//! Two ways to lay the strokes (`HatchMode`): along the form (the default: Hertzmann and Zorin
//! 2000, Praun et al. 2001), following a smoothed field of principal directions through a
//! stripe phase per vertex (`field`, uploaded only for meshes whose material hatches so), or
//! the paper's straight strokes mapped triplanar in the mesh's own coordinates.

pub mod field;
pub mod field_part;

use serde::{Deserialize, Serialize};

use crate::error::field;
use crate::error::{Error, Result};
use crate::render::block::{vec4, Block};
use crate::render::color::{check_unit, to_linear, Srgb};
use crate::render::effects::surface_effect::{Hook, Surface, SurfaceEffect, Variant};
use crate::render::scene::model::Model;
use crate::render::stage_part::{Part, ANCHORS};
use crate::render::wgsl;

use field_part::FIELD;

/// Stroke layers of the hatching, added one by one as the tone darkens: along the first
/// principal direction, along the second (cross-hatching), then each again between the strokes
/// already there (triplanar: at 45, -45, 0 and 90 degrees). Layer k (1-based) shows where the tone is below 1 - k / (LAYERS + 1).
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

/// Below this length of the interpolated stripe value psi (1 at the vertices, 0 at the pattern's
/// singular points) strokes fade out, reaching none at half of it: near a singularity the phase
/// turns too fast to draw.
pub const FIELD_FADE: f64 = 0.5;

crate::named_enum! {
    /// How the strokes are laid on the surface.
    pub enum HatchMode {
        /// Along a smoothed field of principal directions (strokes around and along a
        /// cylinder), through a stripe phase per vertex: no blend seams, anchored to the surface.
        Field = "field",
        /// Straight strokes at 45, -45, 0 and 90 degrees in the mesh's own coordinates, blended
        /// over the three axis planes by the normal (Borquez and Yepez's textures without UVs).
        Triplanar = "triplanar",
    }
}

impl Default for HatchMode {
    fn default() -> Self {
        HatchMode::Field
    }
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
    /// How the strokes are laid (settings pickled before the modes existed read as triplanar).
    #[serde(default = "triplanar")]
    pub mode: HatchMode,
}

fn triplanar() -> HatchMode {
    HatchMode::Triplanar
}

impl Default for Hatching {
    fn default() -> Self {
        Hatching {
            ink: DEFAULT_INK,
            spacing: DEFAULT_HATCH_SPACING,
            width: DEFAULT_HATCH_WIDTH,
            mode: HatchMode::default(),
        }
    }
}

impl Hatching {
    /// Checks the settings; `prefix` names them in errors ("" while they are being made).
    pub fn validate(&self, prefix: &str) -> Result<()> {
        check_unit(&field(prefix, "ink"), &self.ink)?;
        // the spacing's and width's bounds are Material's description's
        if !(self.width <= self.spacing) {
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

impl SurfaceEffect for Hatching {
    fn wgsl() -> String {
        let mut s = wgsl::constant_u32("HATCH_LAYERS", HATCH_LAYERS as u32);
        s += &wgsl::constant_vec3("LUMA", LUMA);
        s += &wgsl::constant_f32("FIELD_FADE", FIELD_FADE);
        s + include_str!("hatching.wgsl")
    }

    const HOOKS: &'static [Hook] = &[Hook::Finish];
    const PARTS: &'static [&'static Part] = &[&FIELD];

    fn block() -> crate::render::block::BlockLayout {
        HatchingBlock::layout()
    }

    fn validate_with(&self, s: &Surface<'_>, prefix: &str) -> Result<()> {
        if !matches!(s.model, Model::Bands { .. }) {
            return Err(Error::invalid(field(prefix, "hatching"), "hatches only toon bands"));
        }
        self.validate(prefix)
    }

    fn block_bytes(hatching: Option<&Hatching>) -> Vec<u8> {
        let mut b: HatchingBlock = bytemuck::Zeroable::zeroed();
        if let Some(h) = hatching {
            b.ink = vec4(to_linear(h.ink));
            b.spacing = h.spacing as f32;
            b.width = h.width as f32;
        }
        b.bytes()
    }

    fn variant(hatching: Option<&Hatching>) -> Variant {
        let on = hatching.is_some();
        let field = hatching.is_some_and(|h| h.mode == HatchMode::Field);
        Variant {
            constants: vec![("HATCHING", on as u32 as f64), ("HATCH_FIELD", field as u32 as f64)],
            parts: match (on, field) {
                (true, true) => vec![&ANCHORS, &FIELD],
                (true, false) => vec![&ANCHORS],
                _ => vec![],
            },
        }
    }
}

/// Coverage in [0, 1] of the stroke nearest `x` (strokes at the integers), `px` units of x a
/// pixel, `width` pixels wide (`stroke` in hatching.wgsl).
pub fn stroke(x: f64, px: f64, width: f64) -> f64 {
    let pixels = ((x + 0.5).rem_euclid(1.0) - 0.5).abs() / px;
    (width * 0.5 + 0.5 - pixels).clamp(0.0, 1.0)
}

/// Coverage of one family of strokes along coordinate `u` (strokes at its integers), whose
/// change across a pixel is `per_pixel`: about `spacing` pixels apart on screen, from the two
/// octaves of the pattern that bracket that spacing, shifted by `offset` strokes, and no octave
/// coarser than 2^`lowest` (`stroke_octaves` in hatching.wgsl).
pub fn stroke_octaves(u: f64, per_pixel: f64, offset: f64, lowest: f64, h: &Hatching) -> f64 {
    let (spacing, width) = (h.spacing, h.width);
    let px = per_pixel.max(1e-30);
    let level = (1.0 / (spacing * px)).log2().max(lowest);
    let base = level.floor();
    let f = base.exp2();
    let coarse = stroke(u * f + offset, f * px, width);
    let fine = stroke(u * 2.0 * f + offset, 2.0 * f * px, width);
    coarse.max(fine * (level - base))
}

/// A stripe value psi (interpolated) and its change across a pixel in x and y: the phase in
/// turns, its change across a pixel (|d/dx| + |d/dy|), and the fade near singular points.
pub fn stripe_phase(psi: [f64; 2], dx: [f64; 2], dy: [f64; 2]) -> (f64, f64, f64) {
    let r2 = (psi[0] * psi[0] + psi[1] * psi[1]).max(1e-12);
    let turn = std::f64::consts::TAU;
    let ux = (psi[0] * dx[1] - psi[1] * dx[0]) / r2;
    let uy = (psi[0] * dy[1] - psi[1] * dy[0]) / r2;
    let fade = ((r2.sqrt() - 0.5 * FIELD_FADE) / (0.5 * FIELD_FADE)).clamp(0.0, 1.0);
    (psi[1].atan2(psi[0]) / turn, (ux.abs() + uy.abs()) / turn, fade)
}

/// The four layers' coverage of field hatching at a pixel, from the two stripe values
/// (strokes along the first principal direction, then along the second) and their changes
/// across the pixel: each family, then each again halfway between its strokes.
pub fn field_coverage(psi: [[f64; 2]; 2], dx: [[f64; 2]; 2], dy: [[f64; 2]; 2], h: &Hatching) -> [f64; 4] {
    let [a, b] = [0, 1].map(|k| stripe_phase(psi[k], dx[k], dy[k]));
    let at =
        // a phase repeats at u's integers, so no octave is coarser than them
        |(u, px, fade): (f64, f64, f64), offset| stroke_octaves(u, px, offset, 0.0, h) * fade;
    [at(a, 0.0), at(b, 0.0), at(a, 0.5), at(b, 0.5)]
}

/// The four layers' coverage of triplanar hatching at a pixel (`hatch_layers` in
/// hatching.wgsl): strokes at 45, -45, 0 and 90 degrees on each axis plane of the object-space
/// point `p`, blended by the object normal `n`; `dpx`, `dpy`: the point's change across the
/// pixel in x and y.
pub fn triplanar_coverage(p: [f64; 3], n: [f64; 3], dpx: [f64; 3], dpy: [f64; 3], h: &Hatching) -> [f64; 4] {
    let len = n.iter().map(|c| c * c).sum::<f64>().sqrt();
    let w4 = n.map(|c| if len > 0.0 { (c / len).abs().powi(4) } else { 0.0 });
    let sum = (w4[0] + w4[1] + w4[2]).max(1e-12);
    let s = std::f64::consts::FRAC_1_SQRT_2;
    // the plane's two coordinates of a point: (y, z), (z, x), (x, y)
    let planes = [[1, 2], [2, 0], [0, 1]];
    let mut cover = [0.0; 4];
    for (k, [a, b]) in planes.into_iter().enumerate() {
        // each layer's coordinate, linear in the point
        let coords = |q: [f64; 3]| [s * (q[a] + q[b]), s * (q[a] - q[b]), q[b], q[a]];
        let (u, ux, uy) = (coords(p), coords(dpx), coords(dpy));
        for layer in 0..4 {
            let strokes = stroke_octaves(u[layer], ux[layer].abs() + uy[layer].abs(), 0.0, -1e30, h);
            cover[layer] += w4[k] / sum * strokes;
        }
    }
    cover
}

/// The linear colour of hatching at tone `tone` with the layers' coverage `layers` (the
/// `finish` hook's rule): ink over the paper, layer k where the tone is below 1 - k / 5.
pub fn hatch_finish(paper: [f64; 3], ink: [f64; 3], tone: f64, layers: [f64; 4]) -> [f64; 3] {
    let shown = hatch_layers(tone);
    let cover = layers[..shown].iter().fold(0.0f64, |m, &c| m.max(c));
    std::array::from_fn(|k| paper[k] + (ink[k] - paper[k]) * cover)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn layers_darken_step_by_step() {
        assert_eq!([1.0, 0.85, 0.7, 0.5, 0.3, 0.1, 0.0].map(hatch_layers), [0, 0, 1, 2, 3, 4, 4]);
    }
}

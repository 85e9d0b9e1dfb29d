//! Rim light: a band of light (or of a colour) along the silhouette, where the surface turns
//! away from the viewer (n.v below the rim's width), with a hard border blended over a pixel
//! like the bands' borders, or a soft one; optionally only on the side the lights reach or the
//! side they do not. A per-pixel surface effect in every shading model: `rim.wgsl` changes the
//! shaded colour through the `finish` hook; `rim_amount` and `Rim::finish` are its CPU
//! reference.

#[cfg(test)]
mod gpu_tests;

use crate::error::field;
use crate::error::Result;
use crate::render::block::Block;
use crate::render::color::{check_unit, to_linear, Srgb};
use crate::render::effects::surface_effect::{Hook, Surface, SurfaceEffect, Variant};
use crate::render::scene::model::step_aa;
use crate::render::settings::{check_bounds, settings};

crate::named_enum! {
    /// Which side of the surface the rim shows on.
    pub enum RimSide {
        /// All along the silhouette.
        Both = "both",
        /// Where some light reaches the surface (n.l > 0 for a light).
        Lit = "lit",
        /// Where no light reaches it: a back light's glow on the dark side.
        Shadowed = "shadowed",
    }
}

crate::named_enum! {
    /// How the rim's colour joins the shaded colour.
    pub enum RimBlend {
        /// Added, as light.
        Add = "add",
        /// Painted over, as a colour.
        Mix = "mix",
    }
}

settings! {
    #[derive(Clone, Copy, Debug, PartialEq)]
    pub struct Rim {
        pub color: Srgb = [1.0; 3] => color(), "the rim's sRGB colour";
        /// The rim covers the surface where n.v < width (0 at the silhouette, 1 facing the viewer).
        pub width: f64 = 0.3 => float(closed(0.0, 1.0)), "the rim covers the surface where n.v < width, 0 to 1";
        /// How far in n.v the rim's border fades (0: a hard border, blended over a pixel only).
        pub softness: f64 = 0.0 => float(closed(0.0, 1.0)),
            "how far in n.v its border fades, 0 (a hard border) to 1";
        /// The share of the rim's colour at full coverage.
        pub strength: f64 = 0.6 => float(closed(0.0, 1.0)), "the share of its colour at full coverage, 0 to 1";
        pub side: RimSide = RimSide::Both => choice(RimSide::NAMES),
            "where it shows: 'both' sides, the 'lit' side or the 'shadowed' side";
        pub blend: RimBlend = RimBlend::Add => choice(RimBlend::NAMES),
            "'add' (as light) or 'mix' (painted over, as a colour)";
    }
    described(positional: 1);
}

impl Rim {
    /// Checks the settings; `prefix` names them in errors ("" while they are being made). Its
    /// numbers' bounds are its declaration's.
    pub fn validate(&self, prefix: &str) -> Result<()> {
        check_unit(&field(prefix, "color"), &self.color)?;
        check_bounds(self, prefix)
    }

    /// The shaded linear colour `c` with the rim at `amount` (`rim_amount`): the CPU reference
    /// of `rim_finish`.
    pub fn finish(&self, c: [f32; 3], amount: f32) -> [f32; 3] {
        let rim = to_linear(self.color);
        let k = amount * self.strength as f32;
        std::array::from_fn(|i| match self.blend {
            RimBlend::Add => c[i] + rim[i] * k,
            RimBlend::Mix => c[i] + (rim[i] - c[i]) * k,
        })
    }
}

/// How much of the rim a pixel takes, 0 to 1: `nv` its n.v, `lit` the largest n.l over the
/// lights, and `aa_nv`, `aa_lit` their change across the pixel (zero: hard borders). The CPU
/// reference of `rim_amount` in rim.wgsl.
pub fn rim_amount(rim: &Rim, nv: f32, lit: f32, aa_nv: f32, aa_lit: f32) -> f32 {
    let t = step_aa(rim.width as f32 - nv, 0.0, aa_nv.max(rim.softness as f32));
    let lit = step_aa(lit, 0.0, aa_lit);
    match rim.side {
        RimSide::Both => t,
        RimSide::Lit => t * lit,
        RimSide::Shadowed => t * (1.0 - lit),
    }
}

crate::uniform_block! {
    /// `draw.rim`: the rim of one mesh's material.
    pub struct RimBlock as "RimBlock" {
        /// Linear rgb.
        pub color: [f32; 3],
        /// 0 where the material has no rim.
        pub strength: f32,
        pub width: f32,
        pub softness: f32,
        /// `RimSide` and `RimBlend`, as their index.
        pub side: u32,
        pub blend: u32,
    }
}

impl SurfaceEffect for Rim {
    fn wgsl() -> String {
        include_str!("rim.wgsl").to_string()
    }

    const HOOKS: &'static [Hook] = &[Hook::Finish];

    fn block() -> crate::render::block::BlockLayout {
        RimBlock::layout()
    }

    fn validate_with(&self, _: &Surface<'_>, prefix: &str) -> Result<()> {
        self.validate(&field(prefix, "rim"))
    }

    fn block_bytes(rim: Option<&Rim>) -> Vec<u8> {
        let r = rim.copied().unwrap_or(Rim { strength: 0.0, ..Rim::default() });
        RimBlock {
            color: to_linear(r.color),
            strength: r.strength as f32,
            width: r.width as f32,
            softness: r.softness as f32,
            side: r.side as u32,
            blend: r.blend as u32,
        }
        .bytes()
    }

    fn variant(rim: Option<&Rim>) -> Variant {
        Variant { constants: vec![("RIM", rim.is_some() as u32 as f64)], parts: vec![] }
    }
}

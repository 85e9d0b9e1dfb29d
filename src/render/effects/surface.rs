//! Per-pixel effects: what a material adds to the shading of each pixel (hatching, dithering),
//! each a folder with its settings, its per-draw uniform block, its WGSL and its CPU reference,
//! registered in the one list below. A surface effect costs no pass: its WGSL is compiled into
//! the shading pipeline, specialised by pipeline constants, so materials without it pay
//! nothing.
//!
//! An effect's WGSL defines its block struct (`draw.<name>` in every shader) and implements
//! hooks the shading pass calls for every pixel (`Hook`), named `<name>_<hook>`; the dispatch
//! functions that call every effect's hooks in order are written from this list
//! (`dispatch_wgsl`).

use serde::{Deserialize, Serialize};

use crate::error::Result;
use crate::render::block::BlockLayout;
use crate::render::scene::model::Model;

use super::dither::{self, Dither};
use super::hatching::{self, Hatching};

/// The registry: each per-pixel effect's field in a material's settings and its effect.
macro_rules! surface_effects {
    ($($name:ident: $settings:ty => $effect:path,)*) => {
        /// The per-pixel effects a material carries (None: not used).
        #[derive(Clone, Copy, Debug, Default, PartialEq, Serialize, Deserialize)]
        pub struct SurfaceSettings {
            $(pub $name: Option<$settings>,)*
        }

        /// Every per-pixel effect, in the order their hooks run.
        pub static SURFACE: &[&dyn SurfaceEffect] = &[$(&$effect),*];
    };
}

surface_effects! {
    dither: Dither => dither::EFFECT,
    hatching: Hatching => hatching::EFFECT,
}

/// What a per-pixel effect sees of a material.
pub struct Surface<'a> {
    pub model: &'a Model,
    pub per_vertex: bool,
    pub effects: &'a SurfaceSettings,
}

/// Where a per-pixel effect's WGSL joins the shading of a pixel.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Hook {
    /// `fn <name>_jitter(f: Fragment) -> f32`: added to L.n before the model bands it.
    Jitter,
    /// `fn <name>_finish(f: Fragment, c: vec3<f32>) -> vec3<f32>`: the shaded linear colour,
    /// changed.
    Finish,
}

/// What an effect compiles into a material's shading pipeline.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Variant {
    /// Pipeline constants (override declarations of its WGSL), the same names for every material.
    pub constants: Vec<(&'static str, f64)>,
    /// Whether its fragment code reads the anchors (`Fragment.object_pos`, `object_normal`).
    pub anchored: bool,
}

pub trait SurfaceEffect: Sync {
    /// Its field in `SurfaceSettings` and in the WGSL `Draw` struct, and its hooks' prefix.
    fn name(&self) -> &'static str;
    /// Its WGSL: the block struct, its pipeline constants and its hooks.
    fn wgsl(&self) -> String;
    /// Its per-draw uniform block.
    fn block(&self) -> BlockLayout;
    /// The hooks its WGSL implements.
    fn hooks(&self) -> &'static [Hook];
    /// Checks its settings against the rest of the material; `prefix` names the material.
    fn validate(&self, s: &Surface<'_>, prefix: &str) -> Result<()>;
    /// Its block for a material (zeros where the material does not use it).
    fn block_bytes(&self, s: &Surface<'_>) -> Vec<u8>;
    /// Its part of a material's shading pipeline.
    fn variant(&self, s: &Surface<'_>) -> Variant;
}

impl SurfaceSettings {
    /// Checks every effect's settings against the material's model and shading.
    pub fn validate(&self, model: &Model, per_vertex: bool, prefix: &str) -> Result<()> {
        let s = Surface { model, per_vertex, effects: self };
        SURFACE.iter().try_for_each(|e| e.validate(&s, prefix))
    }
}

/// The WGSL functions that call every effect's hooks in registry order: `surface_jitter(f)`
/// (the sum of the jitters) and `surface_finish(f, c)` (each finish applied in turn).
pub fn dispatch_wgsl() -> String {
    let with = |hook| SURFACE.iter().filter(move |e| e.hooks().contains(&hook)).map(|e| e.name());
    let jitter: String = with(Hook::Jitter).map(|n| format!(" + {n}_jitter(f)")).collect();
    let finish: String = with(Hook::Finish).map(|n| format!("    x = {n}_finish(f, x);\n")).collect();
    format!(
        "// written by src/render/effects/surface.rs\n\
         fn surface_jitter(f: Fragment) -> f32 {{\n    return 0.0{jitter};\n}}\n\n\
         fn surface_finish(f: Fragment, c: vec3<f32>) -> vec3<f32> {{\n    var x = c;\n{finish}    return x;\n}}\n"
    )
}

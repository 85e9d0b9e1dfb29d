//! Per-pixel effects: what a material adds to the shading of each pixel (hatching, dithering),
//! each a folder with its settings, its per-draw uniform block, its WGSL and its CPU reference,
//! registered in the one list below. A surface effect costs no pass: its WGSL is compiled into
//! the shading pipeline, specialised by pipeline constants, so materials without it pay
//! nothing.
//!
//! An effect's WGSL defines its block struct (`draw.<name>` in every shader) and implements
//! hooks the shading pass calls for every pixel (`surface_effect::Hook`), named
//! `<name>_<hook>`; the dispatch functions that call every effect's hooks in order are written
//! from this list. Adding one is a folder and a line in the `registry!` list below.

use serde::{Deserialize, Serialize};

use crate::error::Result;
use crate::render::block::BlockLayout;
use crate::render::stage_part::Part;

use super::surface_effect::{Hook, Surface, SurfaceEffect, Variant};
use super::{dither, hatching, rim};

/// Writes the registry from the list of effects: each one's field (named as the effect, in
/// materials, in the WGSL `Draw` struct and in its hooks) and its settings, which implement
/// the effect (`SurfaceEffect`).
macro_rules! registry {
    ($($name:ident: $settings:ty,)*) => {
        /// The per-pixel effects a material carries (None: not used).
        #[derive(Clone, Debug, Default, PartialEq, Serialize, Deserialize)]
        pub struct SurfaceSettings {
            $(pub $name: Option<$settings>,)*
        }

        impl SurfaceSettings {
            /// Checks the settings of every effect the material uses against its model and
            /// shading.
            pub fn validate(&self, s: &Surface<'_>, prefix: &str) -> Result<()> {
                $(if let Some(settings) = &self.$name {
                    settings.validate_with(s, prefix)?;
                })*
                Ok(())
            }

            /// Every effect's block, in the order of `blocks()`.
            pub fn block_bytes(&self) -> Vec<u8> {
                let mut bytes = Vec::new();
                $(bytes.extend(<$settings as SurfaceEffect>::block_bytes(self.$name.as_ref()));)*
                bytes
            }

            /// Every effect's part of the shading pipeline.
            pub fn variants(&self) -> Vec<Variant> {
                vec![$(<$settings as SurfaceEffect>::variant(self.$name.as_ref())),*]
            }
        }

        /// Every effect's name and per-draw block, in the order they follow each other in `Draw`.
        pub fn blocks() -> Vec<(&'static str, BlockLayout)> {
            vec![$((stringify!($name), <$settings as SurfaceEffect>::block())),*]
        }

        /// Every effect's WGSL.
        pub fn wgsl() -> String {
            let mut s = String::new();
            $(s += &<$settings as SurfaceEffect>::wgsl();)*
            s
        }

        /// The stage parts the effects declare, in registry order.
        pub fn parts() -> Vec<&'static Part> {
            let mut parts = Vec::new();
            $(parts.extend(<$settings as SurfaceEffect>::PARTS);)*
            parts
        }

        /// Every effect's name and hooks, in the order they run.
        fn hooks() -> Vec<(&'static str, &'static [Hook])> {
            vec![$((stringify!($name), <$settings as SurfaceEffect>::HOOKS)),*]
        }
    };
}

registry! {
    dither: dither::Dither,
    hatching: hatching::Hatching,
    // after hatching, so that its light shows on the strokes and the paper too
    rim: rim::Rim,
}

/// The WGSL functions that call every effect's hooks in registry order: `surface_jitter(f)`
/// (the sum of the jitters) and `surface_finish(f, c)` (each finish applied in turn).
pub fn dispatch_wgsl() -> String {
    let with = |hook| hooks().into_iter().filter(move |(_, h)| h.contains(&hook)).map(|(n, _)| n);
    let jitter: String = with(Hook::Jitter).map(|n| format!(" + {n}_jitter(f)")).collect();
    let finish: String = with(Hook::Finish).map(|n| format!("    x = {n}_finish(f, x);\n")).collect();
    format!(
        "// written by src/render/effects/surface.rs\n\
         fn surface_jitter(f: Fragment) -> f32 {{\n    return 0.0{jitter};\n}}\n\n\
         fn surface_finish(f: Fragment, c: vec3<f32>) -> vec3<f32> {{\n    var x = c;\n{finish}    return x;\n}}\n"
    )
}

//! The interface of a per-pixel effect (`effects::surface` lists them), implemented by its
//! settings type: its WGSL with its block and hooks, its per-draw block, the stage parts it
//! owns (vertex data, varyings and their code: `render::stage_part`), its part of a material's
//! pipeline, and its checks. A material's block and pipeline are made from the
//! settings it carries, None where it does not use the effect.

use crate::error::Result;
use crate::render::block::BlockLayout;
use crate::render::scene::model::Model;
use crate::render::stage_part::Part;

/// What a per-pixel effect sees of the rest of a material.
pub struct Surface<'a> {
    pub model: &'a Model,
    pub per_vertex: bool,
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
    /// The stage parts its code reads (`stage_part::ANCHORS` for `Fragment.object_pos` and
    /// `object_normal`, or parts of its own), in any order.
    pub parts: Vec<&'static Part>,
}

pub trait SurfaceEffect: Sized {
    /// Its WGSL: the block struct, its pipeline constants and its hooks.
    fn wgsl() -> String;
    /// The hooks its WGSL implements.
    const HOOKS: &'static [Hook];
    /// The stage parts it declares (those its variants may ask for besides the core's).
    const PARTS: &'static [&'static Part] = &[];
    /// Its per-draw uniform block.
    fn block() -> BlockLayout;
    /// Checks the settings of a material that uses the effect with the rest of the material;
    /// `prefix` names the material.
    fn validate_with(&self, s: &Surface<'_>, prefix: &str) -> Result<()>;
    /// Its block for a material (zeros where the material does not use it).
    fn block_bytes(settings: Option<&Self>) -> Vec<u8>;
    /// Its part of a material's shading pipeline.
    fn variant(settings: Option<&Self>) -> Variant;
}

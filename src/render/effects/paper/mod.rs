//! Paper grain: the paper's tooth, which takes pigment on its peaks and leaves its valleys
//! light, as paper takes pencil or watercolour. Over the finished image (tones, hatching and
//! ink lines alike) a grain height g in [0, 1] (a built-in procedural grain or the user's
//! image, `grain.rs`) sets the share of pigment the paper takes, m = 1 - strength (1 - g), and
//! the blank paper's own tone, 1 - tone (1 - g); in linear light a pixel's colour c becomes
//! `paper (1 - m) + c m`. The grain is fixed to the screen's pixels, or to the scene's surfaces
//! (a triplanar mapping of world coordinates, read back from the geometry target; the
//! background keeps the screen's grain). A frame effect with one full-screen pass after the
//! ink (`pass.rs`); `paper_color`, `grain_at` and `surface_grain` are its CPU reference.

#[cfg(test)]
mod gpu_tests;
pub mod grain;
mod pass;
pub mod settings;

use std::sync::Arc;

use glam::{DMat4, DVec3};

use crate::error::Result;
use crate::render::block::{Block, BlockLayout};
use crate::render::graph::effect::{FrameEffect, FrameInputs, PlanInputs, Steps};
use crate::render::graph::target::GeometryLayout;
use crate::render::scene::camera::ResolvedCamera;
use crate::render::scene::checked::CheckedScene;
use crate::render::scene::Output;
use crate::render::settings::GreyImage;
use crate::render::uniforms::footprint;

pub use grain::{grain_at, surface_grain};
pub use settings::{Paper, PaperSpace};

/// Normalised view space -> grain texels on the surface: world coordinates from the scene's
/// centre (so that a scene far from the origin keeps its precision), divided by the world size
/// of a texel at the centre's depth.
pub fn surface_matrix(paper: &Paper, cam: &ResolvedCamera, center: DVec3, height: u32) -> DMat4 {
    let (a, b) = footprint(cam, height);
    let depth = ((center - cam.eye).dot(cam.forward)).max(cam.near) / cam.scale;
    let texel = (a * depth + b) * cam.scale * paper.scale;
    DMat4::from_scale(DVec3::splat(1.0 / texel))
        * DMat4::from_translation(-center)
        * cam.normalized_view().inverse()
}

/// The grain a paper lays: the user's image or the procedural one.
pub fn tile(paper: &Paper) -> Arc<GreyImage> {
    match &paper.grain {
        Some(g) => Arc::new(g.clone()),
        None => grain::procedural(),
    }
}
crate::uniform_block! {
    /// `frame.paper`: the paper of the frame.
    pub struct PaperBlock as "PaperBlock" {
        /// Normalised view space -> grain texels on the surface (`Paper::surface_matrix`).
        pub to_grain: [[f32; 4]; 4],
        /// Clip space -> normalised view space.
        pub inv_proj: [[f32; 4]; 4],
        /// The output's size in pixels.
        pub size: [f32; 2],
        /// Output pixels a grain texel covers.
        pub scale: f32,
        pub strength: f32,
        pub tone: f32,
        pub _pad0: u32,
        pub _pad1: u32,
        pub _pad2: u32,
    }
}

pub struct PaperEffect;

pub static EFFECT: PaperEffect = PaperEffect;

fn paper_of(scene: &CheckedScene) -> Option<&Paper> {
    scene.scene.effects.paper.as_ref().filter(|_| scene.frame.outputs.has(Output::Color))
}

impl FrameEffect for PaperEffect {
    fn name(&self) -> &'static str {
        "paper"
    }

    /// The grain lies on the whole picture, glass included.
    fn over_glass(&self) -> bool {
        true
    }

    fn block_wgsl(&self) -> String {
        include_str!("block.wgsl").to_string()
    }

    fn block(&self) -> BlockLayout {
        PaperBlock::layout()
    }

    fn frame_block(&self, cx: &FrameInputs<'_>) -> Vec<u8> {
        let mut b: PaperBlock = bytemuck::Zeroable::zeroed();
        if let Some(p) = paper_of(cx.scene) {
            let f = &cx.scene.frame;
            b.to_grain = surface_matrix(p, cx.cam, cx.sphere.center, f.height).as_mat4().to_cols_array_2d();
            b.inv_proj = cx.cam.normalized_proj().inverse().as_mat4().to_cols_array_2d();
            b.size = [f.width as f32, f.height as f32];
            b.scale = p.scale as f32;
            b.strength = p.strength as f32;
            b.tone = p.tone as f32;
        }
        b.bytes()
    }

    fn check(&self, _: &CheckedScene) -> Result<()> {
        Ok(())
    }

    fn geometry(&self, scene: &CheckedScene) -> Option<GeometryLayout> {
        paper_of(scene).filter(|p| p.space == PaperSpace::Surface).map(|_| GeometryLayout::NormalDepth)
    }

    fn plan(&self, cx: &PlanInputs<'_>, steps: &mut Steps) {
        if let Some(p) = paper_of(cx.scene) {
            steps
                .after
                .push(Box::new(pass::PaperPass { surface: p.space == PaperSpace::Surface, grain: tile(p) }));
        }
    }
}

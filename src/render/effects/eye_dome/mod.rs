//! Eye-dome lighting (Boucheny 2009, as CloudCompare and Potree draw point clouds): each pixel
//! darkened by how far its log-depth lies behind its neighbours', which shows a cloud's shape
//! (its silhouettes and depth steps) without normals. A frame effect with one full-screen pass
//! after the shading and before the ink, reading the geometry target's linear depth; with d
//! the log2 of a pixel's depth and d_k its eight neighbours' at the radius (those on the
//! background left out), the colour is multiplied by exp(-300 strength sum(max(0, d - d_k)) / 8)
//! in linear light. The background is left as it is. `shade_at` is its CPU twin.

#[cfg(test)]
mod gpu_tests;
mod pass;
pub mod settings;

use crate::error::Result;
use crate::render::block::{Block, BlockLayout};
use crate::render::graph::effect::{FrameEffect, FrameInputs, PlanInputs, Steps};
use crate::render::graph::target::GeometryLayout;
use crate::render::scene::checked::CheckedScene;
use crate::render::scene::Output;
use crate::render::wgsl;

pub use settings::EyeDome;

/// Neighbours each pixel is held against, evenly around it.
pub const NEIGHBOURS: usize = 8;

/// Potree's and CloudCompare's scale of the mean log2-depth step (at strength 1).
const RESPONSE_PER_STRENGTH: f64 = 300.0;

crate::uniform_block! {
    /// `frame.eye_dome`: eye-dome lighting's neighbours and response.
    pub struct EyeDomeBlock as "EyeDomeBlock" {
        /// The neighbours' offsets in pixels, two to a row.
        pub offsets: [[i32; 4]; NEIGHBOURS / 2],
        /// The darkening per unit of mean log2-depth step.
        pub response: f32,
        pub _pad0: u32,
        pub _pad1: u32,
        pub _pad2: u32,
    }
}

impl EyeDome {
    /// The neighbours' offsets in whole pixels at `radius`, one every 45 degrees.
    pub fn offsets(&self) -> [[i32; 2]; NEIGHBOURS] {
        std::array::from_fn(|k| {
            let a = std::f64::consts::TAU * k as f64 / NEIGHBOURS as f64;
            [(self.radius * a.cos()).round() as i32, (self.radius * a.sin()).round() as i32]
        })
    }

    pub fn response(&self) -> f64 {
        RESPONSE_PER_STRENGTH * self.strength
    }

    /// The shade (the factor on the linear colour) of pixel (x, y) of a `width` x `height`
    /// linear depth image (`depth`, row-major, not finite on the background): the CPU twin of
    /// `fs_eye_dome`.
    pub fn shade_at(&self, depth: &[f32], width: usize, height: usize, x: usize, y: usize) -> f32 {
        let at = |x: i64, y: i64| {
            let inside = (0..width as i64).contains(&x) && (0..height as i64).contains(&y);
            inside.then(|| depth[y as usize * width + x as usize]).filter(|d| d.is_finite())
        };
        let Some(d) = at(x as i64, y as i64) else { return 1.0 };
        let d = d.log2();
        let sum: f32 = self
            .offsets()
            .iter()
            .filter_map(|o| at(x as i64 + o[0] as i64, y as i64 + o[1] as i64))
            .map(|n| (d - n.log2()).max(0.0))
            .sum();
        (-(self.response() as f32) * sum / NEIGHBOURS as f32).exp()
    }
}

pub struct EyeDomeEffect;

pub static EFFECT: EyeDomeEffect = EyeDomeEffect;

fn eye_dome_of(scene: &CheckedScene) -> Option<&EyeDome> {
    scene.scene.effects.eye_dome.as_ref().filter(|_| scene.frame.outputs.has(Output::Color))
}

impl FrameEffect for EyeDomeEffect {
    fn name(&self) -> &'static str {
        "eye_dome"
    }

    fn block_wgsl(&self) -> String {
        wgsl::constant_u32("EYE_DOME_NEIGHBOURS", NEIGHBOURS as u32) + include_str!("block.wgsl")
    }

    fn block(&self) -> BlockLayout {
        EyeDomeBlock::layout()
    }

    fn frame_block(&self, cx: &FrameInputs<'_>) -> Vec<u8> {
        let mut b: EyeDomeBlock = bytemuck::Zeroable::zeroed();
        if let Some(e) = eye_dome_of(cx.scene) {
            let o = e.offsets();
            for (row, pair) in b.offsets.iter_mut().zip(o.chunks(2)) {
                *row = [pair[0][0], pair[0][1], pair[1][0], pair[1][1]];
            }
            b.response = e.response() as f32;
        }
        b.bytes()
    }

    fn check(&self, _: &CheckedScene) -> Result<()> {
        Ok(())
    }

    fn geometry(&self, scene: &CheckedScene) -> Option<GeometryLayout> {
        eye_dome_of(scene).map(|_| GeometryLayout::Depth)
    }

    fn plan(&self, cx: &PlanInputs<'_>, steps: &mut Steps) {
        if eye_dome_of(cx.scene).is_some() {
            let layout = cx.geometry.expect("eye-dome lighting reads the frame's depth");
            steps.after.push(Box::new(pass::EyeDomePass { layout }));
        }
    }
}

//! Supersampling's box filter: averages `factor` x `factor` blocks of the supersampled colour
//! down to the output size, in linear light.

use crate::error::Result;
use crate::render::device::COLOR_FORMAT;
use crate::render::graph::build::{fullscreen_pipeline, texture_group};
use crate::render::graph::target::{Access, Target, Use};
use crate::render::graph::{cleared, FrameCtx, Pass, Recorder};
use crate::render::pipelines::target;

pub const WGSL: &str = include_str!("downsample.wgsl");

#[derive(Debug, Clone, PartialEq)]
pub struct Downsample {
    pub factor: u32,
}

impl Pass for Downsample {
    fn name(&self) -> &'static str {
        "downsample"
    }

    fn uses(&self) -> Vec<Use> {
        vec![Use(Target::ColorHi, Access::Sample), Use(Target::Color, Access::Attach)]
    }

    fn encode(&self, f: &FrameCtx<'_>, rec: &mut Recorder<'_>) -> Result<()> {
        let layouts = &f.pipelines.layouts;
        let pipeline = fullscreen_pipeline(
            f,
            ("downsample", self.factor as u64),
            (WGSL, "fs_downsample", None),
            &[&layouts.frame, &layouts.float_texture],
            &[target(COLOR_FORMAT)],
            &[("FACTOR", self.factor as f64)],
        );
        let source = f.res.bind_group("downsample source", || {
            texture_group(&f.dev.device, &layouts.float_texture, f.res.view(Target::ColorHi))
        });
        let attachments = [cleared(f.res.view(Target::Color), wgpu::Color::TRANSPARENT)];
        rec.fullscreen("downsample", &attachments, &pipeline, &[&f.res.uniforms.frame_group, &source]);
        Ok(())
    }
}

//! Supersampling's box filter: averages `factor` x `factor` blocks of the supersampled colour
//! down to the output size, in linear light.

use crate::error::Result;
use crate::render::device::COLOR_FORMAT;
use crate::render::graph::target::{Access, Target, Use};
use crate::render::graph::{cleared, FrameCtx, Pass};
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

    fn encode(
        &self,
        f: &FrameCtx<'_>,
        encoder: &mut wgpu::CommandEncoder,
        timing: Option<wgpu::RenderPassTimestampWrites<'_>>,
    ) -> Result<()> {
        let layouts = &f.pipelines.layouts;
        let pipeline = f.pipelines.get(("downsample", self.factor as u64), || {
            let module =
                f.pipelines.module(&f.dev.device, "downsample", || crate::render::wgsl::source(WGSL));
            super::fullscreen_pipeline(
                f,
                "downsample",
                &module,
                "fs_downsample",
                &[&layouts.frame, &layouts.float_texture],
                &[target(COLOR_FORMAT)],
                &[("FACTOR", self.factor as f64)],
            )
        });
        let source = f.res.bind_group("downsample source", || {
            super::texture_group(f, &layouts.float_texture, f.res.view(Target::ColorHi))
        });
        let attachments = [cleared(f.res.view(Target::Color), wgpu::Color::TRANSPARENT)];
        super::draw_fullscreen(
            encoder,
            "downsample",
            &attachments,
            timing,
            &pipeline,
            &[&f.res.uniforms.frame_group, &source],
        );
        Ok(())
    }
}

//! The eye-dome pass: the colour multiplied by the shade (`SHADE_BLEND`), from the geometry
//! target's depth.

use crate::error::Result;
use crate::render::device::COLOR_FORMAT;
use crate::render::graph::build::fullscreen_pipeline;
use crate::render::graph::target::{Access, GeometryLayout, Target, Use};
use crate::render::graph::{loaded, FrameCtx, Pass, Recorder};
use crate::render::pipelines::{blended, KEEP};

pub const WGSL: &str = include_str!("eye_dome.wgsl");

/// colour * shade: the shader gives the shade as its colour; the colour's alpha stays.
pub const SHADE_BLEND: wgpu::BlendState = wgpu::BlendState {
    color: wgpu::BlendComponent {
        src_factor: wgpu::BlendFactor::Zero,
        dst_factor: wgpu::BlendFactor::Src,
        operation: wgpu::BlendOperation::Add,
    },
    alpha: KEEP,
};

#[derive(Debug)]
pub struct EyeDomePass {
    /// The geometry target's layout (where its depth is).
    pub layout: GeometryLayout,
}

impl Pass for EyeDomePass {
    fn name(&self) -> &'static str {
        "eye_dome"
    }

    fn uses(&self) -> Vec<Use> {
        vec![Use(Target::Color, Access::Attach), Use(Target::Geometry, Access::Sample)]
    }

    fn encode(&self, f: &FrameCtx<'_>, rec: &mut Recorder<'_>) -> Result<()> {
        let layouts = &f.pipelines.layouts;
        let normal_depth = self.layout == GeometryLayout::NormalDepth;
        let pipeline = fullscreen_pipeline(
            f,
            ("eye_dome", normal_depth as u64),
            (WGSL, "fs_eye_dome", None),
            &[&layouts.frame, &layouts.uint_texture],
            &[blended(COLOR_FORMAT, SHADE_BLEND)],
            &[("NORMAL_DEPTH", normal_depth as u8 as f64)],
        );
        let geometry = f.res.geometry_group(f);
        rec.fullscreen(
            "eye_dome",
            &[loaded(f.res.view(Target::Color))],
            &pipeline,
            &[&f.res.uniforms.frame_group, &geometry],
        );
        Ok(())
    }
}

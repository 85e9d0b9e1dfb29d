//! The `edge_bits` pass of the discontinuity rule: which boundaries between pixels are image-space
//! edges, from the geometry target, for the `edges` pass to ink (`edge_bits.wgsl`;
//! `edges_reference::Discontinuity::is_edge` is its CPU reference).

use crate::error::Result;
use crate::render::graph::build::fullscreen_pipeline;
use crate::render::graph::target::{Access, Target, Use, EDGE_BITS_FORMAT};
use crate::render::graph::{cleared, FrameCtx, Pass, Recorder};
use crate::render::pipelines::target;

pub const WGSL: &str = include_str!("edge_bits.wgsl");

#[derive(Debug, Clone, PartialEq)]
pub struct EdgeBits;

impl Pass for EdgeBits {
    fn name(&self) -> &'static str {
        "edge_bits"
    }

    fn uses(&self) -> Vec<Use> {
        vec![Use(Target::Geometry, Access::Sample), Use(Target::EdgeBits, Access::Attach)]
    }

    fn encode(&self, f: &FrameCtx<'_>, rec: &mut Recorder<'_>) -> Result<()> {
        let layouts = &f.pipelines.layouts;
        let pipeline = fullscreen_pipeline(
            f,
            ("edge_bits", 0),
            (WGSL, "fs_edge_bits", None),
            &[&layouts.frame, &layouts.uint_texture],
            &[target(EDGE_BITS_FORMAT)],
            &[],
        );
        let geometry = f.res.geometry_group(f);
        let attachments = [cleared(f.res.view(Target::EdgeBits), wgpu::Color::TRANSPARENT)];
        rec.fullscreen("edge_bits", &attachments, &pipeline, &[&f.res.uniforms.frame_group, &geometry]);
        Ok(())
    }
}

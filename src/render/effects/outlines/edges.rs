//! Image-space outlines (Borquez and Yepez): Sobel on the normal and depth buffers of the
//! geometry target, with `edges::detect`'s rule and thresholds, painted in the image ink over the
//! colour and/or into the outline coverage. `edges_reference.rs` is its CPU reference.

use crate::error::Result;
use crate::render::graph::build::fullscreen_pipeline;
use crate::render::graph::target::Use;
use crate::render::graph::{FrameCtx, Pass, Recorder};
use crate::render::pipelines::PipelineKey;

use super::ink::Ink;

pub const WGSL: &str = include_str!("edges.wgsl");

#[derive(Debug, Clone, PartialEq)]
pub struct Edges {
    pub ink: Ink,
}

impl Pass for Edges {
    fn name(&self) -> &'static str {
        "edges"
    }

    fn uses(&self) -> Vec<Use> {
        self.ink.uses()
    }

    fn encode(&self, f: &FrameCtx<'_>, rec: &mut Recorder<'_>) -> Result<()> {
        let layouts = &f.pipelines.layouts;
        let pipeline = f.pipelines.get(PipelineKey::new("edges", self.ink.bits()), || {
            let module = f.module("edges", WGSL, None);
            fullscreen_pipeline(
                f,
                "edges",
                &module,
                self.ink.entry(),
                &[&layouts.frame, &layouts.uint_texture],
                &self.ink.targets(),
                &[],
            )
        });
        let geometry = f.res.geometry_group(f);
        let attachments = self.ink.attachments(f);
        rec.fullscreen("edges", &attachments, &pipeline, &[&f.res.uniforms.frame_group, &geometry]);
        Ok(())
    }
}

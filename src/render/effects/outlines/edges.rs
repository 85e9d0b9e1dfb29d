//! Image-space outlines painted in the image ink over the colour and/or into the outline
//! coverage: under the discontinuity rule, lines `width` pixels wide around the edge boundaries
//! that `edge_bits` found; under the paper rule (Borquez and Yepez), Sobel on the normal and
//! depth buffers of the geometry target with `edges::detect`'s thresholds. `edges_reference.rs`
//! is the CPU reference of both.

use crate::error::Result;
use crate::render::graph::build::fullscreen_pipeline;
use crate::render::graph::target::{Access, Target, Use};
use crate::render::graph::{FrameCtx, Pass, Recorder};

use super::ink::Ink;
use super::settings::ImageRule;

pub const WGSL: &str = concat!(include_str!("inked.wgsl"), include_str!("edges.wgsl"));

#[derive(Debug, Clone, PartialEq)]
pub struct Edges {
    pub ink: Ink,
    /// The rule: the paper's reads the geometry target, the discontinuity rule the edge bits
    /// (`edge_bits`).
    pub rule: ImageRule,
}

impl Edges {
    fn source(&self) -> Target {
        match self.rule {
            ImageRule::Paper => Target::Geometry,
            ImageRule::Discontinuity => Target::EdgeBits,
        }
    }
}

impl Pass for Edges {
    fn name(&self) -> &'static str {
        "edges"
    }

    fn uses(&self) -> Vec<Use> {
        let mut u = self.ink.uses();
        u.retain(|x| x.0 != Target::Geometry);
        u.push(Use(self.source(), Access::Sample));
        u
    }

    fn encode(&self, f: &FrameCtx<'_>, rec: &mut Recorder<'_>) -> Result<()> {
        let layouts = &f.pipelines.layouts;
        let pipeline = fullscreen_pipeline(
            f,
            ("edges", self.ink.bits()),
            (WGSL, self.ink.entry(), None),
            &[&layouts.frame, &layouts.uint_texture],
            &self.ink.targets(),
            &[],
        );
        let source = match self.rule {
            ImageRule::Paper => f.res.geometry_group(f),
            ImageRule::Discontinuity => f.res.edge_bits_group(f),
        };
        let attachments = self.ink.attachments(f);
        rec.fullscreen("edges", &attachments, &pipeline, &[&f.res.uniforms.frame_group, &source]);
        Ok(())
    }
}

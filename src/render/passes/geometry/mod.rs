//! The geometry pass: the view-space normal and linear depth at the output size, one sample per
//! pixel, when the shading pass cannot write them (multisampled or supersampled colour, or no
//! colour asked for). A coloured mesh with an alpha cutoff reads its colour here too, so that
//! no normal or depth is written where its pixels are cut.

use crate::error::Result;
use crate::render::graph::build::depth_pass_pipeline;
use crate::render::graph::mesh_stages::MeshStages;
use crate::render::graph::target::{Access, GeometryLayout, Target, Use};
use crate::render::graph::{cleared, depth_buffer, geometry_clear, DrawItem, FrameCtx, Pass, Recorder};

#[derive(Debug, Clone, PartialEq)]
pub struct Geometry {
    pub layout: GeometryLayout,
}

impl Pass for Geometry {
    fn name(&self) -> &'static str {
        "gbuffer"
    }

    fn uses(&self) -> Vec<Use> {
        vec![Use(Target::Geometry, Access::Attach), Use(Target::GeometryDepth, Access::Attach)]
    }

    fn encode(&self, f: &FrameCtx<'_>, rec: &mut Recorder<'_>) -> Result<()> {
        let layout = self.layout;
        let stages = |cut| MeshStages { albedo: cut, geometry: Some(layout), ..Default::default() };
        let pipeline = |d: &DrawItem<'_>| depth_pass_pipeline(f, "gbuffer", d, stages, d.cull);
        let attachments = [cleared(f.res.view(Target::Geometry), geometry_clear(layout))];
        let mut pass =
            rec.begin("gbuffer", &attachments, depth_buffer(f.res.view(Target::GeometryDepth), false));
        f.draw_meshes(&mut pass, pipeline);
        Ok(())
    }
}

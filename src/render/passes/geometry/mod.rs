//! The geometry pass: the view-space normal and linear depth at the output size, one sample per
//! pixel, when the shading pass cannot write them (multisampled or supersampled colour, or no
//! colour asked for).

use crate::error::Result;
use crate::render::graph::build::{cull_bits, mesh_pipeline, MeshDraw};
use crate::render::graph::target::{Access, GeometryLayout, Target, Use};
use crate::render::graph::{cleared, depth_buffer, geometry_clear, FrameCtx, Pass, Recorder};
use crate::render::pipelines::{target, PipelineKey};

pub const WGSL: &str = include_str!("geometry.wgsl");

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
        let pipeline = |cull: Option<wgpu::Face>| {
            f.pipelines.get(PipelineKey::new("gbuffer", layout as u64 | cull_bits(cull) << 8), || {
                let module = f.module("gbuffer", WGSL, None);
                let entry = match layout {
                    GeometryLayout::NormalDepth => "fs_normal_depth",
                    GeometryLayout::Depth => "fs_depth",
                };
                let targets = [target(layout.format())];
                mesh_pipeline(
                    f,
                    &module,
                    MeshDraw {
                        label: "gbuffer",
                        entry,
                        targets: &targets,
                        samples: 1,
                        constants: &[],
                        more: &[],
                        cull,
                        field: false,
                    },
                )
            })
        };
        let attachments = [cleared(f.res.view(Target::Geometry), geometry_clear(layout))];
        let mut pass =
            rec.begin("gbuffer", &attachments, depth_buffer(f.res.view(Target::GeometryDepth), false));
        f.draw_meshes(&mut pass, |d| pipeline(d.cull));
        Ok(())
    }
}

//! The geometry pass: the view-space normal and linear depth at the output size, one sample per
//! pixel, when the shading pass cannot write them (multisampled or supersampled colour, or no
//! colour asked for).

use crate::error::Result;
use crate::render::graph::target::{Access, GeometryLayout, Target, Use};
use crate::render::graph::{cleared, depth_buffer, geometry_clear, FrameCtx, Pass};
use crate::render::pipelines::target;

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

    fn encode(
        &self,
        f: &FrameCtx<'_>,
        encoder: &mut wgpu::CommandEncoder,
        timing: Option<wgpu::RenderPassTimestampWrites<'_>>,
    ) -> Result<()> {
        let layout = self.layout;
        let pipeline = |cull: Option<wgpu::Face>| {
            f.pipelines.get(("gbuffer", layout as u64 | super::cull_bits(cull) << 8), || {
                let module =
                    f.pipelines.module(&f.dev.device, "gbuffer", || crate::render::wgsl::source(WGSL));
                let entry = match layout {
                    GeometryLayout::NormalDepth => "fs_normal_depth",
                    GeometryLayout::Depth => "fs_depth",
                };
                super::mesh_pipeline(
                    f,
                    "gbuffer",
                    &module,
                    entry,
                    &[target(layout.format())],
                    1,
                    &[],
                    &[],
                    cull,
                )
            })
        };
        let attachments = [cleared(f.res.view(Target::Geometry), geometry_clear(layout))];
        let mut pass = encoder.begin_render_pass(&wgpu::RenderPassDescriptor {
            label: Some("gbuffer"),
            color_attachments: &attachments,
            depth_stencil_attachment: depth_buffer(f.res.view(Target::GeometryDepth)),
            timestamp_writes: timing,
            occlusion_query_set: None,
            multiview_mask: None,
        });
        f.draw_meshes(&mut pass, |d| pipeline(d.cull));
        Ok(())
    }
}

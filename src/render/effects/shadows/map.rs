//! The shadow map pass: every mesh's depth from the shadow-casting light (Kang, Kim and Yoon's
//! shadow z-buffer), read by the shading and shadow passes.

use crate::error::Result;
use crate::render::gpu_mesh::GpuMesh;
use crate::render::graph::build::{cull_bits, nearest_wins};
use crate::render::graph::target::{Access, Target, Use};
use crate::render::graph::{depth_buffer, FrameCtx, Pass, Recorder};
use crate::render::pipelines::PipelineKey;

pub const WGSL: &str = include_str!("map.wgsl");

#[derive(Debug, Clone, PartialEq)]
pub struct ShadowMap;

impl Pass for ShadowMap {
    fn name(&self) -> &'static str {
        "shadow_map"
    }

    fn uses(&self) -> Vec<Use> {
        vec![Use(Target::ShadowMap, Access::Attach)]
    }

    fn encode(&self, f: &FrameCtx<'_>, rec: &mut Recorder<'_>) -> Result<()> {
        let pipeline = |cull: Option<wgpu::Face>| {
            f.pipelines.get(PipelineKey::new("shadow_map", cull_bits(cull)), || {
                let device = &f.dev.device;
                let layouts = &f.pipelines.layouts;
                let module = f.module("shadow_map", WGSL, None);
                let layout = f.pipelines.layout(device, "shadow_map", &[&layouts.frame, &layouts.draw]);
                device.create_render_pipeline(&wgpu::RenderPipelineDescriptor {
                    label: Some("shadow_map"),
                    layout: Some(&layout),
                    vertex: wgpu::VertexState {
                        module: &module,
                        entry_point: Some("vs_shadow"),
                        compilation_options: Default::default(),
                        buffers: &[Some(GpuMesh::vertex_layout())],
                    },
                    // both sides cast (open surfaces and planes too), but the inner sides of a
                    // closed mesh never show to the light
                    primitive: wgpu::PrimitiveState { cull_mode: cull, ..Default::default() },
                    depth_stencil: nearest_wins(),
                    multisample: Default::default(),
                    fragment: None,
                    multiview_mask: None,
                    cache: None,
                })
            })
        };
        let mut pass = rec.begin("shadow_map", &[], depth_buffer(f.res.view(Target::ShadowMap), true));
        f.draw_meshes(&mut pass, |d| pipeline(d.light_cull));
        Ok(())
    }
}

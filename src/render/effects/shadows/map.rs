//! The shadow map pass: every mesh's depth from the shadow-casting light (Kang, Kim and Yoon's
//! shadow z-buffer), read by the shading and shadow passes. A mesh whose colour has an alpha
//! cutoff is drawn with its colour (`graph::mesh_stages`), so that its cut-out pixels cast no
//! shadow; the others need no fragment stage.

use crate::error::Result;
use crate::render::gpu_albedo::GpuAlbedo;
use crate::render::gpu_mesh::GpuMesh;
use crate::render::graph::build::{cull_bits, depth_pass_pipeline, nearest_wins};
use crate::render::graph::mesh_stages::MeshStages;
use crate::render::graph::target::{Access, Target, Use};
use crate::render::graph::{depth_buffer, DrawItem, FrameCtx, Pass, Recorder};
use crate::render::pipelines::PipelineKey;

pub const WGSL: &str = include_str!("map.wgsl");
/// The WGSL the stages of a cut mesh's draw are written after (its colour's sampling).
pub const CUT_WGSL: &str = include_str!("../../shaders/albedo.wgsl");

/// The stages of a cut mesh's draw into the map: its colour read, drawn from the light, no
/// target but the depth.
pub fn cut_stages() -> MeshStages {
    MeshStages { albedo: true, clip: Some("frame.shadows.to_light"), ..Default::default() }
}

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
        let cut_pipeline = |d: &DrawItem<'_>, albedo: &GpuAlbedo| {
            depth_pass_pipeline(f, "shadow_map", CUT_WGSL, cut_stages(), albedo.constants(), d.light_cull)
        };
        let mut pass = rec.begin("shadow_map", &[], depth_buffer(f.res.view(Target::ShadowMap), true));
        f.draw_meshes_with(
            &mut pass,
            |d| match d.cut_albedo() {
                Some(albedo) => cut_pipeline(d, albedo),
                None => pipeline(d.light_cull),
            },
            |d| d.cut_albedo().is_some(),
        );
        Ok(())
    }
}

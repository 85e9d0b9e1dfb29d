//! The two kinds of pipeline passes build: mesh draws (the camera's passes and the shadow map)
//! and full-screen triangles (image passes), and the states they share.

use std::sync::Arc;

use crate::render::gpu_albedo::GpuAlbedo;
use crate::render::pipelines::PipelineKey;

use super::effect::ShadeHook;
use super::mesh_stages::MeshStages;
use super::target::DEPTH_FORMAT;
use super::{DrawItem, FrameCtx};

/// The depth test of every mesh draw (camera and shadow map): the nearest surface wins and is
/// written.
pub fn nearest_wins() -> Option<wgpu::DepthStencilState> {
    Some(wgpu::DepthStencilState {
        format: DEPTH_FORMAT,
        depth_write_enabled: Some(true),
        depth_compare: Some(wgpu::CompareFunction::Less),
        stencil: Default::default(),
        bias: Default::default(),
    })
}

/// A pipeline-cache key's bits for a cull mode.
pub fn cull_bits(cull: Option<wgpu::Face>) -> u64 {
    match cull {
        None => 0,
        Some(wgpu::Face::Back) => 1,
        Some(wgpu::Face::Front) => 2,
    }
}

/// How a mesh pipeline draws: its stages (what they read and the targets they write, in the
/// module's `vs_mesh` and `fs_mesh`), sample count, pipeline constants, the bind groups after
/// the frame's and the draw's, and the faces it skips.
pub struct MeshDraw<'a> {
    pub label: &'static str,
    pub stages: MeshStages,
    pub samples: u32,
    pub constants: &'a [(&'a str, f64)],
    pub more: &'a [Option<&'a wgpu::BindGroupLayout>],
    pub cull: Option<wgpu::Face>,
}

/// A pipeline that draws meshes (groups 0 and 1: frame and draw uniforms, then `more`, then
/// the groups its stages' parts read, each at the index the stages give it) with depth testing.
pub fn mesh_pipeline(f: &FrameCtx<'_>, module: &wgpu::ShaderModule, d: MeshDraw<'_>) -> wgpu::RenderPipeline {
    let device = &f.dev.device;
    let layouts = &f.pipelines.layouts;
    let part_groups: Vec<(u32, wgpu::BindGroupLayout)> = d
        .stages
        .groups()
        .into_iter()
        .filter_map(|(g, part)| part.bindings.as_ref().map(|b| (g, (b.layout)(device))))
        .collect();
    let mut groups = vec![Some(&layouts.frame), Some(&layouts.draw)];
    groups.extend(d.more.iter().copied());
    for (g, layout) in &part_groups {
        groups.resize(groups.len().max(*g as usize), None);
        groups.push(Some(layout));
    }
    let layout = f.pipelines.layout_with_gaps(device, d.label, &groups);
    let options = wgpu::PipelineCompilationOptions { constants: d.constants, ..Default::default() };
    let buffers = d.stages.vertex_buffers();
    let targets = d.stages.targets();
    device.create_render_pipeline(&wgpu::RenderPipelineDescriptor {
        label: Some(d.label),
        layout: Some(&layout),
        vertex: wgpu::VertexState {
            module,
            entry_point: Some("vs_mesh"),
            compilation_options: options.clone(),
            buffers: &buffers,
        },
        // Both sides are drawn unless one cannot show: a camera inside a mesh, or an open
        // surface, shows back faces.
        primitive: wgpu::PrimitiveState {
            cull_mode: d.cull,
            front_face: wgpu::FrontFace::Ccw,
            ..Default::default()
        },
        depth_stencil: nearest_wins(),
        multisample: wgpu::MultisampleState { count: d.samples, mask: !0, alpha_to_coverage_enabled: false },
        fragment: d.stages.fragment().then(|| wgpu::FragmentState {
            module,
            entry_point: Some("fs_mesh"),
            compilation_options: options,
            targets: &targets,
        }),
        multiview_mask: None,
        cache: None,
    })
}

/// The pipeline of a depth pass's draw of `d` (one sample a pixel, no bind group but the
/// frame's, the draw's and its stages' parts', no WGSL but its stages'): the geometry pass's and
/// the shadow map's, cached under `label` with the stages, the cull mode and the constants; with
/// its stages, for `FrameCtx::draw_meshes`. `stages(cut)` are the draw's stages; `cut`: the
/// mesh's colour has an alpha cutoff (`DrawItem::cut_albedo`), so the draw reads its colour to
/// drop the cut pixels.
pub fn depth_pass_pipeline(
    f: &FrameCtx<'_>,
    label: &'static str,
    d: &DrawItem<'_>,
    stages: impl FnOnce(bool) -> MeshStages,
    cull: Option<wgpu::Face>,
) -> (Arc<wgpu::RenderPipeline>, MeshStages) {
    let albedo = d.cut_albedo();
    let stages = stages(albedo.is_some());
    let constants = albedo.map_or(vec![], GpuAlbedo::constants);
    let key = PipelineKey::new(label, stages.bits() | cull_bits(cull) << 16).with(&constants);
    let pipeline = f.pipelines.get(key, || {
        let module = f.mesh_module(label, "", stages, None);
        let draw = MeshDraw { label, stages, samples: 1, constants: &constants, more: &[], cull };
        mesh_pipeline(f, &module, draw)
    });
    (pipeline, stages)
}

/// The pipeline `label` that covers the output with one triangle (`vs_fullscreen` in
/// common.wgsl) and runs entry `entry` of `wgsl` (with `hook`'s WGSL): built on first use, and
/// cached under `label` and `variant`, which must tell apart whatever changes its groups,
/// targets and constants.
pub fn fullscreen_pipeline(
    f: &FrameCtx<'_>,
    (label, variant): (&'static str, u64),
    (wgsl, entry, hook): (&'static str, &str, Option<&dyn ShadeHook>),
    groups: &[&wgpu::BindGroupLayout],
    targets: &[Option<wgpu::ColorTargetState>],
    constants: &[(&str, f64)],
) -> Arc<wgpu::RenderPipeline> {
    f.pipelines.get(PipelineKey::new(label, variant), || {
        let module = &f.module(label, wgsl, hook);
        let device = &f.dev.device;
        let layout = f.pipelines.layout(device, label, groups);
        let options = wgpu::PipelineCompilationOptions { constants, ..Default::default() };
        device.create_render_pipeline(&wgpu::RenderPipelineDescriptor {
            label: Some(label),
            layout: Some(&layout),
            vertex: wgpu::VertexState {
                module,
                entry_point: Some("vs_fullscreen"),
                compilation_options: options.clone(),
                buffers: &[],
            },
            primitive: Default::default(),
            depth_stencil: None,
            multisample: Default::default(),
            fragment: Some(wgpu::FragmentState {
                module,
                entry_point: Some(entry),
                compilation_options: options,
                targets,
            }),
            multiview_mask: None,
            cache: None,
        })
    })
}

/// A bind group of one texture view.
pub fn texture_group(
    device: &wgpu::Device,
    layout: &wgpu::BindGroupLayout,
    view: &wgpu::TextureView,
) -> wgpu::BindGroup {
    device.create_bind_group(&wgpu::BindGroupDescriptor {
        label: None,
        layout,
        entries: &[wgpu::BindGroupEntry { binding: 0, resource: wgpu::BindingResource::TextureView(view) }],
    })
}

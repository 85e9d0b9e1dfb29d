//! The passes a frame can run, one module each with its WGSL beside it. A pass declares the
//! targets it uses (`graph::Pass::uses`); `render::plan` decides which passes a frame runs.

pub mod downsample;
pub mod edges;
pub mod geometry;
pub mod lines;
pub mod readback;
pub mod shade;
pub mod shadow;
pub mod shadow_map;

use crate::render::gpu_mesh::GpuMesh;
use crate::render::graph::target::DEPTH_FORMAT;
use crate::render::graph::FrameCtx;

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

/// Every pass's own WGSL, for the shader validation test.
pub const SHADERS: [&str; 6] =
    [shade::WGSL, geometry::WGSL, downsample::WGSL, edges::WGSL, lines::WGSL, shadow_map::WGSL];
/// The passes' WGSL that tests the shadow map.
pub const SHADOWED_SHADERS: [&str; 2] = [shade::WGSL, shadow::WGSL];

/// A pipeline that draws meshes (groups 0 and 1: frame and draw uniforms, then `more`) with
/// depth testing, skipping the faces of `cull` (`render::culling`).
#[allow(clippy::too_many_arguments)]
pub fn mesh_pipeline(
    f: &FrameCtx<'_>,
    label: &'static str,
    module: &wgpu::ShaderModule,
    entry: &str,
    targets: &[Option<wgpu::ColorTargetState>],
    samples: u32,
    constants: &[(&str, f64)],
    more: &[&wgpu::BindGroupLayout],
    cull: Option<wgpu::Face>,
) -> wgpu::RenderPipeline {
    let device = &f.dev.device;
    let layouts = &f.pipelines.layouts;
    let mut groups = vec![&layouts.frame, &layouts.draw];
    groups.extend_from_slice(more);
    let layout = f.pipelines.layout(device, label, &groups);
    let options = wgpu::PipelineCompilationOptions { constants, ..Default::default() };
    device.create_render_pipeline(&wgpu::RenderPipelineDescriptor {
        label: Some(label),
        layout: Some(&layout),
        vertex: wgpu::VertexState {
            module,
            entry_point: Some("vs_main"),
            compilation_options: options.clone(),
            buffers: &[Some(GpuMesh::vertex_layout())],
        },
        // Both sides are drawn unless one cannot show: a camera inside a mesh, or an open
        // surface, shows back faces.
        primitive: wgpu::PrimitiveState {
            cull_mode: cull,
            front_face: wgpu::FrontFace::Ccw,
            ..Default::default()
        },
        depth_stencil: nearest_wins(),
        multisample: wgpu::MultisampleState { count: samples, mask: !0, alpha_to_coverage_enabled: false },
        fragment: Some(wgpu::FragmentState {
            module,
            entry_point: Some(entry),
            compilation_options: options,
            targets,
        }),
        multiview_mask: None,
        cache: None,
    })
}

/// A pipeline that covers the output with one triangle (`vs_fullscreen` in common.wgsl).
pub fn fullscreen_pipeline(
    f: &FrameCtx<'_>,
    label: &'static str,
    module: &wgpu::ShaderModule,
    entry: &str,
    groups: &[&wgpu::BindGroupLayout],
    targets: &[Option<wgpu::ColorTargetState>],
    constants: &[(&str, f64)],
) -> wgpu::RenderPipeline {
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
}

/// Opens a render pass over `attachments` and draws the one triangle that covers the output,
/// with `pipeline` and `groups` bound in order (group 0 first).
pub fn draw_fullscreen(
    encoder: &mut wgpu::CommandEncoder,
    label: &'static str,
    attachments: &[Option<wgpu::RenderPassColorAttachment<'_>>],
    timing: Option<wgpu::RenderPassTimestampWrites<'_>>,
    pipeline: &wgpu::RenderPipeline,
    groups: &[&wgpu::BindGroup],
) {
    let mut pass = encoder.begin_render_pass(&wgpu::RenderPassDescriptor {
        label: Some(label),
        color_attachments: attachments,
        depth_stencil_attachment: None,
        timestamp_writes: timing,
        occlusion_query_set: None,
        multiview_mask: None,
    });
    pass.set_pipeline(pipeline);
    for (i, g) in groups.iter().enumerate() {
        pass.set_bind_group(i as u32, *g, &[]);
    }
    pass.draw(0..3, 0..1);
}

/// A bind group of one texture view.
pub fn texture_group(
    f: &FrameCtx<'_>,
    layout: &wgpu::BindGroupLayout,
    view: &wgpu::TextureView,
) -> wgpu::BindGroup {
    f.dev.device.create_bind_group(&wgpu::BindGroupDescriptor {
        label: None,
        layout,
        entries: &[wgpu::BindGroupEntry { binding: 0, resource: wgpu::BindingResource::TextureView(view) }],
    })
}

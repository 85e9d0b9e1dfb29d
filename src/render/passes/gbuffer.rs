//! The geometry pass: view-space normal and linear depth at the output size, one sample each.

use crate::render::context::GpuContext;
use crate::render::pipelines::PipelineKey;
use crate::render::targets::FrameTargets;

use super::{attachment, depth_attachment, draw_meshes, linear_depth_clear, normal_clear, DrawList};

pub fn encode(ctx: &GpuContext, encoder: &mut wgpu::CommandEncoder, t: &FrameTargets, list: &DrawList) {
    let normal_view = t.normal.as_ref().map(|n| n.create_view(&Default::default()));
    let depth_view = t.linear_depth.as_ref().map(|d| d.create_view(&Default::default()));
    let mut attachments = Vec::new();
    attachments.extend(normal_view.as_ref().map(|v| attachment(v, normal_clear())));
    attachments.extend(depth_view.as_ref().map(|v| attachment(v, linear_depth_clear())));
    let mut pass = encoder.begin_render_pass(&wgpu::RenderPassDescriptor {
        label: Some("gbuffer"),
        color_attachments: &attachments,
        depth_stencil_attachment: depth_attachment(
            t.gbuffer_depth.as_ref().expect("the geometry pass has a depth buffer"),
        ),
        timestamp_writes: None,
        occlusion_query_set: None,
        multiview_mask: None,
    });
    let key = PipelineKey::GBuffer { normal: normal_view.is_some(), depth: depth_view.is_some() };
    let pipeline = ctx.pipelines.get(&ctx.device, key);
    draw_meshes(&mut pass, list, |_| pipeline.clone());
}

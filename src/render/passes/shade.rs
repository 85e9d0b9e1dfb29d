//! The shading pass: meshes with their materials into the colour target, resolving MSAA on the
//! way; with `gbuffer`, also normal and linear depth.

use crate::render::context::GpuContext;
use crate::render::pipelines::PipelineKey;
use crate::render::targets::FrameTargets;

use super::{attachment, depth_attachment, draw_meshes, linear_depth_clear, normal_clear, DrawList};

pub fn encode(
    ctx: &GpuContext,
    encoder: &mut wgpu::CommandEncoder,
    t: &FrameTargets,
    list: &DrawList,
    gbuffer: bool,
    background: wgpu::Color,
) {
    let key = t.key;
    let final_view = t.color.as_ref().map(|c| c.create_view(&Default::default()));
    // The single-sample image this pass ends in: the output, or its supersampled version.
    let single = t
        .color_hi
        .as_ref()
        .or(final_view.as_ref())
        .expect("the shading pass runs only when colour is asked for");
    let color = match &t.color_ms {
        Some(ms) => Some(wgpu::RenderPassColorAttachment {
            view: ms,
            depth_slice: None,
            resolve_target: Some(single),
            // the samples are needed only until they are resolved
            ops: wgpu::Operations { load: wgpu::LoadOp::Clear(background), store: wgpu::StoreOp::Discard },
        }),
        None => attachment(single, background),
    };
    let normal_view = t.normal.as_ref().filter(|_| gbuffer).map(|n| n.create_view(&Default::default()));
    let depth_view = t.linear_depth.as_ref().filter(|_| gbuffer).map(|d| d.create_view(&Default::default()));
    let mut attachments = vec![color];
    // contiguous, in the order of the pipeline's targets (no gaps: GL mishandles them)
    attachments.extend(normal_view.as_ref().map(|v| attachment(v, normal_clear())));
    attachments.extend(depth_view.as_ref().map(|v| attachment(v, linear_depth_clear())));
    let mut pass = encoder.begin_render_pass(&wgpu::RenderPassDescriptor {
        label: Some("shade"),
        color_attachments: &attachments,
        depth_stencil_attachment: depth_attachment(
            t.shade_depth.as_ref().expect("shading has a depth buffer"),
        ),
        timestamp_writes: None,
        occlusion_query_set: None,
        multiview_mask: None,
    });
    let (normal, depth) = (normal_view.is_some(), depth_view.is_some());
    draw_meshes(&mut pass, list, |d| {
        ctx.pipelines.get(
            &ctx.device,
            PipelineKey::Shade { samples: key.msaa, normal, depth, per_vertex: d.per_vertex },
        )
    });
}

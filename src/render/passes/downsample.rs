//! Supersampling's last step: box-filter the large colour image down to the output size.

use crate::render::context::GpuContext;
use crate::render::pipelines::PipelineKey;
use crate::render::targets::FrameTargets;

use super::attachment;

pub fn encode(ctx: &GpuContext, encoder: &mut wgpu::CommandEncoder, t: &FrameTargets, factor: u32) {
    let source = t.color_hi.as_ref().expect("supersampling renders into a large colour target");
    let output = t.color.as_ref().expect("colour is asked for").create_view(&Default::default());
    let group = ctx.device.create_bind_group(&wgpu::BindGroupDescriptor {
        label: Some("downsample source"),
        layout: &ctx.pipelines.source_layout,
        entries: &[wgpu::BindGroupEntry { binding: 0, resource: wgpu::BindingResource::TextureView(source) }],
    });
    let pipeline = ctx.pipelines.get(&ctx.device, PipelineKey::Downsample { factor });
    let mut pass = encoder.begin_render_pass(&wgpu::RenderPassDescriptor {
        label: Some("downsample"),
        color_attachments: &[attachment(&output, wgpu::Color::TRANSPARENT)],
        depth_stencil_attachment: None,
        timestamp_writes: None,
        occlusion_query_set: None,
        multiview_mask: None,
    });
    pass.set_pipeline(&pipeline);
    pass.set_bind_group(0, &group, &[]);
    pass.draw(0..3, 0..1);
}

//! Mesh-space outlines (Kang, Kim and Yoon): the silhouettes of the view and the mesh's
//! boundaries, creases and non-manifold edges, drawn as antialiased screen-space strips over the
//! colour and/or into the outline coverage, with hidden lines removed against the geometry
//! target's depth. `visibility.rs` holds the same rules on the CPU.

pub mod visibility;

use crate::error::Result;
use crate::render::graph::target::{Access, GeometryLayout, Target, Use};
use crate::render::graph::{FrameCtx, Pass};
use crate::render::uniforms::LineInstance;

use super::edges::{ink_attachments, ink_entry, ink_targets, ink_uses};

pub const WGSL: &str = include_str!("lines.wgsl");

#[derive(Debug, Clone, PartialEq)]
pub struct Lines {
    pub color: bool,
    pub outline: bool,
    pub clear_outline: bool,
    /// Where the depth the lines are tested against is.
    pub layout: GeometryLayout,
}

fn instance_layout() -> wgpu::VertexBufferLayout<'static> {
    const ATTRS: [wgpu::VertexAttribute; 3] =
        wgpu::vertex_attr_array![0 => Float32x3, 1 => Uint32, 2 => Float32x3];
    wgpu::VertexBufferLayout {
        array_stride: std::mem::size_of::<LineInstance>() as u64,
        step_mode: wgpu::VertexStepMode::Instance,
        attributes: &ATTRS,
    }
}

impl Pass for Lines {
    fn name(&self) -> &'static str {
        "lines"
    }

    fn uses(&self) -> Vec<Use> {
        let mut u = vec![Use(Target::Geometry, Access::Sample)];
        u.extend(ink_uses(self.color, self.outline));
        u
    }

    fn encode(
        &self,
        f: &FrameCtx<'_>,
        encoder: &mut wgpu::CommandEncoder,
        timing: Option<wgpu::RenderPassTimestampWrites<'_>>,
    ) -> Result<()> {
        let layouts = &f.pipelines.layouts;
        let variant = self.color as u64 | (self.outline as u64) << 1 | (self.layout as u64) << 2;
        let pipeline = f.pipelines.get(("lines", variant), || {
            let device = &f.dev.device;
            let module = f.pipelines.module(device, "lines", || crate::render::wgsl::source(WGSL));
            let layout =
                f.pipelines.layout(device, "lines", &[&layouts.frame, &layouts.draw, &layouts.uint_texture]);
            let constants = [("DEPTH_COMPONENT", self.layout.depth_component() as f64)];
            let options = wgpu::PipelineCompilationOptions { constants: &constants, ..Default::default() };
            device.create_render_pipeline(&wgpu::RenderPipelineDescriptor {
                label: Some("lines"),
                layout: Some(&layout),
                vertex: wgpu::VertexState {
                    module: &module,
                    entry_point: Some("vs_line"),
                    compilation_options: options.clone(),
                    buffers: &[Some(instance_layout())],
                },
                primitive: wgpu::PrimitiveState {
                    topology: wgpu::PrimitiveTopology::TriangleStrip,
                    cull_mode: None,
                    ..Default::default()
                },
                depth_stencil: None,
                multisample: Default::default(),
                fragment: Some(wgpu::FragmentState {
                    module: &module,
                    entry_point: Some(ink_entry(self.color, self.outline)),
                    compilation_options: options,
                    targets: &ink_targets(self.color, self.outline),
                }),
                multiview_mask: None,
                cache: None,
            })
        });
        let geometry = f.res.bind_group("geometry", || {
            super::texture_group(f, &layouts.uint_texture, f.res.view(Target::Geometry))
        });
        let attachments = ink_attachments(f, self.color, self.outline, self.clear_outline);
        let mut pass = encoder.begin_render_pass(&wgpu::RenderPassDescriptor {
            label: Some("lines"),
            color_attachments: &attachments,
            depth_stencil_attachment: None,
            timestamp_writes: timing,
            occlusion_query_set: None,
            multiview_mask: None,
        });
        if let Some((buffer, _)) = &f.res.lines {
            pass.set_pipeline(&pipeline);
            pass.set_bind_group(0, &f.res.uniforms.frame_group, &[]);
            pass.set_bind_group(2, &geometry, &[]);
            pass.set_vertex_buffer(0, buffer.slice(..));
            for d in f.lines.iter().filter(|d| !d.instances.is_empty()) {
                pass.set_bind_group(1, &f.res.uniforms.draw_group, &[d.uniform_offset]);
                pass.draw(0..4, d.instances.clone());
            }
        }
        Ok(())
    }
}

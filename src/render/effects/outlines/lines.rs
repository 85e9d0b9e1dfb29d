//! Mesh-space outlines (Kang, Kim and Yoon): the silhouettes of the view and the mesh's
//! boundaries, creases and non-manifold edges, drawn as antialiased screen-space strips over the
//! colour and/or into the outline coverage: lines cut on the host by the exact rule
//! (`occluded`) as they are, others with hidden lines removed against the geometry target's
//! depth; dashed where their ink says. `visibility.rs` holds the same rules on the CPU.

use crate::error::Result;
use crate::render::graph::target::{GeometryLayout, Use};
use crate::render::graph::{FrameCtx, Pass, Recorder};
use crate::render::pipelines::PipelineKey;

use super::ink::Ink;
use super::mesh_lines::{FrameLine, ViewSlot};

pub const WGSL: &str = concat!(include_str!("inked.wgsl"), include_str!("lines.wgsl"));

#[derive(Debug, Clone)]
pub struct Lines {
    pub ink: Ink,
    /// Where the depth the lines are tested against is.
    pub layout: GeometryLayout,
    /// The view's lines, found by the `silhouettes` step before the frame is recorded.
    pub view: ViewSlot,
    /// The items whose lines it draws: all (None), or only those that are glass or only those
    /// that are not (a frame with glass draws the opaque items' ink under the glass and the
    /// glass's own over it).
    pub glass: Option<bool>,
}

fn instance_layout() -> wgpu::VertexBufferLayout<'static> {
    wgpu::VertexBufferLayout {
        array_stride: std::mem::size_of::<FrameLine>() as u64,
        step_mode: wgpu::VertexStepMode::Instance,
        attributes: &FrameLine::ATTRIBUTES,
    }
}

impl Pass for Lines {
    fn name(&self) -> &'static str {
        if self.glass == Some(true) {
            "glass_lines"
        } else {
            "lines"
        }
    }

    fn uses(&self) -> Vec<Use> {
        self.ink.uses()
    }

    fn encode(&self, f: &FrameCtx<'_>, rec: &mut Recorder<'_>) -> Result<()> {
        let layouts = &f.pipelines.layouts;
        let variant = self.ink.bits() | (self.layout as u64) << 2;
        let pipeline = f.pipelines.get(PipelineKey::new("lines", variant), || {
            let device = &f.dev.device;
            let module = f.module("lines", WGSL, None);
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
                    entry_point: Some(self.ink.entry()),
                    compilation_options: options,
                    targets: &self.ink.targets(),
                }),
                multiview_mask: None,
                cache: None,
            })
        });
        let geometry = f.res.geometry_group(f);
        let view = self.view.get().expect("the silhouettes step ran before the frame was recorded");
        let buffer = f.res.vertices(f.dev, "line instances", bytemuck::cast_slice(&view.instances));
        let attachments = self.ink.attachments(f);
        let mut pass = rec.begin(self.name(), &attachments, None);
        if let Some(buffer) = buffer {
            pass.set_pipeline(&pipeline);
            pass.set_bind_group(0, &f.res.uniforms.frame_group, &[]);
            pass.set_bind_group(2, &geometry, &[]);
            pass.set_vertex_buffer(0, buffer.slice(..));
            let drawn = |item: usize| self.glass.is_none_or(|g| f.draws[item].glass == g);
            for d in view.draws.iter().filter(|d| !d.instances.is_empty() && drawn(d.item)) {
                pass.set_bind_group(1, &f.res.uniforms.draw_group, &[f.res.draw_offset(d.item)]);
                pass.draw(0..4, d.instances.clone());
            }
        }
        Ok(())
    }
}

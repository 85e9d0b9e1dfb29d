//! The passes of a render plan (see `plan.rs`), each encoding its work into a command encoder.

pub mod downsample;
pub mod gbuffer;
pub mod shade;

use std::sync::Arc;

use super::gpu_mesh::GpuMesh;

/// One mesh to draw, with its uniforms bound.
pub struct Draw {
    pub mesh: Arc<GpuMesh>,
    pub uniforms: wgpu::BindGroup,
    pub per_vertex: bool,
}

/// What every mesh-drawing pass binds.
pub struct DrawList {
    pub frame_uniforms: wgpu::BindGroup,
    pub draws: Vec<Draw>,
}

/// Draws every mesh, switching pipelines only when the variant changes.
pub fn draw_meshes(
    pass: &mut wgpu::RenderPass<'_>,
    list: &DrawList,
    pipeline_for: impl Fn(&Draw) -> Arc<wgpu::RenderPipeline>,
) {
    pass.set_bind_group(0, &list.frame_uniforms, &[]);
    let mut current: Option<Arc<wgpu::RenderPipeline>> = None;
    for d in &list.draws {
        let p = pipeline_for(d);
        if current.as_ref().map(|c| !Arc::ptr_eq(c, &p)).unwrap_or(true) {
            pass.set_pipeline(&p);
            current = Some(p);
        }
        pass.set_bind_group(1, &d.uniforms, &[]);
        pass.set_vertex_buffer(0, d.mesh.vertices.slice(..));
        match &d.mesh.indices {
            Some(ib) => {
                pass.set_index_buffer(ib.slice(..), wgpu::IndexFormat::Uint32);
                pass.draw_indexed(0..d.mesh.draw_count, 0, 0..1);
            }
            None => pass.draw(0..d.mesh.draw_count, 0..1),
        }
    }
}

/// Clear values of the normal and linear-depth targets: no normal, depth +inf.
pub fn normal_clear() -> wgpu::Color {
    wgpu::Color::TRANSPARENT
}

pub fn linear_depth_clear() -> wgpu::Color {
    wgpu::Color { r: f32::INFINITY.to_bits() as f64, g: 0.0, b: 0.0, a: 0.0 }
}

pub fn attachment(
    view: &wgpu::TextureView,
    clear: wgpu::Color,
) -> Option<wgpu::RenderPassColorAttachment<'_>> {
    Some(wgpu::RenderPassColorAttachment {
        view,
        depth_slice: None,
        resolve_target: None,
        ops: wgpu::Operations { load: wgpu::LoadOp::Clear(clear), store: wgpu::StoreOp::Store },
    })
}

pub fn depth_attachment(view: &wgpu::TextureView) -> Option<wgpu::RenderPassDepthStencilAttachment<'_>> {
    Some(wgpu::RenderPassDepthStencilAttachment {
        view,
        depth_ops: Some(wgpu::Operations { load: wgpu::LoadOp::Clear(1.0), store: wgpu::StoreOp::Discard }),
        stencil_ops: None,
    })
}

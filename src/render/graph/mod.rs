//! The frame graph. A frame is a list of passes (see `render::plan`); each pass declares the
//! targets it writes and reads, the frame's textures are allocated from those declarations
//! (`resources`), and the whole frame is recorded into one command encoder and submitted once.
//! Frame effects (`effect`) add their passes and host steps to the list.

pub mod build;
pub mod effect;
pub mod glass_layer;
pub mod mesh_stages;
pub mod report;
pub mod resources;
pub mod target;

use std::sync::Arc;

use crate::error::Result;

use super::device::Device;
use super::gpu_albedo;
use super::gpu_mesh::GpuMesh;
use super::pipelines::PipelineCache;
use super::wgsl;
use effect::ShadeHook;
use mesh_stages::{MeshStages, ALBEDO};
use resources::FrameResources;
use target::{Shape, Use};

/// One step of a frame.
pub trait Pass: std::fmt::Debug + Send + Sync {
    /// The name `RenderResult.passes` shows.
    fn name(&self) -> &'static str;

    /// The targets this pass writes and reads.
    fn uses(&self) -> Vec<Use>;

    /// Whether the pass is a render pass, timed on the GPU where timestamps exist (copies are not).
    fn timed(&self) -> bool {
        true
    }

    /// Records the pass.
    fn encode(&self, f: &FrameCtx<'_>, rec: &mut Recorder<'_>) -> Result<()>;
}

/// The frame's command encoder, and the timestamps of the pass being recorded.
pub struct Recorder<'a> {
    pub encoder: &'a mut wgpu::CommandEncoder,
    pub timing: Option<wgpu::RenderPassTimestampWrites<'a>>,
}

impl Recorder<'_> {
    /// Opens the pass's render pass over `color` (and `depth`), timed where timestamps exist.
    pub fn begin<'p>(
        &'p mut self,
        label: &'static str,
        color: &[Option<wgpu::RenderPassColorAttachment<'_>>],
        depth: Option<wgpu::RenderPassDepthStencilAttachment<'_>>,
    ) -> wgpu::RenderPass<'p> {
        self.encoder.begin_render_pass(&wgpu::RenderPassDescriptor {
            label: Some(label),
            color_attachments: color,
            depth_stencil_attachment: depth,
            timestamp_writes: self.timing.take(),
            occlusion_query_set: None,
            multiview_mask: None,
        })
    }

    /// Opens a render pass over `color` and draws the one triangle that covers the output,
    /// with `pipeline` and `groups` bound in order (group 0 first).
    pub fn fullscreen(
        &mut self,
        label: &'static str,
        color: &[Option<wgpu::RenderPassColorAttachment<'_>>],
        pipeline: &wgpu::RenderPipeline,
        groups: &[&wgpu::BindGroup],
    ) {
        let mut pass = self.begin(label, color, None);
        pass.set_pipeline(pipeline);
        for (i, g) in groups.iter().enumerate() {
            pass.set_bind_group(i as u32, *g, &[]);
        }
        pass.draw(0..3, 0..1);
    }
}

/// One mesh to draw, with the offset of its uniforms in the frame's draw buffer.
pub struct DrawItem<'a> {
    pub mesh: &'a GpuMesh,
    pub uniform_offset: u32,
    pub material: &'a crate::render::scene::material::Material,
    /// The faces the camera's passes may skip, and those the shadow map may (`render::culling`).
    pub cull: Option<wgpu::Face>,
    pub light_cull: Option<wgpu::Face>,
    /// The vertex buffers its shading derives from the mesh, each with its slot
    /// (`render::derived_vertices`).
    pub derived: &'a [(u32, std::sync::Arc<wgpu::Buffer>)],
    /// The mesh is glass (`scene::checked::is_glass`): only the glass stage draws it.
    pub glass: bool,
}

impl<'a> DrawItem<'a> {
    /// The mesh's colour where an alpha cutoff may drop its pixels: the passes that write depth
    /// without shading (geometry, shadow map) read it too, to drop them.
    pub fn cut_albedo(&self) -> Option<&'a crate::render::gpu_albedo::GpuAlbedo> {
        self.mesh.albedo.as_ref().filter(|a| a.alpha_cutoff.is_some())
    }
}

/// What every pass of a frame may use while it records.
pub struct FrameCtx<'a> {
    pub dev: &'a Device,
    pub pipelines: &'a PipelineCache,
    pub res: &'a FrameResources,
    pub shape: Shape,
    pub draws: &'a [DrawItem<'a>],
    /// The WGSL every shader module starts with (`render::shader`).
    pub preamble: &'a str,
    /// Linear-light background colour and alpha.
    pub background: wgpu::Color,
    /// The scene's number of lights.
    pub lights: u32,
    /// Bit k set when the shader's light k is a point light (the shadow-casting light first):
    /// only those need a direction per pixel.
    pub point_lights: u32,
}

/// A mesh pass's own WGSL: its file, then the stages written for `stages`.
pub fn mesh_pass_wgsl(pass: &str, stages: MeshStages) -> String {
    format!("{pass}\n{}", stages.wgsl())
}

/// A whole module's WGSL: the renderer's `preamble`, the shading hooks of `hook` (the defaults
/// where None), the pass's own WGSL.
pub fn module_wgsl(preamble: &str, pass: &str, hook: Option<&dyn ShadeHook>) -> String {
    wgsl::compose(preamble, hook.map_or(wgsl::DEFAULT_HOOKS, |h| h.wgsl()), pass)
}

impl FrameCtx<'_> {
    /// The shader module `name` of a pass's WGSL, with the shading hooks of `hook` (the
    /// defaults where None), compiled on first use.
    pub fn module(&self, name: &'static str, pass: &str, hook: Option<&dyn ShadeHook>) -> wgpu::ShaderModule {
        self.module_keyed(name.to_string(), || pass.to_string(), hook)
    }

    /// `module` for a mesh pass: its WGSL and the stages written for `stages`, each combination
    /// written and compiled on first use.
    pub fn mesh_module(
        &self,
        name: &'static str,
        pass: &str,
        stages: MeshStages,
        hook: Option<&dyn ShadeHook>,
    ) -> wgpu::ShaderModule {
        self.module_keyed(format!("{name} ({})", stages.name()), || mesh_pass_wgsl(pass, stages), hook)
    }

    fn module_keyed(
        &self,
        name: String,
        pass: impl FnOnce() -> String,
        hook: Option<&dyn ShadeHook>,
    ) -> wgpu::ShaderModule {
        let key = match hook {
            Some(h) => format!("{name}+{}", h.name()),
            None => name,
        };
        self.pipelines.module(&self.dev.device, key, || module_wgsl(self.preamble, &pass(), hook))
    }

    /// Draws every opaque mesh (glass is the glass stage's: `draw_glass`) with the pipeline
    /// `pipeline_for` gives it, switching pipelines only when the variant changes, and binds
    /// what the pipeline's stages read: the mesh's positions, its colour (vertex buffer and
    /// texture group) where the stages have the albedo part, and the vertex data derived for its
    /// shading.
    pub fn draw_meshes(
        &self,
        pass: &mut wgpu::RenderPass<'_>,
        pipeline_for: impl Fn(&DrawItem<'_>) -> (Arc<wgpu::RenderPipeline>, MeshStages),
    ) {
        self.draw_items(pass, false, pipeline_for, |_, _| {});
    }

    /// `draw_meshes` for the glass meshes, with `bind` binding what else their stages read.
    pub fn draw_glass(
        &self,
        pass: &mut wgpu::RenderPass<'_>,
        pipeline_for: impl Fn(&DrawItem<'_>) -> (Arc<wgpu::RenderPipeline>, MeshStages),
        bind: impl Fn(&mut wgpu::RenderPass<'_>, MeshStages),
    ) {
        self.draw_items(pass, true, pipeline_for, bind);
    }

    fn draw_items(
        &self,
        pass: &mut wgpu::RenderPass<'_>,
        glass: bool,
        pipeline_for: impl Fn(&DrawItem<'_>) -> (Arc<wgpu::RenderPipeline>, MeshStages),
        bind: impl Fn(&mut wgpu::RenderPass<'_>, MeshStages),
    ) {
        pass.set_bind_group(0, &self.res.uniforms.frame_group, &[]);
        let mut current: Option<Arc<wgpu::RenderPipeline>> = None;
        for d in self.draws.iter().filter(|d| d.glass == glass) {
            let (p, stages) = pipeline_for(d);
            if current.as_ref().is_none_or(|c| !Arc::ptr_eq(c, &p)) {
                pass.set_pipeline(&p);
                current = Some(p);
            }
            pass.set_bind_group(1, &self.res.uniforms.draw_group, &[d.uniform_offset]);
            bind(pass, stages);
            pass.set_vertex_buffer(0, d.mesh.vertices.slice(..));
            if let (Some(group), Some(a)) = (stages.group_of(&ALBEDO), &d.mesh.albedo) {
                pass.set_vertex_buffer(gpu_albedo::SLOT, a.vertices.slice(..));
                pass.set_bind_group(group, &a.group, &[]);
            }
            for (slot, buffer) in d.derived {
                pass.set_vertex_buffer(*slot, buffer.slice(..));
            }
            match &d.mesh.indices {
                Some(ib) => {
                    pass.set_index_buffer(ib.slice(..), wgpu::IndexFormat::Uint32);
                    pass.draw_indexed(0..d.mesh.draw_count, 0, 0..1);
                }
                None => pass.draw(0..d.mesh.draw_count, 0..1),
            }
        }
    }
}

/// A colour attachment cleared to `clear` and stored.
pub fn cleared(view: &wgpu::TextureView, clear: wgpu::Color) -> Option<wgpu::RenderPassColorAttachment<'_>> {
    Some(wgpu::RenderPassColorAttachment {
        view,
        depth_slice: None,
        resolve_target: None,
        ops: wgpu::Operations { load: wgpu::LoadOp::Clear(clear), store: wgpu::StoreOp::Store },
    })
}

/// A colour attachment drawn over (its contents kept) and stored.
pub fn loaded(view: &wgpu::TextureView) -> Option<wgpu::RenderPassColorAttachment<'_>> {
    Some(wgpu::RenderPassColorAttachment {
        view,
        depth_slice: None,
        resolve_target: None,
        ops: wgpu::Operations { load: wgpu::LoadOp::Load, store: wgpu::StoreOp::Store },
    })
}

/// A depth buffer cleared to the far plane and stored only when `keep` (a shadow map).
pub fn depth_buffer(
    view: &wgpu::TextureView,
    keep: bool,
) -> Option<wgpu::RenderPassDepthStencilAttachment<'_>> {
    let store = if keep { wgpu::StoreOp::Store } else { wgpu::StoreOp::Discard };
    Some(wgpu::RenderPassDepthStencilAttachment {
        view,
        depth_ops: Some(wgpu::Operations { load: wgpu::LoadOp::Clear(1.0), store }),
        stencil_ops: None,
    })
}

/// A cleared colour target whose texels hold f32 bit patterns (`bits` per channel).
pub fn bits_clear(bits: [f32; 4]) -> wgpu::Color {
    let [r, g, b, a] = bits.map(|x| x.to_bits() as f64);
    wgpu::Color { r, g, b, a }
}

/// Clear value of the geometry target: normal (0, 0, 0) and depth +inf, as f32 bits.
pub fn geometry_clear(layout: target::GeometryLayout) -> wgpu::Color {
    let inf = f32::INFINITY;
    match layout {
        target::GeometryLayout::NormalDepth => bits_clear([0.0, 0.0, 0.0, inf]),
        target::GeometryLayout::Depth => bits_clear([inf, 0.0, 0.0, 0.0]),
    }
}

//! The frame graph. A frame is a list of passes (see `render::plan`); each pass declares the
//! targets it writes and reads, the frame's textures are allocated from those declarations
//! (`resources`), and the whole frame is recorded into one command encoder and submitted once.

pub mod resources;
pub mod target;

use std::ops::Range;
use std::sync::Arc;

use crate::error::Result;

use super::device::Device;
use super::gpu_mesh::GpuMesh;
use super::pipelines::PipelineCache;
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

    /// Records the pass. `timing` is passed on to the render pass it opens.
    fn encode(
        &self,
        f: &FrameCtx<'_>,
        encoder: &mut wgpu::CommandEncoder,
        timing: Option<wgpu::RenderPassTimestampWrites<'_>>,
    ) -> Result<()>;
}

/// One mesh to draw, with the offset of its uniforms in the frame's draw buffer.
pub struct DrawItem<'a> {
    pub mesh: &'a GpuMesh,
    pub uniform_offset: u32,
    pub variant: ShadingVariant,
    /// The faces the camera's passes may skip, and those the shadow map may (`render::culling`).
    pub cull: Option<wgpu::Face>,
    pub light_cull: Option<wgpu::Face>,
}

/// What a material needs compiled into the shading pipeline.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub struct ShadingVariant {
    /// The shading model's id (`Model::id`).
    pub model: u32,
    pub per_vertex: bool,
    pub hatching: bool,
    pub dither:
        Option<(crate::render::scene::style::DitherPattern, crate::render::scene::style::DitherSpace)>,
}

impl ShadingVariant {
    pub fn of(m: &crate::render::scene::material::Material) -> Self {
        ShadingVariant {
            model: m.model.id(),
            per_vertex: m.per_vertex,
            hatching: m.hatching.is_some(),
            dither: m.dither.map(|d| (d.pattern, d.space)),
        }
    }

    /// Whether the fragment stage reads the vertex stage's anchors (object coordinates and
    /// per-vertex colours; `Anchors` in common.wgsl): hatching, object-space dithering and
    /// per-vertex shading do.
    pub fn anchored(&self) -> bool {
        let object_dither =
            matches!(self.dither, Some((_, crate::render::scene::style::DitherSpace::Object)));
        self.per_vertex || self.hatching || object_dither
    }

    /// The variant as bits of a pipeline key.
    pub fn bits(&self) -> u64 {
        let (pattern, object) = match self.dither {
            Some((p, s)) => (p as u64, (s == crate::render::scene::style::DitherSpace::Object) as u64),
            None => (0, 0),
        };
        self.per_vertex as u64
            | (self.hatching as u64) << 1
            | pattern << 2
            | object << 5
            | (self.model as u64) << 6
    }

    /// The shader's pipeline constants.
    pub fn constants(&self) -> [(&'static str, f64); 5] {
        let (pattern, object) = match self.dither {
            Some((p, s)) => {
                (p as u32 as f64, (s == crate::render::scene::style::DitherSpace::Object) as u32 as f64)
            }
            None => (0.0, 0.0),
        };
        [
            ("PER_VERTEX", self.per_vertex as u32 as f64),
            ("HATCHING", self.hatching as u32 as f64),
            ("DITHER", pattern),
            ("DITHER_OBJECT", object),
            ("MODEL", self.model as f64),
        ]
    }
}

/// The mesh-space lines of one mesh: a range of the frame's line instances.
pub struct LineDraw {
    pub uniform_offset: u32,
    pub instances: Range<u32>,
}

/// What every pass of a frame may use while it records.
pub struct FrameCtx<'a> {
    pub dev: &'a Device,
    pub pipelines: &'a PipelineCache,
    pub res: &'a FrameResources,
    pub shape: Shape,
    pub draws: &'a [DrawItem<'a>],
    pub lines: &'a [LineDraw],
    /// Linear-light background colour and alpha.
    pub background: wgpu::Color,
    /// The scene's number of lights.
    pub lights: u32,
    /// Bit k set when the shader's light k is a point light (`uniforms::shader_lights` order):
    /// only those need a direction per pixel.
    pub point_lights: u32,
    /// How the shadow map is read, when a light casts shadows.
    pub shadow_filter: Option<crate::render::scene::shadows::ShadowFilter>,
}

impl FrameCtx<'_> {
    /// Draws every mesh, switching pipelines only when the variant changes.
    pub fn draw_meshes(
        &self,
        pass: &mut wgpu::RenderPass<'_>,
        pipeline_for: impl Fn(&DrawItem<'_>) -> Arc<wgpu::RenderPipeline>,
    ) {
        pass.set_bind_group(0, &self.res.uniforms.frame_group, &[]);
        let mut current: Option<Arc<wgpu::RenderPipeline>> = None;
        for d in self.draws {
            let p = pipeline_for(d);
            if current.as_ref().is_none_or(|c| !Arc::ptr_eq(c, &p)) {
                pass.set_pipeline(&p);
                current = Some(p);
            }
            pass.set_bind_group(1, &self.res.uniforms.draw_group, &[d.uniform_offset]);
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

/// A depth buffer cleared to the far plane; its contents are not needed after the pass.
pub fn depth_buffer(view: &wgpu::TextureView) -> Option<wgpu::RenderPassDepthStencilAttachment<'_>> {
    Some(wgpu::RenderPassDepthStencilAttachment {
        view,
        depth_ops: Some(wgpu::Operations { load: wgpu::LoadOp::Clear(1.0), store: wgpu::StoreOp::Discard }),
        stencil_ops: None,
    })
}

/// Clear value of the geometry target: normal (0, 0, 0) and depth +inf, as f32 bits.
pub fn geometry_clear(layout: target::GeometryLayout) -> wgpu::Color {
    let inf = f32::INFINITY.to_bits() as f64;
    match layout {
        target::GeometryLayout::NormalDepth => wgpu::Color { r: 0.0, g: 0.0, b: 0.0, a: inf },
        target::GeometryLayout::Depth => wgpu::Color { r: inf, g: 0.0, b: 0.0, a: 0.0 },
    }
}

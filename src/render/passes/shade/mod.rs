//! The shading pass: meshes with their materials into the colour target, resolving MSAA on the
//! way. When it runs at the output size with one sample per pixel and the frame needs the
//! geometry target, it writes that too (one draw instead of two). A frame effect may swap in
//! shading hooks (`graph::effect::ShadeHook`: the shadow test).

pub mod variant;

use std::sync::Arc;

use crate::error::Result;
use crate::render::graph::build::{cull_bits, mesh_pipeline, MeshDraw};
use crate::render::graph::effect::ShadeHook;
use crate::render::graph::mesh_stages::MeshStages;
use crate::render::graph::target::{Access, GeometryLayout, Target, Use};
use crate::render::graph::{cleared, depth_buffer, geometry_clear, DrawItem, FrameCtx, Pass, Recorder};
use crate::render::pipelines::PipelineKey;

use variant::ShadingVariant;

/// The pass's WGSL, which its stages (`graph::mesh_stages`) are written after.
pub const WGSL: &str = include_str!("shade.wgsl");

#[derive(Debug, Clone)]
pub struct Shade {
    pub samples: u32,
    /// Renders into the supersampled colour target, which `downsample` then averages.
    pub supersampled: bool,
    /// Also writes the geometry target, in this layout.
    pub geometry: Option<GeometryLayout>,
    /// What a frame effect swaps into the shading.
    pub hook: Option<Arc<dyn ShadeHook>>,
}

impl Shade {
    /// The single-sample colour image this pass ends in.
    fn single(&self) -> Target {
        if self.supersampled {
            Target::ColorHi
        } else {
            Target::Color
        }
    }

    fn pipeline(&self, f: &FrameCtx<'_>, d: &DrawItem<'_>) -> (Arc<wgpu::RenderPipeline>, MeshStages) {
        let shading = ShadingVariant::of(d.material, d.mesh.albedo.as_ref());
        let hook = self.hook.as_deref();
        let stages = shading.stages(self.geometry);
        let bits = self.samples as u64
            | hook.map_or(0, |h| h.key()) << 12
            | cull_bits(d.cull) << 20
            | (f.lights as u64) << 32
            | (f.point_lights as u64) << 40
            | stages.bits() << 48;
        let pipeline = f.pipelines.get(PipelineKey::new("shade", bits).with(&shading.constants), || {
            let module = f.mesh_module("shade", WGSL, stages, hook);
            let mut constants = shading.frame_constants(f.lights, f.point_lights);
            let mut more = vec![];
            if let Some(h) = hook {
                constants.extend(h.constants());
                more.push(Some(h.layout(&f.pipelines.layouts)));
            }
            mesh_pipeline(
                f,
                &module,
                MeshDraw {
                    label: "shade",
                    stages,
                    samples: self.samples,
                    constants: &constants,
                    more: &more,
                    cull: d.cull,
                },
            )
        });
        (pipeline, stages)
    }
}

impl Pass for Shade {
    fn name(&self) -> &'static str {
        "shade"
    }

    fn uses(&self) -> Vec<Use> {
        let mut u = vec![Use(self.single(), Access::Attach), Use(Target::ShadeDepth, Access::Attach)];
        if self.samples > 1 {
            u.push(Use(Target::ColorMs, Access::Attach));
        }
        if self.geometry.is_some() {
            u.push(Use(Target::Geometry, Access::Attach));
        }
        if let Some(h) = &self.hook {
            u.extend(h.uses());
        }
        u
    }

    fn encode(&self, f: &FrameCtx<'_>, rec: &mut Recorder<'_>) -> Result<()> {
        let single = f.res.view(self.single());
        let color = if self.samples > 1 {
            Some(wgpu::RenderPassColorAttachment {
                view: f.res.view(Target::ColorMs),
                depth_slice: None,
                resolve_target: Some(single),
                // the samples are needed only until they are resolved
                ops: wgpu::Operations {
                    load: wgpu::LoadOp::Clear(f.background),
                    store: wgpu::StoreOp::Discard,
                },
            })
        } else {
            cleared(single, f.background)
        };
        let mut attachments = vec![color];
        if let Some(g) = self.geometry {
            attachments.push(cleared(f.res.view(Target::Geometry), geometry_clear(g)));
        }
        let mut pass = rec.begin("shade", &attachments, depth_buffer(f.res.view(Target::ShadeDepth), false));
        if let Some(h) = &self.hook {
            pass.set_bind_group(2, &h.bind_group(f), &[]);
        }
        f.draw_meshes(&mut pass, |d| self.pipeline(f, d));
        Ok(())
    }
}

//! Glass: exact, order-independent compositing of the meshes that let light through
//! (`scene::checked::is_glass`), by depth peeling. The opaque meshes are drawn as in a frame
//! without glass (every other pass skips glass: `FrameCtx::draw_meshes`), their ink included
//! (the glass's own ink is drawn over the composite: `Steps::over_glass`);
//! then `layers` peels each find, per pixel, the nearest glass fragment strictly behind the
//! last layer's and in front of the opaque surface (the geometry target's linear depth), shade
//! it with its opacity, and add it under the layers before (front to back); a last pass lays
//! the sum over the opaque colour. Beyond `layers` glass surfaces a pixel drops the farthest.
//! One sample a pixel, at the output size. CPU twin: `reference`.
//!
//! Each layer costs a draw of the glass meshes and a full-screen pass; glass casts no shadow and
//! receives none.

#[cfg(test)]
mod gpu_tests;
pub mod reference;

use std::sync::Arc;

use crate::error::Result;
use crate::render::graph::build::{fullscreen_pipeline, mesh_pipeline, texture_group, MeshDraw};
use crate::render::graph::mesh_stages::{MeshStages, GLASS};
use crate::render::graph::target::{Access, Target, Use};
use crate::render::graph::{bits_clear, cleared, depth_buffer, loaded, DrawItem, FrameCtx, Pass, Recorder};
use crate::render::passes::clear::Clear;
use crate::render::passes::shade::{variant::ShadingVariant, WGSL as SHADE_WGSL};
use crate::render::pipelines::{blended, PipelineKey};

/// The full-screen passes' WGSL.
pub const WGSL: &str = include_str!("glass.wgsl");
pub use crate::render::graph::glass_layer::{peel_layout, LAYER_FORMAT, PEELED_FORMAT, PEEL_WGSL};

/// The layer under the layers so far: sum += (1 - sum.a) layer (front to back).
const UNDER: wgpu::BlendComponent = wgpu::BlendComponent {
    src_factor: wgpu::BlendFactor::OneMinusDstAlpha,
    dst_factor: wgpu::BlendFactor::One,
    operation: wgpu::BlendOperation::Add,
};

/// The glass stage's passes for `layers` layers: a clear of the depth the first peel starts
/// from, a peel and its addition per layer, the composite.
pub fn passes(layers: u32) -> Vec<Box<dyn Pass>> {
    let mut passes: Vec<Box<dyn Pass>> =
        vec![Box::new(Clear { name: "glass_clear", target: Target::Peeled(1), value: bits_clear([0.0; 4]) })];
    for layer in 0..layers {
        passes.push(Box::new(Peel { layer }));
        passes.push(Box::new(Under { first: layer == 0 }));
    }
    passes.push(Box::new(Composite));
    passes
}

/// The targets a peel writes and reads: the depth it writes, the depth it reads.
fn peeled(layer: u32) -> (Target, Target) {
    let k = (layer % 2) as u8;
    (Target::Peeled(k), Target::Peeled(1 - k))
}

/// Peels layer `layer` of the glass.
#[derive(Debug, Clone, PartialEq)]
pub struct Peel {
    pub layer: u32,
}

impl Peel {
    fn pipeline(&self, f: &FrameCtx<'_>, d: &DrawItem<'_>) -> (Arc<wgpu::RenderPipeline>, MeshStages) {
        let shading = ShadingVariant::of(d.material, d.mesh.albedo.as_ref());
        let stages = MeshStages { color: false, glass: true, ..shading.stages(None) };
        let word = f.shape.geometry.expect("a frame with glass has the geometry target").depth_component();
        let bits =
            stages.bits() | (f.lights as u64) << 16 | (f.point_lights as u64) << 24 | (word as u64) << 32;
        let pipeline = f.pipelines.get(PipelineKey::new("glass_peel", bits).with(&shading.constants), || {
            let module = f.mesh_module("glass_peel", SHADE_WGSL, stages, None);
            let mut constants = shading.frame_constants(f.lights, f.point_lights);
            constants.push(("OPAQUE_DEPTH_WORD", word as f64));
            // both sides: the back of a glass mesh shows through its front
            let draw = MeshDraw {
                label: "glass_peel",
                stages,
                samples: 1,
                constants: &constants,
                more: &[],
                cull: None,
            };
            mesh_pipeline(f, &module, draw)
        });
        (pipeline, stages)
    }
}

impl Pass for Peel {
    fn name(&self) -> &'static str {
        "glass_peel"
    }

    fn uses(&self) -> Vec<Use> {
        let (write, read) = peeled(self.layer);
        vec![
            Use(Target::GlassLayer, Access::Attach),
            Use(write, Access::Attach),
            Use(Target::GeometryDepth, Access::Attach),
            Use(read, Access::Sample),
            Use(Target::Geometry, Access::Sample),
        ]
    }

    fn encode(&self, f: &FrameCtx<'_>, rec: &mut Recorder<'_>) -> Result<()> {
        let (write, read) = peeled(self.layer);
        let name = if self.layer % 2 == 0 { "glass peel even" } else { "glass peel odd" };
        let group = f.res.bind_group(name, || {
            let views = [f.res.view(Target::Geometry), f.res.view(read)];
            f.dev.device.create_bind_group(&wgpu::BindGroupDescriptor {
                label: Some(name),
                layout: &peel_layout(&f.dev.device),
                entries: &[
                    wgpu::BindGroupEntry {
                        binding: 0,
                        resource: wgpu::BindingResource::TextureView(views[0]),
                    },
                    wgpu::BindGroupEntry {
                        binding: 1,
                        resource: wgpu::BindingResource::TextureView(views[1]),
                    },
                ],
            })
        });
        // where no glass is left, the depth stays beyond every surface: later peels find none
        let attachments = [
            cleared(f.res.view(Target::GlassLayer), wgpu::Color::TRANSPARENT),
            cleared(f.res.view(write), bits_clear([f32::INFINITY, 0.0, 0.0, 0.0])),
        ];
        let mut pass =
            rec.begin("glass_peel", &attachments, depth_buffer(f.res.view(Target::GeometryDepth), false));
        f.draw_glass(
            &mut pass,
            |d| self.pipeline(f, d),
            |pass, stages| {
                if let Some(g) = stages.group_of(&GLASS) {
                    pass.set_bind_group(g, &group, &[]);
                }
            },
        );
        Ok(())
    }
}

/// The full-screen pass `label` that blends `source` into `dest` with `blend`.
fn blend_into(
    f: &FrameCtx<'_>,
    rec: &mut Recorder<'_>,
    (label, group): (&'static str, &'static str),
    (source, dest, format): (Target, Target, wgpu::TextureFormat),
    blend: wgpu::BlendState,
    clear: bool,
) {
    let layouts = &f.pipelines.layouts;
    let pipeline = fullscreen_pipeline(
        f,
        (label, 0),
        (WGSL, "fs_glass", None),
        &[&layouts.frame, &layouts.float_texture],
        &[blended(format, blend)],
        &[],
    );
    let source =
        f.res.bind_group(group, || texture_group(&f.dev.device, &layouts.float_texture, f.res.view(source)));
    let view = f.res.view(dest);
    let attachment = if clear { cleared(view, wgpu::Color::TRANSPARENT) } else { loaded(view) };
    rec.fullscreen(label, &[attachment], &pipeline, &[&f.res.uniforms.frame_group, &source]);
}

/// Adds the layer just peeled under the layers before it.
#[derive(Debug, Clone, PartialEq)]
pub struct Under {
    /// The first layer: the sum starts from nothing.
    pub first: bool,
}

impl Pass for Under {
    fn name(&self) -> &'static str {
        "glass_under"
    }

    fn uses(&self) -> Vec<Use> {
        vec![Use(Target::GlassLayer, Access::Sample), Use(Target::GlassSum, Access::Attach)]
    }

    fn encode(&self, f: &FrameCtx<'_>, rec: &mut Recorder<'_>) -> Result<()> {
        let blend = wgpu::BlendState { color: UNDER, alpha: UNDER };
        let targets = (Target::GlassLayer, Target::GlassSum, LAYER_FORMAT);
        blend_into(f, rec, ("glass_under", "glass layer"), targets, blend, self.first);
        Ok(())
    }
}

/// Lays the glass over the opaque colour (ink included).
#[derive(Debug, Clone, PartialEq)]
pub struct Composite;

impl Pass for Composite {
    fn name(&self) -> &'static str {
        "glass_composite"
    }

    fn uses(&self) -> Vec<Use> {
        vec![Use(Target::GlassSum, Access::Sample), Use(Target::Color, Access::Attach)]
    }

    fn encode(&self, f: &FrameCtx<'_>, rec: &mut Recorder<'_>) -> Result<()> {
        let targets = (Target::GlassSum, Target::Color, crate::render::device::COLOR_FORMAT);
        let blend = wgpu::BlendState::PREMULTIPLIED_ALPHA_BLENDING;
        blend_into(f, rec, ("glass_composite", "glass sum"), targets, blend, false);
        Ok(())
    }
}

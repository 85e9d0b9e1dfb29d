//! Shadows: the shadow test that the shading pass and this pass share (`shadow_test.wgsl`), and
//! the `shadow` pass, which writes the shadow-casting light's visibility at each pixel for the
//! shadow output. `raycast` is the CPU truth both are measured against.

pub mod raycast;

use crate::error::Result;
use crate::render::graph::target::{Access, Target, Use, SHADOW_FORMAT};
use crate::render::graph::{FrameCtx, Pass};
use crate::render::pipelines::target;
use crate::render::scene::shadows::ShadowFilter;

pub const WGSL: &str = include_str!("shadow.wgsl");
/// `light_visibility` against the shadow map (bind group 2).
pub const SHADOW_TEST: &str = include_str!("shadow_test.wgsl");

/// The shadow map and its filter's sampler, bind group 2 of the passes that test shadows.
pub fn shadow_group(f: &FrameCtx<'_>, filter: ShadowFilter) -> wgpu::BindGroup {
    let name = match filter {
        ShadowFilter::Nearest => "shadow map, nearest",
        ShadowFilter::Pcf => "shadow map, pcf",
    };
    f.res.bind_group(name, || {
        f.dev.device.create_bind_group(&wgpu::BindGroupDescriptor {
            label: Some(name),
            layout: &f.pipelines.layouts.shadow,
            entries: &[
                wgpu::BindGroupEntry {
                    binding: 0,
                    resource: wgpu::BindingResource::TextureView(f.res.view(Target::ShadowMap)),
                },
                wgpu::BindGroupEntry {
                    binding: 1,
                    resource: wgpu::BindingResource::Sampler(&f.pipelines.shadow_samplers[filter as usize]),
                },
            ],
        })
    })
}

/// The pipeline constants of a shadow filter.
pub fn filter_constants(filter: ShadowFilter) -> [(&'static str, f64); 1] {
    [("PCF", (filter == ShadowFilter::Pcf) as u32 as f64)]
}

#[derive(Debug, Clone, PartialEq)]
pub struct ShadowMask;

impl Pass for ShadowMask {
    fn name(&self) -> &'static str {
        "shadow"
    }

    fn uses(&self) -> Vec<Use> {
        vec![
            Use(Target::Geometry, Access::Sample),
            Use(Target::ShadowMap, Access::Sample),
            Use(Target::Shadow, Access::Attach),
        ]
    }

    fn encode(
        &self,
        f: &FrameCtx<'_>,
        encoder: &mut wgpu::CommandEncoder,
        timing: Option<wgpu::RenderPassTimestampWrites<'_>>,
    ) -> Result<()> {
        let filter = f.shadow_filter.expect("the plan runs the shadow pass only with a shadow-casting light");
        let layouts = &f.pipelines.layouts;
        let pipeline = f.pipelines.get(("shadow", filter as u64), || {
            let module =
                f.pipelines.module(&f.dev.device, "shadow", || crate::render::wgsl::source_shadowed(WGSL));
            super::fullscreen_pipeline(
                f,
                "shadow",
                &module,
                "fs_shadow",
                &[&layouts.frame, &layouts.uint_texture, &layouts.shadow],
                &[target(SHADOW_FORMAT)],
                &filter_constants(filter),
            )
        });
        let geometry = f.res.bind_group("geometry", || {
            super::texture_group(f, &layouts.uint_texture, f.res.view(Target::Geometry))
        });
        let shadow = shadow_group(f, filter);
        let one = f32::to_bits(1.0) as f64;
        let attachments = [crate::render::graph::cleared(
            f.res.view(Target::Shadow),
            wgpu::Color { r: one, g: 0.0, b: 0.0, a: 0.0 },
        )];
        super::draw_fullscreen(
            encoder,
            "shadow",
            &attachments,
            timing,
            &pipeline,
            &[&f.res.uniforms.frame_group, &geometry, &shadow],
        );
        Ok(())
    }
}

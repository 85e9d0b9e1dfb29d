//! Shadows (Kang, Kim and Yoon's shadow z-buffer): a light with `Shadows` settings gets a
//! shadow map, every mesh drawn from the light (`map`); shading tests it (`shadow_test.wgsl`,
//! swapped in for the default light visibility), and the `shadow` output is the light's
//! visibility at each pixel (`mask`). `raycast` is the CPU truth both are measured against.

pub mod map;
pub mod mask;
pub mod raycast;
pub mod settings;

use std::sync::Arc;

use glam::{DMat4, DVec3};

use crate::error::{Error, Result};
use crate::render::block::{Block, BlockLayout};
use crate::render::graph::effect::{FrameEffect, FrameInputs, PlanInputs, ReadbackRequest, ShadeHook, Steps};
use crate::render::graph::target::{Access, GeometryLayout, Target, Use};
use crate::render::graph::FrameCtx;
use crate::render::pipelines::Layouts;
use crate::render::scene::checked::CheckedScene;
use crate::render::scene::light::ViewLight;
use crate::render::scene::Output;

use settings::{ShadowFilter, MAX_BIAS_SLOPE};

crate::uniform_block! {
    /// `frame.shadows`: the shadow-casting light's view of the scene.
    pub struct ShadowsBlock as "ShadowsBlock" {
        /// Normalised view space -> the light's clip space.
        pub to_light: [[f32; 4]; 4],
        /// Depth tolerance per unit of receiver slope (light depth units).
        pub tolerance: f32,
        /// The largest receiver slope biased.
        pub max_slope: f32,
        /// How far (normalised view units) a receiver moves along its normal before the test.
        pub normal_offset: f32,
        /// The share of the light a shadow takes away (`Shadows::strength`).
        pub strength: f32,
    }
}

/// Normalised view space -> the clip space of an orthographic view along the unit vector
/// `toward` the light that just holds the sphere `c`, `r` (normalised view space): x and y in
/// [-1, 1] across it, depth 0 on the side nearest the light and 1 on the far side.
pub fn shadow_matrix(toward: DVec3, c: DVec3, r: f64) -> DMat4 {
    let w = toward;
    let helper = if w.x.abs() < 0.9 { DVec3::X } else { DVec3::Y };
    let u = w.cross(helper).normalize();
    let v = w.cross(u);
    let rows = [
        [u.x / r, u.y / r, u.z / r, -u.dot(c) / r],
        [v.x / r, v.y / r, v.z / r, -v.dot(c) / r],
        [-w.x / (2.0 * r), -w.y / (2.0 * r), -w.z / (2.0 * r), (w.dot(c) + r) / (2.0 * r)],
        [0.0, 0.0, 0.0, 1.0],
    ];
    DMat4::from_cols_array_2d(&rows).transpose()
}

/// The shading's shadow test: bind group 2 holds the shadow map and its filter's sampler.
#[derive(Debug)]
pub struct ShadowTest {
    pub filter: ShadowFilter,
}

impl ShadeHook for ShadowTest {
    fn name(&self) -> &'static str {
        "shadowed"
    }

    fn wgsl(&self) -> &'static str {
        include_str!("shadow_test.wgsl")
    }

    fn constants(&self) -> Vec<(&'static str, f64)> {
        vec![("PCF", (self.filter == ShadowFilter::Pcf) as u32 as f64)]
    }

    fn key(&self) -> u64 {
        1 + self.filter as u64
    }

    fn layout<'a>(&self, layouts: &'a Layouts) -> &'a wgpu::BindGroupLayout {
        &layouts.shadow
    }

    fn bind_group(&self, f: &FrameCtx<'_>) -> wgpu::BindGroup {
        let name = match self.filter {
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
                        resource: wgpu::BindingResource::Sampler(
                            &f.pipelines.shadow_samplers[self.filter as usize],
                        ),
                    },
                ],
            })
        })
    }

    fn uses(&self) -> Vec<Use> {
        vec![Use(Target::ShadowMap, Access::Sample)]
    }
}

pub struct ShadowsEffect;

pub static EFFECT: ShadowsEffect = ShadowsEffect;

impl FrameEffect for ShadowsEffect {
    fn name(&self) -> &'static str {
        "shadows"
    }

    fn block_wgsl(&self) -> String {
        include_str!("block.wgsl").to_string()
    }

    fn block(&self) -> BlockLayout {
        ShadowsBlock::layout()
    }

    fn frame_block(&self, cx: &FrameInputs<'_>) -> Vec<u8> {
        let mut b: ShadowsBlock = bytemuck::Zeroable::zeroed();
        if let Some(c) = &cx.scene.caster {
            if let ViewLight::Toward(l) = c.light.to_view(&cx.cam.view) {
                let center = cx.cam.normalized_view().transform_point3(cx.sphere.center);
                let r = cx.sphere.radius / cx.cam.scale;
                b.to_light = shadow_matrix(l, center, r).as_mat4().to_cols_array_2d();
                b.tolerance = c.settings.tolerance() as f32;
                b.max_slope = MAX_BIAS_SLOPE as f32;
                // the map's side spans the sphere's diameter
                b.normal_offset = (c.settings.normal_offset() * 2.0 * r) as f32;
                b.strength = c.settings.strength as f32;
            }
        }
        b.bytes()
    }

    fn check(&self, scene: &CheckedScene) -> Result<()> {
        if scene.frame.outputs.has(Output::Shadow) && scene.caster.is_none() {
            return Err(Error::invalid(
                "outputs",
                "'shadow' needs a light that casts shadows (Light.directional(..., shadows=True))",
            ));
        }
        Ok(())
    }

    fn geometry(&self, scene: &CheckedScene) -> Option<GeometryLayout> {
        scene.frame.outputs.has(Output::Shadow).then_some(GeometryLayout::NormalDepth)
    }

    fn plan(&self, cx: &PlanInputs<'_>, steps: &mut Steps) {
        let o = cx.scene.frame.outputs;
        // colour is shaded with shadows where there is something to cast them; the shadow
        // output is made whenever asked for (all lit in an empty scene)
        let shaded = o.has(Output::Color) && cx.scene.casting().is_some();
        let output = o.has(Output::Shadow);
        let Some(caster) = cx.scene.caster.filter(|_| shaded || output) else { return };
        steps.shape.shadow_size = Some(caster.settings.size);
        steps.before.push(Box::new(map::ShadowMap));
        let test = Arc::new(ShadowTest { filter: caster.settings.filter });
        if shaded {
            steps.shade_hook = Some(test.clone());
        }
        if output {
            steps.after.push(Box::new(mask::ShadowMask { test }));
            steps.readbacks.push(ReadbackRequest {
                name: "readback_shadow",
                target: Target::Shadow,
                output: Output::Shadow,
            });
        }
    }
}

//! The shading pass: meshes with their materials into the colour target, resolving MSAA on the
//! way. When it runs at the output size with one sample per pixel and the frame needs the
//! geometry target, it writes that too (one draw instead of two).

use std::sync::Arc;

use crate::error::Result;
use crate::render::device::COLOR_FORMAT;
use crate::render::graph::target::{Access, GeometryLayout, Target, Use};
use crate::render::graph::{cleared, depth_buffer, geometry_clear, FrameCtx, Pass, ShadingVariant};
use crate::render::pipelines::target;
use crate::render::scene::shadows::ShadowFilter;

pub const WGSL: &str = include_str!("shade.wgsl");

#[derive(Debug, Clone, PartialEq)]
pub struct Shade {
    pub samples: u32,
    /// Renders into the supersampled colour target, which `downsample` then averages.
    pub supersampled: bool,
    /// Also writes the geometry target, in this layout.
    pub geometry: Option<GeometryLayout>,
    /// Tests the shadow map (`shadow_map` ran before).
    pub shadowed: bool,
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

    fn pipeline(
        &self,
        f: &FrameCtx<'_>,
        shading: ShadingVariant,
        shadows: Option<ShadowFilter>,
        cull: Option<wgpu::Face>,
    ) -> Arc<wgpu::RenderPipeline> {
        let variant = self.samples as u64
            | super::cull_bits(cull) << 14
            | shading.bits() << 16
            | (self.geometry.map_or(0, |g| 1 + g as u64)) << 9
            | (shadows.map_or(0, |s| 1 + s as u64)) << 12
            | (f.lights as u64) << 32
            | (f.point_lights as u64) << 40;
        f.pipelines.get(("shade", variant), || {
            let module = match shadows {
                None => f.pipelines.module(&f.dev.device, "shade", || crate::render::wgsl::source(WGSL)),
                Some(_) => f
                    .pipelines
                    .module(&f.dev.device, "shade, shadowed", || crate::render::wgsl::source_shadowed(WGSL)),
            };
            let mut targets = vec![target(COLOR_FORMAT)];
            let entry = match (self.geometry, shading.anchored()) {
                (None, false) => "fs_color",
                (None, true) => "fs_color_anchored",
                (Some(g), anchored) => {
                    targets.push(target(g.format()));
                    match (g, anchored) {
                        (GeometryLayout::NormalDepth, false) => "fs_color_normal_depth",
                        (GeometryLayout::NormalDepth, true) => "fs_color_normal_depth_anchored",
                        (GeometryLayout::Depth, false) => "fs_color_depth",
                        (GeometryLayout::Depth, true) => "fs_color_depth_anchored",
                    }
                }
            };
            let mut constants = shading.constants().to_vec();
            constants.push(("LIGHTS", f.lights as f64));
            constants.push(("POINT_LIGHTS", f.point_lights as f64));
            let mut more = vec![];
            if let Some(filter) = shadows {
                constants.extend(super::shadow::filter_constants(filter));
                more.push(&f.pipelines.layouts.shadow);
            }
            super::mesh_pipeline(f, "shade", &module, entry, &targets, self.samples, &constants, &more, cull)
        })
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
        if self.shadowed {
            u.push(Use(Target::ShadowMap, Access::Sample));
        }
        u
    }

    fn encode(
        &self,
        f: &FrameCtx<'_>,
        encoder: &mut wgpu::CommandEncoder,
        timing: Option<wgpu::RenderPassTimestampWrites<'_>>,
    ) -> Result<()> {
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
        let mut pass = encoder.begin_render_pass(&wgpu::RenderPassDescriptor {
            label: Some("shade"),
            color_attachments: &attachments,
            depth_stencil_attachment: depth_buffer(f.res.view(Target::ShadeDepth)),
            timestamp_writes: timing,
            occlusion_query_set: None,
            multiview_mask: None,
        });
        let shadows = f.shadow_filter.filter(|_| self.shadowed);
        if let Some(filter) = shadows {
            pass.set_bind_group(2, &super::shadow::shadow_group(f, filter), &[]);
        }
        f.draw_meshes(&mut pass, |d| self.pipeline(f, d.variant, shadows, d.cull));
        Ok(())
    }
}

//! The paper pass: the grain over the finished colour, by blending (`PAPER_BLEND`), reading
//! the geometry target where the grain is fixed to the surfaces.

use std::sync::Arc;

use wgpu::util::DeviceExt;

use crate::error::Result;
use crate::render::device::COLOR_FORMAT;
use crate::render::graph::build::{fullscreen_pipeline, texture_group};
use crate::render::graph::target::{Access, Target, Use};
use crate::render::graph::{loaded, FrameCtx, Pass, Recorder};
use crate::render::pipelines::{blended, KEEP};
use crate::render::settings::GreyImage;

pub const WGSL: &str = include_str!("paper.wgsl");

/// paper (1 - m) + colour m: the shader gives paper (1 - m) as its colour and m as its alpha;
/// the colour's alpha stays.
pub const PAPER_BLEND: wgpu::BlendState = wgpu::BlendState {
    color: wgpu::BlendComponent {
        src_factor: wgpu::BlendFactor::One,
        dst_factor: wgpu::BlendFactor::SrcAlpha,
        operation: wgpu::BlendOperation::Add,
    },
    alpha: KEEP,
};

#[derive(Debug)]
pub struct PaperPass {
    /// The grain is fixed to the surfaces (else to the screen).
    pub surface: bool,
    pub grain: Arc<GreyImage>,
}

impl PaperPass {
    /// The grain as a texture of its own, for this frame.
    fn tile(&self, f: &FrameCtx<'_>) -> wgpu::TextureView {
        let g = &self.grain;
        let texture = f.dev.device.create_texture_with_data(
            &f.dev.queue,
            &wgpu::TextureDescriptor {
                label: Some("paper grain"),
                size: wgpu::Extent3d { width: g.width, height: g.height, depth_or_array_layers: 1 },
                mip_level_count: 1,
                sample_count: 1,
                dimension: wgpu::TextureDimension::D2,
                format: wgpu::TextureFormat::R32Float,
                usage: wgpu::TextureUsages::TEXTURE_BINDING,
                view_formats: &[],
            },
            wgpu::util::TextureDataOrder::LayerMajor,
            bytemuck::cast_slice(&g.values),
        );
        texture.create_view(&Default::default())
    }
}

impl Pass for PaperPass {
    fn name(&self) -> &'static str {
        "paper"
    }

    fn uses(&self) -> Vec<Use> {
        let mut u = vec![Use(Target::Color, Access::Attach)];
        if self.surface {
            u.push(Use(Target::Geometry, Access::Sample));
        }
        u
    }

    fn encode(&self, f: &FrameCtx<'_>, rec: &mut Recorder<'_>) -> Result<()> {
        let layouts = &f.pipelines.layouts;
        let mut groups = vec![&layouts.frame, &layouts.float_texture];
        if self.surface {
            groups.push(&layouts.uint_texture);
        }
        let entry = if self.surface { "fs_surface" } else { "fs_screen" };
        let targets = [blended(COLOR_FORMAT, PAPER_BLEND)];
        let pipeline = fullscreen_pipeline(
            f,
            ("paper", self.surface as u64),
            (WGSL, entry, None),
            &groups,
            &targets,
            &[],
        );
        let tile = texture_group(&f.dev.device, &layouts.float_texture, &self.tile(f));
        let geometry = self.surface.then(|| f.res.geometry_group(f));
        let mut groups = vec![&f.res.uniforms.frame_group, &tile];
        groups.extend(geometry.as_ref());
        rec.fullscreen("paper", &[loaded(f.res.view(Target::Color))], &pipeline, &groups);
        Ok(())
    }
}

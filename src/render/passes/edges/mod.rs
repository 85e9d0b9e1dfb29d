//! Image-space outlines (Borquez and Yepez): Sobel on the normal and depth buffers of the
//! geometry target, with `edges::detect`'s rule and thresholds, painted in the image ink over the
//! colour and/or into the outline coverage. `reference.rs` is its CPU reference.

pub mod reference;

use crate::error::Result;
use crate::render::device::COLOR_FORMAT;
use crate::render::graph::target::{Access, Target, Use, OUTLINE_FORMAT};
use crate::render::graph::{cleared, loaded, FrameCtx, Pass};
use crate::render::pipelines::blended;

pub const WGSL: &str = include_str!("edges.wgsl");

/// Ink over colour: premultiplied "over".
pub const INK_OVER: wgpu::BlendState = wgpu::BlendState::PREMULTIPLIED_ALPHA_BLENDING;
/// Coverage of overlapping ink: the largest.
pub const COVERAGE_MAX: wgpu::BlendState = wgpu::BlendState {
    color: wgpu::BlendComponent {
        src_factor: wgpu::BlendFactor::One,
        dst_factor: wgpu::BlendFactor::One,
        operation: wgpu::BlendOperation::Max,
    },
    alpha: wgpu::BlendComponent {
        src_factor: wgpu::BlendFactor::One,
        dst_factor: wgpu::BlendFactor::One,
        operation: wgpu::BlendOperation::Max,
    },
};

/// The ink attachments of an ink pass (colour, then outline coverage: contiguous for GL).
pub fn ink_targets(color: bool, outline: bool) -> Vec<Option<wgpu::ColorTargetState>> {
    let mut t = Vec::new();
    if color {
        t.push(blended(COLOR_FORMAT, INK_OVER));
    }
    if outline {
        t.push(blended(OUTLINE_FORMAT, COVERAGE_MAX));
    }
    t
}

/// The ink targets an ink pass draws into.
pub fn ink_uses(color: bool, outline: bool) -> Vec<Use> {
    let mut u = Vec::new();
    if color {
        u.push(Use(Target::Color, Access::Attach));
    }
    if outline {
        u.push(Use(Target::Outline, Access::Attach));
    }
    u
}

/// The ink attachments; the first pass to write the outline coverage clears it.
pub fn ink_attachments<'a>(
    f: &'a FrameCtx<'_>,
    color: bool,
    outline: bool,
    clear_outline: bool,
) -> Vec<Option<wgpu::RenderPassColorAttachment<'a>>> {
    let mut a = Vec::new();
    if color {
        a.push(loaded(f.res.view(Target::Color)));
    }
    if outline {
        let view = f.res.view(Target::Outline);
        a.push(if clear_outline { cleared(view, wgpu::Color::TRANSPARENT) } else { loaded(view) });
    }
    a
}

/// The entry point for a set of ink targets.
pub fn ink_entry(color: bool, outline: bool) -> &'static str {
    match (color, outline) {
        (true, false) => "fs_color",
        (false, true) => "fs_outline",
        _ => "fs_both",
    }
}

#[derive(Debug, Clone, PartialEq)]
pub struct Edges {
    /// Paint the colour image.
    pub color: bool,
    /// Write the outline coverage.
    pub outline: bool,
    /// This is the first pass to write the outline coverage.
    pub clear_outline: bool,
}

impl Pass for Edges {
    fn name(&self) -> &'static str {
        "edges"
    }

    fn uses(&self) -> Vec<Use> {
        let mut u = vec![Use(Target::Geometry, Access::Sample)];
        u.extend(ink_uses(self.color, self.outline));
        u
    }

    fn encode(
        &self,
        f: &FrameCtx<'_>,
        encoder: &mut wgpu::CommandEncoder,
        timing: Option<wgpu::RenderPassTimestampWrites<'_>>,
    ) -> Result<()> {
        let layouts = &f.pipelines.layouts;
        let variant = self.color as u64 | (self.outline as u64) << 1;
        let pipeline = f.pipelines.get(("edges", variant), || {
            let module = f.pipelines.module(&f.dev.device, "edges", || crate::render::wgsl::source(WGSL));
            super::fullscreen_pipeline(
                f,
                "edges",
                &module,
                ink_entry(self.color, self.outline),
                &[&layouts.frame, &layouts.uint_texture],
                &ink_targets(self.color, self.outline),
                &[],
            )
        });
        let geometry = f.res.bind_group("geometry", || {
            super::texture_group(f, &layouts.uint_texture, f.res.view(Target::Geometry))
        });
        let attachments = ink_attachments(f, self.color, self.outline, self.clear_outline);
        super::draw_fullscreen(
            encoder,
            "edges",
            &attachments,
            timing,
            &pipeline,
            &[&f.res.uniforms.frame_group, &geometry],
        );
        Ok(())
    }
}

//! What the ink passes (image-space edges, mesh-space lines) share: they draw over the colour
//! and/or into the outline coverage, the first of them to write the coverage clearing it.

use crate::render::device::COLOR_FORMAT;
use crate::render::graph::target::{Access, Target, Use, OUTLINE_FORMAT};
use crate::render::graph::{cleared, loaded, FrameCtx};
use crate::render::pipelines::blended;

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

/// Where an ink pass draws: over the colour, into the coverage, and whether it is the first to
/// write the coverage (and so clears it).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Ink {
    pub color: bool,
    pub outline: bool,
    pub clear_outline: bool,
}

impl Ink {
    /// The pipeline-key bits of the targets.
    pub fn bits(self) -> u64 {
        self.color as u64 | (self.outline as u64) << 1
    }

    /// The colour targets of the pass's pipeline (colour, then coverage: contiguous for GL).
    pub fn targets(self) -> Vec<Option<wgpu::ColorTargetState>> {
        let mut t = Vec::new();
        if self.color {
            t.push(blended(COLOR_FORMAT, INK_OVER));
        }
        if self.outline {
            t.push(blended(OUTLINE_FORMAT, COVERAGE_MAX));
        }
        t
    }

    pub fn uses(self) -> Vec<Use> {
        let mut u = vec![Use(Target::Geometry, Access::Sample)];
        if self.color {
            u.push(Use(Target::Color, Access::Attach));
        }
        if self.outline {
            u.push(Use(Target::Outline, Access::Attach));
        }
        u
    }

    pub fn attachments<'a>(self, f: &'a FrameCtx<'_>) -> Vec<Option<wgpu::RenderPassColorAttachment<'a>>> {
        let mut a = Vec::new();
        if self.color {
            a.push(loaded(f.res.view(Target::Color)));
        }
        if self.outline {
            let view = f.res.view(Target::Outline);
            a.push(if self.clear_outline { cleared(view, wgpu::Color::TRANSPARENT) } else { loaded(view) });
        }
        a
    }

    /// The fragment entry point for the targets (each ink shader has the three).
    pub fn entry(self) -> &'static str {
        match (self.color, self.outline) {
            (true, false) => "fs_color",
            (false, true) => "fs_outline",
            _ => "fs_both",
        }
    }
}

//! The render plan: a scene and frame spec become the ordered list of passes they need, and
//! nothing else runs. `RenderOutput::passes` reports the plan that ran, so tests can hold it.
//!
//! Effects of later versions plug in here, each with the condition that makes it run:
//! a shadow-map pass before `Shade` when a light casts shadows onto something; mesh-space lines
//! after `Shade` when silhouette/crease outlines are asked for (depth-tested against it);
//! image-space edges (Sobel) after `GBuffer` when image outlines are asked for (they make the
//! geometry pass run even when normal/depth are not read back); hatching and dithering as
//! variants of `Shade` (pipeline keys), and a composite pass before the readbacks.

use super::scene::FrameSpec;
use super::targets::TargetKey;

#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Output {
    Color,
    Normal,
    Depth,
}

#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Pass {
    /// Draw the meshes with their materials into the colour target (multisampled and/or at the
    /// supersampled size when asked). With `gbuffer`, it also writes normal and linear depth.
    Shade { gbuffer: bool },
    /// Draw the meshes once more at the output size, one sample per pixel, writing only normal
    /// and linear depth: colour is multisampled or supersampled, or not asked for.
    GBuffer,
    /// Average `factor` x `factor` blocks of the supersampled colour to the output size.
    Downsample { factor: u32 },
    /// Copy one output to host memory.
    Readback(Output),
}

impl Pass {
    pub fn name(&self) -> &'static str {
        match self {
            Pass::Shade { .. } => "shade",
            Pass::GBuffer => "gbuffer",
            Pass::Downsample { .. } => "downsample",
            Pass::Readback(Output::Color) => "readback_color",
            Pass::Readback(Output::Normal) => "readback_normal",
            Pass::Readback(Output::Depth) => "readback_depth",
        }
    }
}

/// The passes for `frame`, in the order they run.
pub fn plan(frame: &FrameSpec) -> Vec<Pass> {
    let key = TargetKey::of(frame);
    let o = frame.outputs;
    let gbuffer = o.normal || o.depth;
    let mut passes = Vec::new();
    if o.color {
        passes.push(Pass::Shade { gbuffer: gbuffer && key.gbuffer_in_shade() });
    }
    if gbuffer && !key.gbuffer_in_shade() {
        passes.push(Pass::GBuffer);
    }
    if o.color && frame.supersample > 1 {
        passes.push(Pass::Downsample { factor: frame.supersample });
    }
    for (wanted, out) in [(o.color, Output::Color), (o.normal, Output::Normal), (o.depth, Output::Depth)] {
        if wanted {
            passes.push(Pass::Readback(out));
        }
    }
    passes
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::render::scene::Outputs;

    fn names(f: &FrameSpec) -> Vec<&'static str> {
        plan(f).iter().map(|p| p.name()).collect()
    }

    #[test]
    fn minimal_scene_runs_one_pass_and_one_readback() {
        assert_eq!(names(&FrameSpec::default()), ["shade", "readback_color"]);
    }

    #[test]
    fn gbuffer_joins_shading_only_when_sample_counts_match() {
        let mut f =
            FrameSpec { outputs: Outputs { color: true, normal: true, depth: true }, ..Default::default() };
        assert_eq!(names(&f), ["shade", "readback_color", "readback_normal", "readback_depth"]);
        assert_eq!(plan(&f)[0], Pass::Shade { gbuffer: true });
        f.msaa = 4;
        f.supersample = 2;
        assert_eq!(
            names(&f),
            ["shade", "gbuffer", "downsample", "readback_color", "readback_normal", "readback_depth"]
        );
        f.outputs = Outputs { color: false, normal: false, depth: true };
        assert_eq!(names(&f), ["gbuffer", "readback_depth"]);
    }
}

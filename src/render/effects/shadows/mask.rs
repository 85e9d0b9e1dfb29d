//! The `shadow` pass: the shadow-casting light's visibility at each pixel for the shadow
//! output, from the geometry target, with the shading's own shadow test.

use std::sync::Arc;

use crate::error::Result;
use crate::render::graph::build::fullscreen_pipeline;
use crate::render::graph::effect::ShadeHook;
use crate::render::graph::target::{Access, Target, Use, SHADOW_FORMAT};
use crate::render::graph::{bits_clear, cleared, FrameCtx, Pass, Recorder};
use crate::render::pipelines::target;

use super::ShadowTest;

pub const WGSL: &str = include_str!("mask.wgsl");

#[derive(Debug)]
pub struct ShadowMask {
    pub test: Arc<ShadowTest>,
}

impl Pass for ShadowMask {
    fn name(&self) -> &'static str {
        "shadow"
    }

    fn uses(&self) -> Vec<Use> {
        let mut u = vec![Use(Target::Geometry, Access::Sample), Use(Target::Shadow, Access::Attach)];
        u.extend(self.test.uses());
        u
    }

    fn encode(&self, f: &FrameCtx<'_>, rec: &mut Recorder<'_>) -> Result<()> {
        let layouts = &f.pipelines.layouts;
        let pipeline = fullscreen_pipeline(
            f,
            ("shadow", self.test.key()),
            (WGSL, "fs_shadow", Some(self.test.as_ref())),
            &[&layouts.frame, &layouts.uint_texture, self.test.layout(layouts)],
            &[target(SHADOW_FORMAT)],
            &self.test.constants(),
        );
        let geometry = f.res.geometry_group(f);
        let shadow = self.test.bind_group(f);
        let attachments = [cleared(f.res.view(Target::Shadow), bits_clear([1.0, 0.0, 0.0, 0.0]))];
        rec.fullscreen("shadow", &attachments, &pipeline, &[&f.res.uniforms.frame_group, &geometry, &shadow]);
        Ok(())
    }
}

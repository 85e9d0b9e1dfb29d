//! The shadow map pass: every mesh's depth from the shadow-casting light (Kang, Kim and Yoon's
//! shadow z-buffer), read by the shading and shadow passes. A mesh whose colour has an alpha
//! cutoff is drawn with its colour (`graph::mesh_stages`), so that its cut-out pixels cast no
//! shadow; the others need no fragment stage.

use crate::error::Result;
use crate::render::graph::build::depth_pass_pipeline;
use crate::render::graph::mesh_stages::MeshStages;
use crate::render::graph::target::{Access, Target, Use};
use crate::render::graph::{depth_buffer, FrameCtx, Pass, Recorder};

/// The stages of a mesh's draw into the map: drawn from the light, no target but the depth;
/// a mesh whose colour has an alpha cutoff reads its colour, to cut its pixels.
pub fn map_stages(cut: bool) -> MeshStages {
    MeshStages { albedo: cut, clip: Some("frame.shadows.to_light"), ..Default::default() }
}

#[derive(Debug, Clone, PartialEq)]
pub struct ShadowMap;

impl Pass for ShadowMap {
    fn name(&self) -> &'static str {
        "shadow_map"
    }

    fn uses(&self) -> Vec<Use> {
        vec![Use(Target::ShadowMap, Access::Attach)]
    }

    fn encode(&self, f: &FrameCtx<'_>, rec: &mut Recorder<'_>) -> Result<()> {
        let mut pass = rec.begin("shadow_map", &[], depth_buffer(f.res.view(Target::ShadowMap), true));
        f.draw_meshes(&mut pass, |d| depth_pass_pipeline(f, "shadow_map", d, map_stages, d.light_cull));
        Ok(())
    }
}

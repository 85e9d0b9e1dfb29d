//! Whether the frames of a scene form a sequence whose suggestive contours hold still
//! (`render::scene::sequence`, `edges::coherence`).

use crate::edges::outlines::LineKind;
use crate::render::scene::checked::CheckedScene;

/// Whether the frames of `scene` form a sequence: suggestive contours are drawn, with
/// coherence.
pub fn is_sequence(scene: &CheckedScene) -> bool {
    scene.scene.outlines.as_ref().is_some_and(|o| {
        o.suggestive_coherence && o.draws_mesh_lines() && o.styles[LineKind::Suggestive as usize].is_some()
    })
}

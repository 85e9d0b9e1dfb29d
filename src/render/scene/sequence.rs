//! The frames of `Renderer::render_views` as a sequence, where suggestive contours hold still
//! across them (`edges::coherence`, `Outlines::suggestive_coherence`): each frame knows the
//! cameras next to it and what each item drew in the frame before. The frames' host steps run
//! in camera order, so the frame before has always drawn when the next one asks.

use std::sync::{Arc, Mutex};

use super::camera::ResolvedCamera;
use crate::edges::coherence::Drawn;

/// One frame's place in a sequence.
#[derive(Clone, Debug)]
pub struct SequenceFrame {
    pub before: Option<ResolvedCamera>,
    pub after: Option<ResolvedCamera>,
    /// What each item (by index) drew in the frame before, replaced as this frame draws.
    pub drawn: Arc<Mutex<Vec<Drawn>>>,
}

/// Each frame's place among `cameras` (resolved for the scene), sharing what was drawn.
pub fn sequence(cameras: &[ResolvedCamera], items: usize) -> Vec<SequenceFrame> {
    let drawn = Arc::new(Mutex::new((0..items).map(|_| Drawn::default()).collect()));
    (0..cameras.len())
        .map(|k| SequenceFrame {
            before: k.checked_sub(1).map(|b| cameras[b]),
            after: cameras.get(k + 1).copied(),
            drawn: drawn.clone(),
        })
        .collect()
}

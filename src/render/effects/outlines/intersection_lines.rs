//! The `intersections` step: where the surfaces of two scene items cross (`edges::intersections`,
//! through the hierarchies kept with each mesh), as lines of the kind `intersection` of the
//! first item of each pair, chained. It runs when a scene of several items draws that kind.

use std::sync::{Arc, OnceLock};

use crate::edges::intersections::{between, chain};
use crate::edges::outlines::LineKind;
use crate::error::{Error, Result};
use crate::render::graph::effect::{HostInputs, HostStep};
use crate::render::graph::report::FrameReport;
use crate::render::uniforms::model_view;

use super::mesh_lines::{Chain, MeshLines};

/// Where the step leaves each item's intersection lines (in its stored coordinates) for the
/// `silhouettes` step.
pub type IntersectionSlot = Arc<OnceLock<Vec<Vec<Chain>>>>;

#[derive(Debug)]
pub struct Intersections {
    pub found: IntersectionSlot,
}

impl HostStep for Intersections {
    fn name(&self) -> &'static str {
        "intersections"
    }

    fn run(&self, cx: &HostInputs<'_>, _report: &mut FrameReport) -> Result<()> {
        let items = &cx.scene.scene.items;
        let lines: Vec<Arc<MeshLines>> = cx.records.iter().map(|r| MeshLines::of(r)).collect();
        let bvhs: Vec<_> = crate::parallel::install(|| {
            use rayon::prelude::*;
            lines.par_iter().zip(cx.records).map(|(l, r)| l.bvh(&r.host)).collect::<Vec<_>>()
        });
        // each item's stored coordinates -> the view's (the camera cancels out between two)
        let to_view: Vec<_> = items
            .iter()
            .zip(cx.records)
            .map(|(item, rec)| model_view(item, &rec.gpu.placement, cx.cam))
            .collect();
        let mut found: Vec<Vec<Chain>> = vec![Vec::new(); items.len()];
        for i in 0..items.len() {
            let from_view = to_view[i].inverse();
            for j in i + 1..items.len() {
                let j_to_i = from_view * to_view[j];
                let crossings = crate::parallel::install(|| between(bvhs[i], bvhs[j], Some(&j_to_i)));
                found[i].extend(chain(&crossings).into_iter().map(|points| Chain {
                    kind: LineKind::Intersection,
                    points,
                    strength: Vec::new(),
                    traced: false,
                    occlusion: None,
                }));
            }
        }
        self.found.set(found).map_err(|_| Error::Internal("intersection lines found twice in a frame".into()))
    }
}

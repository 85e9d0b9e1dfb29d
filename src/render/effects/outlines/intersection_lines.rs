//! The `intersections` step: where the surfaces of two scene items cross (`edges::intersections`,
//! through the hierarchies kept with each mesh), as lines of the kind `intersection` of the
//! first item of each pair, chained. It runs when a scene of several items draws that kind.
//! Items are kept in coordinates of their own, so a vertex two items share (a part stored as
//! pieces) is one point only to within rounding: the crossing rule's `SEAM` leaves out where
//! their triangles only meet, a border or a crease, drawn as such.

use std::sync::{Arc, OnceLock};

use crate::edges::intersections::{between, chain};
use crate::edges::outlines::LineKind;
use crate::error::{Error, Result};
use crate::render::graph::effect::{HostInputs, HostStep};
use crate::render::graph::report::FrameReport;
use crate::render::uniforms::model_matrix;

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
        let lines = MeshLines::with_hierarchies(cx.records);
        let bvhs: Vec<_> = lines.iter().zip(cx.records).map(|(l, r)| l.bvh(&r.host)).collect();
        // each item's stored coordinates -> the world's: the camera plays no part, so a still
        // scene's lines are found once (`MeshLines::crossings_with`)
        let to_world: Vec<_> =
            items.iter().zip(cx.records).map(|(item, rec)| model_matrix(item, &rec.gpu.placement)).collect();
        let mut found: Vec<Vec<Chain>> = vec![Vec::new(); items.len()];
        for i in 0..items.len() {
            let from_world = to_world[i].inverse();
            for j in i + 1..items.len() {
                if items[i].splats || items[j].splats {
                    continue;
                }
                let j_to_i = from_world * to_world[j];
                let find = || chain(&crate::parallel::install(|| between(bvhs[i], bvhs[j], Some(&j_to_i))));
                let lines = lines[i].crossings_with(&cx.records[j], &j_to_i, find);
                found[i].extend(lines.iter().map(|points| Chain {
                    kind: LineKind::Intersection,
                    points: points.clone(),
                    strength: Vec::new(),
                    traced: false,
                    occlusion: None,
                    own: None,
                }));
            }
        }
        self.found.set(found).map_err(|_| Error::Internal("intersection lines found twice in a frame".into()))
    }
}

//! The `intersections` step: where the surfaces of two scene items cross (`edges::intersections`,
//! through the hierarchies kept with each mesh), as lines of the kind `intersection` of the
//! first item of each pair, chained. It runs when a scene of several items draws that kind.
//!
//! Items are kept in coordinates of their own, so a vertex that two items share (a part stored
//! as pieces, a fold between two plates) is one point to within rounding, not to the bit: the
//! segments where two triangles only meet along an edge of each (a seam) or at a point are left
//! out here, within `SEAM` of the pair's size; a seam is a border or a crease, drawn as such.

use std::sync::{Arc, OnceLock};

use glam::DVec3;

use crate::edges::intersections::{between, chain, Crossing};
use crate::edges::outlines::LineKind;
use crate::error::{Error, Result};
use crate::render::gpu_mesh::HostMesh;
use crate::render::graph::effect::{HostInputs, HostStep};
use crate::render::graph::report::FrameReport;
use crate::render::uniforms::model_matrix;

use super::mesh_lines::{Chain, MeshLines};

/// A crossing within this fraction of its triangles' longest edge of an edge of each (or
/// this short) is where they meet, not where they cross: rounding's room, well above it.
pub const SEAM: f64 = 1e-7;

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
        // each item's stored coordinates -> the world's: the camera plays no part, so a still
        // scene's lines are found once (`MeshLines::crossings_with`)
        let to_world: Vec<_> =
            items.iter().zip(cx.records).map(|(item, rec)| model_matrix(item, &rec.gpu.placement)).collect();
        let mut found: Vec<Vec<Chain>> = vec![Vec::new(); items.len()];
        for i in 0..items.len() {
            let from_world = to_world[i].inverse();
            for j in i + 1..items.len() {
                let j_to_i = from_world * to_world[j];
                let find = || {
                    let (a, b) = (&cx.records[i].host, &cx.records[j].host);
                    let crossings: Vec<Crossing> =
                        crate::parallel::install(|| between(bvhs[i], bvhs[j], Some(&j_to_i)))
                            .into_iter()
                            .filter(|c| {
                                let tb = corners(b, c.faces[1]).map(|p| j_to_i.transform_point3(p));
                                !meets(c, &corners(a, c.faces[0]), &tb)
                            })
                            .collect();
                    chain(&crossings)
                };
                let lines = lines[i].crossings_with(&cx.records[j], &j_to_i, find);
                found[i].extend(lines.iter().map(|points| Chain {
                    kind: LineKind::Intersection,
                    points: points.clone(),
                    strength: Vec::new(),
                    traced: false,
                    occlusion: None,
                }));
            }
        }
        self.found.set(found).map_err(|_| Error::Internal("intersection lines found twice in a frame".into()))
    }
}

/// The corners of face `f` of `mesh`.
fn corners(mesh: &HostMesh, f: u32) -> [DVec3; 3] {
    mesh.faces[f as usize].map(|v| DVec3::from_array(mesh.positions[v as usize]))
}

/// Whether crossing `c` of triangles `ta` and `tb` (one frame) is where they only meet: a point,
/// or a segment along an edge of each (`SEAM`).
pub fn meets(c: &Crossing, ta: &[DVec3; 3], tb: &[DVec3; 3]) -> bool {
    let longest = |t: &[DVec3; 3]| (0..3).map(|k| t[k].distance(t[(k + 1) % 3])).fold(0.0, f64::max);
    let eps = SEAM * longest(ta).max(longest(tb));
    let [p, q] = c.ends.map(DVec3::from_array);
    let along_an_edge = |t: &[DVec3; 3]| {
        (0..3).any(|k| {
            distance_to_segment(p, t[k], t[(k + 1) % 3]) <= eps
                && distance_to_segment(q, t[k], t[(k + 1) % 3]) <= eps
        })
    };
    p.distance(q) <= eps || (along_an_edge(ta) && along_an_edge(tb))
}

fn distance_to_segment(p: DVec3, a: DVec3, b: DVec3) -> f64 {
    let ab = b - a;
    let t =
        if ab.length_squared() > 0.0 { ((p - a).dot(ab) / ab.length_squared()).clamp(0.0, 1.0) } else { 0.0 };
    p.distance(a + ab * t)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_seam_or_a_touch_is_no_crossing_and_a_pipe_through_a_plate_is() {
        let v = |x: f64, y: f64, z: f64| DVec3::new(x, y, z);
        // two plates folded along x = 0 .. 1 (y = z = 0), the second a rounding away
        let ta = [v(0.0, 0.0, 0.0), v(1.0, 0.0, 0.0), v(1.0, 1.0, 0.0)];
        let tb = [v(0.0, 1e-17, 0.0), v(0.0, 0.0, -1.0), v(1.0, 0.0, 1e-17)];
        let seam = Crossing { ends: [[0.0, 0.0, 0.0], [1.0, 0.0, 0.0]], faces: [0, 0] };
        assert!(meets(&seam, &ta, &tb));
        let point = Crossing { ends: [[0.5, 0.0, 0.0], [0.5, 1e-12 * 1e-6, 0.0]], faces: [0, 0] };
        assert!(meets(&point, &ta, &tb));
        // a triangle through the middle of another: a crossing
        let tc = [v(0.2, 0.5, -1.0), v(0.9, 0.5, -1.0), v(0.6, 0.5, 1.0)];
        let through = Crossing { ends: [[0.5, 0.5, 0.0], [0.75, 0.5, 0.0]], faces: [0, 0] };
        assert!(!meets(&through, &ta, &tc));
    }
}

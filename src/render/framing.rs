//! How far a scene's meshes reach in a direction, for a fitted camera to frame them as near as
//! they allow (`scene::camera`): over the vertices their faces use, as placed, where that is
//! affordable, else over each mesh's box and bounding sphere (which enclose it).

use std::sync::{Arc, OnceLock};

use glam::{DMat3, DVec3};
use rayon::prelude::*;

use super::mesh_record::MeshRecord;
use super::scene::camera::length_of;
use super::scene::SceneItem;

/// The most vertices one frame's framing visits (summed over the scene's placed meshes); the
/// meshes beyond it are framed by their boxes.
pub const FRAMING_BUDGET: usize = 4_000_000;

/// Vertices a thread takes at once.
const CHUNK: usize = 65_536;

/// The vertices a mesh's faces use (in stored coordinates), kept with it; None when every
/// vertex is used (the host positions are then the list).
#[derive(Default)]
struct FramePoints(OnceLock<Option<Vec<[f64; 3]>>>);

fn used_points(rec: &MeshRecord) -> Arc<FramePoints> {
    let points = rec.derived(FramePoints::default);
    points.0.get_or_init(|| {
        let host = &rec.host;
        let mut used = vec![false; host.positions.len()];
        for &i in host.faces.iter().flatten() {
            used[i as usize] = true;
        }
        if used.iter().all(|&u| u) {
            return None;
        }
        Some(host.positions.iter().zip(&used).filter(|(_, &u)| u).map(|(p, _)| *p).collect())
    });
    points
}

/// The reach of `items` (drawing `records`) along each of four directions, from `center`: the
/// largest `n . (p - center)` over their used vertices as placed; past `FRAMING_BUDGET`
/// vertices, the smaller of a mesh's box's and sphere's.
pub fn scene_support<'a>(
    items: &'a [SceneItem],
    records: &'a [Arc<MeshRecord>],
    center: DVec3,
) -> impl Fn([DVec3; 4]) -> [f64; 4] + 'a {
    let mut budget = FRAMING_BUDGET;
    let exact: Vec<Option<Arc<FramePoints>>> = records
        .iter()
        .map(|rec| {
            let n = rec.host.positions.len();
            (n <= budget).then(|| {
                budget -= n;
                used_points(rec)
            })
        })
        .collect();
    move |normals: [DVec3; 4]| {
        let mut best = [f64::NEG_INFINITY; 4];
        for ((item, rec), points) in items.iter().zip(records).zip(&exact) {
            let m = item.model_matrix();
            let (a, t) = (DMat3::from_mat4(m), m.w_axis.truncate());
            let g = &rec.gpu;
            // n . (A p + t - center) = (A^T n) . p + n . (t - center), p in the mesh's own frame
            let along = normals.map(|n| a.transpose() * n);
            let shift = normals.map(|n| n.dot(t - center));
            let reach: [f64; 4] = match points {
                Some(p) => {
                    // p = origin + scale * stored
                    let list = p.0.get().and_then(|l| l.as_deref()).unwrap_or(&rec.host.positions);
                    let origin = DVec3::from_array(g.placement.origin);
                    let reach = |chunk: &[[f64; 3]]| {
                        chunk.iter().fold([f64::NEG_INFINITY; 4], |m, s| {
                            let s = DVec3::from_array(*s);
                            std::array::from_fn(|k| m[k].max(along[k].dot(s)))
                        })
                    };
                    // in parallel only where a mesh is large enough to pay for it (many
                    // instances of a small one are many small lists)
                    let far = if list.len() <= CHUNK {
                        reach(list)
                    } else {
                        list.par_chunks(CHUNK)
                            .map(reach)
                            .reduce(|| [f64::NEG_INFINITY; 4], |a, b| std::array::from_fn(|k| a[k].max(b[k])))
                    };
                    std::array::from_fn(|k| along[k].dot(origin) + shift[k] + g.placement.scale * far[k])
                }
                None => {
                    let [lo, hi] = g.bounding_box();
                    let sphere = g.sphere();
                    std::array::from_fn(|k| {
                        let corner = DVec3::select(along[k].cmpge(DVec3::ZERO), hi, lo);
                        let round = along[k].dot(sphere.center) + sphere.radius * length_of(along[k]);
                        along[k].dot(corner).min(round) + shift[k]
                    })
                }
            };
            best = std::array::from_fn(|k| best[k].max(reach[k]));
        }
        best
    }
}

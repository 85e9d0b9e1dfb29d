//! How far a scene's meshes reach in a direction, for a fitted camera to frame them as near as
//! they allow (`scene::camera`): over the vertices their faces use, as placed, where that is
//! affordable, else over each mesh's box and bounding sphere (which enclose it).

use std::sync::{Arc, OnceLock};

use glam::{DMat3, DVec3};
use rayon::prelude::*;

use super::mesh_record::MeshRecord;
use super::scene::camera::length_of;
use super::scene::lines::LineSet;
use super::scene::up::FLAT_THICKNESS;
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

/// `support` (the meshes' reach) widened to the points of the line sets `sets` as placed (the
/// points their segments join), so that a fitted camera frames them too.
pub fn with_lines<'a>(
    support: impl Fn([DVec3; 4]) -> [f64; 4] + 'a,
    sets: &[LineSet],
    center: DVec3,
) -> impl Fn([DVec3; 4]) -> [f64; 4] + 'a {
    let points: Vec<DVec3> = sets
        .iter()
        .flat_map(|set| {
            let m = set.model_matrix();
            set.segments
                .iter()
                .flatten()
                .map(move |&i| m.transform_point3(DVec3::from_array(set.positions[i as usize])))
        })
        .collect();
    move |normals: [DVec3; 4]| {
        let meshes = support(normals);
        std::array::from_fn(|k| points.iter().fold(meshes[k], |r, p| r.max(normals[k].dot(*p - center))))
    }
}

/// A mesh's used vertices' count, sum and sum of outer products, in stored coordinates (within
/// the unit cube about its placement's origin, so the sums keep their precision), kept with it.
#[derive(Default)]
struct Moments(OnceLock<(f64, DVec3, DMat3)>);

fn moments(rec: &MeshRecord) -> Arc<Moments> {
    let moments = rec.derived(Moments::default);
    moments.0.get_or_init(|| {
        let points = used_points(rec);
        let list = points.0.get().and_then(|l| l.as_deref()).unwrap_or(&rec.host.positions);
        let add = |(n, sum, outer): (f64, DVec3, DMat3), s: &[f64; 3]| {
            let s = DVec3::from_array(*s);
            (n + 1.0, sum + s, outer + DMat3::from_cols(s * s.x, s * s.y, s * s.z))
        };
        let zero = || (0.0, DVec3::ZERO, DMat3::ZERO);
        list.par_chunks(CHUNK)
            .map(|chunk| chunk.iter().fold(zero(), add))
            .reduce(zero, |a, b| (a.0 + b.0, a.1 + b.1, a.2 + b.2))
    });
    moments
}

/// The unit normal of a flat scene (a plate, a sheet: no thicker along its least spread than
/// `FLAT_THICKNESS` of its extent across its greatest, within its plane), or None: the spreads'
/// directions are those of the covariance of the meshes' used vertices as placed (each mesh past `FRAMING_BUDGET` vertices
/// stands for its box's corners); the thickness and extent are measured by `support`.
pub fn flat_normal(
    items: &[SceneItem],
    records: &[Arc<MeshRecord>],
    center: DVec3,
    support: &dyn Fn([DVec3; 4]) -> [f64; 4],
) -> Option<DVec3> {
    let mut budget = FRAMING_BUDGET;
    let (mut n, mut sum, mut outer) = (0.0, DVec3::ZERO, DMat3::ZERO);
    for (item, rec) in items.iter().zip(records) {
        let m = item.model_matrix();
        let (a, t) = (DMat3::from_mat4(m), m.w_axis.truncate() - center);
        // p = A (origin + scale s) + t = B s + c, about the scene's centre
        let b = a * rec.gpu.placement.scale;
        let c = a * DVec3::from_array(rec.gpu.placement.origin) + t;
        let (k, s, ss) = if rec.host.positions.len() <= budget {
            budget -= rec.host.positions.len();
            *moments(rec).0.get().expect("made above")
        } else {
            // the box's corners, in stored coordinates
            let [lo, hi] = rec.gpu.bounding_box();
            let (o, scale) = (DVec3::from_array(rec.gpu.placement.origin), rec.gpu.placement.scale);
            (0..8).fold((0.0, DVec3::ZERO, DMat3::ZERO), |(k, s, ss), i| {
                let p =
                    (DVec3::select(glam::BVec3::new(i & 1 == 1, i & 2 == 2, i & 4 == 4), hi, lo) - o) / scale;
                (k + 1.0, s + p, ss + DMat3::from_cols(p * p.x, p * p.y, p * p.z))
            })
        };
        let bs = b * s;
        n += k;
        sum += bs + c * k;
        outer += b * ss * b.transpose()
            + DMat3::from_cols(bs * c.x, bs * c.y, bs * c.z)
            + DMat3::from_cols(c * bs.x, c * bs.y, c * bs.z)
            + DMat3::from_cols(c * c.x, c * c.y, c * c.z) * k;
    }
    if n < 3.0 {
        return None;
    }
    let mean = sum / n;
    let cov = outer * (1.0 / n) - DMat3::from_cols(mean * mean.x, mean * mean.y, mean * mean.z);
    let trace = cov.x_axis.x + cov.y_axis.y + cov.z_axis.z;
    if !(trace > 0.0 && trace.is_finite()) {
        return None;
    }
    // the least and the greatest spread's directions, and the one between (in the plate, across
    // a strip: a rod is no plate)
    let normal = greatest_spread(DMat3::from_diagonal(DVec3::splat(trace)) - cov)?;
    let long = greatest_spread(cov)?;
    let across = normal.cross(long - normal * normal.dot(long));
    let across = if across.length() > 1e-9 { across.normalize() } else { normal.any_orthonormal_vector() };
    let [a, b, c, d] = support([normal, -normal, across, -across]);
    let (thickness, extent) = (a + b, c + d);
    (thickness.is_finite() && extent > 0.0 && thickness <= FLAT_THICKNESS * extent).then_some(normal)
}

/// The unit direction along which the symmetric positive semi-definite `m` is greatest (its
/// greatest eigenvalue's eigenvector), by power iteration; None where it is zero or not finite.
fn greatest_spread(m: DMat3) -> Option<DVec3> {
    // from its longest column: never at right angles to the greatest eigenvector
    let mut v =
        [m.x_axis, m.y_axis, m.z_axis].into_iter().max_by(|a, b| a.length().total_cmp(&b.length()))?;
    for _ in 0..200 {
        let w = m * v;
        let len = w.length();
        if !(len > 0.0 && len.is_finite()) {
            return None;
        }
        v = w / len;
    }
    Some(v)
}

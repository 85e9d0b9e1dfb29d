//! Guidance normals (Zhang et al. 2015): for each face, the area-weighted mean normal of the
//! most consistent patch that contains it. A patch is a face with its vertex ring; candidates
//! for face i are the patches centred at i and at each face of its ring. A patch's
//! inconsistency is H = D R: D the largest |n_a - n_b| between two of its faces (see `spread`), R the largest
//! |n_a - n_b| across one of its inner edges over the sum across all of them (small when the
//! variation is spread out, as noise is, large when it is one crease through the patch).
//! A patch on one side of a crease is consistent; one across it is not, so guidance normals
//! keep creases sharp even where the noise is as strong as the feature.

use rayon::prelude::*;

use super::faces::{dist2, unit_or_zero, FaceData};
use super::rings::FaceRings;

/// Keeps R finite on a patch whose faces all agree exactly.
const EPSILON: f64 = 1e-9;

/// Per patch (one per face, centred there): its inconsistency and mean normal.
#[derive(Clone, Copy, Default)]
pub struct Patch {
    inconsistency: f64,
    mean: [f64; 3],
}

fn patch(
    rings: &FaceRings,
    data: &[FaceData],
    normals: &[[f64; 3]],
    centre: usize,
    members: &mut Vec<u32>,
) -> Patch {
    members.clear();
    members.push(centre as u32);
    members.extend_from_slice(rings.ring.row(centre));
    members.sort_unstable();
    let mut sum_n = [0.0; 3];
    for &a in members.iter() {
        let (na, w) = (normals[a as usize], data[a as usize].area);
        for c in 0..3 {
            sum_n[c] += w * na[c];
        }
    }
    let mean = unit_or_zero(sum_n);
    let largest = spread(members, normals, mean);
    let (mut edge_max, mut edge_sum) = (0.0f64, 0.0f64);
    for &a in members.iter() {
        for &b in rings.edge_ring.row(a as usize) {
            if b > a && members.binary_search(&b).is_ok() {
                let d = dist2(normals[a as usize], normals[b as usize]).sqrt();
                edge_max = edge_max.max(d);
                edge_sum += d;
            }
        }
    }
    Patch { inconsistency: largest.sqrt() * edge_max / (EPSILON + edge_sum), mean }
}

/// The largest |n_a - n_b|^2 over the patch, taken from the normal farthest from the mean
/// (exact when the normals form two clusters, as across a crease; within a factor of 4
/// otherwise): linear in the patch size, where all pairs would be quadratic, and a fan of
/// thousands of faces must not cost millions of pairs.
fn spread(members: &[u32], normals: &[[f64; 3]], mean: [f64; 3]) -> f64 {
    let far = members
        .iter()
        .map(|&a| normals[a as usize])
        .max_by(|a, b| dist2(*a, mean).total_cmp(&dist2(*b, mean)))
        .unwrap_or(mean);
    members.iter().map(|&a| dist2(normals[a as usize], far)).fold(0.0, f64::max)
}

/// `out[i]`: face i's guidance normal from the current `normals`. `patches` is scratch.
pub fn guidance(
    rings: &FaceRings,
    data: &[FaceData],
    normals: &[[f64; 3]],
    patches: &mut Vec<Patch>,
    out: &mut [[f64; 3]],
) {
    patches.resize(normals.len(), Patch::default());
    patches
        .par_iter_mut()
        .with_min_len(1024)
        .enumerate()
        .for_each_init(Vec::new, |members, (i, p)| *p = patch(rings, data, normals, i, members));
    let patches: &[Patch] = patches;
    out.par_iter_mut().with_min_len(1024).enumerate().for_each(|(i, o)| {
        let mut best = patches[i];
        for &j in rings.ring.row(i) {
            let p = patches[j as usize];
            if p.inconsistency < best.inconsistency {
                best = p;
            }
        }
        *o = if best.mean == [0.0; 3] { normals[i] } else { best.mean };
    });
}

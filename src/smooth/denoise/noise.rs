//! How noisy a mesh is, from its face normals: the 90th percentile, over pairs of faces that
//! share an edge, of |n_i - n_j|. On a part made of smooth patches and creases, most pairs lie
//! inside a patch, so this measures the noise more than the features (creases are a few
//! percent of the pairs on any but the coarsest mesh); on a clean mesh it is about the
//! dihedral angle of its tessellation. A high percentile rather than the median, so that
//! impulsive noise (a few vertices moved far, most not at all) is seen too.

use rayon::prelude::*;

use super::faces::dist2;
use super::rings::FaceRings;

/// Which fraction of the pairs is at or below the estimate.
pub const QUANTILE: f64 = 0.9;

pub fn normal_noise(rings: &FaceRings, normals: &[[f64; 3]]) -> f64 {
    let mut d: Vec<f64> = (0..normals.len())
        .into_par_iter()
        .with_min_len(4096)
        .flat_map_iter(|i| {
            rings
                .edge_ring
                .row(i)
                .iter()
                .filter(move |&&j| (j as usize) > i)
                .filter(move |&&j| normals[i] != [0.0; 3] && normals[j as usize] != [0.0; 3])
                .map(move |&j| dist2(normals[i], normals[j as usize]).sqrt())
        })
        .collect();
    if d.is_empty() {
        return 0.0;
    }
    let mid = ((d.len() - 1) as f64 * QUANTILE) as usize;
    *d.select_nth_unstable_by(mid, f64::total_cmp).1
}

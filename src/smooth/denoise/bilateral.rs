//! One pass of (joint) bilateral filtering of face normals (Zheng et al. 2011; with a guide,
//! Zhang et al. 2015): each face's normal becomes the normalised sum over its vertex ring
//! (itself included) of area x spatial weight x range weight x normal. The range weight
//! compares the normals themselves, or, in the joint filter, the guidance normals and, at a
//! smaller share, the normals themselves.

use rayon::prelude::*;

use super::faces::{dist2, unit_or_zero, FaceData};
use super::rings::Csr;

/// The Gaussian kernels' widths: `sigma_s` a length (between face centroids), `sigma_r` a
/// distance between unit normals (|n_i - n_j| = 2 sin(angle / 2)) compared in the guide;
/// `sigma_own` the same for the normals themselves in the joint filter (None: the guide alone).
#[derive(Debug, Clone, Copy)]
pub struct Kernels {
    pub sigma_s: f64,
    pub sigma_r: f64,
    pub sigma_own: Option<f64>,
}

/// `out[i]`: face i's filtered normal from `normals` over itself and `near.row(i)`, with range
/// weights from `guide` (the normals themselves when None; `k.sigma_own` is then ignored). A
/// face whose weights all vanish (degenerate faces only) keeps its normal.
pub fn filter(
    near: &Csr,
    data: &[FaceData],
    normals: &[[f64; 3]],
    guide: Option<&[[f64; 3]]>,
    k: Kernels,
    out: &mut [[f64; 3]],
) {
    let g = guide.unwrap_or(normals);
    let inv = |sigma: f64| -0.5 / (sigma * sigma);
    let (is, ir) = (inv(k.sigma_s), inv(k.sigma_r));
    let io = guide.and(k.sigma_own).map_or(0.0, inv);
    out.par_iter_mut().with_min_len(1024).enumerate().for_each(|(i, o)| {
        let (ci, gi) = (data[i].centroid, g[i]);
        let term = |j: usize| {
            let range = ir * dist2(gi, g[j]) + io * dist2(normals[i], normals[j]);
            data[j].area * (is * dist2(ci, data[j].centroid) + range).exp()
        };
        let w = term(i);
        let mut sum = normals[i].map(|c| w * c);
        for &j in near.row(i) {
            let j = j as usize;
            let w = term(j);
            for (s, n) in sum.iter_mut().zip(normals[j]) {
                *s += w * n;
            }
        }
        let n = unit_or_zero(sum);
        *o = if n == [0.0; 3] { normals[i] } else { n };
    });
}

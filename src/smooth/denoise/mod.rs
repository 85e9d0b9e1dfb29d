//! Feature-preserving smoothing by normal filtering: bilateral (Zheng et al. 2011) and guided
//! (Zhang et al. 2015). Face normals are filtered, with weights that fall off across creases,
//! and the vertices are moved to fit the filtered normals (`vertex_fit`), so flat sides are
//! flattened and the creases between them stay sharp: the bilateral filter fits once, after
//! all its passes; the guided filter after each of its later passes, as Zhang et al.'s local
//! scheme does after every pass (`options::GUIDED_NORMALS_ALONE` says why not every one).
//!
//! Positions are computed in f64 and returned in the caller's precision; pinned vertices (and
//! vertices no face uses) come back bit for bit. Every pass is parallel over faces or vertices,
//! each item computed in a fixed order, so the result does not depend on the thread count.

pub mod bilateral;
pub mod faces;
pub mod guidance;
pub mod neighbourhood;
pub mod noise;
pub mod options;
pub mod rings;
pub mod vertex_fit;

use rayon::prelude::*;

use crate::cancel::Cancel;
use crate::error::Result;
use crate::real::{Real, Vec3};
use crate::smooth::preset::Preset;
pub use options::{resolve, Args, Filter, Options};

/// `x0` smoothed as `opts` says, at a fitted scale and on the welded mesh where asked (see
/// `smooth::Run::run`, which calls it), stopping with `Error::Interrupted` at the next pass
/// after `cancel` is raised.
pub(crate) fn denoise_mesh<T: Real>(
    x0: &[Vec3<T>],
    faces: &[[u32; 3]],
    opts: &Options,
    pinned: Option<&[bool]>,
    cancel: &Cancel,
) -> Result<Vec<Vec3<T>>> {
    let rings = rings::FaceRings::new(x0.len(), faces);
    let mut x: Vec<[f64; 3]> = x0.par_iter().map(|p| p.map(|c| c.to_f64())).collect();
    let mut data = Vec::new();
    faces::face_data(&x, faces, &mut data);
    let edge = crate::mesh::edge_length::mean_edge_length(&x, faces);
    if edge.is_nan() || edge <= 0.0 {
        return Ok(x0.to_vec());
    }
    let mut normals: Vec<[f64; 3]> = data.iter().map(|d| d.normal).collect();
    let noise = noise::normal_noise(&rings, &normals);
    let kernels = bilateral::Kernels {
        sigma_s: opts.sigma_s * edge,
        sigma_r: opts.sigma_r_for(noise),
        sigma_own: opts.sigma_own_for(noise),
    };
    let mut filtered = vec![[0.0; 3]; faces.len()];
    let mut next = Vec::new();
    match opts.filter {
        Filter::Bilateral => {
            for _ in 0..opts.iterations {
                cancel.check()?;
                bilateral::filter(&rings.ring, &data, &normals, None, kernels, &mut filtered);
                std::mem::swap(&mut normals, &mut filtered);
            }
            for _ in 0..opts.vertex_iterations {
                cancel.check()?;
                vertex_fit::fit(&rings, faces, &normals, pinned, &mut data, &mut x, &mut next);
            }
        }
        Filter::Guided => {
            let mut guide = vec![[0.0; 3]; faces.len()];
            let mut scratch = guidance::Scratch::default();
            let alone = opts.passes_before_fitting();
            // The paper preset: Zhang et al.'s neighbourhood and spatial width, from the
            // distances between adjacent centroids (the width re-measured after every fit).
            let paper = opts.preset == Preset::Paper;
            let mut kernels = kernels;
            let within;
            let near = if paper {
                let d = neighbourhood::mean_centroid_distance(&rings, &data);
                kernels.sigma_s = opts.sigma_s * d;
                within = neighbourhood::within(&rings, &data, neighbourhood::PAPER_RADIUS * d);
                &within
            } else {
                &rings.ring
            };
            for pass in 0..opts.iterations {
                cancel.check()?;
                guidance::guidance(&rings, faces, &data, &normals, &mut scratch, &mut guide);
                bilateral::filter(near, &data, &normals, Some(&guide), kernels, &mut filtered);
                if pass < alone {
                    std::mem::swap(&mut normals, &mut filtered);
                    continue;
                }
                // Zhang et al.'s local scheme: fit the vertices to the filtered normals, then
                // filter the fitted mesh's own normals in the next pass.
                for _ in 0..opts.vertex_iterations {
                    cancel.check()?;
                    vertex_fit::fit(&rings, faces, &filtered, pinned, &mut data, &mut x, &mut next);
                }
                faces::face_data(&x, faces, &mut data);
                for (n, d) in normals.iter_mut().zip(&data) {
                    *n = d.normal;
                }
                if paper {
                    kernels.sigma_s = opts.sigma_s * neighbourhood::mean_centroid_distance(&rings, &data);
                }
            }
        }
    }
    // Vertices that did not move come back exactly as given.
    Ok(x.par_iter()
        .zip(x0.par_iter())
        .map(|(p, q)| if *p == q.map(|c| c.to_f64()) { *q } else { p.map(T::from_f64) })
        .collect())
}

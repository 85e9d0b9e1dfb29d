//! Moving the vertices to fit the filtered face normals (Sun et al. 2007, as used by Zheng et
//! al. and Zhang et al.): each step moves every vertex by the mean, over its faces, of its
//! offset to the face's plane through the centroid along the target normal:
//! x_i += (1/|F_i|) sum_j n_j (n_j . (c_j - x_i)).
//!
//! Guard against flipped faces: a face whose normal turns against its target normal in a step
//! (while it agreed before) has its vertices' moves undone for that step. A face that had no
//! normal before the step (zero area) is not guarded.

use rayon::prelude::*;

use super::faces::{cross, dot, FaceData};
use super::rings::FaceRings;

/// Rounds of undoing moves before a step is dropped for every vertex it would flip a face at.
const UNDO_ROUNDS: usize = 4;

pub fn fit(
    rings: &FaceRings,
    faces: &[[u32; 3]],
    target: &[[f64; 3]],
    frozen: Option<&[bool]>,
    data: &mut Vec<FaceData>,
    x: &mut Vec<[f64; 3]>,
    next: &mut Vec<[f64; 3]>,
) {
    super::faces::face_data(x, faces, data);
    next.resize(x.len(), [0.0; 3]);
    {
        let (xr, d): (&[[f64; 3]], &[FaceData]) = (x, data);
        next.par_iter_mut().with_min_len(1024).enumerate().for_each(|(i, o)| {
            let p = xr[i];
            *o = p;
            if frozen.is_some_and(|f| f[i]) {
                return;
            }
            let fs = rings.vertex_faces.row(i);
            let mut moved = [0.0; 3];
            let mut count = 0usize;
            for &j in fs {
                let n = target[j as usize];
                if n == [0.0; 3] {
                    continue;
                }
                let c = d[j as usize].centroid;
                let t = dot(n, [c[0] - p[0], c[1] - p[1], c[2] - p[2]]);
                for k in 0..3 {
                    moved[k] += n[k] * t;
                }
                count += 1;
            }
            if count > 0 {
                *o = std::array::from_fn(|k| p[k] + moved[k] / count as f64);
            }
        });
    }
    // Undo the moves at faces this step flips against their targets.
    for round in 0..=UNDO_ROUNDS {
        let flipped: Vec<u32> = (0..faces.len() as u32)
            .into_par_iter()
            .with_min_len(4096)
            .filter(|&j| {
                let (f, n, before) = (faces[j as usize], target[j as usize], data[j as usize].normal);
                // A face without a normal before the step (degenerate by the shared rule) has no
                // side to keep: its sign would be rounding.
                n != [0.0; 3]
                    && before != [0.0; 3]
                    && dot(before, n) >= 0.0
                    && dot(raw_normal(next, f), n) < 0.0
            })
            .collect();
        if flipped.is_empty() {
            break;
        }
        for &j in &flipped {
            for v in faces[j as usize] {
                next[v as usize] = x[v as usize];
            }
        }
        if round == UNDO_ROUNDS {
            // Faces still flipped: this step is dropped everywhere.
            next.copy_from_slice(x);
        }
    }
    std::mem::swap(x, next);
}

#[inline]
fn raw_normal(x: &[[f64; 3]], f: [u32; 3]) -> [f64; 3] {
    let [a, b, c] = f.map(|i| x[i as usize]);
    cross(std::array::from_fn(|k| b[k] - a[k]), std::array::from_fn(|k| c[k] - a[k]))
}

//! The geometric neighbourhood of Zhang et al. 2015's filter: for each face, the faces whose
//! centroids lie within a radius of its own, reached through faces that do (so that a face
//! across a narrow gap is not taken in), and the length their radius is a multiple of.

use rayon::prelude::*;

use super::faces::{dist2, FaceData};
use super::rings::{Csr, FaceRings};

/// The paper preset's neighbourhood radius, in mean distances between the centroids of faces
/// sharing an edge (the authors' code's default).
pub const PAPER_RADIUS: f64 = 2.0;

/// The mean distance between the centroids of faces sharing an edge (0 without such pairs),
/// summed in fixed chunks, in order, so that the result does not depend on the thread count.
pub fn mean_centroid_distance(rings: &FaceRings, data: &[FaceData]) -> f64 {
    let partial: Vec<(f64, usize)> = (0..data.len())
        .collect::<Vec<_>>()
        .par_chunks(4096)
        .map(|chunk| {
            let (mut sum, mut n) = (0.0, 0);
            for &i in chunk {
                for &j in rings.edge_ring.row(i) {
                    sum += dist2(data[i].centroid, data[j as usize].centroid).sqrt();
                    n += 1;
                }
            }
            (sum, n)
        })
        .collect();
    let (sum, n) = partial.iter().fold((0.0, 0), |(s, n), (a, b)| (s + a, n + b));
    if n == 0 {
        0.0
    } else {
        sum / n as f64
    }
}

/// Per face: the other faces whose centroid is within `radius` of its own and that are
/// reached from it through vertex rings of such faces, ascending.
pub fn within(rings: &FaceRings, data: &[FaceData], radius: f64) -> Csr {
    let n = data.len();
    let r2 = radius * radius;
    Csr::from_rows_with(
        n,
        || (vec![u32::MAX; n], Vec::new()),
        |(seen, queue): &mut (Vec<u32>, Vec<u32>), i, out| {
            let stamp = i as u32;
            seen[i] = stamp;
            queue.clear();
            queue.push(i as u32);
            let start = out.len();
            let mut head = 0;
            while head < queue.len() {
                let f = queue[head] as usize;
                head += 1;
                for &g in rings.ring.row(f) {
                    if seen[g as usize] == stamp {
                        continue;
                    }
                    seen[g as usize] = stamp;
                    if dist2(data[i].centroid, data[g as usize].centroid) <= r2 {
                        queue.push(g);
                        out.push(g);
                    }
                }
            }
            out[start..].sort_unstable();
        },
    )
}

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

#[cfg(test)]
mod tests {
    use super::*;
    use crate::smooth::denoise::faces::face_data;

    /// A strip of unit right triangles along x: faces 2k and 2k + 1 fill the square [k, k + 1].
    fn strip(squares: u32) -> (Vec<[f64; 3]>, Vec<[u32; 3]>) {
        let x = (0..=squares).flat_map(|k| [[k as f64, 0.0, 0.0], [k as f64, 1.0, 0.0]]).collect();
        let faces = (0..squares)
            .flat_map(|k| [[2 * k, 2 * k + 2, 2 * k + 3], [2 * k, 2 * k + 3, 2 * k + 1]])
            .collect();
        (x, faces)
    }

    #[test]
    fn the_radius_takes_the_faces_whose_centroids_are_near_through_near_faces() {
        let (x, faces) = strip(6);
        let rings = FaceRings::new(x.len(), &faces);
        let mut data = Vec::new();
        face_data(&x, &faces, &mut data);
        // Adjacent centroids: across a square's diagonal (sqrt(2) / 3) and between squares.
        let d = mean_centroid_distance(&rings, &data);
        assert!(d > 0.4 && d < 1.0, "{d}");
        let near = within(&rings, &data, 1.5);
        // Face 6 (square 3, centroid (3.67, 0.33)) takes the faces of squares 2-4 within 1.5,
        // not those of square 5 (1.7 and 2.0 away) that square 4's faces touch, nor itself.
        let row = near.row(6);
        assert!([4, 7, 8, 9].iter().all(|f| row.contains(f)), "{row:?}");
        assert!([1, 6, 10, 11].iter().all(|f| !row.contains(f)), "{row:?}");
        assert!(row.windows(2).all(|w| w[0] < w[1]));
        assert_eq!(within(&rings, &data, 0.0).row(6), &[] as &[u32]);
    }
}

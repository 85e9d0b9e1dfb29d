//! The mean length of a mesh's edges: the unit that scale-free defaults (kernel widths, stripe
//! periods) are measured in.

use rayon::prelude::*;

use crate::real::{norm, sub};

/// The mean length of the faces' edges (each face counts its three; 0 without faces), summed in
/// fixed chunks, in order, so that the result does not depend on how the work was split between
/// threads.
pub fn mean_edge_length(x: &[[f64; 3]], faces: &[[u32; 3]]) -> f64 {
    let partial: Vec<f64> = faces
        .par_chunks(4096)
        .map(|chunk| {
            chunk
                .iter()
                .map(|f| {
                    let [a, b, c] = f.map(|i| x[i as usize]);
                    (norm(sub(a, b)) + norm(sub(b, c)) + norm(sub(c, a))) / 3.0
                })
                .sum::<f64>()
        })
        .collect();
    partial.iter().sum::<f64>() / faces.len().max(1) as f64
}

//! CPU reference of the image-space edge pass: `edges::detect`'s rule on the read-back normal and
//! depth buffers, which is what the GPU pass computes from the same values.

use crate::edges::detect::paper_gradient;
use crate::error::Result;

/// The edge mask of (H, W, 3) normals and (H, W) depths with the given thresholds.
pub fn edge_mask(
    normal: &[f32],
    depth: &[f32],
    height: usize,
    width: usize,
    thresholds: (f32, f32),
) -> Result<Vec<bool>> {
    let gn = paper_gradient(normal, height, width, 3)?;
    let gd = paper_gradient(depth, height, width, 1)?;
    Ok(gn.iter().zip(&gd).map(|(n, d)| *n > thresholds.0 || *d > thresholds.1).collect())
}

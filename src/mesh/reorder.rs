//! A spatial vertex order for cache locality.
//!
//! Iterating over a mesh gathers each vertex's neighbours; when neighbours are scattered in
//! memory (a scan written in acquisition order, a shuffled mesh) every gather misses the cache.
//! Sorting vertices along a Morton (Z-order) curve makes neighbours close in memory. The order
//! is computed from positions only, so it is the same for any thread count, and results are
//! mapped back to the caller's order.

use rayon::prelude::*;

use crate::error::Result;
use crate::mesh::Bounds;
use crate::real::{Real, Vec3};

/// Below this many vertices the mesh fits in cache and reordering does not pay.
pub const MIN_VERTICES: usize = 32_768;

/// Faces per sampled window, and vertices per block, in `is_scattered`.
const WINDOW: usize = 64;
const BLOCK_SHIFT: u32 = 6;
const WINDOWS: usize = 64;
/// Above this share of distinct blocks per window, neighbours are scattered in memory.
const SCATTERED: f64 = 0.12;

/// Does the vertex order scatter neighbours across memory? Counts, in a few windows of
/// consecutive faces, how many distinct blocks of 64 vertices their corners touch. A mesh
/// written in a local order (subdivision, a grid, most exporters) touches a few blocks per
/// window, which the cache serves well even when individual indices are far apart; a shuffled
/// or acquisition-ordered mesh touches nearly one block per corner. Costs microseconds.
pub fn is_scattered(faces: &[[u32; 3]]) -> bool {
    let windows = (faces.len() / WINDOW).min(WINDOWS);
    if windows == 0 {
        return false;
    }
    let stride = faces.len() / windows;
    let mut blocks = [0u32; 3 * WINDOW];
    let mut distinct = 0usize;
    for w in 0..windows {
        for (k, f) in faces[w * stride..w * stride + WINDOW].iter().enumerate() {
            for j in 0..3 {
                blocks[3 * k + j] = f[j] >> BLOCK_SHIFT;
            }
        }
        blocks.sort_unstable();
        distinct += 1 + blocks.windows(2).filter(|p| p[0] != p[1]).count();
    }
    distinct as f64 / (windows * 3 * WINDOW) as f64 > SCATTERED
}

pub struct Reordering {
    /// new index -> old index
    order: Vec<u32>,
    /// old index -> new index
    inverse: Vec<u32>,
}

/// Spreads the low 21 bits of `v` to every third bit.
fn spread(v: u64) -> u64 {
    let mut x = v & 0x1f_ffff;
    x = (x | (x << 32)) & 0x1f_0000_0000_ffff;
    x = (x | (x << 16)) & 0x1f_0000_ff00_00ff;
    x = (x | (x << 8)) & 0x100f_00f0_0f00_f00f;
    x = (x | (x << 4)) & 0x10c3_0c30_c30c_30c3;
    x = (x | (x << 2)) & 0x1249_2492_4924_9249;
    x
}

impl Reordering {
    pub fn spatial<T: Real>(x: &[Vec3<T>]) -> Reordering {
        let b = Bounds::of(x);
        let extent = (0..3).map(|k| b.max[k] - b.min[k]).fold(0.0f64, f64::max);
        let scale = if extent > 0.0 { ((1u64 << 21) - 1) as f64 / extent } else { 0.0 };
        let mut keyed: Vec<(u64, u32)> = x
            .par_iter()
            .enumerate()
            .map(|(i, p)| {
                let q = |k: usize| ((p[k].to_f64() - b.min[k]) * scale) as u64;
                (spread(q(0)) | (spread(q(1)) << 1) | (spread(q(2)) << 2), i as u32)
            })
            .collect();
        // Ties keep index order, so the permutation is fully determined.
        keyed.par_sort_unstable();
        let order: Vec<u32> = keyed.into_iter().map(|(_, i)| i).collect();
        let mut inverse = vec![0u32; order.len()];
        for (new, &old) in order.iter().enumerate() {
            inverse[old as usize] = new as u32;
        }
        Reordering { order, inverse }
    }

    /// New index -> old index.
    pub fn order(&self) -> &[u32] {
        &self.order
    }

    pub fn positions<T: Real>(&self, x: &[Vec3<T>]) -> Vec<Vec3<T>> {
        self.order.par_iter().map(|&o| x[o as usize]).collect()
    }

    pub fn mask(&self, m: &[bool]) -> Vec<bool> {
        self.order.par_iter().map(|&o| m[o as usize]).collect()
    }

    /// Faces with new indices, in their original order (sorting them as well was measured to
    /// cost more than it saved).
    pub fn faces(&self, faces: &[[u32; 3]]) -> Vec<[u32; 3]> {
        faces.par_iter().map(|f| f.map(|i| self.inverse[i as usize])).collect()
    }

    /// Puts per-vertex results back in the caller's order.
    pub fn restore<T: Copy + Send + Sync>(&self, y: Vec<T>) -> Vec<T> {
        self.inverse.par_iter().map(|&n| y[n as usize]).collect()
    }
}

/// New positions from `work` on the mesh in the vertex order that suits it best: spatial when
/// the mesh is large and its neighbours scattered, given back in the caller's order; as it is
/// otherwise.
pub fn on_best_order<T: Real>(
    x0: &[Vec3<T>],
    faces: &[[u32; 3]],
    pinned: Option<&[bool]>,
    work: impl FnOnce(&[Vec3<T>], &[[u32; 3]], Option<&[bool]>) -> Result<Vec<Vec3<T>>>,
) -> Result<Vec<Vec3<T>>> {
    if x0.len() < MIN_VERTICES || !is_scattered(faces) {
        return work(x0, faces, pinned);
    }
    let r = Reordering::spatial(x0);
    let pinned = pinned.map(|p| r.mask(p));
    Ok(r.restore(work(&r.positions(x0), &r.faces(faces), pinned.as_deref())?))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn subdivision_order_is_local_and_a_shuffle_is_not() {
        let (v, f) = crate::mesh::shapes::icosphere(6, 0.0, 0).unwrap();
        assert!(!is_scattered(&f));
        let mut rng = crate::mesh::shapes::SplitMix64::new(9);
        let mut perm: Vec<u32> = (0..v.len() as u32).collect();
        for i in (1..perm.len()).rev() {
            perm.swap(i, (rng.next_u64() % (i as u64 + 1)) as usize);
        }
        let shuffled: Vec<[u32; 3]> = f.iter().map(|t| t.map(|i| perm[i as usize])).collect();
        assert!(is_scattered(&shuffled));
        // Sorting along the curve makes the shuffled mesh local again.
        let mut vs = v.clone();
        for (old, &new) in perm.iter().enumerate() {
            vs[new as usize] = v[old];
        }
        let r = Reordering::spatial(&vs);
        assert!(!is_scattered(&r.faces(&shuffled)));
    }

    #[test]
    fn round_trips() {
        let (v, f) = crate::mesh::shapes::icosphere(2, 0.0, 0).unwrap();
        let r = Reordering::spatial(&v);
        let v2 = r.positions(&v);
        assert_eq!(r.restore(v2.clone()), v);
        let f2 = r.faces(&f);
        let mut a: Vec<[[u64; 3]; 3]> =
            f.iter().map(|t| t.map(|i| v[i as usize].map(f64::to_bits))).collect();
        let mut b: Vec<[[u64; 3]; 3]> =
            f2.iter().map(|t| t.map(|i| v2[i as usize].map(f64::to_bits))).collect();
        a.sort();
        b.sort();
        assert_eq!(a, b);
    }
}

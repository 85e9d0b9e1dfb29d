//! Procedural meshes for tests, benchmarks and demos, so nothing large has to be stored.

use std::collections::HashMap;

use crate::error::{Error, Result};

/// A small, fast, seedable generator (SplitMix64): the same numbers on every platform.
pub struct SplitMix64(u64);

/// `count` faces of seeded random corners among `n_vertices` vertices: a messy mesh (repeated
/// corners, non-manifold edges) for tests to check against a brute-force answer.
#[cfg(test)]
pub fn random_faces(seed: u64, n_vertices: usize, count: usize) -> Vec<[u32; 3]> {
    let mut rng = SplitMix64::new(seed);
    (0..count).map(|_| [0, 1, 2].map(|_| (rng.next_u64() % n_vertices as u64) as u32)).collect()
}

impl SplitMix64 {
    pub fn new(seed: u64) -> Self {
        SplitMix64(seed)
    }
    pub fn next_u64(&mut self) -> u64 {
        self.0 = self.0.wrapping_add(0x9E37_79B9_7F4A_7C15);
        let mut z = self.0;
        z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
        z ^ (z >> 31)
    }
    /// Uniform in [-1, 1).
    pub fn symmetric(&mut self) -> f64 {
        (self.next_u64() >> 11) as f64 / (1u64 << 53) as f64 * 2.0 - 1.0
    }
}

pub type Shape = (Vec<[f64; 3]>, Vec<[u32; 3]>);

/// A unit icosphere: `subdivisions` rounds of 1-to-4 splitting of an icosahedron, giving
/// 10 * 4^s + 2 vertices. Each vertex is then moved along its radius by `noise` times a seeded
/// uniform number in [-1, 1).
pub fn icosphere(subdivisions: i64, noise: f64, seed: u64) -> Result<Shape> {
    if !(0..=10).contains(&subdivisions) {
        return Err(Error::invalid("subdivisions", format!("must be in [0, 10], got {subdivisions}")));
    }
    if !noise.is_finite() || noise < 0.0 {
        return Err(Error::invalid("noise", format!("must be finite and >= 0, got {noise}")));
    }
    let t = (1.0 + 5f64.sqrt()) / 2.0;
    let mut v: Vec<[f64; 3]> = vec![
        [-1.0, t, 0.0],
        [1.0, t, 0.0],
        [-1.0, -t, 0.0],
        [1.0, -t, 0.0],
        [0.0, -1.0, t],
        [0.0, 1.0, t],
        [0.0, -1.0, -t],
        [0.0, 1.0, -t],
        [t, 0.0, -1.0],
        [t, 0.0, 1.0],
        [-t, 0.0, -1.0],
        [-t, 0.0, 1.0],
    ];
    let mut f: Vec<[u32; 3]> = vec![
        [0, 11, 5],
        [0, 5, 1],
        [0, 1, 7],
        [0, 7, 10],
        [0, 10, 11],
        [1, 5, 9],
        [5, 11, 4],
        [11, 10, 2],
        [10, 7, 6],
        [7, 1, 8],
        [3, 9, 4],
        [3, 4, 2],
        [3, 2, 6],
        [3, 6, 8],
        [3, 8, 9],
        [4, 9, 5],
        [2, 4, 11],
        [6, 2, 10],
        [8, 6, 7],
        [9, 8, 1],
    ];
    for p in v.iter_mut() {
        *p = normalized(*p);
    }
    for _ in 0..subdivisions {
        let mut mid: HashMap<(u32, u32), u32> = HashMap::with_capacity(f.len() * 3 / 2);
        let mut next = Vec::with_capacity(f.len() * 4);
        for tri in &f {
            let mut m = [0u32; 3];
            for j in 0..3 {
                let (a, b) = (tri[j], tri[(j + 1) % 3]);
                let key = (a.min(b), a.max(b));
                m[j] = *mid.entry(key).or_insert_with(|| {
                    let (pa, pb) = (v[a as usize], v[b as usize]);
                    v.push(normalized([pa[0] + pb[0], pa[1] + pb[1], pa[2] + pb[2]]));
                    (v.len() - 1) as u32
                });
            }
            next.push([tri[0], m[0], m[2]]);
            next.push([tri[1], m[1], m[0]]);
            next.push([tri[2], m[2], m[1]]);
            next.push([m[0], m[1], m[2]]);
        }
        f = next;
    }
    if noise > 0.0 {
        let mut rng = SplitMix64::new(seed);
        for p in v.iter_mut() {
            let r = 1.0 + noise * rng.symmetric();
            *p = [p[0] * r, p[1] * r, p[2] * r];
        }
    }
    Ok((v, f))
}

/// An open, flat `n` x `n` grid of vertices on [0, 1]^2 (z = 0), two triangles per cell,
/// with seeded noise of amplitude `noise` added to z.
pub fn grid(n: i64, noise: f64, seed: u64) -> Result<Shape> {
    if !(2..=4096).contains(&n) {
        return Err(Error::invalid("n", format!("must be in [2, 4096], got {n}")));
    }
    let n = n as u32;
    if !noise.is_finite() || noise < 0.0 {
        return Err(Error::invalid("noise", format!("must be finite and >= 0, got {noise}")));
    }
    let mut rng = SplitMix64::new(seed);
    let step = 1.0 / (n - 1) as f64;
    let mut v = Vec::with_capacity((n * n) as usize);
    for r in 0..n {
        for c in 0..n {
            let z = if noise > 0.0 { noise * rng.symmetric() } else { 0.0 };
            v.push([c as f64 * step, r as f64 * step, z]);
        }
    }
    let mut f = Vec::with_capacity(2 * ((n - 1) * (n - 1)) as usize);
    for r in 0..n - 1 {
        for c in 0..n - 1 {
            let i = r * n + c;
            f.push([i, i + 1, i + n + 1]);
            f.push([i, i + n + 1, i + n]);
        }
    }
    Ok((v, f))
}

fn normalized(p: [f64; 3]) -> [f64; 3] {
    let l = (p[0] * p[0] + p[1] * p[1] + p[2] * p[2]).sqrt();
    [p[0] / l, p[1] / l, p[2] / l]
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn icosphere_counts() {
        let (v, f) = icosphere(2, 0.0, 0).unwrap();
        assert_eq!(v.len(), 162);
        assert_eq!(f.len(), 320);
        let (v2, _) = icosphere(2, 0.01, 7).unwrap();
        let (v3, _) = icosphere(2, 0.01, 7).unwrap();
        assert_eq!(v2, v3);
        assert!(v2
            .iter()
            .all(|p| ((p[0] * p[0] + p[1] * p[1] + p[2] * p[2]).sqrt() - 1.0).abs() <= 0.01 + 1e-12));
    }

    #[test]
    fn grid_counts() {
        let (v, f) = grid(3, 0.0, 0).unwrap();
        assert_eq!((v.len(), f.len()), (9, 8));
    }
}

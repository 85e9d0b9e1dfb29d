//! Averages of per-vertex fields over a patch of surface around each vertex, weighted by a
//! bell of width `sigma` in distance: what "the curvature at a feature size" means on a scan,
//! where the one-ring estimate follows the scanner's noise.
//!
//! A vertex's patch is grown from it along the mesh's edges while the bell is not zero (up to
//! 2.5 sigma away in space) and the vertex normals agree (n . n' > 0), so a thin part's other
//! side is not mixed in. A neighbour's weight is the bell times its Voronoi area times n . n'
//! (Rusinkiewicz's trimesh2 filters the same way). The bell is (1 - d^2 / (6.25 sigma^2))^2:
//! within a few percent of a Gaussian of width sigma near the centre, and exactly zero at its
//! edge, so a patch is finite.

use glam::DVec3;
use rayon::prelude::*;

use crate::cancel::Cancel;
use crate::error::Result;
use crate::mesh::buckets::{Buckets, RingCorner};

/// How far the bell reaches, in widths: its weight is zero from 2.5 sigma on.
const REACH: f64 = 2.5;

/// The patches of a mesh for a width `sigma`: what `average` needs.
pub struct Patches<'a> {
    pub positions: &'a [DVec3],
    pub normals: &'a [DVec3],
    /// Each vertex's Voronoi area.
    pub areas: &'a [f64],
    pub ring: &'a Buckets<RingCorner>,
    pub sigma: f64,
}

impl Patches<'_> {
    fn bell(&self, d2: f64) -> f64 {
        let x = d2 / (REACH * REACH * self.sigma * self.sigma);
        if x < 1.0 {
            (1.0 - x) * (1.0 - x)
        } else {
            0.0
        }
    }

    /// Each vertex's weighted mean of `of(at, from)`: the field of vertex `from` expressed where
    /// it is read, at vertex `at` (a tensor turned into `at`'s frame, say). A vertex with no
    /// weight about it (no area) keeps its own value.
    pub fn average<const K: usize>(
        &self,
        of: impl Fn(usize, usize) -> [f64; K] + Sync,
        cancel: &Cancel,
    ) -> Result<Vec<[f64; K]>> {
        let n = self.positions.len();
        let out: Vec<[f64; K]> = (0..n)
            .into_par_iter()
            .map_init(
                || (vec![u32::MAX; n], Vec::new()),
                |(seen, stack), v| {
                    if v % 4096 == 0 && cancel.is_requested() {
                        return [0.0; K];
                    }
                    self.average_at(v, &of, seen, stack)
                },
            )
            .collect();
        cancel.check()?;
        Ok(out)
    }

    fn average_at<const K: usize>(
        &self,
        v: usize,
        of: &impl Fn(usize, usize) -> [f64; K],
        seen: &mut [u32],
        stack: &mut Vec<u32>,
    ) -> [f64; K] {
        let (p, nv) = (self.positions[v], self.normals[v]);
        let mut sum = [0.0; K];
        let mut weight = 0.0;
        // `seen` holds, per vertex, the last patch that reached it: no clearing between patches
        seen[v] = v as u32;
        stack.clear();
        stack.push(v as u32);
        while let Some(u) = stack.pop() {
            let u = u as usize;
            let agree = nv.dot(self.normals[u]);
            let w = self.bell(p.distance_squared(self.positions[u])) * agree.max(0.0);
            if !(w > 0.0) {
                continue;
            }
            let w = w * self.areas[u];
            if w > 0.0 {
                let x = of(v, u);
                (0..K).for_each(|i| sum[i] += w * x[i]);
                weight += w;
            }
            for &[next, prev, _] in self.ring.at(u) {
                for q in [next, prev] {
                    if seen[q as usize] != v as u32 {
                        seen[q as usize] = v as u32;
                        stack.push(q);
                    }
                }
            }
        }
        if weight > 0.0 && sum.iter().all(|x| x.is_finite()) {
            sum.map(|x| x / weight)
        } else {
            of(v, v)
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A flat grid of unit squares, n x n vertices, normals up, unit areas.
    fn grid(n: u32) -> (Vec<DVec3>, Vec<[u32; 3]>) {
        let positions = (0..n * n).map(|i| DVec3::new((i % n) as f64, (i / n) as f64, 0.0)).collect();
        let mut faces = Vec::new();
        for y in 0..n - 1 {
            for x in 0..n - 1 {
                let a = y * n + x;
                faces.push([a, a + 1, a + n + 1]);
                faces.push([a, a + n + 1, a + n]);
            }
        }
        (positions, faces)
    }

    #[test]
    fn a_linear_field_is_kept_inside_and_a_spike_spreads() {
        let (positions, faces) = grid(21);
        let normals = vec![DVec3::Z; positions.len()];
        let areas = vec![1.0; positions.len()];
        let ring = Buckets::<RingCorner>::corners_with_ids(positions.len(), &faces).unwrap();
        let patches =
            Patches { positions: &positions, normals: &normals, areas: &areas, ring: &ring, sigma: 1.5 };
        // a symmetric patch keeps a linear field at its centre
        let linear = patches.average(|_, u| [positions[u].x], Cancel::never()).unwrap();
        let centre = 10 * 21 + 10;
        assert!((linear[centre][0] - 10.0).abs() < 1e-12);
        // a spike: its vertex keeps a share, its neighbours get some, far ones none
        let spike = patches.average(|_, u| [(u == centre) as u8 as f64], Cancel::never()).unwrap();
        assert!(spike[centre][0] > 0.0 && spike[centre][0] < 0.5);
        assert!(spike[centre + 1][0] > 0.0 && spike[centre + 1][0] < spike[centre][0]);
        assert_eq!(spike[centre + 4][0], 0.0); // 4 > 2.5 sigma away
                                               // normals that disagree cut a vertex out of the patch
        let mut flipped = normals.clone();
        flipped[centre + 1] = -DVec3::Z;
        let cut = Patches { normals: &flipped, ..patches };
        let spike = cut.average(|_, u| [(u == centre + 1) as u8 as f64], Cancel::never()).unwrap();
        assert_eq!(spike[centre][0], 0.0);
    }
}

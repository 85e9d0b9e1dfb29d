//! Operators that reproduce trimesh's `laplacian_calculation`, quirks included.
//!
//! Uniform: neighbours come from the directed half-edges f0->f1, f1->f2, f2->f0; row i has
//! 1/d_i for each distinct target, where d_i counts i's outgoing half-edges with duplicates.
//! Rows sum below one where half-edges repeat, and unreferenced vertices get an empty row,
//! so such vertices drift toward the origin exactly as they do in trimesh. On a mesh whose fans
//! are all closed and consistently oriented, that is the plain neighbour mean.
//! Distance (`equal_weight=False`): distinct undirected neighbours, w = 1/max(1e-6, |xi - xj|)
//! from the initial positions, normalised per row. Pinned rows are the identity.

use super::operator::Operator;
use crate::mesh::Adjacency;
use crate::real::{self, Real, Vec3};

pub fn uniform(adj: &Adjacency, faces: &[[u32; 3]], pinned: Option<&[bool]>) -> Operator {
    let n = adj.n_vertices();
    if adj.all_fans_closed {
        // Outgoing half-edges reach each neighbour once: the plain neighbour mean.
        return Operator::Uniform { frozen: pinned.map_or_else(|| vec![false; n], <[bool]>::to_vec) };
    }
    let mut outgoing = vec![0u32; n];
    let mut targets: Vec<Vec<u32>> = vec![Vec::new(); n];
    for f in faces {
        for j in 0..3 {
            let (a, b) = (f[j] as usize, f[(j + 1) % 3]);
            outgoing[a] += 1;
            targets[a].push(b);
        }
    }
    Operator::from_rows(adj, pinned, |i, row| {
        if outgoing[i] == 0 {
            return 0.0; // an empty row: the vertex drifts toward the origin, as in trimesh
        }
        let inv = 1.0 / outgoing[i] as f64;
        let t = &mut targets[i];
        t.sort_unstable();
        t.dedup();
        let nbrs = adj.neighbours(i);
        let mut own = 0.0;
        for &b in t.iter() {
            if b as usize == i {
                own = inv;
            } else {
                row[nbrs.binary_search(&b).expect("every half-edge target is a neighbour")] = inv;
            }
        }
        own
    })
}

/// trimesh's floor on an edge length for inverse-distance weights, in the mesh's units.
pub const DISTANCE_FLOOR: f64 = 1e-6;

/// Inverse-distance rows; `floor` is `DISTANCE_FLOOR` at the scale `x` is given in.
pub fn distance<T: Real>(adj: &Adjacency, x: &[Vec3<T>], pinned: Option<&[bool]>, floor: f64) -> Operator {
    Operator::from_rows(adj, pinned, |i, row| {
        let xi = real::to_f64(x[i]);
        for (r, &j) in row.iter_mut().zip(adj.neighbours(i)) {
            *r = 1.0 / real::norm(real::sub(xi, real::to_f64(x[j as usize]))).max(floor);
        }
        let total: f64 = row.iter().sum();
        row.iter_mut().for_each(|r| *r /= total);
        0.0
    })
}

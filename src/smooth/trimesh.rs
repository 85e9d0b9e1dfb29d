//! Operators that reproduce trimesh's `laplacian_calculation`, quirks included.
//!
//! Uniform: neighbours come from the directed half-edges f0->f1, f1->f2, f2->f0; row i has
//! 1/d_i for each distinct target, where d_i counts i's outgoing half-edges with duplicates.
//! Rows sum below one where half-edges repeat, and unreferenced vertices get an empty row,
//! so such vertices drift toward the origin exactly as they do in trimesh.
//! Distance (`equal_weight=False`): distinct undirected neighbours, w = 1/max(1e-6, |xi - xj|)
//! from the initial positions, normalised per row. Pinned rows are the identity.

use super::operator::Operator;
use crate::mesh::Adjacency;
use crate::real::{self, Real, Vec3};

pub fn uniform(adj: &Adjacency, faces: &[[u32; 3]], pinned: Option<&[bool]>) -> Operator {
    let n = adj.n_vertices();
    let mut outgoing = vec![0u32; n];
    let mut targets: Vec<Vec<u32>> = vec![Vec::new(); n];
    for f in faces {
        for j in 0..3 {
            let (a, b) = (f[j] as usize, f[(j + 1) % 3]);
            outgoing[a] += 1;
            targets[a].push(b);
        }
    }
    let mut self_w = vec![0.0; n];
    let mut w = vec![0.0; adj.nbrs.len()];
    for i in 0..n {
        if pinned.is_some_and(|p| p[i]) {
            self_w[i] = 1.0;
            continue;
        }
        if outgoing[i] == 0 {
            continue;
        }
        let inv = 1.0 / outgoing[i] as f64;
        let t = &mut targets[i];
        t.sort_unstable();
        t.dedup();
        let slots = adj.slots(i);
        for &b in t.iter() {
            if b as usize == i {
                self_w[i] = inv;
            } else {
                let k =
                    adj.nbrs[slots.clone()].binary_search(&b).expect("every half-edge target is a neighbour");
                w[slots.start + k] = inv;
            }
        }
    }
    Operator::Weighted { self_w, w }
}

pub fn distance<T: Real>(adj: &Adjacency, x: &[Vec3<T>], pinned: Option<&[bool]>) -> Operator {
    let n = adj.n_vertices();
    let mut self_w = vec![0.0; n];
    let mut w = vec![0.0; adj.nbrs.len()];
    for i in 0..n {
        if pinned.is_some_and(|p| p[i]) {
            self_w[i] = 1.0;
            continue;
        }
        let xi = real::to_f64(x[i]);
        let slots = adj.slots(i);
        let mut total = 0.0;
        for s in slots.clone() {
            let d = real::norm(real::sub(xi, real::to_f64(x[adj.nbrs[s] as usize])));
            w[s] = 1.0 / d.max(1e-6);
            total += w[s];
        }
        for s in slots {
            w[s] /= total;
        }
    }
    Operator::Weighted { self_w, w }
}

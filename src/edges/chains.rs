//! Edges chained into polylines, for plotting and export.
//!
//! A chain runs between vertices whose degree (in the given edge set) is not 2 (ends and
//! junctions), passing through degree-2 vertices. Chains are started from those vertices in
//! ascending index order, taking their edges in the given order; what is left are closed loops,
//! each started at the first unused edge in the given order, from its first vertex, and closed
//! by repeating that vertex at the end. Every edge is used exactly once.

use crate::error::{Error, Result};

/// Edges given as pairs of vertex indices (the argument `arg`), each index checked to be a
/// vertex index (in [0, 2^32 - 1)).
pub fn vertex_pairs(arg: &str, rows: impl IntoIterator<Item = [i64; 2]>) -> Result<Vec<[u32; 2]>> {
    let valid = |i: i64| (0..u32::MAX as i64).contains(&i);
    rows.into_iter()
        .enumerate()
        .map(|(k, [a, b])| match valid(a) && valid(b) {
            true => Ok([a as u32, b as u32]),
            false => {
                Err(Error::out_of_range(arg, format!("edge {k} has an invalid vertex index ({a}, {b})")))
            }
        })
        .collect()
}

/// Polylines as one flat index list and the offsets where each polyline starts (CSR).
pub fn chain_edges(edges: &[[u32; 2]]) -> (Vec<u32>, Vec<u32>) {
    let n = edges.iter().map(|e| e[0].max(e[1]) as usize + 1).max().unwrap_or(0);
    let mut start = vec![0u32; n + 1];
    for e in edges {
        start[e[0] as usize + 1] += 1;
        start[e[1] as usize + 1] += 1;
    }
    for i in 0..n {
        start[i + 1] += start[i];
    }
    let mut incident = vec![0u32; start[n] as usize];
    let mut cursor = start.clone();
    for (k, e) in edges.iter().enumerate() {
        for &v in e {
            incident[cursor[v as usize] as usize] = k as u32;
            cursor[v as usize] += 1;
        }
    }
    let degree = |v: u32| start[v as usize + 1] - start[v as usize];
    let mut used = vec![false; edges.len()];
    let mut flat = Vec::with_capacity(edges.len() * 2);
    let mut offsets = vec![0u32];

    let walk = |first: u32, e0: usize, used: &mut Vec<bool>, flat: &mut Vec<u32>| {
        let (mut v, mut e) = (first, e0);
        flat.push(v);
        loop {
            used[e] = true;
            let [a, b] = edges[e];
            v = if a == v { b } else { a };
            flat.push(v);
            if degree(v) != 2 {
                break;
            }
            let next = incident[start[v as usize] as usize..start[v as usize + 1] as usize]
                .iter()
                .map(|&k| k as usize)
                .find(|&k| !used[k]);
            match next {
                Some(k) => e = k,
                None => break,
            }
        }
    };

    for v in 0..n as u32 {
        if degree(v) == 2 || degree(v) == 0 {
            continue;
        }
        for slot in start[v as usize]..start[v as usize + 1] {
            let e = incident[slot as usize] as usize;
            if !used[e] {
                walk(v, e, &mut used, &mut flat);
                offsets.push(flat.len() as u32);
            }
        }
    }
    for e in 0..edges.len() {
        if !used[e] {
            walk(edges[e][0], e, &mut used, &mut flat);
            offsets.push(flat.len() as u32);
        }
    }
    (flat, offsets)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn split(edges: &[[u32; 2]]) -> Vec<Vec<u32>> {
        let (flat, off) = chain_edges(edges);
        off.windows(2).map(|w| flat[w[0] as usize..w[1] as usize].to_vec()).collect()
    }

    #[test]
    fn open_path_loop_and_junction() {
        assert_eq!(split(&[[0, 1], [1, 2], [2, 3]]), vec![vec![0, 1, 2, 3]]);
        assert_eq!(split(&[[4, 5], [5, 6], [4, 6]]), vec![vec![4, 5, 6, 4]]);
        // a T junction at 1: three chains
        assert_eq!(split(&[[0, 1], [1, 2], [1, 3]]), vec![vec![0, 1], vec![1, 2], vec![1, 3]]);
        assert!(split(&[]).is_empty());
    }
}

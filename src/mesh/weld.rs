//! Merging vertices at identical positions, so that UV seams and split normals (the same point
//! stored twice) do not show up as boundaries.

use rayon::prelude::*;

use crate::real::{Real, Vec3};

/// For every vertex, the smallest index of a vertex at exactly the same position (-0.0 and
/// 0.0 count as equal). Exact comparison keeps the result free of any tolerance and of the
/// grid-cell effects of rounding-based welds.
pub fn weld_map<T: Real>(positions: &[Vec3<T>]) -> Vec<u32> {
    let key = |i: u32| {
        let p = positions[i as usize];
        // Adding 0.0 turns -0.0 into 0.0.
        [(p[0].to_f64() + 0.0).to_bits(), (p[1].to_f64() + 0.0).to_bits(), (p[2].to_f64() + 0.0).to_bits()]
    };
    let mut order: Vec<u32> = (0..positions.len() as u32).collect();
    order.par_sort_unstable_by_key(|&i| (key(i), i));
    let mut map = vec![0u32; positions.len()];
    let mut k = 0;
    while k < order.len() {
        let rep = order[k];
        let mut e = k;
        while e < order.len() && key(order[e]) == key(rep) {
            map[order[e] as usize] = rep;
            e += 1;
        }
        k = e;
    }
    map
}

/// Faces with every index replaced by its representative.
pub fn weld_faces(faces: &[[u32; 3]], map: &[u32]) -> Vec<[u32; 3]> {
    faces.par_iter().map(|f| f.map(|i| map[i as usize])).collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn merges_exact_duplicates_to_smallest_index() {
        let v = vec![[1.0, 0.0, 0.0], [0.0, 0.0, 0.0], [1.0, -0.0, 0.0], [0.0, 0.0, 1e-300]];
        assert_eq!(weld_map(&v), vec![0, 1, 0, 3]);
    }
}

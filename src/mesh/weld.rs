//! Merging vertices at identical positions, so that UV seams and split normals (the same point
//! stored twice) do not show up as boundaries: outlines use the merged faces in the original
//! indices, smoothing the merged mesh itself (`Merged`).

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

/// The welded mesh with one vertex per position: the representatives (smallest index of each
/// position), in ascending order, so a mesh whose copies come after the vertices they copy
/// merges into exactly the mesh it was split from.
pub struct Merged {
    /// For every vertex, its position's index in the merged mesh.
    pub index: Vec<u32>,
    /// Merged index -> the representative's original index, ascending.
    pub reps: Vec<u32>,
}

impl Merged {
    pub fn of<T: Real>(positions: &[Vec3<T>]) -> Merged {
        let map = weld_map(positions);
        let mut index = vec![0u32; map.len()];
        let mut reps = Vec::new();
        for i in 0..map.len() {
            // map[i] <= i, so a copy's representative already has its index.
            index[i] = if map[i] as usize == i {
                reps.push(i as u32);
                reps.len() as u32 - 1
            } else {
                index[map[i] as usize]
            };
        }
        Merged { index, reps }
    }

    /// Are any two vertices at the same position?
    pub fn has_copies(&self) -> bool {
        self.reps.len() < self.index.len()
    }

    /// Per merged vertex: the representative's value.
    pub fn gather<V: Copy + Send + Sync>(&self, values: &[V]) -> Vec<V> {
        self.reps.par_iter().map(|&r| values[r as usize]).collect()
    }

    /// The faces in merged indices.
    pub fn faces(&self, faces: &[[u32; 3]]) -> Vec<[u32; 3]> {
        faces.par_iter().map(|f| f.map(|i| self.index[i as usize])).collect()
    }

    /// Per merged vertex: is any of its copies marked?
    pub fn any(&self, mask: &[bool]) -> Vec<bool> {
        let mut out = vec![false; self.reps.len()];
        for (&k, &m) in self.index.iter().zip(mask) {
            out[k as usize] |= m;
        }
        out
    }

    /// Per original vertex: its merged vertex's value (every copy gets the same).
    pub fn scatter<V: Copy + Send + Sync>(&self, merged: &[V]) -> Vec<V> {
        self.index.par_iter().map(|&k| merged[k as usize]).collect()
    }
}

/// New positions from `work` on the mesh, run on the welded mesh when `weld` and some vertices
/// share a position (a merged vertex is pinned when any of its copies is), and given back to
/// every copy; on the mesh as it is otherwise.
pub fn on_welded<T: Real, E>(
    x0: &[Vec3<T>],
    faces: &[[u32; 3]],
    pinned: Option<&[bool]>,
    weld: bool,
    work: impl FnOnce(&[Vec3<T>], &[[u32; 3]], Option<&[bool]>) -> Result<Vec<Vec3<T>>, E>,
) -> Result<Vec<Vec3<T>>, E> {
    if weld {
        let merged = Merged::of(x0);
        if merged.has_copies() {
            let pinned = pinned.map(|p| merged.any(p));
            let out = work(&merged.gather(x0), &merged.faces(faces), pinned.as_deref())?;
            return Ok(merged.scatter(&out));
        }
    }
    work(x0, faces, pinned)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn merges_exact_duplicates_to_smallest_index() {
        let v = vec![[1.0, 0.0, 0.0], [0.0, 0.0, 0.0], [1.0, -0.0, 0.0], [0.0, 0.0, 1e-300]];
        assert_eq!(weld_map(&v), vec![0, 1, 0, 3]);
    }

    #[test]
    fn the_merged_mesh_keeps_representatives_in_order() {
        let v = vec![[1.0, 0.0, 0.0], [0.0, 0.0, 0.0], [1.0, -0.0, 0.0], [2.0, 0.0, 0.0], [0.0; 3]];
        let m = Merged::of(&v);
        assert_eq!((&m.index[..], &m.reps[..]), (&[0, 1, 0, 2, 1][..], &[0, 1, 3][..]));
        assert!(m.has_copies() && !Merged::of(&v[..2]).has_copies());
        assert_eq!(m.faces(&[[4, 2, 3]]), vec![[1, 0, 2]]);
        assert_eq!(m.any(&[false, false, true, false, false]), vec![true, false, false]);
        assert_eq!(m.gather(&[10, 11, 12, 13, 14]), vec![10, 11, 13]);
        assert_eq!(m.scatter(&[7, 8, 9]), vec![7, 8, 7, 9, 8]);
    }
}

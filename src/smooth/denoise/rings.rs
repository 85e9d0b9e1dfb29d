//! The face neighbourhoods normal filtering works on, in compressed sparse row form: the faces
//! around each vertex, and for each face the faces that share a vertex with it (its vertex
//! ring, the neighbourhood of Zheng et al.) and those that share an edge with it.

use rayon::prelude::*;

/// Rows of u32 in CSR form.
#[derive(Debug, Default)]
pub struct Csr {
    offsets: Vec<u32>,
    items: Vec<u32>,
}

impl Csr {
    pub fn row(&self, i: usize) -> &[u32] {
        &self.items[self.offsets[i] as usize..self.offsets[i + 1] as usize]
    }

    /// Where row i's items sit in the flat list, for arrays aligned with it.
    pub fn span(&self, i: usize) -> std::ops::Range<usize> {
        self.offsets[i] as usize..self.offsets[i + 1] as usize
    }

    /// The total number of items.
    pub fn n_items(&self) -> usize {
        self.items.len()
    }

    pub fn len(&self) -> usize {
        self.offsets.len() - 1
    }

    pub fn is_empty(&self) -> bool {
        self.len() == 0
    }

    /// Rows built in parallel by `f`, a chunk of rows at a time (no allocation per row), then
    /// packed in order.
    fn from_rows(n: usize, f: impl Fn(usize, &mut Vec<u32>) + Sync) -> Csr {
        Csr::from_rows_with(n, || (), |_, i, out| f(i, out))
    }

    /// As `from_rows`, with scratch state `S` made by `init` once per chunk and handed to `f`.
    pub(super) fn from_rows_with<S>(
        n: usize,
        init: impl Fn() -> S + Sync,
        f: impl Fn(&mut S, usize, &mut Vec<u32>) + Sync,
    ) -> Csr {
        const CHUNK: usize = 4096;
        let chunks: Vec<(Vec<u32>, Vec<u32>)> = (0..n.div_ceil(CHUNK))
            .into_par_iter()
            .map(|c| {
                let (mut lens, mut items) = (Vec::with_capacity(CHUNK), Vec::with_capacity(CHUNK * 16));
                let mut state = init();
                for i in c * CHUNK..((c + 1) * CHUNK).min(n) {
                    let before = items.len();
                    f(&mut state, i, &mut items);
                    lens.push((items.len() - before) as u32);
                }
                (lens, items)
            })
            .collect();
        let mut offsets = Vec::with_capacity(n + 1);
        offsets.push(0u32);
        let mut total = 0u32;
        for (lens, _) in &chunks {
            for l in lens {
                total += l;
                offsets.push(total);
            }
        }
        let mut items = Vec::with_capacity(total as usize);
        for (_, c) in chunks {
            items.extend_from_slice(&c);
        }
        Csr { offsets, items }
    }
}

pub struct FaceRings {
    /// Faces around each vertex (each face once per distinct vertex it has).
    pub vertex_faces: Csr,
    /// Per face: the other faces sharing at least one vertex with it, ascending.
    pub ring: Csr,
    /// Per face: the other faces sharing an edge (two distinct vertices) with it, ascending.
    pub edge_ring: Csr,
}

impl FaceRings {
    pub fn new(n_vertices: usize, faces: &[[u32; 3]]) -> FaceRings {
        let mut count = vec![0u32; n_vertices + 1];
        for f in faces {
            for (k, &v) in f.iter().enumerate() {
                if !f[..k].contains(&v) {
                    count[v as usize + 1] += 1;
                }
            }
        }
        for i in 0..n_vertices {
            count[i + 1] += count[i];
        }
        let mut items = vec![0u32; count[n_vertices] as usize];
        let mut next = count.clone();
        for (fi, f) in faces.iter().enumerate() {
            for (k, &v) in f.iter().enumerate() {
                if !f[..k].contains(&v) {
                    items[next[v as usize] as usize] = fi as u32;
                    next[v as usize] += 1;
                }
            }
        }
        let vertex_faces = Csr { offsets: count, items };
        let ring = Csr::from_rows(faces.len(), |fi, out| {
            let start = out.len();
            for &v in &faces[fi] {
                out.extend(vertex_faces.row(v as usize).iter().filter(|&&g| g as usize != fi));
            }
            out[start..].sort_unstable();
            let mut kept = start;
            for k in start..out.len() {
                if kept == start || out[k] != out[kept - 1] {
                    out[kept] = out[k];
                    kept += 1;
                }
            }
            out.truncate(kept);
        });
        let edge_ring = Csr::from_rows(faces.len(), |fi, out| {
            let f = faces[fi];
            for &g in ring.row(fi) {
                let shared = faces[g as usize];
                let n =
                    f.iter().enumerate().filter(|(k, v)| !f[..*k].contains(v) && shared.contains(v)).count();
                if n >= 2 {
                    out.push(g);
                }
            }
        });
        FaceRings { vertex_faces, ring, edge_ring }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn rings_of_a_strip() {
        // 0-1-2 / 1-3-2 / 2-3-4: a strip of three triangles.
        let faces = [[0, 1, 2], [1, 3, 2], [2, 3, 4]];
        let r = FaceRings::new(5, &faces);
        assert_eq!(r.vertex_faces.row(2), &[0, 1, 2]);
        assert_eq!(r.ring.row(0), &[1, 2]);
        assert_eq!(r.edge_ring.row(0), &[1]);
        assert_eq!(r.edge_ring.row(1), &[0, 2]);
    }

    #[test]
    fn a_degenerate_face_counts_its_vertex_once() {
        let faces = [[0, 0, 1], [0, 1, 2]];
        let r = FaceRings::new(3, &faces);
        assert_eq!(r.vertex_faces.row(0), &[0, 1]);
        assert_eq!(r.edge_ring.row(1), &[0]);
    }
}

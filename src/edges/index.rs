//! `EdgeIndex`: the once-per-mesh work (edges, face normals, boundaries, creases) kept so that
//! silhouettes for each new view cost one pass over faces and one over edges. This is the
//! pre-processing / run-time split of Kang, Kim and Yoon.

use rayon::prelude::*;

use super::face_normals;
use super::feature::{crease_pair, feature_edges, FeatureEdges, PREFETCH_AHEAD};
use super::silhouette::{face_side, facing, View, BACK, FRONT};
use crate::error::Result;
use crate::mesh::edge_table::FaceUse;
use crate::mesh::weld::{weld_faces, weld_map};
use crate::mesh::EdgeTable;
use crate::real::{Real, Vec3};

#[derive(Debug, Clone)]
pub struct EdgeIndex {
    positions: Vec<[f64; 3]>,
    table: EdgeTable,
    normals: Vec<[f64; 3]>,
    /// n . p for a vertex p of each face: its plane is n . x = offset.
    offsets: Vec<f64>,
    /// Edges with exactly two distinct faces that both have normals, and those faces.
    manifold_edges: Vec<[u32; 2]>,
    manifold_faces: Vec<[u32; 2]>,
    /// Table indices of edges with three or more face-edges.
    nonmanifold: Vec<u32>,
    /// When welding, the representative of every vertex.
    weld: Option<Vec<u32>>,
}

const CHUNK: usize = 16384;

/// One chunk's manifold edges, their face pairs, and its non-manifold edge ids.
type ChunkPairs = (Vec<[u32; 2]>, Vec<[u32; 2]>, Vec<u32>);

impl EdgeIndex {
    pub fn build<T: Real>(positions: &[Vec3<T>], faces: &[[u32; 3]], weld: bool) -> Result<EdgeIndex> {
        let map = weld.then(|| weld_map(positions));
        let welded;
        let faces = match &map {
            Some(m) => {
                welded = weld_faces(faces, m);
                &welded[..]
            }
            None => faces,
        };
        let (table, normals) =
            rayon::join(|| EdgeTable::build(positions.len(), faces), || face_normals(positions, faces));
        let table = table?;
        let offsets: Vec<f64> = normals
            .par_iter()
            .zip(faces.par_iter())
            .map(|(n, f)| {
                let p = positions[f[0] as usize];
                n[0] * p[0].to_f64() + n[1] * p[1].to_f64() + n[2] * p[2].to_f64()
            })
            .collect();
        let n = table.len();
        let parts: Vec<ChunkPairs> = (0..n.div_ceil(CHUNK))
            .into_par_iter()
            .map(|c| {
                let (mut me, mut mf, mut nm) = (Vec::new(), Vec::new(), Vec::new());
                for e in c * CHUNK..((c + 1) * CHUNK).min(n) {
                    table.prefetch_faces(e + PREFETCH_AHEAD, &normals);
                    match table.face_count(e) {
                        1 => {}
                        2 => {
                            if let Some((f1, f2, _)) = crease_pair(&table, e, &normals) {
                                me.push(table.edges[e]);
                                mf.push([f1, f2]);
                            }
                        }
                        _ => nm.push(e as u32),
                    }
                }
                (me, mf, nm)
            })
            .collect();
        let (mut manifold_edges, mut manifold_faces, mut nonmanifold) = (Vec::new(), Vec::new(), Vec::new());
        for (me, mf, nm) in parts {
            manifold_edges.extend(me);
            manifold_faces.extend(mf);
            nonmanifold.extend(nm);
        }
        let positions = positions.par_iter().map(|p| [p[0].to_f64(), p[1].to_f64(), p[2].to_f64()]).collect();
        Ok(EdgeIndex {
            positions,
            table,
            normals,
            offsets,
            manifold_edges,
            manifold_faces,
            nonmanifold,
            weld: map,
        })
    }

    pub fn n_vertices(&self) -> usize {
        self.positions.len()
    }

    pub fn n_faces(&self) -> usize {
        self.normals.len()
    }

    pub fn n_edges(&self) -> usize {
        self.table.len()
    }

    pub fn positions(&self) -> &[[f64; 3]] {
        &self.positions
    }

    pub fn normals(&self) -> &[[f64; 3]] {
        &self.normals
    }

    pub fn weld_map(&self) -> Option<&[u32]> {
        self.weld.as_deref()
    }

    /// The faces on `edge` (its ends numbered as this index numbers them, welded where it
    /// welds), each with the way it walks the edge; none if no face has that edge.
    pub fn faces_on(&self, edge: [u32; 2]) -> impl Iterator<Item = FaceUse> + '_ {
        let e = self.table.edges.binary_search(&[edge[0].min(edge[1]), edge[0].max(edge[1])]).ok();
        e.into_iter().flat_map(move |e| self.table.uses(e))
    }

    /// The edges with exactly two faces that both have normals, and those faces (the edges
    /// `silhouette` tests against its faces, outside the non-manifold ones).
    pub fn manifold(&self) -> (&[[u32; 2]], &[[u32; 2]]) {
        (&self.manifold_edges, &self.manifold_faces)
    }

    /// Indices of faces without a normal.
    pub fn degenerate_faces(&self) -> Vec<u32> {
        (0..self.normals.len() as u32).filter(|&f| self.normals[f as usize] == [0.0; 3]).collect()
    }

    /// Whether any edge has three or more face-edges.
    pub fn has_nonmanifold(&self) -> bool {
        !self.nonmanifold.is_empty()
    }

    pub fn feature_edges(&self, crease_angle: f64) -> Result<FeatureEdges> {
        feature_edges(&self.positions, &self.table, &self.normals, crease_angle)
    }

    /// Silhouette edges for one view, in lexicographic order.
    pub fn silhouette(&self, view: View) -> Result<Vec<[u32; 2]>> {
        let view = view.check()?;
        let side = facing(&self.normals, &self.offsets, view);
        let manifold: Vec<[u32; 2]> = self
            .manifold_faces
            .par_chunks(CHUNK)
            .zip(self.manifold_edges.par_chunks(CHUNK))
            .flat_map_iter(|(faces, edges)| {
                let side = &side;
                faces
                    .iter()
                    .zip(edges)
                    .filter(move |(f, _)| side[f[0] as usize] != side[f[1] as usize])
                    .map(|(_, &e)| e)
            })
            .collect();
        if self.nonmanifold.is_empty() {
            return Ok(manifold);
        }
        let other: Vec<[u32; 2]> = self
            .nonmanifold
            .iter()
            .filter(|&&e| {
                let mut seen = [false; 3];
                for u in self.table.uses(e as usize) {
                    seen[side[u.face as usize] as usize] = true;
                }
                seen[FRONT as usize] && seen[BACK as usize]
            })
            .map(|&e| self.table.edges[e as usize])
            .collect();
        Ok(merge_sorted(&manifold, &other))
    }
}

impl EdgeIndex {
    /// The silhouette edges among `edges` (edges of the mesh, sorted) for one view, by the rule
    /// of `silhouette`, facing only their faces: for a few edges (the creases a smooth contour
    /// stops at) without a pass over every face.
    pub fn silhouette_among(&self, view: View, edges: &[[u32; 2]]) -> Result<Vec<[u32; 2]>> {
        let view = view.check()?;
        Ok(edges
            .par_iter()
            .filter(|e| {
                let Ok(id) = self.table.edges.binary_search(e) else { return false };
                let mut seen = [false; 3];
                for u in self.table.uses(id) {
                    let f = u.face as usize;
                    seen[face_side(&self.normals[f], self.offsets[f], view) as usize] = true;
                }
                seen[FRONT as usize] && seen[BACK as usize]
            })
            .copied()
            .collect())
    }
}

fn merge_sorted(a: &[[u32; 2]], b: &[[u32; 2]]) -> Vec<[u32; 2]> {
    let mut out = Vec::with_capacity(a.len() + b.len());
    let (mut i, mut j) = (0, 0);
    while i < a.len() && j < b.len() {
        if a[i] <= b[j] {
            out.push(a[i]);
            i += 1;
        } else {
            out.push(b[j]);
            j += 1;
        }
    }
    out.extend_from_slice(&a[i..]);
    out.extend_from_slice(&b[j..]);
    out
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::mesh::shapes::{grid, icosphere};

    #[test]
    fn sphere_silhouette_is_a_closed_ring() {
        let (v, f) = icosphere(3, 0.0, 0).unwrap();
        let idx = EdgeIndex::build(&v, &f, false).unwrap();
        let fe = idx.feature_edges(30.0).unwrap();
        assert!(fe.boundary.is_empty() && fe.crease.is_empty() && fe.nonmanifold.is_empty());
        let s = idx.silhouette(View::Eye([0.0, 0.0, 5.0])).unwrap();
        assert!(!s.is_empty());
        let mut deg = vec![0; v.len()];
        for e in &s {
            deg[e[0] as usize] += 1;
            deg[e[1] as usize] += 1;
        }
        assert!(deg.iter().all(|&d| d == 0 || d == 2), "a sphere's silhouette is a union of loops");
        let o = idx.silhouette(View::Direction([0.0, 0.0, -1.0])).unwrap();
        assert!(!o.is_empty());
        assert!(idx.silhouette(View::Direction([0.0; 3])).is_err());
        // among a subset of the edges: the same rule, on those edges only
        let some: Vec<[u32; 2]> = idx.table.edges.iter().step_by(3).copied().collect();
        let among = idx.silhouette_among(View::Eye([0.0, 0.0, 5.0]), &some).unwrap();
        let expected: Vec<[u32; 2]> = s.iter().filter(|e| some.binary_search(e).is_ok()).copied().collect();
        assert!(!expected.is_empty());
        assert_eq!(among, expected);
    }

    #[test]
    fn flat_grid_seen_edge_on_has_no_silhouette() {
        let (v, f) = grid(8, 0.0, 0).unwrap();
        let idx = EdgeIndex::build(&v, &f, false).unwrap();
        assert!(idx.silhouette(View::Eye([0.5, 0.5, 0.0])).unwrap().is_empty());
        assert!(idx.silhouette(View::Direction([1.0, 0.0, 0.0])).unwrap().is_empty());
        assert_eq!(idx.feature_edges(30.0).unwrap().boundary.len(), 4 * 7);
    }
}

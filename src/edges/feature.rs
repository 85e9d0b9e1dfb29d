//! Boundary, crease and non-manifold edges: the view-independent outlines, found once per mesh.
//!
//! Rules (stated in the Python docstrings too):
//! - boundary: exactly one face-edge on the edge;
//! - non-manifold: three or more face-edges;
//! - crease: exactly two face-edges, from two different faces that both have a normal, whose
//!   dihedral angle atan2(|n1 x n2|, n1 . n2) exceeds the threshold (strictly). The atan2 form
//!   keeps full precision near 0 and 180 degrees, where acos(n1 . n2) loses half the digits.
//!   An edge next to a degenerate face (see `mesh::normals`) is never a crease: a face without
//!   a normal has no angle to its neighbour.
//! - a crease is convex (a ridge) when (n1 x n2) . (b - a) >= 0, where face 1 walks the edge from
//!   a to b; this is independent of which face is called 1 when the two faces are consistently
//!   oriented, and concave (a valley) otherwise.

use rayon::prelude::*;

use crate::error::Result;
use crate::mesh::edge_table::{prefetch, EdgeTable, FaceUse};
use crate::mesh::normals::is_defined;
use crate::mesh::Buckets;
use crate::real::{Real, Vec3};

pub use crate::mesh::dihedral::{check_crease_angle, dihedral, CreaseTest};

#[derive(Debug, Clone, Default, PartialEq)]
pub struct FeatureEdges {
    pub boundary: Vec<[u32; 2]>,
    pub crease: Vec<[u32; 2]>,
    /// Dihedral angle of each crease in degrees, in (threshold, 180].
    pub crease_angle: Vec<f64>,
    /// Whether each crease is convex (a ridge) rather than concave (a valley).
    pub crease_convex: Vec<bool>,
    pub nonmanifold: Vec<[u32; 2]>,
}

/// The two faces of a manifold edge when both have normals, first the one that walks a -> b.
#[inline]
pub fn crease_pair(table: &EdgeTable, e: usize, normals: &[[f64; 3]]) -> Option<(u32, u32, bool)> {
    pair_with_normals(table.uses(e), normals)
}

#[inline]
fn pair_with_normals(
    mut uses: impl Iterator<Item = FaceUse>,
    normals: &[[f64; 3]],
) -> Option<(u32, u32, bool)> {
    let (u1, u2) = (uses.next()?, uses.next()?);
    if u1.face == u2.face || !is_defined(normals[u1.face as usize]) || !is_defined(normals[u2.face as usize])
    {
        return None;
    }
    Some((u1.face, u2.face, u1.reversed))
}

const CHUNK: usize = 16384;
/// How many edges ahead to prefetch face normals: enough to cover a memory latency.
pub const PREFETCH_AHEAD: usize = 16;

/// The per-edge rule, shared by the table and bucket paths.
struct Classifier<'a, T> {
    positions: &'a [Vec3<T>],
    normals: &'a [[f64; 3]],
    test: CreaseTest,
}

impl<'a, T: Real> Classifier<'a, T> {
    fn new(positions: &'a [Vec3<T>], normals: &'a [[f64; 3]], crease_angle: f64) -> Result<Self> {
        Ok(Classifier { positions, normals, test: CreaseTest::new(crease_angle)? })
    }

    #[inline]
    fn classify(&self, out: &mut FeatureEdges, edge: [u32; 2], uses: impl ExactSizeIterator<Item = FaceUse>) {
        match uses.len() {
            1 => out.boundary.push(edge),
            2 => {
                let normals = self.normals;
                let Some((f1, f2, reversed)) = pair_with_normals(uses, normals) else {
                    return;
                };
                let along = || {
                    let (pa, pb) = (self.positions[edge[0] as usize], self.positions[edge[1] as usize]);
                    let mut along = [0.0; 3];
                    for k in 0..3 {
                        along[k] = pb[k].to_f64() - pa[k].to_f64();
                        if reversed {
                            along[k] = -along[k];
                        }
                    }
                    along
                };
                if let Some((angle, convex)) =
                    self.test.crease(normals[f1 as usize], normals[f2 as usize], along)
                {
                    out.crease.push(edge);
                    out.crease_angle.push(angle);
                    out.crease_convex.push(convex);
                }
            }
            _ => out.nonmanifold.push(edge),
        }
    }
}

fn concatenate(parts: Vec<FeatureEdges>) -> FeatureEdges {
    let mut all = FeatureEdges::default();
    for p in parts {
        all.boundary.extend(p.boundary);
        all.crease.extend(p.crease);
        all.crease_angle.extend(p.crease_angle);
        all.crease_convex.extend(p.crease_convex);
        all.nonmanifold.extend(p.nonmanifold);
    }
    all
}

/// Feature edges from a built edge table (what `EdgeIndex` keeps).
pub fn feature_edges<T: Real>(
    positions: &[Vec3<T>],
    table: &EdgeTable,
    normals: &[[f64; 3]],
    crease_angle: f64,
) -> Result<FeatureEdges> {
    let rule = Classifier::new(positions, normals, crease_angle)?;
    let n = table.len();
    let parts: Vec<FeatureEdges> = (0..n.div_ceil(CHUNK))
        .into_par_iter()
        .map(|c| {
            let mut out = FeatureEdges::default();
            for e in c * CHUNK..((c + 1) * CHUNK).min(n) {
                table.prefetch_faces(e + PREFETCH_AHEAD, normals);
                rule.classify(&mut out, table.edges[e], table.uses(e));
            }
            out
        })
        .collect();
    Ok(concatenate(parts))
}

/// Feature edges straight from the face-edge buckets, classifying each edge as its bucket is
/// sorted: a one-off query never builds the full edge table.
pub fn feature_edges_from_buckets<T: Real>(
    positions: &[Vec3<T>],
    buckets: &mut Buckets<u64>,
    normals: &[[f64; 3]],
    crease_angle: f64,
) -> Result<FeatureEdges> {
    let rule = Classifier::new(positions, normals, crease_angle)?;
    let parts = buckets.visit_edges(
        |_| FeatureEdges::default(),
        |ahead| {
            for &entry in ahead {
                prefetch(normals, FaceUse::unpack(entry as u32).face as usize);
            }
        },
        |out, edge, uses| rule.classify(out, edge, uses.iter().map(|&x| FaceUse::unpack(x as u32))),
    );
    Ok(concatenate(parts))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::mesh::normals::face_normals;

    fn run(v: &[[f64; 3]], f: &[[u32; 3]], angle: f64) -> FeatureEdges {
        let t = EdgeTable::build(v.len(), f).unwrap();
        feature_edges(v, &t, &face_normals(v, f), angle).unwrap()
    }

    /// Two triangles on edge 0-1 (along x); the second is folded by `fold` radians.
    fn hinge(fold: f64) -> (Vec<[f64; 3]>, Vec<[u32; 3]>) {
        let v = vec![[0.0, 0.0, 0.0], [1.0, 0.0, 0.0], [0.5, 1.0, 0.0], [0.5, -fold.cos(), -fold.sin()]];
        (v, vec![[0, 1, 2], [1, 0, 3]])
    }

    #[test]
    fn ridge_valley_and_precision() {
        for deg in [1e-6f64, 0.5, 30.0, 90.0, 179.0, 180.0 - 1e-6] {
            let (v, f) = hinge(deg.to_radians());
            let r = run(&v, &f, 0.0);
            assert_eq!(r.crease, vec![[0, 1]]);
            assert!((r.crease_angle[0] - deg).abs() < 1e-9 * deg.max(1.0), "{deg}: {}", r.crease_angle[0]);
            assert!(r.crease_convex[0], "folding down is a ridge");
            let (v, f) = hinge(-deg.to_radians());
            assert!(!run(&v, &f, 0.0).crease_convex[0], "folding up is a valley");
        }
        let (v, f) = hinge(0.0);
        assert!(run(&v, &f, 0.0).crease.is_empty(), "coplanar faces are not a crease");
    }

    #[test]
    fn degenerate_face_never_creases() {
        let v = vec![[0.0, 0.0, 0.0], [1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [2.0, 0.0, 0.0]];
        let r = run(&v, &[[0, 1, 2], [1, 0, 3]], 10.0);
        assert!(r.crease.is_empty());
        assert_eq!(r.boundary, vec![[0, 2], [0, 3], [1, 2], [1, 3]]);
        assert!(check_crease_angle(-1.0).is_err() && check_crease_angle(f64::NAN).is_err());
    }

    #[test]
    fn table_and_bucket_paths_agree() {
        let (v, f) = crate::mesh::shapes::icosphere(4, 0.02, 3).unwrap();
        let normals = face_normals(&v, &f);
        let table = EdgeTable::build(v.len(), &f).unwrap();
        let mut buckets = Buckets::face_edges(v.len(), &f).unwrap();
        for angle in [0.0, 5.0, 30.0] {
            let a = feature_edges(&v, &table, &normals, angle).unwrap();
            let b = feature_edges_from_buckets(&v, &mut buckets, &normals, angle).unwrap();
            assert_eq!(a, b);
            assert!(!a.crease.is_empty());
        }
    }
}

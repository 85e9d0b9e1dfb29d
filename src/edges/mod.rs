//! Outlines: boundary, crease and non-manifold edges and silhouettes found on the mesh
//! (Kang, Kim and Yoon), and Sobel edges found in images (Borquez and Yepez).

pub mod chains;
pub mod coherence;
pub mod contours;
pub mod crease_pieces;
pub mod crooked_creases;
pub mod detect;
pub mod face_clusters;
pub mod feature;
pub mod index;
pub mod intersections;
pub mod occlusion;
pub mod outlines;
pub mod short_creases;
pub mod silhouette;
pub mod sobel;
pub mod views;
pub mod zero_set;

pub use feature::FeatureEdges;
pub use index::EdgeIndex;
pub use silhouette::View;

use crate::error::Result;
use crate::mesh::{weld, Buckets};

/// Dihedral angle in degrees above which an edge is a crease, when none is given.
pub const DEFAULT_CREASE_ANGLE: f64 = 30.0;
use crate::real::{Real, Vec3};

/// Face normals as `mesh::normals::face_normals` computes them, in a huge-page buffer.
pub fn face_normals<T: Real>(positions: &[Vec3<T>], faces: &[[u32; 3]]) -> Vec<[f64; 3]> {
    let mut out = crate::huge_pages::filled_vec(faces.len(), [0.0; 3]);
    crate::mesh::normals::face_normals_into(positions, faces, &mut out);
    out
}

/// Feature edges of a mesh in one call, and the indices of its degenerate faces. With `weld`,
/// vertices at identical positions are merged first (see `mesh::weld`).
pub fn find_feature_edges<T: Real>(
    positions: &[Vec3<T>],
    faces: &[[u32; 3]],
    crease_angle: f64,
    weld: bool,
) -> Result<(FeatureEdges, Vec<u32>)> {
    feature::check_crease_angle(crease_angle)?;
    let welded;
    let faces = if weld {
        welded = weld::weld_faces(faces, &weld::weld_map(positions));
        &welded[..]
    } else {
        faces
    };
    let (buckets, normals) =
        rayon::join(|| Buckets::face_edges(positions.len(), faces), || face_normals(positions, faces));
    let fe = feature::feature_edges_from_buckets(positions, &mut buckets?, &normals, crease_angle)?;
    let degenerate = (0..normals.len() as u32).filter(|&i| normals[i as usize] == [0.0; 3]).collect();
    Ok((fe, degenerate))
}

//! View-dependent lines from smooth surfaces, as zero sets (`zero_set`) of fields at the
//! vertices:
//!
//! - *Smooth contours* (Hertzmann and Zorin 2000): where n . v = 0, n the interpolated vertex
//!   normal and v the unit vector to the eye; the curve the shading's terminator shows, through
//!   the faces rather than along their edges, so it does not zigzag on scans.
//! - *Suggestive contours* (DeCarlo et al. 2003): where the radial curvature kr (the normal
//!   curvature along the view vector projected into the tangent plane) is zero, its derivative
//!   along that direction is positive, and the surface faces the viewer: contours in nearby
//!   views, the lines artists draw on a neck or a haunch. The derivative test is cut at a
//!   threshold relative to the mesh's feature size (so it does not depend on units).

use std::sync::OnceLock;

use rayon::prelude::*;

use super::silhouette::View;
use super::zero_set::{zero_set, Polylines};
use crate::cancel::Cancel;
use crate::error::{Error, Result};
use crate::mesh::crease_normals::{split_normals, ListedEdges};
use crate::mesh::curvature::{curvature, Curvature};
use crate::mesh::normals::vertex_normals;
use crate::mesh::weld::{weld_faces, weld_map};
use crate::mesh::Bounds;
use crate::real::{dot, sub, Real, Vec3};

/// A mesh prepared for contours, once: its positions in f64, its faces (welded when asked, so
/// that seams do not cut the lines), its shading normals, and its curvature once a view asks
/// for suggestive contours.
pub struct ContourMesh {
    positions: Vec<[f64; 3]>,
    faces: Vec<[u32; 3]>,
    normals: Vec<[f64; 3]>,
    curvature: OnceLock<(Curvature, f64)>,
}

impl ContourMesh {
    pub fn build<T: Real>(positions: &[Vec3<T>], faces: &[[u32; 3]], weld: bool) -> ContourMesh {
        let faces = if weld { weld_faces(faces, &weld_map(positions)) } else { faces.to_vec() };
        let normals = vertex_normals(positions, &faces);
        let positions = positions.par_iter().map(|p| p.map(|x| x.to_f64())).collect();
        ContourMesh { positions, faces, normals, curvature: OnceLock::new() }
    }

    /// A mesh whose smooth contours stop at hard edges: vertices split into their fans at the
    /// edges of `hard` (sorted, [smaller, larger] index, in the welded numbering when welding)
    /// and at boundary and non-manifold edges (`mesh::crease_normals`), each fan with its own
    /// normal.
    pub fn split_at<T: Real>(
        positions: &[Vec3<T>],
        faces: &[[u32; 3]],
        weld: bool,
        hard: &[[u32; 2]],
    ) -> Result<ContourMesh> {
        let faces = if weld { weld_faces(faces, &weld_map(positions)) } else { faces.to_vec() };
        let split = split_normals(positions, &faces, &ListedEdges(hard))?;
        let positions = split.source.par_iter().map(|&s| positions[s as usize].map(|x| x.to_f64())).collect();
        Ok(ContourMesh { positions, faces: split.faces, normals: split.normals, curvature: OnceLock::new() })
    }

    /// Smooth contours of one view.
    pub fn smooth(&self, view: View) -> Polylines {
        smooth_contours(&self.positions, &self.faces, &self.normals, view)
    }

    /// The mesh's curvature and feature size, computed on first use.
    pub fn curvature(&self, cancel: &Cancel) -> Result<&(Curvature, f64)> {
        if let Some(c) = self.curvature.get() {
            return Ok(c);
        }
        let c = curvature(&self.positions, &self.faces, cancel)?;
        let size = feature_size(&self.positions, &c);
        Ok(self.curvature.get_or_init(|| (c, size)))
    }

    /// Suggestive contours of one view; `threshold` relative to the feature size squared.
    pub fn suggestive(&self, view: View, threshold: f64, cancel: &Cancel) -> Result<Polylines> {
        let (c, size) = self.curvature(cancel)?;
        Ok(suggestive_contours(&self.positions, &self.faces, c, view, threshold, *size))
    }
}

/// The derivative threshold of suggestive contours, relative to the feature size squared, when
/// none is given (DeCarlo et al.'s implementation uses the same).
pub const DEFAULT_SUGGESTIVE_THRESHOLD: f64 = 0.01;

/// Checks a suggestive-contour threshold: a finite number >= 0.
pub fn check_threshold(arg: &str, t: f64) -> Result<f64> {
    if t.is_finite() && t >= 0.0 {
        Ok(t)
    } else {
        Err(Error::invalid(arg, format!("must be a finite number >= 0, got {t}")))
    }
}

/// The unit vector from p toward the viewer.
fn to_viewer(view: View, p: [f64; 3]) -> [f64; 3] {
    let v = match view {
        View::Eye(e) => sub(e, p),
        View::Direction(d) => [-d[0], -d[1], -d[2]],
    };
    let len = dot(v, v).sqrt();
    if len > 0.0 && len.is_finite() {
        v.map(|x| x / len)
    } else {
        [0.0; 3]
    }
}

/// Smooth contours of one view: the zero set of n . v over `faces`, with `normals` the vertex
/// normals the surface is shaded with.
pub fn smooth_contours(
    positions: &[[f64; 3]],
    faces: &[[u32; 3]],
    normals: &[[f64; 3]],
    view: View,
) -> Polylines {
    let ndotv: Vec<f64> =
        positions.par_iter().zip(normals.par_iter()).map(|(p, n)| dot(*n, to_viewer(view, *p))).collect();
    zero_set(positions, faces, &ndotv, &[])
}

/// The feature size of a curved mesh (DeCarlo et al.'s rule): 1% of the reciprocal of the 10th
/// percentile of |k| over both principal curvatures, at most 5% of the bounding box's
/// half-diagonal. A length in the mesh's units.
pub fn feature_size(positions: &[[f64; 3]], c: &Curvature) -> f64 {
    let half_diagonal = 0.5 * Bounds::of(positions).diagonal();
    let cap = 0.05 * half_diagonal;
    let mut k: Vec<f64> = c.k1.iter().chain(&c.k2).map(|x| x.abs()).filter(|x| x.is_finite()).collect();
    if k.is_empty() {
        return cap;
    }
    let which = k.len() / 10;
    let (_, tenth, _) = k.select_nth_unstable_by(which, |a, b| a.total_cmp(b));
    let size = 0.01 / *tenth;
    if size.is_finite() && size > 0.0 {
        size.min(cap)
    } else {
        cap
    }
}

/// Suggestive contours of one view from the mesh's curvature (its normals and principal
/// frame): the zero set of kr where D_w kr / |w| > threshold / feature_size^2 and n . v > 0.
pub fn suggestive_contours(
    positions: &[[f64; 3]],
    faces: &[[u32; 3]],
    c: &Curvature,
    view: View,
    threshold: f64,
    feature_size: f64,
) -> Polylines {
    let cutoff = threshold / (feature_size * feature_size);
    let per_vertex: Vec<(f64, f64, f64)> = (0..positions.len())
        .into_par_iter()
        .map(|i| {
            let v = to_viewer(view, positions[i]);
            let ndotv = dot(c.normals[i], v);
            let (u, w) = (dot(v, c.d1[i]), dot(v, c.d2[i]));
            let (u2, w2) = (u * u, w * w);
            let sin2 = u2 + w2;
            // kr sin^2(theta): the same zero set as kr where the view is not along the normal
            let kr = c.k1[i] * u2 + c.k2[i] * w2;
            if !(sin2 > 1e-12) {
                return (kr, -1.0, ndotv);
            }
            let [c0, c1, c2, c3] = c.derivatives[i];
            // D_w kr sin(theta) / cos(theta): the third-order term C(w, w, w) and the term of the
            // principal frame's turning (the torsion along w)
            let cw = u2 * (u * c0 + 3.0 * w * c1) + w2 * (3.0 * u * c2 + w * c3);
            let torsion = (c.k2[i] - c.k1[i]) * u * w / sin2;
            let num = cw / sin2 - 2.0 * ndotv * torsion * torsion;
            (kr, num - cutoff * ndotv, ndotv)
        })
        .collect();
    let kr: Vec<f64> = per_vertex.iter().map(|x| x.0).collect();
    let test: Vec<f64> = per_vertex.iter().map(|x| x.1).collect();
    let ndotv: Vec<f64> = per_vertex.iter().map(|x| x.2).collect();
    zero_set(positions, faces, &kr, &[&test, &ndotv])
}

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

use std::sync::{Arc, Mutex, OnceLock};

use rayon::prelude::*;

use super::face_clusters::{FaceClusters, Sides};
use super::silhouette::View;
use super::zero_set::{zero_set, zero_set_marking, Polylines};
use crate::cancel::Cancel;
use crate::error::{Error, Result};
use crate::mesh::crease_normals::{split_normals, ListedEdges};
use crate::mesh::curvature::{curvature, Curvature};
use crate::mesh::edge_length::mean_edge_length;
use crate::mesh::normals::vertex_normals;
use crate::mesh::weld::{weld_faces, weld_map};
use crate::mesh::Bounds;
use crate::real::{dot, sub, Real, Vec3};

/// A mesh prepared for contours, once: its positions in f64, its faces (welded when asked, so
/// that seams do not cut the lines), its shading normals, and what suggestive contours are
/// traced on once a view asks for them (kept for the last smoothing asked).
pub struct ContourMesh {
    positions: Vec<[f64; 3]>,
    /// The faces in clusters, so that a view visits only those near its contours.
    clusters: FaceClusters,
    normals: Vec<[f64; 3]>,
    suggestive: Mutex<Option<(u64, Arc<SuggestiveBasis>)>>,
    /// `auto_smoothing` of this mesh, once asked.
    auto_smoothing: OnceLock<f64>,
}

/// What suggestive contours are traced on, per mesh and smoothing: the curvature, the feature
/// size, and the faces where some view can find kr = 0, renumbered over their own vertices.
/// Elsewhere kr keeps its sign in every view: kr = k1 cos^2 + k2 sin^2 of the angle to d1 (up
/// to the factor sin^2 of the view to the normal), so kr > 0 needs k1 > 0 at a vertex and
/// kr <= 0 needs k2 <= 0, and a face without both has no zero crossing. On a convex shape no
/// face is left, and on a scan only its saddles are visited per view.
pub struct SuggestiveBasis {
    pub curvature: Curvature,
    pub feature_size: f64,
    /// The vertices of the faces kept (mesh numbering), their positions, and the faces in their
    /// numbering, in clusters bounding the curvature's normals (a view visits the clusters
    /// that face it).
    vertices: Vec<u32>,
    positions: Vec<[f64; 3]>,
    clusters: FaceClusters,
}

impl SuggestiveBasis {
    fn build(positions: &[[f64; 3]], faces: &[[u32; 3]], curvature: Curvature) -> SuggestiveBasis {
        let feature_size = feature_size(positions, &curvature);
        let crossable = |f: &[u32; 3]| {
            f.iter().any(|&v| curvature.k1[v as usize] > 0.0)
                && f.iter().any(|&v| curvature.k2[v as usize] <= 0.0)
        };
        let kept: Vec<[u32; 3]> = faces.par_iter().filter(|f| crossable(f)).copied().collect();
        let mut vertices: Vec<u32> = kept.iter().flatten().copied().collect();
        vertices.par_sort_unstable();
        vertices.dedup();
        let local = |v: u32| vertices.binary_search(&v).expect("a kept face's vertex") as u32;
        let faces: Vec<[u32; 3]> = kept.par_iter().map(|f| f.map(local)).collect();
        let positions: Vec<[f64; 3]> = vertices.iter().map(|&v| positions[v as usize]).collect();
        let normals: Vec<[f64; 3]> = vertices.iter().map(|&v| curvature.normals[v as usize]).collect();
        let clusters = FaceClusters::build(&positions, &normals, &faces);
        SuggestiveBasis { curvature, feature_size, vertices, positions, clusters }
    }

    /// Faces where some view can find a suggestive contour.
    pub fn n_faces(&self) -> usize {
        self.clusters.faces.len()
    }
}

impl ContourMesh {
    pub fn build<T: Real>(positions: &[Vec3<T>], faces: &[[u32; 3]], weld: bool) -> ContourMesh {
        let faces = if weld { weld_faces(faces, &weld_map(positions)) } else { faces.to_vec() };
        let normals = vertex_normals(positions, &faces);
        let positions: Vec<[f64; 3]> = positions.par_iter().map(|p| p.map(|x| x.to_f64())).collect();
        let clusters = FaceClusters::build(&positions, &normals, &faces);
        ContourMesh {
            positions,
            clusters,
            normals,
            suggestive: Mutex::new(None),
            auto_smoothing: OnceLock::new(),
        }
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
        let positions: Vec<[f64; 3]> =
            split.source.par_iter().map(|&s| positions[s as usize].map(|x| x.to_f64())).collect();
        let clusters = FaceClusters::build(&positions, &split.normals, &split.faces);
        Ok(ContourMesh {
            positions,
            clusters,
            normals: split.normals,
            suggestive: Mutex::new(None),
            auto_smoothing: OnceLock::new(),
        })
    }

    /// Its vertices' positions and normals, and its faces.
    pub fn positions(&self) -> &[[f64; 3]] {
        &self.positions
    }

    pub fn normals(&self) -> &[[f64; 3]] {
        &self.normals
    }

    pub fn faces(&self) -> &[[u32; 3]] {
        &self.clusters.faces
    }

    /// Smooth contours of one view.
    pub fn smooth(&self, view: View) -> Polylines {
        smooth_contours(&self.positions, &self.clusters, &self.normals, view)
    }

    /// The curvature at `smoothing` (`mesh::curvature`; None: `auto_smoothing`) and what goes
    /// with it, computed when first asked at that smoothing.
    pub fn suggestive_basis(&self, smoothing: Option<f64>, cancel: &Cancel) -> Result<Arc<SuggestiveBasis>> {
        let smoothing = smoothing.unwrap_or_else(|| {
            *self.auto_smoothing.get_or_init(|| auto_smoothing(&self.positions, &self.clusters.faces))
        });
        let key = smoothing.to_bits();
        if let Some((k, b)) = &*self.suggestive.lock().unwrap_or_else(|e| e.into_inner()) {
            if *k == key {
                return Ok(b.clone());
            }
        }
        let c = curvature(&self.positions, &self.clusters.faces, smoothing, cancel)?;
        let basis = Arc::new(SuggestiveBasis::build(&self.positions, &self.clusters.faces, c));
        *self.suggestive.lock().unwrap_or_else(|e| e.into_inner()) = Some((key, basis.clone()));
        Ok(basis)
    }

    /// Suggestive contours of one view; `threshold` relative to the feature size squared,
    /// `smoothing` the curvature's in mean edge lengths (None: `auto_smoothing`).
    pub fn suggestive(
        &self,
        view: View,
        threshold: f64,
        smoothing: Option<f64>,
        cancel: &Cancel,
    ) -> Result<Polylines> {
        let basis = self.suggestive_basis(smoothing, cancel)?;
        Ok(suggestive_contours(&basis, view, threshold))
    }
}

/// The derivative threshold of suggestive contours, relative to the feature size squared, when
/// none is given (DeCarlo et al.'s implementation uses the same).
pub const DEFAULT_SUGGESTIVE_THRESHOLD: f64 = 0.01;

/// The width the curvature of suggestive contours is measured at when none is given
/// (`mesh::diffuse`): 2 mean edge lengths, where a scan's noise lives, but at most 1% of the
/// bounding-box diagonal, so a coarse mesh's features (a cow's 3,000 vertices) are not smoothed
/// away. On the raw Stanford bunny that is 1.7 edges and takes its 197 scribbles to 27 lines;
/// on the cow 0.6 edges.
pub const AUTO_SMOOTHING_EDGES: f64 = 2.0;
pub const AUTO_SMOOTHING_OF_DIAGONAL: f64 = 0.01;

/// The curvature smoothing, in mean edge lengths, that `None` asks for (see above).
pub fn auto_smoothing(positions: &[[f64; 3]], faces: &[[u32; 3]]) -> f64 {
    let edge = mean_edge_length(positions, faces);
    let cap = AUTO_SMOOTHING_OF_DIAGONAL * Bounds::of(positions).diagonal() / edge;
    if cap.is_finite() {
        AUTO_SMOOTHING_EDGES.min(cap)
    } else {
        0.0
    }
}

/// Checks a curvature smoothing width: a finite number >= 0 of mean edge lengths.
pub fn check_smoothing(arg: &str, s: f64) -> Result<f64> {
    non_negative(arg, s, " of mean edge lengths")
}

/// How fast suggestive contours come in past the threshold, relative to the feature size squared
/// (the authors' implementation fades them the same way): a line whose derivative test passes
/// by this much has strength 1/2.
pub const SUGGESTIVE_FADE: f64 = 0.03;

/// The strength of a line whose test passes by `excess` (>= 0): excess / (fade + excess), 0 at
/// the threshold and toward 1 well past it.
fn strength(excess: f64, fade: f64) -> f64 {
    let s = excess / (fade + excess);
    if s.is_finite() {
        s.clamp(0.0, 1.0)
    } else {
        1.0
    }
}

/// Checks a suggestive-contour threshold: a finite number >= 0.
pub fn check_threshold(arg: &str, t: f64) -> Result<f64> {
    non_negative(arg, t, "")
}

fn non_negative(arg: &str, x: f64, unit: &str) -> Result<f64> {
    if x.is_finite() && x >= 0.0 {
        Ok(x)
    } else {
        Err(Error::invalid(arg, format!("must be a finite number{unit} >= 0, got {x}")))
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

/// Smooth contours of one view: the zero set of n . (eye - p) over the faces (n . d for a view
/// direction d), with `normals` the vertex normals the surface is shaded with, interpolated
/// unnormalised as Hertzmann and Zorin do (the same zero set as with the unit vector to the
/// eye, without a square root per corner), visiting only the clusters where it may change
/// sign.
pub fn smooth_contours(
    positions: &[[f64; 3]],
    clusters: &FaceClusters,
    normals: &[[f64; 3]],
    view: View,
) -> Polylines {
    let faces = clusters.select(view, |s| s == Sides::Both);
    let facing = |v: u32| {
        let (n, p) = (normals[v as usize], positions[v as usize]);
        match view {
            View::Eye(e) => dot(n, sub(e, p)),
            View::Direction(d) => -dot(n, d),
        }
    };
    zero_set(positions, &faces, facing, |_| [], |_| 1.0)
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

/// The radial curvature's fields at one vertex of a basis (local numbering) in one view.
#[derive(Clone, Copy, Debug)]
pub struct Radial {
    /// kr sin^2(theta), theta the angle of the view to the normal: the same zero set as kr
    /// where the view is not along the normal.
    pub kr_sin2: f64,
    /// sin^2(theta).
    pub sin2: f64,
    /// D_w kr sin(theta) / cos(theta) with its terms as below; the derivative test is
    /// `num - cutoff * ndotv` (-1 where the view is along the normal: no direction w).
    pub num: Option<f64>,
    pub ndotv: f64,
}

impl Radial {
    /// The derivative test against `cutoff` (relative to nothing: 1 / length^2): positive
    /// where it passes.
    pub fn test(&self, cutoff: f64) -> f64 {
        self.num.map_or(-1.0, |num| num - cutoff * self.ndotv)
    }
}

impl SuggestiveBasis {
    /// The radial curvature's fields at vertex `local` seen from `view`.
    pub fn radial(&self, local: u32, view: View) -> Radial {
        let c = &self.curvature;
        let i = self.vertices[local as usize] as usize;
        let v = to_viewer(view, self.positions[local as usize]);
        let ndotv = dot(c.normals[i], v);
        let (u, w) = (dot(v, c.d1[i]), dot(v, c.d2[i]));
        let (u2, w2) = (u * u, w * w);
        let sin2 = u2 + w2;
        let kr_sin2 = c.k1[i] * u2 + c.k2[i] * w2;
        if !(sin2 > 1e-12) {
            return Radial { kr_sin2, sin2, num: None, ndotv };
        }
        let [c0, c1, c2, c3] = c.derivatives[i];
        // D_w kr sin(theta) / cos(theta): the third-order term C(w, w, w) and the term of the
        // principal frame's turning (the torsion along w)
        let cw = u2 * (u * c0 + 3.0 * w * c1) + w2 * (3.0 * u * c2 + w * c3);
        let torsion = (c.k2[i] - c.k1[i]) * u * w / sin2;
        let num = cw / sin2 - 2.0 * ndotv * torsion * torsion;
        Radial { kr_sin2, sin2, num: Some(num), ndotv }
    }

    /// Its vertices' positions (local numbering).
    pub fn positions(&self) -> &[[f64; 3]] {
        &self.positions
    }

    /// The derivative threshold `threshold` (relative to the feature size squared) and the
    /// fade `SUGGESTIVE_FADE` in the mesh's units (1 / length^2).
    pub fn cutoff_and_fade(&self, threshold: f64) -> (f64, f64) {
        let squared = self.feature_size * self.feature_size;
        (threshold / squared, SUGGESTIVE_FADE / squared)
    }

    /// The faces a view can find suggestive contours on: a cluster that faces away fails the
    /// n . v > 0 condition everywhere.
    pub fn faces_seen(&self, view: View) -> Vec<&[[u32; 3]]> {
        self.clusters.select(view, |s| s != Sides::Back)
    }

    /// How many vertices it numbers.
    pub fn n_vertices(&self) -> usize {
        self.vertices.len()
    }
}

/// The strength of a suggestive contour's point from its derivative test and n . v
/// (interpolated there): the test divided by n . v is how far D_w kr / |w| passes the threshold.
pub fn test_strength(test: f64, ndotv: f64, fade: f64) -> f64 {
    strength(test / ndotv, fade)
}

/// Suggestive contours of one view from the mesh's curvature (its normals and principal
/// frame): the zero set of kr where D_w kr / |w| > threshold / feature_size^2 and n . v > 0,
/// over the faces where some view finds kr = 0.
pub fn suggestive_contours(basis: &SuggestiveBasis, view: View, threshold: f64) -> Polylines {
    suggestive_contours_marking(basis, view, threshold, |_| {})
}

/// `suggestive_contours`, calling `mark` with each face a line runs through.
pub fn suggestive_contours_marking(
    basis: &SuggestiveBasis,
    view: View,
    threshold: f64,
    mark: impl Fn(&[u32; 3]) + Sync,
) -> Polylines {
    let (cutoff, fade) = basis.cutoff_and_fade(threshold);
    zero_set_marking(
        &basis.positions,
        &basis.faces_seen(view),
        |v| basis.radial(v, view).kr_sin2,
        |v| {
            let r = basis.radial(v, view);
            [r.test(cutoff), r.ndotv]
        },
        |[test, ndotv]| test_strength(test, ndotv, fade),
        mark,
    )
}

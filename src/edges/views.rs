//! One view's lines of a mesh, asked for by name: its silhouette edges, its smooth contours or
//! its suggestive contours (`Query`); and `MeshLines`, which keeps what they are found from so
//! that many views of one mesh share it.

use std::sync::OnceLock;

use super::contours::{check_smoothing, check_threshold, ContourMesh, DEFAULT_SUGGESTIVE_THRESHOLD};
use super::outlines::{Outline, Statics};
use super::zero_set::Polylines;
use super::{EdgeIndex, View};
use crate::cancel::Cancel;
use crate::error::{Error, Result};
use crate::real::{Real, Vec3};

/// What one view of a mesh is asked for.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Query {
    Silhouette,
    Contours,
    Suggestive { threshold: f64, smoothing: Option<f64> },
}

/// The lines of one view: edges (vertex pairs) or polylines.
pub enum Lines {
    Edges(Vec<[u32; 2]>),
    Polylines(Polylines),
}

impl Query {
    /// `what` ("silhouette", "contours" or "suggestive"); the suggestive contours' `threshold`
    /// and curvature `smoothing`, read only for them, take their defaults when None.
    pub fn parse(
        what: &str,
        threshold: impl FnOnce() -> Result<Option<f64>>,
        smoothing: impl FnOnce() -> Result<Option<f64>>,
    ) -> Result<Query> {
        Ok(match what {
            "silhouette" => Query::Silhouette,
            "contours" => Query::Contours,
            "suggestive" => Query::Suggestive {
                threshold: threshold()?
                    .map(|t| check_threshold("threshold", t))
                    .transpose()?
                    .unwrap_or(DEFAULT_SUGGESTIVE_THRESHOLD),
                smoothing: smoothing()?.map(|s| check_smoothing("smoothing", s)).transpose()?,
            },
            other => return Err(Error::invalid("what", format!("no view query {other:?}"))),
        })
    }

    /// The lines asked for of a mesh, building only what they need: the edge index for
    /// silhouettes, the contour mesh for contours.
    pub fn lines<T: Real>(
        self,
        positions: &[Vec3<T>],
        faces: &[[u32; 3]],
        weld: bool,
        view: View,
        cancel: &Cancel,
    ) -> Result<Lines> {
        match self {
            Query::Silhouette => EdgeIndex::build(positions, faces, weld)?.silhouette(view).map(Lines::Edges),
            _ => self.trace(&ContourMesh::build(positions, faces, weld), view, cancel),
        }
    }

    /// The contours asked for, traced on `mesh`.
    fn trace(self, mesh: &ContourMesh, view: View, cancel: &Cancel) -> Result<Lines> {
        let lines = match self {
            Query::Suggestive { threshold, smoothing } => {
                mesh.suggestive(view, threshold, smoothing, cancel)?
            }
            _ => mesh.smooth(view),
        };
        Ok(Lines::Polylines(lines))
    }
}

/// The once-per-mesh part of finding lines; immutable, so one serves many threads. The outlines
/// at each crease angle are kept as they are found, and what contours are traced on (normals;
/// the curvature once suggestive contours are asked) is built on the first contour asked for.
pub struct MeshLines {
    pub index: EdgeIndex,
    statics: Statics,
    faces: Vec<[u32; 3]>,
    weld: bool,
    contours: OnceLock<ContourMesh>,
}

impl MeshLines {
    pub fn build<T: Real>(positions: &[Vec3<T>], faces: &[[u32; 3]], weld: bool) -> Result<MeshLines> {
        let index = EdgeIndex::build(positions, faces, weld)?;
        let faces = faces.to_vec();
        Ok(MeshLines { index, statics: Default::default(), faces, weld, contours: OnceLock::new() })
    }

    /// One view's lines (see `Query`).
    pub fn view_lines(&self, query: Query, view: View, cancel: &Cancel) -> Result<Lines> {
        match query {
            Query::Silhouette => self.index.silhouette(view).map(Lines::Edges),
            _ => {
                let build = || ContourMesh::build(self.index.positions(), &self.faces, self.weld);
                query.trace(self.contours.get_or_init(build), view, cancel)
            }
        }
    }

    /// The outline set of one view: silhouettes, boundaries, creases and non-manifold edges,
    /// each edge once, with each edge's kind.
    pub fn outlines(&self, crease_angle: f64, view: View) -> Result<Outline> {
        let index = &self.index;
        let s = self.statics.at(crease_angle, 0.0, 180.0, || index.feature_edges(crease_angle))?;
        Ok(s.with_silhouettes(&index.silhouette(view)?))
    }
}

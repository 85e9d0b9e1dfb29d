//! Python bindings for `crate::edges`. The public API, docstrings and result classes live in
//! `python/toonmesh/edges.py`; these are the underscored entry points it calls.

use std::sync::OnceLock;

use numpy::ndarray::Dimension;
use numpy::{
    PyArray1, PyArray2, PyArrayMethods, PyReadonlyArray, PyReadonlyArray2, PyReadonlyArray3, PyUntypedArray,
    PyUntypedArrayMethods,
};
use pyo3::prelude::*;
use pyo3::IntoPyObjectExt;

use super::args;
use super::convert::{
    by_dtype, grid_to_numpy, index_rows_to_numpy, indices_to_numpy, native_order, on_positions, positions,
    rows_to_numpy, vec_to_numpy,
};
use super::mesh_input::MeshInput;
use super::runtime::{detached, detached_cancellable};
use crate::cancel::Cancel;
use crate::edges::chains::chain_edges;
use crate::edges::contours::{check_smoothing, check_threshold, ContourMesh, DEFAULT_SUGGESTIVE_THRESHOLD};
use crate::edges::detect::{paper_gradient, threshold_mask};
use crate::edges::feature::FeatureEdges;
use crate::edges::outlines::Statics;
use crate::edges::sobel::{sobel, Convention, Output};
use crate::edges::zero_set::Polylines;
use crate::edges::{find_feature_edges, EdgeIndex, View};
use crate::error::{Error, Result};
use crate::mesh::curvature::curvature;
use crate::real::Real;

type Pairs<'py> = Bound<'py, PyArray2<i64>>;
type Indices<'py> = Bound<'py, PyArray1<i64>>;
/// boundary, crease, crease angles (degrees), crease convex, non-manifold, degenerate faces
type FeatureOut<'py> =
    (Pairs<'py>, Pairs<'py>, Bound<'py, PyArray1<f64>>, Bound<'py, PyArray1<bool>>, Pairs<'py>, Indices<'py>);

fn feature_to_numpy(py: Python<'_>, fe: FeatureEdges, degenerate: Vec<u32>) -> FeatureOut<'_> {
    (
        index_rows_to_numpy(py, fe.boundary),
        index_rows_to_numpy(py, fe.crease),
        vec_to_numpy(py, fe.crease_angle),
        vec_to_numpy(py, fe.crease_convex),
        index_rows_to_numpy(py, fe.nonmanifold),
        indices_to_numpy(py, degenerate),
    )
}

/// The view from `eye=` or `direction=` (None or absent: not given).
fn view_of(eye: Option<&Bound<'_, PyAny>>, direction: Option<&Bound<'_, PyAny>>) -> Result<View> {
    let eye = args::optional("eye", eye, args::triple)?;
    let direction = args::optional("direction", direction, args::triple)?;
    match (eye, direction) {
        (Some(e), None) => View::Eye(e).check(),
        (None, Some(d)) => View::Direction(d).check(),
        _ => Err(Error::invalid(
            "eye, direction",
            "give exactly one of eye= (perspective) or direction= (orthographic)",
        )),
    }
}

/// A crease threshold in degrees, read and checked.
fn crease_angle_of(obj: &Bound<'_, PyAny>) -> Result<f64> {
    let angle = args::number("crease_angle", obj)?;
    crate::edges::feature::check_crease_angle(angle)?;
    Ok(angle)
}

#[pyfunction]
fn _feature_edges<'py>(
    py: Python<'py>,
    vertices: &Bound<'py, PyAny>,
    faces: &Bound<'py, PyAny>,
    crease_angle: &Bound<'py, PyAny>,
    weld: &Bound<'py, PyAny>,
) -> PyResult<FeatureOut<'py>> {
    let crease_angle = crease_angle_of(crease_angle)?;
    let weld = args::flag("weld", weld)?;
    let mesh = MeshInput::read(vertices, faces)?;
    let (fe, degenerate) =
        mesh.run(py, faces, |p, f, _| on_positions!(p, v => find_feature_edges(v, f, crease_angle, weld)))?;
    Ok(feature_to_numpy(py, fe, degenerate))
}

/// k1, k2 (N,), d1, d2, normals (N, 3), derivatives (N, 4), all float64
type CurvatureOut<'py> = (
    Bound<'py, PyArray1<f64>>,
    Bound<'py, PyArray1<f64>>,
    Bound<'py, PyArray2<f64>>,
    Bound<'py, PyArray2<f64>>,
    Bound<'py, PyArray2<f64>>,
    Bound<'py, PyArray2<f64>>,
);

#[pyfunction]
#[pyo3(signature = (vertices, faces, smoothing))]
fn _curvature<'py>(
    py: Python<'py>,
    vertices: &Bound<'py, PyAny>,
    faces: &Bound<'py, PyAny>,
    smoothing: &Bound<'py, PyAny>,
) -> PyResult<CurvatureOut<'py>> {
    let smoothing = args::number("smoothing", smoothing).and_then(|s| check_smoothing("smoothing", s))?;
    let mesh = MeshInput::read(vertices, faces)?;
    let c = mesh.run(py, faces, |p, f, cancel| on_positions!(p, v => curvature(v, f, smoothing, cancel)))?;
    Ok((
        vec_to_numpy(py, c.k1),
        vec_to_numpy(py, c.k2),
        rows_to_numpy(py, c.d1),
        rows_to_numpy(py, c.d2),
        rows_to_numpy(py, c.normals),
        rows_to_numpy(py, c.derivatives),
    ))
}

/// What one view of a mesh is asked for: its silhouette edges, its smooth contours or its
/// suggestive contours.
#[derive(Clone, Copy)]
enum Query {
    Silhouette,
    Contours,
    Suggestive { threshold: f64, smoothing: Option<f64> },
}

impl Query {
    /// `what` ("silhouette", "contours" or "suggestive") and its view, read from the arguments;
    /// the suggestive contours' threshold and curvature smoothing take their defaults when None.
    fn read(
        what: &str,
        (eye, direction): (Option<&Bound<'_, PyAny>>, Option<&Bound<'_, PyAny>>),
        threshold: Option<&Bound<'_, PyAny>>,
        smoothing: Option<&Bound<'_, PyAny>>,
    ) -> Result<(Query, View)> {
        let view = view_of(eye, direction)?;
        let query = match what {
            "silhouette" => Query::Silhouette,
            "contours" => Query::Contours,
            "suggestive" => Query::Suggestive {
                threshold: args::optional("threshold", threshold, args::number)?
                    .map(|t| check_threshold("threshold", t))
                    .transpose()?
                    .unwrap_or(DEFAULT_SUGGESTIVE_THRESHOLD),
                smoothing: args::optional("smoothing", smoothing, args::number)?
                    .map(|s| check_smoothing("smoothing", s))
                    .transpose()?,
            },
            other => return Err(Error::invalid("what", format!("no view query {other:?}"))),
        };
        Ok((query, view))
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

/// The lines of one view: edges (vertex pairs) or polylines.
enum Lines {
    Edges(Vec<[u32; 2]>),
    Polylines(Polylines),
}

impl Lines {
    /// Edges as (K, 2) int64; polylines as their flat (P, 3) points and int64 line starts.
    fn into_python(self, py: Python<'_>) -> PyResult<Bound<'_, PyAny>> {
        match self {
            Lines::Edges(e) => Ok(index_rows_to_numpy(py, e).into_any()),
            Lines::Polylines(l) => {
                (rows_to_numpy(py, l.points), indices_to_numpy(py, l.starts)).into_bound_py_any(py)
            }
        }
    }
}

/// One view's lines of a mesh (see `Query`), building only what they need: the edge index for
/// silhouettes, the contour mesh for contours.
#[pyfunction]
#[pyo3(signature = (what, vertices, faces, eye, direction, weld, threshold = None, smoothing = None))]
#[allow(clippy::too_many_arguments)]
fn _view_lines<'py>(
    py: Python<'py>,
    what: &str,
    vertices: &Bound<'py, PyAny>,
    faces: &Bound<'py, PyAny>,
    eye: Option<&Bound<'py, PyAny>>,
    direction: Option<&Bound<'py, PyAny>>,
    weld: &Bound<'py, PyAny>,
    threshold: Option<&Bound<'py, PyAny>>,
    smoothing: Option<&Bound<'py, PyAny>>,
) -> PyResult<Bound<'py, PyAny>> {
    let (query, view) = Query::read(what, (eye, direction), threshold, smoothing)?;
    let weld = args::flag("weld", weld)?;
    let mesh = MeshInput::read(vertices, faces)?;
    let lines = mesh.run(py, faces, |p, f, cancel| match query {
        Query::Silhouette => {
            on_positions!(p, v => EdgeIndex::build(v, f, weld)?.silhouette(view)).map(Lines::Edges)
        }
        _ => query.trace(&on_positions!(p, v => ContourMesh::build(v, f, weld)), view, cancel),
    })?;
    lines.into_python(py)
}

/// The once-per-mesh part of outline finding; immutable, so one index serves many threads.
#[pyclass(frozen, name = "_EdgeIndex", module = "toonmesh._core")]
struct PyEdgeIndex {
    inner: EdgeIndex,
    statics: Statics,
    /// The faces and the weld rule, and what contours are traced on (normals; the curvature once
    /// suggestive contours are asked), built on the first contour asked for.
    faces: Vec<[u32; 3]>,
    weld: bool,
    contours: OnceLock<ContourMesh>,
}

impl PyEdgeIndex {
    fn contour_mesh(&self) -> &ContourMesh {
        self.contours.get_or_init(|| ContourMesh::build(self.inner.positions(), &self.faces, self.weld))
    }
}

#[pymethods]
impl PyEdgeIndex {
    #[new]
    fn new(
        py: Python<'_>,
        vertices: &Bound<'_, PyAny>,
        faces: &Bound<'_, PyAny>,
        weld: &Bound<'_, PyAny>,
    ) -> PyResult<Self> {
        let weld = args::flag("weld", weld)?;
        let mesh = MeshInput::read(vertices, faces)?;
        let (inner, faces) = mesh.run(
            py,
            faces,
            |p, f, _| on_positions!(p, v => Ok((EdgeIndex::build(v, f, weld)?, f.to_vec()))),
        )?;
        Ok(PyEdgeIndex { inner, statics: Default::default(), faces, weld, contours: OnceLock::new() })
    }

    /// One view's lines (see `_view_lines`); the contour mesh is built on the first contour
    /// asked for, and the curvature on the first suggestive one, and both are kept.
    #[pyo3(signature = (what, eye, direction, threshold = None, smoothing = None))]
    fn view_lines<'py>(
        &self,
        py: Python<'py>,
        what: &str,
        eye: Option<&Bound<'py, PyAny>>,
        direction: Option<&Bound<'py, PyAny>>,
        threshold: Option<&Bound<'py, PyAny>>,
        smoothing: Option<&Bound<'py, PyAny>>,
    ) -> PyResult<Bound<'py, PyAny>> {
        let (query, view) = Query::read(what, (eye, direction), threshold, smoothing)?;
        let lines = detached_cancellable(py, |cancel| match query {
            Query::Silhouette => self.inner.silhouette(view).map(Lines::Edges),
            _ => query.trace(self.contour_mesh(), view, cancel),
        })?;
        lines.into_python(py)
    }

    /// The outline set of one view: silhouettes, boundaries, creases and non-manifold edges,
    /// each edge once, and with `kinds` each edge's kind (`edges::outlines::LineKind` as an
    /// int8; None without).
    #[pyo3(signature = (crease_angle, eye, direction, kinds))]
    fn outlines<'py>(
        &self,
        py: Python<'py>,
        crease_angle: &Bound<'py, PyAny>,
        eye: Option<&Bound<'py, PyAny>>,
        direction: Option<&Bound<'py, PyAny>>,
        kinds: &Bound<'py, PyAny>,
    ) -> PyResult<(Pairs<'py>, Option<Bound<'py, PyArray1<i8>>>)> {
        let crease_angle = crease_angle_of(crease_angle)?;
        let view = view_of(eye, direction)?;
        let with_kinds = args::flag("kinds", kinds)?;
        let (inner, statics) = (&self.inner, &self.statics);
        let all = detached(py, || {
            let s = statics.at(crease_angle, 0.0, 180.0, || inner.feature_edges(crease_angle))?;
            Ok(s.with_silhouettes(&inner.silhouette(view)?))
        })?;
        let kinds = with_kinds.then(|| vec_to_numpy(py, all.kinds.iter().map(|&k| k as i8).collect()));
        Ok((index_rows_to_numpy(py, all.edges), kinds))
    }

    fn feature_edges<'py>(
        &self,
        py: Python<'py>,
        crease_angle: &Bound<'py, PyAny>,
    ) -> PyResult<FeatureOut<'py>> {
        let crease_angle = crease_angle_of(crease_angle)?;
        let inner = &self.inner;
        let (fe, degenerate) =
            detached(py, || Ok((inner.feature_edges(crease_angle)?, inner.degenerate_faces())))?;
        Ok(feature_to_numpy(py, fe, degenerate))
    }

    fn face_normals<'py>(&self, py: Python<'py>) -> Bound<'py, PyArray2<f64>> {
        rows_to_numpy(py, self.inner.normals().to_vec())
    }

    fn vertices<'py>(&self, py: Python<'py>) -> Bound<'py, PyArray2<f64>> {
        rows_to_numpy(py, self.inner.positions().to_vec())
    }

    fn weld_map<'py>(&self, py: Python<'py>) -> Option<Indices<'py>> {
        self.inner.weld_map().map(|m| indices_to_numpy(py, m.iter().copied()))
    }

    #[getter]
    fn n_vertices(&self) -> usize {
        self.inner.n_vertices()
    }

    #[getter]
    fn n_faces(&self) -> usize {
        self.inner.n_faces()
    }

    #[getter]
    fn n_edges(&self) -> usize {
        self.inner.n_edges()
    }
}

/// Reads (K, 2) non-negative integer pairs.
fn read_pairs(arg: &str, obj: &Bound<'_, PyAny>) -> Result<Vec<[u32; 2]>> {
    let a = obj.cast::<PyUntypedArray>().map_err(|_| Error::wrong_type(arg, "expected a NumPy array"))?;
    if a.ndim() != 2 || a.shape()[1] != 2 {
        return Err(Error::invalid(arg, format!("expected shape (K, 2), got {:?}", a.shape())));
    }
    let x = obj
        .extract::<PyReadonlyArray2<'_, i64>>()
        .map_err(|_| Error::wrong_type(arg, "expected an int64 array (the Python wrapper converts)"))?;
    let view = x.as_array();
    let mut out = Vec::with_capacity(view.nrows());
    for (k, row) in view.rows().into_iter().enumerate() {
        if row[0] < 0 || row[1] < 0 || row[0] > u32::MAX as i64 - 1 || row[1] > u32::MAX as i64 - 1 {
            return Err(Error::out_of_range(
                arg,
                format!("edge {k} has an invalid vertex index ({}, {})", row[0], row[1]),
            ));
        }
        out.push([row[0] as u32, row[1] as u32]);
    }
    Ok(out)
}

#[pyfunction]
fn _chains<'py>(py: Python<'py>, edges: &Bound<'py, PyAny>) -> PyResult<(Indices<'py>, Indices<'py>)> {
    let e = read_pairs("edges", edges)?;
    let (flat, offsets) = detached(py, || Ok(chain_edges(&e)))?;
    Ok((indices_to_numpy(py, flat), indices_to_numpy(py, offsets)))
}

/// The number of `vertices`, checked as every mesh function checks them.
#[pyfunction]
fn _vertex_count(vertices: &Bound<'_, PyAny>) -> PyResult<usize> {
    Ok(positions("vertices", vertices)?.len())
}

/// The values of an array that the Python wrapper made C-contiguous (`arg` in errors).
fn c_contiguous<'a, T: numpy::Element, D: Dimension>(
    arg: &str,
    a: &'a PyReadonlyArray<'_, T, D>,
) -> Result<&'a [T]> {
    if !a.is_c_contiguous() {
        return Err(Error::invalid(arg, "must be C-contiguous (the Python wrapper makes it so)"));
    }
    a.as_slice().map_err(|_| Error::Internal(format!("{arg} is not C-contiguous")))
}

fn sobel_typed<'py, T: Real + numpy::Element>(
    py: Python<'py>,
    image: PyReadonlyArray2<'py, T>,
    output: Output,
    convention: Convention,
) -> PyResult<Bound<'py, PyArray2<T>>> {
    let (h, w) = image.as_array().dim();
    let data = c_contiguous("image", &image)?;
    // NumPy's allocator asks the kernel for huge pages on large arrays; a Vec here would pay
    // one page fault per 4 KiB of output, which costs as much as the filter itself.
    // SAFETY: every element is written by `sobel` before the array is returned (on error it is
    // dropped unread).
    let result = unsafe { PyArray2::<T>::new(py, [h, w], false) };
    {
        let mut rw = result.readwrite();
        let out = rw.as_slice_mut().map_err(|_| Error::Internal("sobel: new array not contiguous".into()))?;
        detached(py, || sobel(data, h, w, out, output, convention))?;
    }
    Ok(result)
}

/// Sobel of a C-contiguous 2-D float32 or float64 image; the Python wrapper does dtype rules.
#[pyfunction]
fn _sobel<'py>(
    py: Python<'py>,
    image: &Bound<'py, PyAny>,
    output: &str,
    convention: &Bound<'py, PyAny>,
) -> PyResult<Bound<'py, PyAny>> {
    let output = Output::parse(output)?;
    let convention = args::text("convention", convention).and_then(|c| Convention::parse(&c))?;
    let image = &native_order(image)?;
    by_dtype!(image, PyReadonlyArray2<f32, f64>, |x| sobel_typed(py, x, output, convention).map(Bound::into_any))
        .unwrap_or_else(|| Err(Error::wrong_type("image", "expected a 2-D float32 or float64 array").into()))
}

type Edges<'py> = (Bound<'py, PyAny>, Bound<'py, PyArray2<bool>>);

fn edges_typed<'py, T: Real + numpy::Element>(
    py: Python<'py>,
    name: &str,
    buffer: PyReadonlyArray3<'py, T>,
    threshold: f64,
) -> PyResult<Edges<'py>> {
    let (h, w, c) = buffer.as_array().dim();
    let data = c_contiguous(name, &buffer)?;
    let arg = format!("{name}_threshold");
    let (gradient, mask) = detached(py, || {
        let g = paper_gradient(data, h, w, c)?;
        let m = threshold_mask(&arg, &g, threshold)?;
        Ok((g, m))
    })?;
    Ok((grid_to_numpy(py, (h, w), gradient).into_any(), grid_to_numpy(py, (h, w), mask)))
}

/// The paper's gradient max over channels of max(|Gx|, |Gy|) of a C-contiguous (H, W, C) float
/// buffer, and the mask where it exceeds the threshold. `name` ("normal" or "depth") names the
/// buffer and its threshold (`<name>_threshold`) in errors.
#[pyfunction]
fn _paper_edges<'py>(
    py: Python<'py>,
    name: &str,
    buffer: &Bound<'py, PyAny>,
    threshold: &Bound<'py, PyAny>,
) -> PyResult<Edges<'py>> {
    let threshold = args::number(&format!("{name}_threshold"), threshold)?;
    by_dtype!(buffer, PyReadonlyArray3<f32, f64>, |x| edges_typed(py, name, x, threshold))
        .unwrap_or_else(|| Err(Error::wrong_type(name, "expected a 3-D float32 or float64 array").into()))
}

pub fn register(m: &Bound<'_, PyModule>) -> PyResult<()> {
    m.add_function(wrap_pyfunction!(_feature_edges, m)?)?;
    m.add_function(wrap_pyfunction!(_curvature, m)?)?;
    m.add_function(wrap_pyfunction!(_view_lines, m)?)?;
    m.add_function(wrap_pyfunction!(_chains, m)?)?;
    m.add_function(wrap_pyfunction!(_sobel, m)?)?;
    m.add_function(wrap_pyfunction!(_paper_edges, m)?)?;
    m.add_function(wrap_pyfunction!(_vertex_count, m)?)?;
    m.add_class::<PyEdgeIndex>()?;
    Ok(())
}

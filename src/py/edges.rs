//! Python bindings for `crate::edges`. The public API, docstrings and result classes live in
//! `python/toonmesh/edges.py`; these are the underscored entry points it calls.

use numpy::{PyArray2, PyArrayMethods, PyReadonlyArray2, PyReadonlyArray3, PyUntypedArrayMethods};
use pyo3::prelude::*;

use super::args;
use super::convert::{array_values, by_dtype, native_order, rows, shaped_to_numpy, ToPython};
use super::mesh_input::{on_mesh, MeshInput, PositionsIn};
use super::runtime::{detached, detached_cancellable};
use crate::edges::chains::{chain_edges, vertex_pairs};
use crate::edges::contours::check_smoothing;
use crate::edges::detect::{paper_gradient, threshold_mask};
use crate::edges::feature::FeatureEdges;
use crate::edges::intersections::{among, chain, Crossing};
use crate::edges::sobel::{sobel, Convention, Output};
use crate::edges::views::{MeshLines, Query};
use crate::edges::{find_feature_edges, View};
use crate::error::{Error, Result};
use crate::mesh::bvh::triangles;
use crate::mesh::curvature::curvature;
use crate::mesh::dihedral::check_crease_angle;
use crate::mesh::positions::on_positions;

type Out<'py> = PyResult<Bound<'py, PyAny>>;

/// boundary, crease, crease angles (degrees), crease convex, non-manifold, degenerate faces
fn features(py: Python<'_>, (fe, degenerate): (FeatureEdges, Vec<u32>)) -> Out<'_> {
    (fe.boundary, fe.crease, fe.crease_angle, fe.crease_convex, fe.nonmanifold, degenerate).to_python(py)
}

/// A crease threshold in degrees, read and checked.
fn crease_angle_of(obj: &Bound<'_, PyAny>) -> Result<f64> {
    let angle = args::number("crease_angle", obj)?;
    check_crease_angle(angle).map(|()| angle)
}

/// The view from `eye=` or `direction=` (None or absent: not given).
fn view_of(eye: Option<&Bound<'_, PyAny>>, direction: Option<&Bound<'_, PyAny>>) -> Result<View> {
    let eye = args::optional("eye", eye, args::triple)?;
    View::of(eye, args::optional("direction", direction, args::triple)?)
}

/// What one view is asked for (see `Query`) and the view, from `eye=` or `direction=`.
fn query(
    what: &str,
    (eye, direction): (Option<&Bound<'_, PyAny>>, Option<&Bound<'_, PyAny>>),
    threshold: Option<&Bound<'_, PyAny>>,
    smoothing: Option<&Bound<'_, PyAny>>,
) -> Result<(Query, View)> {
    let view = view_of(eye, direction)?;
    let number = |name, obj| move || args::optional(name, obj, args::number);
    Ok((Query::parse(what, number("threshold", threshold), number("smoothing", smoothing))?, view))
}

#[pyfunction]
pub(super) fn _feature_edges<'py>(
    py: Python<'py>,
    mesh: &Bound<'py, PyAny>,
    crease_angle: &Bound<'py, PyAny>,
    weld: &Bound<'py, PyAny>,
) -> Out<'py> {
    let crease_angle = crease_angle_of(crease_angle)?;
    let weld = args::flag("weld", weld)?;
    features(py, on_mesh!(py, mesh, |v, f, _| find_feature_edges(v, f, crease_angle, weld))?)
}

/// k1, k2 (N,), d1, d2, normals (N, 3), derivatives (N, 4), all float64
#[pyfunction]
pub(super) fn _curvature<'py>(
    py: Python<'py>,
    mesh: &Bound<'py, PyAny>,
    smoothing: &Bound<'py, PyAny>,
) -> Out<'py> {
    let smoothing = args::number("smoothing", smoothing).and_then(|s| check_smoothing("smoothing", s))?;
    let c = on_mesh!(py, mesh, |v, f, cancel| curvature(v, f, smoothing, cancel))?;
    (c.k1, c.k2, c.d1, c.d2, c.normals, c.derivatives).to_python(py)
}

/// One view's lines of a mesh (see `Query::lines`).
#[pyfunction]
#[pyo3(signature = (what, mesh, eye, direction, weld, threshold = None, smoothing = None))]
pub(super) fn _view_lines<'py>(
    py: Python<'py>,
    what: &str,
    mesh: &Bound<'py, PyAny>,
    eye: Option<&Bound<'py, PyAny>>,
    direction: Option<&Bound<'py, PyAny>>,
    weld: &Bound<'py, PyAny>,
    threshold: Option<&Bound<'py, PyAny>>,
    smoothing: Option<&Bound<'py, PyAny>>,
) -> Out<'py> {
    let (query, view) = query(what, (eye, direction), threshold, smoothing)?;
    let weld = args::flag("weld", weld)?;
    on_mesh!(py, mesh, |v, f, cancel| query.lines(v, f, weld, view, cancel))?.to_python(py)
}

/// The once-per-mesh part of outline finding (`MeshLines`).
#[pyclass(frozen, name = "_EdgeIndex", module = "toonmesh._core")]
pub(super) struct PyEdgeIndex(MeshLines);

#[pymethods]
impl PyEdgeIndex {
    #[new]
    fn new(py: Python<'_>, mesh: &Bound<'_, PyAny>, weld: &Bound<'_, PyAny>) -> PyResult<Self> {
        let weld = args::flag("weld", weld)?;
        on_mesh!(py, mesh, |v, f, _| MeshLines::build(v, f, weld)).map(PyEdgeIndex)
    }

    /// One view's lines (see `_view_lines`); what contours are traced on is kept.
    #[pyo3(signature = (what, eye, direction, threshold = None, smoothing = None))]
    fn view_lines<'py>(
        &self,
        py: Python<'py>,
        what: &str,
        eye: Option<&Bound<'py, PyAny>>,
        direction: Option<&Bound<'py, PyAny>>,
        threshold: Option<&Bound<'py, PyAny>>,
        smoothing: Option<&Bound<'py, PyAny>>,
    ) -> Out<'py> {
        let (query, view) = query(what, (eye, direction), threshold, smoothing)?;
        detached_cancellable(py, |cancel| self.0.view_lines(query, view, cancel))?.to_python(py)
    }

    /// The outline set of one view (`MeshLines::outlines`), and with `kinds` each edge's kind
    /// (`edges::outlines::LineKind` as an int8; None without).
    #[pyo3(signature = (crease_angle, eye, direction, kinds))]
    fn outlines<'py>(
        &self,
        py: Python<'py>,
        crease_angle: &Bound<'py, PyAny>,
        eye: Option<&Bound<'py, PyAny>>,
        direction: Option<&Bound<'py, PyAny>>,
        kinds: &Bound<'py, PyAny>,
    ) -> Out<'py> {
        let (crease_angle, view) = (crease_angle_of(crease_angle)?, view_of(eye, direction)?);
        let with_kinds = args::flag("kinds", kinds)?;
        let all = detached(py, || self.0.outlines(crease_angle, view))?;
        let kinds = with_kinds.then(|| all.kinds.iter().map(|&k| k as i8).collect::<Vec<_>>());
        (all.edges, kinds).to_python(py)
    }

    fn feature_edges<'py>(&self, py: Python<'py>, crease_angle: &Bound<'py, PyAny>) -> Out<'py> {
        let (crease_angle, index) = (crease_angle_of(crease_angle)?, &self.0.index);
        features(py, detached(py, || Ok((index.feature_edges(crease_angle)?, index.degenerate_faces())))?)
    }

    fn face_normals<'py>(&self, py: Python<'py>) -> Out<'py> {
        self.0.index.normals().to_vec().to_python(py)
    }

    fn vertices<'py>(&self, py: Python<'py>) -> Out<'py> {
        self.0.index.positions().to_vec().to_python(py)
    }

    /// (vertices, faces, distinct edges)
    #[getter]
    fn sizes(&self) -> (usize, usize, usize) {
        let index = &self.0.index;
        (index.n_vertices(), index.n_faces(), index.n_edges())
    }
}

/// Edges (K, 2) of non-negative int64 vertex indices chained into polylines: the flat vertex
/// list and where each polyline starts.
#[pyfunction]
pub(super) fn _chains<'py>(py: Python<'py>, edges: &Bound<'py, PyAny>) -> Out<'py> {
    let x: Vec<[i64; 2]> = rows(&array_values("edges", edges, &["int64"], (&[None, Some(2)], "(K, 2)"))?.0);
    let e = vertex_pairs("edges", x.into_iter())?;
    detached(py, || Ok(chain_edges(&e)))?.to_python(py)
}

/// Every crossing among `meshes` (a list of (vertices, faces), all in one frame; see
/// `intersections::among`), with the GIL released; errors name the mesh (`meshes[2].faces`).
fn crossings(
    py: Python<'_>,
    meshes: &Bound<'_, PyAny>,
    self_intersections: &Bound<'_, PyAny>,
    brute_force: bool,
) -> PyResult<Vec<Crossing>> {
    let with_self = args::flag("self_intersections", self_intersections)?;
    let place = |i: usize| format!("meshes[{i}]");
    let inputs = args::items("meshes", meshes, "a list of meshes, each (vertices, faces)")?
        .iter()
        .enumerate()
        .map(|(i, m)| MeshInput::of(m).map_err(|e| e.in_item(&place(i))))
        .collect::<Result<Vec<_>>>()?;
    let parts: Vec<_> = inputs.iter().map(|m| (m.parts(), m.vertices.count())).collect();
    detached_cancellable(py, |cancel| {
        let faces = parts
            .iter()
            .enumerate()
            .map(|(i, ((_, f), n))| f.checked("faces", *n).map_err(|e| e.in_item(&place(i))))
            .collect::<Result<Vec<_>>>()?;
        let meshes = parts
            .iter()
            .zip(&faces)
            .map(|(((p, _), _), f)| (on_positions!(*p, v => triangles(v, f)), &f[..]));
        among(meshes.collect(), with_self, brute_force, cancel)
    })
}

/// (N, 2, 3) float64: the segments where the surfaces of `meshes` cross (see `crossings`);
/// `brute_force` compares every pair of triangles (the reference the tests hold it to).
#[pyfunction]
pub(super) fn _intersections<'py>(
    py: Python<'py>,
    meshes: &Bound<'py, PyAny>,
    self_intersections: &Bound<'py, PyAny>,
    brute_force: bool,
) -> Out<'py> {
    let found = crossings(py, meshes, self_intersections, brute_force)?;
    let flat: Vec<f64> = found.iter().flat_map(|c| c.ends.into_iter().flatten()).collect();
    shaped_to_numpy(py, vec![found.len(), 2, 3], flat)
}

/// The segments of `_intersections` chained into polylines: their flat (P, 3) float64 points
/// and int64 starts.
#[pyfunction]
pub(super) fn _intersection_lines<'py>(
    py: Python<'py>,
    meshes: &Bound<'py, PyAny>,
    self_intersections: &Bound<'py, PyAny>,
) -> Out<'py> {
    let found = crossings(py, meshes, self_intersections, false)?;
    let lines = detached(py, || Ok(chain(&found)))?;
    let mut starts = vec![0u32];
    for line in &lines {
        starts.push(starts[starts.len() - 1] + line.len() as u32);
    }
    (lines.into_iter().flatten().collect::<Vec<_>>(), starts).to_python(py)
}

/// The number of `vertices`, checked as every mesh function checks them.
#[pyfunction]
pub(super) fn _vertex_count(vertices: &Bound<'_, PyAny>) -> PyResult<usize> {
    Ok(PositionsIn::read("vertices", vertices)?.count())
}

/// `$body` on the values `$x` (f32 or f64, as NumPy holds them) and the dimensions `$dim` of
/// the argument `$arg`, a C-contiguous float `$array` (the Python wrapper makes it so) with
/// `$axes` axes; a TypeError for any other.
macro_rules! on_floats {
    ($obj:expr, $arg:expr, $array:ident, $axes:literal, |$x:ident, $dim:pat_param| $body:expr) => {
        by_dtype!($obj, $array<f32, f64>, |a| {
            let $dim = a.as_array().dim();
            if !a.is_c_contiguous() {
                return Err(Error::invalid($arg, "must be C-contiguous (the Python wrapper makes it so)").into());
            }
            let $x = a.as_slice().map_err(|e| Error::Internal(e.to_string()))?;
            $body
        })
        .unwrap_or_else(|| {
            Err(Error::wrong_type($arg, concat!("expected a ", $axes, " float32 or float64 array")).into())
        })
    };
}

/// Sobel of a C-contiguous 2-D float32 or float64 image; the Python wrapper does dtype rules.
#[pyfunction]
pub(super) fn _sobel<'py>(
    py: Python<'py>,
    image: &Bound<'py, PyAny>,
    output: &str,
    convention: &Bound<'py, PyAny>,
) -> Out<'py> {
    let output = Output::parse(output)?;
    let convention = args::text("convention", convention).and_then(|c| Convention::parse(&c))?;
    let image = &native_order(image)?;
    on_floats!(image, "image", PyReadonlyArray2, "2-D", |x, (h, w)| {
        // NumPy's allocator asks the kernel for huge pages on large arrays; a Vec here would pay
        // one page fault per 4 KiB of output, which costs as much as the filter itself.
        // SAFETY: every element is written by `sobel` before the array is returned (on error it
        // is dropped unread).
        let result = unsafe { PyArray2::new(py, [h, w], false) };
        let mut rw = result.readwrite();
        let out = rw.as_slice_mut().map_err(|_| Error::Internal("sobel: new array not contiguous".into()))?;
        detached(py, || sobel(x, h, w, out, output, convention))?;
        drop(rw);
        Ok(result.into_any())
    })
}

/// The paper's gradient max over channels of max(|Gx|, |Gy|) of a C-contiguous (H, W, C) float
/// buffer, and the mask where it exceeds the threshold. `name` ("normal" or "depth") names the
/// buffer and its threshold (`<name>_threshold`) in errors.
#[pyfunction]
pub(super) fn _paper_edges<'py>(
    py: Python<'py>,
    name: &str,
    buffer: &Bound<'py, PyAny>,
    threshold: &Bound<'py, PyAny>,
) -> Out<'py> {
    let arg = format!("{name}_threshold");
    let threshold = args::number(&arg, threshold)?;
    on_floats!(buffer, name, PyReadonlyArray3, "3-D", |x, (h, w, c)| {
        let gradient = detached(py, || paper_gradient(x, h, w, c))?;
        let mask = detached(py, || threshold_mask(&arg, &gradient, threshold))?;
        (shaped_to_numpy(py, vec![h, w], gradient)?, shaped_to_numpy(py, vec![h, w], mask)?).to_python(py)
    })
}

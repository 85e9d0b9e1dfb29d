//! Python bindings for `crate::edges`. The public API, docstrings and result classes live in
//! `python/toonmesh/edges.py`; these are the underscored entry points it calls.

use std::sync::OnceLock;

use numpy::ndarray::Array2;
use numpy::{
    IntoPyArray, PyArray1, PyArray2, PyArrayMethods, PyReadonlyArray2, PyReadonlyArray3, PyUntypedArray,
    PyUntypedArrayMethods,
};
use pyo3::prelude::*;

use super::args;
use super::convert::{native_order, positions, vec_to_numpy, Positions};
use super::errors::to_py;
use super::mesh_input::{on_positions, MeshInput, PositionsRef};
use super::runtime::{detached, detached_cancellable};
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
/// boundary, crease, crease angles (degrees), crease convex, non-manifold, degenerate faces
type FeatureOut<'py> = (
    Pairs<'py>,
    Pairs<'py>,
    Bound<'py, PyArray1<f64>>,
    Bound<'py, PyArray1<bool>>,
    Pairs<'py>,
    Bound<'py, PyArray1<i64>>,
);

fn pairs_to_numpy(py: Python<'_>, pairs: Vec<[u32; 2]>) -> Pairs<'_> {
    let k = pairs.len();
    let flat: Vec<i64> = pairs.into_iter().flat_map(|p| p.map(|i| i as i64)).collect();
    Array2::from_shape_vec((k, 2), flat).expect("length is 2k").into_pyarray(py)
}

fn feature_to_numpy(py: Python<'_>, fe: FeatureEdges, degenerate: Vec<u32>) -> FeatureOut<'_> {
    (
        pairs_to_numpy(py, fe.boundary),
        pairs_to_numpy(py, fe.crease),
        vec_to_numpy(py, fe.crease_angle),
        vec_to_numpy(py, fe.crease_convex),
        pairs_to_numpy(py, fe.nonmanifold),
        vec_to_numpy(py, degenerate.into_iter().map(|f| f as i64).collect()),
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
    let crease_angle = crease_angle_of(crease_angle).map_err(to_py)?;
    let weld = args::flag("weld", weld).map_err(to_py)?;
    let mesh = MeshInput::read(vertices, faces).map_err(to_py)?;
    let (fe, degenerate) =
        mesh.run(py, faces, |p, f, _| on_positions!(p, v => find_feature_edges(v, f, crease_angle, weld)))?;
    Ok(feature_to_numpy(py, fe, degenerate))
}

#[pyfunction]
#[pyo3(signature = (vertices, faces, eye, direction, weld))]
fn _silhouette<'py>(
    py: Python<'py>,
    vertices: &Bound<'py, PyAny>,
    faces: &Bound<'py, PyAny>,
    eye: Option<&Bound<'py, PyAny>>,
    direction: Option<&Bound<'py, PyAny>>,
    weld: &Bound<'py, PyAny>,
) -> PyResult<Pairs<'py>> {
    let s = on_view(
        py,
        (vertices, faces),
        (eye, direction),
        weld,
        |p, f, view, weld, _| on_positions!(p, v => EdgeIndex::build(v, f, weld)?.silhouette(view)),
    )?;
    Ok(pairs_to_numpy(py, s))
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

fn rows_to_numpy<const K: usize>(py: Python<'_>, rows: Vec<[f64; K]>) -> Bound<'_, PyArray2<f64>> {
    let n = rows.len();
    Array2::from_shape_vec((n, K), rows.into_iter().flatten().collect()).expect("n * K").into_pyarray(py)
}

#[pyfunction]
#[pyo3(signature = (vertices, faces, smoothing))]
fn _curvature<'py>(
    py: Python<'py>,
    vertices: &Bound<'py, PyAny>,
    faces: &Bound<'py, PyAny>,
    smoothing: &Bound<'py, PyAny>,
) -> PyResult<CurvatureOut<'py>> {
    let smoothing =
        args::number("smoothing", smoothing).and_then(|s| check_smoothing("smoothing", s)).map_err(to_py)?;
    let mesh = MeshInput::read(vertices, faces).map_err(to_py)?;
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

type PolylinesOut<'py> = (Bound<'py, PyArray2<f64>>, Bound<'py, PyArray1<i64>>);

fn polylines_to_numpy(py: Python<'_>, lines: Polylines) -> PolylinesOut<'_> {
    (rows_to_numpy(py, lines.points), vec_to_numpy(py, lines.starts.into_iter().map(i64::from).collect()))
}

/// `work` on a mesh and a view read from the arguments (the GIL released, Ctrl-C honoured).
fn on_view<R: Send>(
    py: Python<'_>,
    (vertices, faces): (&Bound<'_, PyAny>, &Bound<'_, PyAny>),
    (eye, direction): (Option<&Bound<'_, PyAny>>, Option<&Bound<'_, PyAny>>),
    weld: &Bound<'_, PyAny>,
    work: impl Fn(PositionsRef<'_>, &[[u32; 3]], View, bool, &crate::cancel::Cancel) -> Result<R> + Send + Sync,
) -> PyResult<R> {
    let view = view_of(eye, direction).map_err(to_py)?;
    let weld = args::flag("weld", weld).map_err(to_py)?;
    let mesh = MeshInput::read(vertices, faces).map_err(to_py)?;
    mesh.run(py, faces, |p, f, cancel| work(p, f, view, weld, cancel))
}

/// Lines of one view traced on a `ContourMesh` by `trace`, as flat points and line starts.
fn view_lines<'py>(
    py: Python<'py>,
    mesh: (&Bound<'py, PyAny>, &Bound<'py, PyAny>),
    view: (Option<&Bound<'py, PyAny>>, Option<&Bound<'py, PyAny>>),
    weld: &Bound<'py, PyAny>,
    trace: impl Fn(&ContourMesh, View, &crate::cancel::Cancel) -> Result<Polylines> + Send + Sync,
) -> PyResult<PolylinesOut<'py>> {
    let lines = on_view(py, mesh, view, weld, |p, f, view, weld, cancel| {
        let m = on_positions!(p, v => ContourMesh::build(v, f, weld));
        trace(&m, view, cancel)
    })?;
    Ok(polylines_to_numpy(py, lines))
}

#[pyfunction]
#[pyo3(signature = (vertices, faces, eye, direction, weld))]
fn _contours<'py>(
    py: Python<'py>,
    vertices: &Bound<'py, PyAny>,
    faces: &Bound<'py, PyAny>,
    eye: Option<&Bound<'py, PyAny>>,
    direction: Option<&Bound<'py, PyAny>>,
    weld: &Bound<'py, PyAny>,
) -> PyResult<PolylinesOut<'py>> {
    view_lines(py, (vertices, faces), (eye, direction), weld, |m, view, _| Ok(m.smooth(view)))
}

/// The suggestive-contour arguments, threshold and curvature smoothing; None takes the
/// default.
fn read_suggestive(threshold: &Bound<'_, PyAny>, smoothing: &Bound<'_, PyAny>) -> Result<(f64, Option<f64>)> {
    let threshold = match threshold.is_none() {
        true => DEFAULT_SUGGESTIVE_THRESHOLD,
        false => check_threshold("threshold", args::number("threshold", threshold)?)?,
    };
    let smoothing = match smoothing.is_none() {
        true => None,
        false => Some(check_smoothing("smoothing", args::number("smoothing", smoothing)?)?),
    };
    Ok((threshold, smoothing))
}

#[pyfunction]
#[pyo3(signature = (vertices, faces, eye, direction, weld, threshold, smoothing))]
#[allow(clippy::too_many_arguments)]
fn _suggestive_contours<'py>(
    py: Python<'py>,
    vertices: &Bound<'py, PyAny>,
    faces: &Bound<'py, PyAny>,
    eye: Option<&Bound<'py, PyAny>>,
    direction: Option<&Bound<'py, PyAny>>,
    weld: &Bound<'py, PyAny>,
    threshold: &Bound<'py, PyAny>,
    smoothing: &Bound<'py, PyAny>,
) -> PyResult<PolylinesOut<'py>> {
    let (threshold, smoothing) = read_suggestive(threshold, smoothing).map_err(to_py)?;
    view_lines(py, (vertices, faces), (eye, direction), weld, |m, view, cancel| {
        m.suggestive(view, threshold, smoothing, cancel)
    })
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
        let weld = args::flag("weld", weld).map_err(to_py)?;
        let mesh = MeshInput::read(vertices, faces).map_err(to_py)?;
        let (inner, faces) = mesh.run(
            py,
            faces,
            |p, f, _| on_positions!(p, v => Ok((EdgeIndex::build(v, f, weld)?, f.to_vec()))),
        )?;
        Ok(PyEdgeIndex { inner, statics: Default::default(), faces, weld, contours: OnceLock::new() })
    }

    /// Smooth contours of one view, as flat points and line starts.
    #[pyo3(signature = (eye, direction))]
    fn contours<'py>(
        &self,
        py: Python<'py>,
        eye: Option<&Bound<'py, PyAny>>,
        direction: Option<&Bound<'py, PyAny>>,
    ) -> PyResult<PolylinesOut<'py>> {
        let view = view_of(eye, direction).map_err(to_py)?;
        let lines = detached(py, || Ok(self.contour_mesh().smooth(view)))?;
        Ok(polylines_to_numpy(py, lines))
    }

    /// Suggestive contours of one view (the curvature is computed on the first call and kept).
    #[pyo3(signature = (eye, direction, threshold, smoothing))]
    fn suggestive_contours<'py>(
        &self,
        py: Python<'py>,
        eye: Option<&Bound<'py, PyAny>>,
        direction: Option<&Bound<'py, PyAny>>,
        threshold: &Bound<'py, PyAny>,
        smoothing: &Bound<'py, PyAny>,
    ) -> PyResult<PolylinesOut<'py>> {
        let view = view_of(eye, direction).map_err(to_py)?;
        let (threshold, smoothing) = read_suggestive(threshold, smoothing).map_err(to_py)?;
        let lines = detached_cancellable(py, |cancel| {
            self.contour_mesh().suggestive(view, threshold, smoothing, cancel)
        })?;
        Ok(polylines_to_numpy(py, lines))
    }

    #[pyo3(signature = (eye, direction))]
    fn silhouette<'py>(
        &self,
        py: Python<'py>,
        eye: Option<&Bound<'py, PyAny>>,
        direction: Option<&Bound<'py, PyAny>>,
    ) -> PyResult<Pairs<'py>> {
        let view = view_of(eye, direction).map_err(to_py)?;
        let inner = &self.inner;
        let s = detached(py, || inner.silhouette(view))?;
        Ok(pairs_to_numpy(py, s))
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
        let crease_angle = crease_angle_of(crease_angle).map_err(to_py)?;
        let view = view_of(eye, direction).map_err(to_py)?;
        let with_kinds = args::flag("kinds", kinds).map_err(to_py)?;
        let (inner, statics) = (&self.inner, &self.statics);
        let all = detached(py, || {
            let s = statics.at(crease_angle, 0.0, 180.0, || inner.feature_edges(crease_angle))?;
            Ok(s.with_silhouettes(&inner.silhouette(view)?))
        })?;
        let kinds = with_kinds.then(|| vec_to_numpy(py, all.kinds.iter().map(|&k| k as i8).collect()));
        Ok((pairs_to_numpy(py, all.edges), kinds))
    }

    fn feature_edges<'py>(
        &self,
        py: Python<'py>,
        crease_angle: &Bound<'py, PyAny>,
    ) -> PyResult<FeatureOut<'py>> {
        let crease_angle = crease_angle_of(crease_angle).map_err(to_py)?;
        let inner = &self.inner;
        let (fe, degenerate) =
            detached(py, || Ok((inner.feature_edges(crease_angle)?, inner.degenerate_faces())))?;
        Ok(feature_to_numpy(py, fe, degenerate))
    }

    fn face_normals<'py>(&self, py: Python<'py>) -> Bound<'py, PyArray2<f64>> {
        let flat: Vec<f64> = self.inner.normals().iter().flatten().copied().collect();
        Array2::from_shape_vec((self.inner.n_faces(), 3), flat).expect("3m").into_pyarray(py)
    }

    fn vertices<'py>(&self, py: Python<'py>) -> Bound<'py, PyArray2<f64>> {
        let flat: Vec<f64> = self.inner.positions().iter().flatten().copied().collect();
        Array2::from_shape_vec((self.inner.n_vertices(), 3), flat).expect("3n").into_pyarray(py)
    }

    fn weld_map<'py>(&self, py: Python<'py>) -> Option<Bound<'py, PyArray1<i64>>> {
        self.inner.weld_map().map(|m| vec_to_numpy(py, m.iter().map(|&i| i as i64).collect()))
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
fn _chains<'py>(
    py: Python<'py>,
    edges: &Bound<'py, PyAny>,
) -> PyResult<(Bound<'py, PyArray1<i64>>, Bound<'py, PyArray1<i64>>)> {
    let e = read_pairs("edges", edges).map_err(to_py)?;
    let (flat, offsets) = detached(py, || Ok(chain_edges(&e)))?;
    Ok((
        vec_to_numpy(py, flat.into_iter().map(|i| i as i64).collect()),
        vec_to_numpy(py, offsets.into_iter().map(|i| i as i64).collect()),
    ))
}

/// End points of edges, (K, 2, 3) in the vertices' dtype; `edges` is (K, 2) int64.
#[pyfunction]
fn _segments<'py>(
    py: Python<'py>,
    vertices: &Bound<'py, PyAny>,
    edges: &Bound<'py, PyAny>,
) -> PyResult<Bound<'py, PyAny>> {
    let v = positions("vertices", vertices).map_err(to_py)?;
    let e = read_pairs("edges", edges).map_err(to_py)?;
    let n = v.len();
    if let Some(k) = e.iter().position(|p| p[0] as usize >= n || p[1] as usize >= n) {
        return Err(to_py(Error::out_of_range(
            "edges",
            format!("edge {k} ({}, {}) refers to a vertex outside [0, {n})", e[k][0], e[k][1]),
        )));
    }
    fn ends<'py, T: Real + numpy::Element>(
        py: Python<'py>,
        v: &[[T; 3]],
        e: &[[u32; 2]],
    ) -> Bound<'py, PyAny> {
        let flat: Vec<T> = e.iter().flat_map(|p| p.iter().flat_map(|&i| v[i as usize])).collect();
        numpy::ndarray::Array3::from_shape_vec((e.len(), 2, 3), flat).expect("6k").into_pyarray(py).into_any()
    }
    Ok(match &v {
        Positions::F32(v) => ends(py, v, &e),
        Positions::F64(v) => ends(py, v, &e),
    })
}

fn sobel_typed<'py, T: Real + numpy::Element>(
    py: Python<'py>,
    image: PyReadonlyArray2<'py, T>,
    output: Output,
    convention: Convention,
) -> PyResult<Bound<'py, PyArray2<T>>> {
    let (h, w) = image.as_array().dim();
    if !image.is_c_contiguous() {
        return Err(to_py(Error::invalid("image", "must be C-contiguous (the Python wrapper makes it so)")));
    }
    let data =
        image.as_slice().map_err(|_| to_py(Error::Internal("sobel: image is not C-contiguous".into())))?;
    // NumPy's allocator asks the kernel for huge pages on large arrays; a Vec here would pay
    // one page fault per 4 KiB of output, which costs as much as the filter itself.
    // SAFETY: every element is written by `sobel` before the array is returned (on error it is
    // dropped unread).
    let result = unsafe { PyArray2::<T>::new(py, [h, w], false) };
    {
        let mut rw = result.readwrite();
        let out = rw
            .as_slice_mut()
            .map_err(|_| to_py(Error::Internal("sobel: new array not contiguous".into())))?;
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
    let output = Output::parse(output).map_err(to_py)?;
    let convention =
        args::text("convention", convention).and_then(|c| Convention::parse(&c)).map_err(to_py)?;
    let image = &native_order(image).map_err(to_py)?;
    if let Ok(x) = image.extract::<PyReadonlyArray2<'py, f32>>() {
        Ok(sobel_typed(py, x, output, convention)?.into_any())
    } else if let Ok(x) = image.extract::<PyReadonlyArray2<'py, f64>>() {
        Ok(sobel_typed(py, x, output, convention)?.into_any())
    } else {
        Err(to_py(Error::wrong_type("image", "expected a 2-D float32 or float64 array")))
    }
}

type Edges<'py> = (Bound<'py, PyAny>, Bound<'py, PyArray2<bool>>);

fn edges_typed<'py, T: Real + numpy::Element>(
    py: Python<'py>,
    name: &str,
    buffer: PyReadonlyArray3<'py, T>,
    threshold: f64,
) -> PyResult<Edges<'py>> {
    let (h, w, c) = buffer.as_array().dim();
    if !buffer.is_c_contiguous() {
        return Err(to_py(Error::invalid(name, "must be C-contiguous (the Python wrapper makes it so)")));
    }
    let data =
        buffer.as_slice().map_err(|_| to_py(Error::Internal(format!("{name} is not C-contiguous"))))?;
    let arg = format!("{name}_threshold");
    let (gradient, mask) = detached(py, || {
        let g = paper_gradient(data, h, w, c)?;
        let m = threshold_mask(&arg, &g, threshold)?;
        Ok((g, m))
    })?;
    Ok((
        Array2::from_shape_vec((h, w), gradient).expect("h*w").into_pyarray(py).into_any(),
        Array2::from_shape_vec((h, w), mask).expect("h*w").into_pyarray(py),
    ))
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
    let threshold = args::number(&format!("{name}_threshold"), threshold).map_err(to_py)?;
    if let Ok(x) = buffer.extract::<PyReadonlyArray3<'py, f32>>() {
        edges_typed(py, name, x, threshold)
    } else if let Ok(x) = buffer.extract::<PyReadonlyArray3<'py, f64>>() {
        edges_typed(py, name, x, threshold)
    } else {
        Err(to_py(Error::wrong_type(name, "expected a 3-D float32 or float64 array")))
    }
}

pub fn register(m: &Bound<'_, PyModule>) -> PyResult<()> {
    m.add_function(wrap_pyfunction!(_feature_edges, m)?)?;
    m.add_function(wrap_pyfunction!(_silhouette, m)?)?;
    m.add_function(wrap_pyfunction!(_curvature, m)?)?;
    m.add_function(wrap_pyfunction!(_contours, m)?)?;
    m.add_function(wrap_pyfunction!(_suggestive_contours, m)?)?;
    m.add_function(wrap_pyfunction!(_chains, m)?)?;
    m.add_function(wrap_pyfunction!(_sobel, m)?)?;
    m.add_function(wrap_pyfunction!(_paper_edges, m)?)?;
    m.add_function(wrap_pyfunction!(_segments, m)?)?;
    m.add_class::<PyEdgeIndex>()?;
    Ok(())
}

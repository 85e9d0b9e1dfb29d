//! Python bindings for `crate::render`: the device-side `Renderer` (meshes kept on the device,
//! scenes rendered without the GIL into the core's images, handed to NumPy without a copy),
//! `gpu_info` and PNG encoding. Every argument is converted with a check that names it.

use numpy::PyUntypedArray;
use pyo3::prelude::*;
use pyo3::types::{PyBytes, PyDict, PyString, PyTuple};
use pyo3::IntoPyObjectExt;

use super::albedo::albedo;
use super::args::{self, number, text, triple, type_name};
use super::convert::{array_values, python, shaped_to_numpy, ToPython};
use super::mesh_input::{on_mesh, MeshInput, PositionsIn};
use super::runtime::detached_cancellable;
use super::settings::values::{each, transform};
use super::settings::{PyCamera, PyMaterial, PyRenderOptions};
use crate::cancel::Cancel;
use crate::error::{Error, Result};
use crate::mesh::normals::given_unit_normals;
use crate::mesh::positions::on_positions;
use crate::parallel::catching_panics;
use crate::render::effects::shadows::raycast::mesh_shadow_truth;
use crate::render::gpu_mesh::{MeshNormals, NormalMode};
use crate::render::image_out::{decode_png as decode_png_bytes, encode_png};
use crate::render::scene::lines::LineSet;
use crate::render::scene::options::{LineSpec, MeshSpec};
use crate::render::scene::up::Axis;
use crate::render::{BackendChoice, FrameReport, Image, Renderer, ViewImages};

/// Runs GPU work with the GIL released, catching panics. Not in the compute pool: a render
/// mostly waits on the device, and concurrent renders should not queue behind each other there.
pub(super) fn without_gil<T: Send>(py: Python<'_>, work: impl FnOnce() -> Result<T> + Send) -> PyResult<T> {
    py.detach(|| catching_panics(work)).map_err(PyErr::from)
}

/// The backend asked for (None: the default choice).
fn backend_of(backend: Option<&Bound<'_, PyAny>>) -> Result<BackendChoice> {
    BackendChoice::resolve(backend.map(|b| text("backend", b)).transpose()?.as_deref())
}

/// `normals`: "smooth", "flat", "auto" (split at `DEFAULT_CREASE_ANGLE`), ("auto", crease
/// angle in degrees), None (`NormalMode::DEFAULT`), or an (N, 3) float array of the mesh's own
/// vertex normals for a mesh of `n_vertices`.
fn mesh_normals(obj: &Bound<'_, PyAny>, n_vertices: usize) -> Result<MeshNormals> {
    if obj.is_none() {
        return Ok(NormalMode::DEFAULT.into());
    }
    if obj.is_instance_of::<PyString>() {
        return Ok(NormalMode::parse("normals", &text("normals", obj)?)?.into());
    }
    if let Ok(pair) = obj.cast::<PyTuple>() {
        if let (2, Ok(name)) = (pair.len(), pair.get_item(0).and_then(|n| n.extract::<String>())) {
            let angle = pair.get_item(1).map_err(|e| Error::invalid("normals", e.to_string()))?;
            return Ok(NormalMode::with_angle("normals", &name, || number("normals", &angle))?.into());
        }
    }
    if obj.cast::<PyUntypedArray>().is_ok() {
        let given = PositionsIn::read("normals", obj)?;
        return Ok(MeshNormals::Given(
            on_positions!(given.get(), n => given_unit_normals("normals", n, n_vertices))?,
        ));
    }
    Err(Error::wrong_type(
        "normals",
        format!(
            "expected 'smooth', 'flat', 'auto', ('auto', crease angle in degrees), None or an (N, 3) float \
             array of vertex normals, got {}",
            type_name(obj)
        ),
    ))
}

/// Normals in their shortest spelling: "auto" for ('auto', the default angle); a mesh's own as
/// `given`, the caller's array.
fn normal_spelling<'py>(
    py: Python<'py>,
    normals: &MeshNormals,
    given: &Bound<'py, PyAny>,
) -> PyResult<Bound<'py, PyAny>> {
    match normals {
        MeshNormals::Given(_) => Ok(given.clone()),
        MeshNormals::Mode(mode) => match mode.written_angle() {
            Some(angle) => (mode.name(), angle).into_bound_py_any(py),
            None => mode.name().into_bound_py_any(py),
        },
    }
}

/// _normal_mode(normals, n_vertices) -> str | (str, float) | array: `normals` checked for a
/// mesh of `n_vertices`: a mode in its shortest spelling, or the mesh's own normals as given.
#[pyfunction]
pub(super) fn _normal_mode<'py>(
    py: Python<'py>,
    normals: &Bound<'py, PyAny>,
    n_vertices: usize,
) -> PyResult<Bound<'py, PyAny>> {
    normal_spelling(py, &mesh_normals(normals, n_vertices)?, normals)
}

/// _up_axis(up) -> str | None: an up axis ("x", "y" or "z") checked; None stays None.
#[pyfunction]
pub(super) fn _up_axis(up: &Bound<'_, PyAny>) -> PyResult<Option<&'static str>> {
    let up = args::optional("up", Some(up), args::text)?;
    Ok(up.map(|u| Axis::parse("up", &u)).transpose()?.map(Axis::name))
}

/// _transform(transform) -> (4, 4) float64: a mesh's transform checked (see `RenderOptions`).
#[pyfunction]
pub(super) fn _transform<'py>(py: Python<'py>, transform: &Bound<'py, PyAny>) -> PyResult<Bound<'py, PyAny>> {
    let t = self::transform("transform", transform)?;
    crate::render::scene::check_transform("transform", &t)?;
    t.to_vec().to_python(py)
}

/// The meshes of a render as the Python layer makes them: [(mesh id, Material or None, 4x4
/// transform or None, up axis or None)]; the core checks the transforms in the scene.
pub(super) fn mesh_specs(items: &Bound<'_, PyAny>) -> Result<Vec<MeshSpec>> {
    type Item<'py> = (u64, Bound<'py, PyAny>, Option<[[f64; 4]; 4]>, Option<String>);
    let expected = "expected (mesh id, Material or None, 4x4 transform or None, up axis or None)";
    let read = |(i, item): (usize, &Bound<'_, PyAny>)| {
        let (id, material, transform, up): Item<'_> =
            item.extract().map_err(|_| Error::wrong_type(format!("meshes[{i}]"), expected))?;
        let material = args::optional(&format!("meshes[{i}].material"), Some(&material), |arg, m| {
            let why = || format!("expected a toonmesh.Material, got {}", type_name(m));
            m.cast::<PyMaterial>().map(|m| m.get().inner.clone()).map_err(|_| Error::wrong_type(arg, why()))
        })?;
        let up = up.map(|u| Axis::parse(&format!("meshes[{i}].up"), &u)).transpose()?;
        Ok((id, material, transform, up))
    };
    args::items("meshes", items, "a list of meshes")?.iter().enumerate().map(read).collect()
}

/// The line sets of a render as the Python layer makes them: [(positions (N, 3) float64,
/// segments (K, 2) int64, 4x4 transform or None, sRGB colour or None, width in pixels or None,
/// up axis or None)]; the core checks them in the scene (errors name `lines[i]`).
pub(super) fn line_specs(items: &Bound<'_, PyAny>) -> Result<Vec<LineSpec>> {
    type Item<'py> = (
        Bound<'py, PyAny>,
        Bound<'py, PyAny>,
        Option<[[f64; 4]; 4]>,
        Option<[f64; 3]>,
        Option<f32>,
        Option<String>,
    );
    let expected =
        "expected (positions, segments, transform or None, colour or None, width or None, up or None)";
    let read = |(i, item): (usize, &Bound<'_, PyAny>)| {
        let (positions, segments, transform, color, width, up): Item<'_> =
            item.extract().map_err(|_| Error::wrong_type(format!("lines[{i}]"), expected))?;
        let at = |field: &str| format!("lines[{i}].{field}");
        let positions =
            array_values::<f64>(&at("positions"), &positions, &["float64"], (&[None, Some(3)], "(N, 3)"))?.0;
        let segments =
            array_values::<i64>(&at("segments"), &segments, &["int64"], (&[None, Some(2)], "(K, 2)"))?.0;
        let segments =
            crate::edges::chains::vertex_pairs(&at("segments"), segments.chunks(2).map(|s| [s[0], s[1]]))?;
        let set = LineSet {
            positions: positions.chunks(3).map(|p| [p[0], p[1], p[2]]).collect(),
            segments,
            transform: crate::render::scene::IDENTITY,
            color,
            width,
        };
        let up = up.map(|u| Axis::parse(&at("up"), &u)).transpose()?;
        Ok((set, transform, up))
    };
    args::items("lines", items, "a list of line sets")?.iter().enumerate().map(read).collect()
}

/// The image outputs as the dict `toonmesh.RenderResult` reads: each output's array, None where
/// it was not asked for.
fn image_dict(py: Python<'_>, images: ViewImages) -> PyResult<Bound<'_, PyDict>> {
    let d = PyDict::new(py);
    for (o, shape, image) in images.shaped() {
        let array = match image {
            Some(Image::Bytes(v)) => Some(shaped_to_numpy(py, shape, v)?),
            Some(Image::Floats(v)) => Some(shaped_to_numpy(py, shape, v)?),
            None => None,
        };
        d.set_item(o.name(), array)?;
    }
    Ok(d)
}

/// A render's report as the dict `toonmesh.RenderResult` reads (with its images): its serde
/// form and its lines as flat arrays (`FrameReport::flat_lines`).
fn report_dict<'py>(py: Python<'py>, report: FrameReport) -> PyResult<Bound<'py, PyDict>> {
    let d = python(py, &report)?.cast_into::<PyDict>()?;
    d.set_item("lines", report.flat_lines().to_python(py)?)?;
    Ok(d)
}

/// The device-side half of `toonmesh.Renderer` (see python/toonmesh/rendering/_render.py).
#[pyclass(name = "Renderer", module = "toonmesh._core", frozen)]
pub(super) struct PyRenderer {
    pub(super) inner: Renderer,
}

#[pymethods]
impl PyRenderer {
    #[new]
    #[pyo3(signature = (backend = None))]
    fn new(py: Python<'_>, backend: Option<&Bound<'_, PyAny>>) -> PyResult<Self> {
        let choice = backend_of(backend)?;
        let inner = without_gil(py, || Renderer::new(choice))?;
        Ok(PyRenderer { inner })
    }

    #[getter]
    fn info<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyAny>> {
        python(py, self.inner.info())
    }

    #[getter]
    fn mesh_count(&self) -> usize {
        self.inner.mesh_count()
    }

    /// (mesh id, the normals in their shortest spelling, notes to warn about); `normals` as
    /// `_normal_mode` takes them; `colors`: the colour keywords (see `albedo`).
    #[pyo3(signature = (vertices, faces, normals, **colors))]
    fn add_mesh<'py>(
        &self,
        py: Python<'py>,
        vertices: &Bound<'py, PyAny>,
        faces: &Bound<'py, PyAny>,
        normals: &Bound<'py, PyAny>,
        colors: Option<&Bound<'py, PyDict>>,
    ) -> PyResult<(u64, Bound<'py, PyAny>, Vec<String>)> {
        let mesh = MeshInput::read(vertices, faces)?;
        let normals_in = mesh_normals(normals, mesh.vertices.count())?;
        let a = albedo(colors)?;
        let spelling = normal_spelling(py, &normals_in, normals)?;
        let inner = &self.inner;
        let (id, notes) =
            mesh.run(py, |p, f, _| on_positions!(p, v => inner.add_mesh_with(v, f, normals_in, a)))?;
        Ok((id, spelling, notes))
    }

    fn remove_mesh(&self, mesh: u64) -> bool {
        self.inner.remove_mesh(mesh)
    }

    /// items: [(mesh id, Material or None, 4x4 transform or None)], seen from the cameras of the
    /// one optional argument after `options` (none given: the options' camera, images without a
    /// leading axis), frames in flight: (images, reports). `lines`: the line sets drawn as ink
    /// (`line_specs`).
    #[pyo3(signature = (items, options, *cameras, lines = None))]
    fn render<'py>(
        &self,
        py: Python<'py>,
        items: &Bound<'py, PyAny>,
        options: &PyRenderOptions,
        cameras: &Bound<'py, PyTuple>,
        lines: Option<&Bound<'py, PyAny>>,
    ) -> PyResult<(Bound<'py, PyDict>, Vec<Bound<'py, PyDict>>)> {
        let o = &options.inner;
        let read = |c: &Bound<'_, PyAny>| c.cast::<PyCamera>().ok().map(|c| c.get().inner);
        let cams = cameras
            .iter()
            .next()
            .map(|c| each(&c, "cameras", "a list of toonmesh.Camera", "a toonmesh.Camera", read));
        let cams = cams.transpose()?;
        let sets = lines.map(line_specs).transpose()?.unwrap_or_default();
        let scene = self.inner.check(o.scene_with_lines(&mesh_specs(items)?, sets)?, o.frame)?;
        let (frame, views, inner) = (o.frame, cams.as_ref().map(Vec::len), &self.inner);
        // the images are made and filled without the GIL, and handed to NumPy as they are
        let render = |cancel: &Cancel| {
            let mut images = ViewImages::zeros(&frame, views);
            let reports = match &cams {
                None => vec![inner.render_checked(scene, images.buffers().pop().expect("one view"))?],
                Some(cams) => inner.render_views(&scene, cams, images.buffers(), cancel)?,
            };
            Ok((images, reports))
        };
        let (images, reports) = match views {
            None => without_gil(py, || render(Cancel::never()))?,
            // a long stream of views stops on Ctrl-C between frames
            Some(_) => detached_cancellable(py, render)?,
        };
        let reports = reports.into_iter().map(|r| report_dict(py, r)).collect::<PyResult<_>>()?;
        Ok((image_dict(py, images)?, reports))
    }
}

/// gpu_info(backend=None) -> dict: the adapter a render would use.
#[pyfunction]
#[pyo3(signature = (backend = None))]
pub(super) fn gpu_info<'py>(
    py: Python<'py>,
    backend: Option<&Bound<'py, PyAny>>,
) -> PyResult<Bound<'py, PyAny>> {
    let choice = backend_of(backend)?;
    let ctx = without_gil(py, || crate::render::context::context(choice))?;
    python(py, &ctx.info)
}

/// encode_png(color: uint8 (H, W, 4)) -> bytes
#[pyfunction]
pub(super) fn encode_png_rgba<'py>(
    py: Python<'py>,
    color: &Bound<'py, PyAny>,
) -> PyResult<Bound<'py, PyBytes>> {
    let (pixels, shape) =
        array_values::<u8>("color", color, &["uint8"], (&[None, None, Some(4)], "(H, W, 4)"))?;
    let png = without_gil(py, || encode_png(shape[1] as u32, shape[0] as u32, &pixels))?;
    Ok(PyBytes::new(py, &png))
}

/// decode_png(data: bytes) -> uint8 (H, W, C)
///
/// The pixels of a PNG file's bytes, rows top first: C = 1 grey, 2 grey and alpha, 3 RGB, 4 RGBA,
/// as the file stores them (16-bit and palette files as 8-bit). Raises ValueError for bytes that
/// are not a readable PNG.
#[pyfunction]
pub(super) fn decode_png<'py>(py: Python<'py>, data: &[u8]) -> PyResult<Bound<'py, PyAny>> {
    let (height, width, channels, pixels) = decode_png_bytes(data)?;
    shaped_to_numpy(py, vec![height as usize, width as usize, channels], pixels)
}

/// _shadow_truth((vertices, faces), view_proj, shape, toward_light) -> (H, W) float32
///
/// The ray-cast truth of the shadow output (`render::effects::shadows::raycast`): for a mesh in
/// world space seen through `view_proj` ((4, 4) world -> clip, as `projection @ view_matrix`),
/// at `shape` (H, W) pixels, 1 where the pixel's surface sees the light along `toward_light` (or
/// no surface), else 0.
#[pyfunction]
pub(super) fn _shadow_truth<'py>(
    py: Python<'py>,
    mesh: &Bound<'py, PyAny>,
    view_proj: &Bound<'py, PyAny>,
    shape: (usize, usize),
    toward_light: &Bound<'py, PyAny>,
) -> PyResult<Bound<'py, PyAny>> {
    let ((h, w), toward) = (shape, triple("toward_light", toward_light)?);
    let rows = array_values::<f64>("view_proj", view_proj, &["float64"], (&[Some(4), Some(4)], "(4, 4)"))?.0;
    let vis = on_mesh!(py, mesh, |v, f, _| Ok(mesh_shadow_truth(v, f, &rows, (w, h), toward)))?;
    shaped_to_numpy(py, vec![h, w], vis)
}

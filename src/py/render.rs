//! Python bindings for `crate::render`: the device-side `Renderer` (meshes kept on the device,
//! scenes rendered into NumPy arrays allocated here and filled without the GIL), `gpu_info` and
//! PNG encoding. Every argument is converted with a check that names it.

use numpy::ndarray::Array2;
use numpy::{
    IntoPyArray, PyArray2, PyArray3, PyArrayMethods, PyReadonlyArray2, PyReadonlyArray3,
    PyUntypedArrayMethods,
};
use pyo3::prelude::*;
use pyo3::types::{PyBytes, PyDict, PyString, PyTuple};

use super::args::{integer, number, rgb, rgba, text, type_name};
use super::convert::{faces, positions, Positions};
use super::errors::to_py;
use super::runtime::{catching_panics, detached_cancellable};
use super::scene::{PyCamera, PyLight, PyMaterial, PyOutlines};
use crate::edges::DEFAULT_CREASE_ANGLE;
use crate::error::{Error, Result};
use crate::render::gpu_mesh::NormalMode;
use crate::render::image_out::encode_png;
use crate::render::scene::light::Light;
use crate::render::scene::outlines::{kind_names, Outlines};
use crate::render::scene::{FrameSpec, Outputs, Scene, SceneItem, IDENTITY};
use crate::render::{BackendChoice, FrameReport, GpuInfo, OutputBuffers, Renderer};

type Obj<'a, 'py> = Option<&'a Bound<'py, PyAny>>;

/// Runs GPU work with the GIL released, catching panics. Not in the compute pool: a render
/// mostly waits on the device, and concurrent renders should not queue behind each other there.
fn without_gil<T: Send>(py: Python<'_>, work: impl FnOnce() -> Result<T> + Send) -> PyResult<T> {
    py.detach(|| catching_panics(work)).map_err(to_py)
}

fn info_dict<'py>(py: Python<'py>, info: &GpuInfo) -> PyResult<Bound<'py, PyDict>> {
    let d = PyDict::new(py);
    d.set_item("name", &info.name)?;
    d.set_item("backend", info.backend)?;
    d.set_item("device_type", &info.device_type)?;
    d.set_item("driver", &info.driver)?;
    d.set_item("driver_info", &info.driver_info)?;
    d.set_item("max_texture_size", info.max_texture_size)?;
    d.set_item("msaa_samples", info.msaa_samples.clone())?;
    d.set_item("timestamps", info.timestamps)?;
    Ok(d)
}

fn matrix<'py>(py: Python<'py>, m: [[f64; 4]; 4]) -> Bound<'py, PyAny> {
    Array2::from_shape_vec((4, 4), m.iter().flatten().copied().collect())
        .expect("16 values")
        .into_pyarray(py)
        .into_any()
}

/// `normals`: "smooth", "flat", "auto" (split at `DEFAULT_CREASE_ANGLE`) or ("auto", crease
/// angle in degrees).
fn normal_mode(obj: &Bound<'_, PyAny>) -> Result<NormalMode> {
    if obj.is_instance_of::<PyString>() {
        return NormalMode::parse("normals", &text("normals", obj)?);
    }
    if let Ok(pair) = obj.cast::<PyTuple>() {
        if let (2, Ok(name)) = (pair.len(), pair.get_item(0).and_then(|n| n.extract::<String>())) {
            if name != "auto" {
                return Err(Error::invalid(
                    "normals",
                    format!("only 'auto' takes a crease angle, got ({name:?}, ...)"),
                ));
            }
            let angle = pair.get_item(1).map_err(|e| Error::invalid("normals", e.to_string()))?;
            return NormalMode::auto("normals", number("normals", &angle)?);
        }
    }
    Err(Error::wrong_type(
        "normals",
        format!(
            "expected 'smooth', 'flat', 'auto' or ('auto', crease angle in degrees), got {}",
            type_name(obj)
        ),
    ))
}

/// _normal_mode(normals) -> str | (str, float): `normals` checked, in its shortest spelling
/// ("auto" for ('auto', the default angle)).
#[pyfunction]
fn _normal_mode<'py>(py: Python<'py>, normals: &Bound<'py, PyAny>) -> PyResult<Bound<'py, PyAny>> {
    Ok(match normal_mode(normals).map_err(to_py)? {
        NormalMode::Auto { crease_angle } if crease_angle != DEFAULT_CREASE_ANGLE => {
            ("auto", crease_angle).into_pyobject(py)?.into_any()
        }
        mode => PyString::new(py, mode.name()).into_any(),
    })
}

/// A size in pixels, at least 1.
fn pixels(name: &str, o: &Bound<'_, PyAny>) -> Result<u32> {
    let v = integer(name, o)?;
    if v < 1 {
        return Err(Error::invalid(name, format!("must be at least 1 pixel, got {v}")));
    }
    u32::try_from(v).map_err(|_| Error::invalid(name, format!("{v} pixels is too large")))
}

fn small(name: &str, o: &Bound<'_, PyAny>) -> Result<u32> {
    let v = integer(name, o)?;
    u32::try_from(v).map_err(|_| Error::invalid(name, format!("invalid value {v}")))
}

fn transform(arg: &str, obj: &Bound<'_, PyAny>) -> Result<[[f64; 4]; 4]> {
    if obj.is_none() {
        return Ok(IDENTITY);
    }
    let rows: Vec<Vec<f64>> = obj.extract().map_err(|_| {
        Error::wrong_type(arg, format!("expected a 4x4 array of numbers, got {}", type_name(obj)))
    })?;
    if rows.len() != 4 || rows.iter().any(|r| r.len() != 4) {
        let cols = rows.first().map_or(0, |r| r.len());
        return Err(Error::invalid(arg, format!("expected shape (4, 4), got ({}, {cols})", rows.len())));
    }
    Ok(std::array::from_fn(|i| std::array::from_fn(|j| rows[i][j])))
}

fn outputs(obj: Obj<'_, '_>) -> Result<Outputs> {
    let mut o = Outputs::default();
    let Some(obj) = obj else {
        o.color = true;
        return Ok(o);
    };
    let names: Vec<Bound<'_, PyAny>> = if obj.is_instance_of::<PyString>() {
        vec![obj.clone()]
    } else {
        obj.try_iter()
            .map_err(|_| {
                Error::wrong_type(
                    "outputs",
                    format!("expected a name or a sequence of names, got {}", type_name(obj)),
                )
            })?
            .collect::<PyResult<_>>()
            .map_err(|e| Error::invalid("outputs", e.to_string()))?
    };
    for n in &names {
        o.add("outputs", &text("outputs", n)?)?;
    }
    if !o.any() {
        return Err(Error::invalid(
            "outputs",
            "ask for at least one output ('color', 'normal', 'depth', ...)",
        ));
    }
    Ok(o)
}

fn outlines_arg(obj: Obj<'_, '_>) -> Result<Option<Outlines>> {
    let Some(obj) = obj else { return Ok(None) };
    if let Ok(o) = obj.cast::<PyOutlines>() {
        return Ok(Some(o.get().inner.clone()));
    }
    if obj.is_instance_of::<PyString>() {
        let (mesh, image) = Outlines::parse_kind("outlines", &text("outlines", obj)?)?;
        return Ok(Some(Outlines::new(mesh, image)));
    }
    Err(Error::wrong_type(
        "outlines",
        format!("expected None, 'mesh', 'image', 'both' or a toonmesh.Outlines, got {}", type_name(obj)),
    ))
}

fn lights_arg(obj: Obj<'_, '_>) -> Result<Vec<Light>> {
    let Some(obj) = obj else { return Ok(vec![Light::default()]) };
    if let Ok(l) = obj.cast::<PyLight>() {
        return Ok(vec![l.get().inner]);
    }
    each(obj, "lights", "a toonmesh.Light or a list of them", "a toonmesh.Light", |l| {
        l.cast::<PyLight>().ok().map(|l| l.get().inner)
    })
}

/// The items of the sequence `obj` (argument `name`), each read by `read` (None: the item is
/// not `item`, a TypeError naming `name[i]`); `expected` describes the whole.
fn each<T>(
    obj: &Bound<'_, PyAny>,
    name: &str,
    expected: &str,
    item: &str,
    read: impl Fn(&Bound<'_, PyAny>) -> Option<T>,
) -> Result<Vec<T>> {
    let items = obj
        .try_iter()
        .map_err(|_| Error::wrong_type(name, format!("expected {expected}, got {}", type_name(obj))))?;
    items
        .enumerate()
        .map(|(i, x)| {
            let x = x.map_err(|e| Error::invalid(name, e.to_string()))?;
            read(&x).ok_or_else(|| {
                Error::wrong_type(format!("{name}[{i}]"), format!("expected {item}, got {}", type_name(&x)))
            })
        })
        .collect()
}

fn material_arg(name: &str, obj: &Bound<'_, PyAny>) -> Result<crate::render::scene::material::Material> {
    obj.cast::<PyMaterial>()
        .map(|m| m.get().inner.clone())
        .map_err(|_| Error::wrong_type(name, format!("expected a toonmesh.Material, got {}", type_name(obj))))
}

/// The images and report of a render as the dict `toonmesh.RenderResult` reads.
struct Images<'py> {
    color: Option<Bound<'py, PyArray3<u8>>>,
    normal: Option<Bound<'py, PyArray3<f32>>>,
    depth: Option<Bound<'py, PyArray2<f32>>>,
    outline: Option<Bound<'py, PyArray2<f32>>>,
    shadow: Option<Bound<'py, PyArray2<f32>>>,
}

impl<'py> Images<'py> {
    fn allocate(py: Python<'py>, frame: &FrameSpec) -> Self {
        let (h, w) = (frame.height as usize, frame.width as usize);
        let o = frame.outputs;
        // SAFETY (all four): every element is written by the render before Python sees it.
        Images {
            color: o.color.then(|| unsafe { PyArray3::<u8>::new(py, [h, w, 4], false) }),
            normal: o.normal.then(|| unsafe { PyArray3::<f32>::new(py, [h, w, 3], false) }),
            depth: o.depth.then(|| unsafe { PyArray2::<f32>::new(py, [h, w], false) }),
            outline: o.outline.then(|| unsafe { PyArray2::<f32>::new(py, [h, w], false) }),
            shadow: o.shadow.then(|| unsafe { PyArray2::<f32>::new(py, [h, w], false) }),
        }
    }

    fn buffers(&self) -> OutputBuffers<'_> {
        // SAFETY: the arrays were just made here, are C-contiguous and shared with no one.
        unsafe {
            OutputBuffers {
                color: self.color.as_ref().map(|a| a.as_slice_mut().expect("contiguous")),
                normal: self.normal.as_ref().map(|a| a.as_slice_mut().expect("contiguous")),
                depth: self.depth.as_ref().map(|a| a.as_slice_mut().expect("contiguous")),
                outline: self.outline.as_ref().map(|a| a.as_slice_mut().expect("contiguous")),
                shadow: self.shadow.as_ref().map(|a| a.as_slice_mut().expect("contiguous")),
            }
        }
    }

    fn into_dict(
        self,
        py: Python<'py>,
        frame: &FrameSpec,
        report: FrameReport,
    ) -> PyResult<Bound<'py, PyDict>> {
        let d = PyDict::new(py);
        d.set_item("width", frame.width)?;
        d.set_item("height", frame.height)?;
        d.set_item("color", self.color)?;
        d.set_item("normal", self.normal)?;
        d.set_item("depth", self.depth)?;
        d.set_item("outline", self.outline)?;
        d.set_item("shadow", self.shadow)?;
        match report.lines {
            Some(lines) => {
                let names = kind_names();
                let kinds: Vec<&str> = lines.iter().map(|l| names[l.kind]).collect();
                let arrays: Vec<Bound<'py, PyArray2<f64>>> = lines
                    .into_iter()
                    .map(|l| {
                        let n = l.points.len();
                        Array2::from_shape_vec((n, 2), l.points.into_iter().flatten().collect())
                            .expect("2 numbers a point")
                            .into_pyarray(py)
                    })
                    .collect();
                d.set_item("lines", arrays)?;
                d.set_item("line_kinds", kinds)?;
            }
            None => {
                d.set_item("lines", py.None())?;
                d.set_item("line_kinds", py.None())?;
            }
        }
        d.set_item("passes", report.passes)?;
        d.set_item("timings", report.timings)?;
        d.set_item("gpu_timed", report.gpu_timed)?;
        d.set_item("culled", report.culled)?;
        d.set_item("view", matrix(py, report.view))?;
        d.set_item("proj", matrix(py, report.proj))?;
        d.set_item("near", report.near)?;
        d.set_item("far", report.far)?;
        Ok(d)
    }
}

/// The images of a stream of views, stacked: (K, H, W, ...) arrays, one slice a view.
struct Stacks<'py> {
    color: Option<Bound<'py, numpy::PyArray4<u8>>>,
    normal: Option<Bound<'py, numpy::PyArray4<f32>>>,
    depth: Option<Bound<'py, PyArray3<f32>>>,
    outline: Option<Bound<'py, PyArray3<f32>>>,
    shadow: Option<Bound<'py, PyArray3<f32>>>,
}

impl<'py> Stacks<'py> {
    fn allocate(py: Python<'py>, frame: &FrameSpec, k: usize) -> Self {
        let (h, w) = (frame.height as usize, frame.width as usize);
        let o = frame.outputs;
        // SAFETY (all four): every element is written by the render before Python sees it.
        Stacks {
            color: o.color.then(|| unsafe { numpy::PyArray4::<u8>::new(py, [k, h, w, 4], false) }),
            normal: o.normal.then(|| unsafe { numpy::PyArray4::<f32>::new(py, [k, h, w, 3], false) }),
            depth: o.depth.then(|| unsafe { PyArray3::<f32>::new(py, [k, h, w], false) }),
            outline: o.outline.then(|| unsafe { PyArray3::<f32>::new(py, [k, h, w], false) }),
            shadow: o.shadow.then(|| unsafe { PyArray3::<f32>::new(py, [k, h, w], false) }),
        }
    }

    /// One set of buffers a view.
    fn buffers(&self, k: usize) -> Vec<OutputBuffers<'_>> {
        fn split<T>(s: Option<&mut [T]>, k: usize) -> Vec<Option<&mut [T]>> {
            match s {
                Some(s) if k > 0 => {
                    let n = s.len() / k;
                    s.chunks_mut(n.max(1)).map(Some).collect()
                }
                _ => (0..k).map(|_| None).collect(),
            }
        }
        // SAFETY: the arrays were just made here, are C-contiguous and shared with no one.
        let (c, n, d, o, sh) = unsafe {
            (
                split(self.color.as_ref().map(|a| a.as_slice_mut().expect("contiguous")), k),
                split(self.normal.as_ref().map(|a| a.as_slice_mut().expect("contiguous")), k),
                split(self.depth.as_ref().map(|a| a.as_slice_mut().expect("contiguous")), k),
                split(self.outline.as_ref().map(|a| a.as_slice_mut().expect("contiguous")), k),
                split(self.shadow.as_ref().map(|a| a.as_slice_mut().expect("contiguous")), k),
            )
        };
        c.into_iter()
            .zip(n)
            .zip(d)
            .zip(o)
            .zip(sh)
            .map(|((((color, normal), depth), outline), shadow)| OutputBuffers {
                color,
                normal,
                depth,
                outline,
                shadow,
            })
            .collect()
    }
}

/// The device-side half of `toonmesh.Renderer` (see python/toonmesh/_render.py).
#[pyclass(name = "Renderer", module = "toonmesh._core", frozen)]
struct PyRenderer {
    inner: Renderer,
}

impl PyRenderer {
    /// The scene and frame of `render`'s arguments, checked.
    #[allow(clippy::too_many_arguments)]
    fn scene_and_frame(
        &self,
        items: &Bound<'_, PyAny>,
        width: &Bound<'_, PyAny>,
        height: &Bound<'_, PyAny>,
        msaa: &Bound<'_, PyAny>,
        supersample: &Bound<'_, PyAny>,
        material: Obj<'_, '_>,
        camera: Obj<'_, '_>,
        lights: Obj<'_, '_>,
        ambient: Obj<'_, '_>,
        background: Obj<'_, '_>,
        outputs: Obj<'_, '_>,
        outlines: Obj<'_, '_>,
    ) -> Result<(Scene, FrameSpec)> {
        let default_material = match material {
            None => Default::default(),
            Some(m) => material_arg("material", m)?,
        };
        let mut scene_items = Vec::new();
        let list = items.try_iter().map_err(|_| Error::wrong_type("meshes", "expected a list of meshes"))?;
        for (i, item) in list.enumerate() {
            let arg = format!("meshes[{i}]");
            let item = item.map_err(|e| Error::invalid(&arg, e.to_string()))?;
            let (id, mat, tf): (u64, Bound<'_, PyAny>, Bound<'_, PyAny>) = item
                .extract()
                .map_err(|_| Error::wrong_type(&arg, "expected (mesh id, material, transform)"))?;
            scene_items.push(SceneItem {
                mesh: id,
                material: if mat.is_none() {
                    default_material.clone()
                } else {
                    material_arg(&format!("{arg}.material"), &mat)?
                },
                transform: transform(&format!("{arg}.transform"), &tf)?,
            });
        }
        let camera = match camera {
            None => Default::default(),
            Some(c) => c.cast::<PyCamera>().map(|c| c.get().inner).map_err(|_| {
                Error::wrong_type("camera", format!("expected a toonmesh.Camera, got {}", type_name(c)))
            })?,
        };
        let background = match background {
            None => [1.0f32; 4],
            Some(b) => rgba("background", b)?.map(|c| c as f32),
        };
        let scene = Scene {
            items: scene_items,
            camera,
            lights: lights_arg(lights)?,
            ambient: ambient.map(|a| rgb("ambient", a)).transpose()?.unwrap_or([1.0; 3]),
            outlines: outlines_arg(outlines)?,
        };
        let frame = FrameSpec {
            width: pixels("width", width)?,
            height: pixels("height", height)?,
            outputs: self::outputs(outputs)?,
            msaa: small("msaa", msaa)?,
            supersample: small("supersample", supersample)?,
            background,
        };
        self.inner.check(&scene, &frame)?;
        Ok((scene, frame))
    }
}

#[pymethods]
impl PyRenderer {
    #[new]
    #[pyo3(signature = (backend = None))]
    fn new(py: Python<'_>, backend: Obj<'_, '_>) -> PyResult<Self> {
        let name = backend.map(|b| text("backend", b)).transpose().map_err(to_py)?;
        let choice = BackendChoice::resolve(name.as_deref()).map_err(to_py)?;
        let inner = without_gil(py, || Renderer::new(choice))?;
        Ok(PyRenderer { inner })
    }

    #[getter]
    fn info<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyDict>> {
        info_dict(py, self.inner.info())
    }

    #[getter]
    fn mesh_count(&self) -> usize {
        self.inner.mesh_count()
    }

    #[pyo3(signature = (vertices, faces, normals = None))]
    fn add_mesh(
        &self,
        py: Python<'_>,
        vertices: &Bound<'_, PyAny>,
        faces: &Bound<'_, PyAny>,
        normals: Obj<'_, '_>,
    ) -> PyResult<u64> {
        let (mode, p, f) = (|| {
            let mode = normals.map_or(Ok(NormalMode::DEFAULT), normal_mode)?;
            let p = positions("vertices", vertices)?;
            let f = self::faces("faces", faces, p.len())?;
            Ok((mode, p, f))
        })()
        .map_err(to_py)?;
        let inner = &self.inner;
        without_gil(py, || match &p {
            Positions::F32(v) => inner.add_mesh(v, f, mode),
            Positions::F64(v) => inner.add_mesh(v, f, mode),
        })
    }

    fn remove_mesh(&self, mesh: u64) -> bool {
        self.inner.remove_mesh(mesh)
    }

    /// items: [(mesh id, Material or None, 4x4 transform or None)].
    #[pyo3(signature = (items, *, width, height, msaa, supersample, material = None, camera = None,
                        lights = None, ambient = None, background = None, outputs = None, outlines = None))]
    #[allow(clippy::too_many_arguments)]
    fn render<'py>(
        &self,
        py: Python<'py>,
        items: &Bound<'py, PyAny>,
        width: &Bound<'py, PyAny>,
        height: &Bound<'py, PyAny>,
        msaa: &Bound<'py, PyAny>,
        supersample: &Bound<'py, PyAny>,
        material: Obj<'_, 'py>,
        camera: Obj<'_, 'py>,
        lights: Obj<'_, 'py>,
        ambient: Obj<'_, 'py>,
        background: Obj<'_, 'py>,
        outputs: Obj<'_, 'py>,
        outlines: Obj<'_, 'py>,
    ) -> PyResult<Bound<'py, PyDict>> {
        let (scene, frame) = self
            .scene_and_frame(
                items,
                width,
                height,
                msaa,
                supersample,
                material,
                camera,
                lights,
                ambient,
                background,
                outputs,
                outlines,
            )
            .map_err(to_py)?;
        let images = Images::allocate(py, &frame);
        let buffers = images.buffers();
        let inner = &self.inner;
        let report = without_gil(py, || inner.render_into(&scene, &frame, buffers))?;
        images.into_dict(py, &frame, report)
    }

    /// The same scene from each of `cameras`, frames in flight: (stacked images, reports).
    #[pyo3(signature = (items, cameras, *, width, height, msaa, supersample, material = None,
                        lights = None, ambient = None, background = None, outputs = None, outlines = None))]
    #[allow(clippy::too_many_arguments)]
    fn render_views<'py>(
        &self,
        py: Python<'py>,
        items: &Bound<'py, PyAny>,
        cameras: &Bound<'py, PyAny>,
        width: &Bound<'py, PyAny>,
        height: &Bound<'py, PyAny>,
        msaa: &Bound<'py, PyAny>,
        supersample: &Bound<'py, PyAny>,
        material: Obj<'_, 'py>,
        lights: Obj<'_, 'py>,
        ambient: Obj<'_, 'py>,
        background: Obj<'_, 'py>,
        outputs: Obj<'_, 'py>,
        outlines: Obj<'_, 'py>,
    ) -> PyResult<(Bound<'py, PyDict>, Vec<Bound<'py, PyDict>>)> {
        let cams = each(cameras, "cameras", "a list of toonmesh.Camera", "a toonmesh.Camera", |c| {
            c.cast::<PyCamera>().ok().map(|c| c.get().inner)
        })
        .map_err(to_py)?;
        let (scene, frame) = self
            .scene_and_frame(
                items,
                width,
                height,
                msaa,
                supersample,
                material,
                None,
                lights,
                ambient,
                background,
                outputs,
                outlines,
            )
            .map_err(to_py)?;
        let stacks = Stacks::allocate(py, &frame, cams.len());
        let buffers = stacks.buffers(cams.len());
        let inner = &self.inner;
        // a long stream of views stops on Ctrl-C between frames
        let reports =
            detached_cancellable(py, |cancel| inner.render_views(&scene, &cams, &frame, buffers, cancel))?;
        let images = PyDict::new(py);
        images.set_item("color", stacks.color)?;
        images.set_item("normal", stacks.normal)?;
        images.set_item("depth", stacks.depth)?;
        images.set_item("outline", stacks.outline)?;
        images.set_item("shadow", stacks.shadow)?;
        let reports = reports
            .into_iter()
            .map(|r| {
                Images { color: None, normal: None, depth: None, outline: None, shadow: None }
                    .into_dict(py, &frame, r)
            })
            .collect::<PyResult<_>>()?;
        Ok((images, reports))
    }
}

/// gpu_info(backend=None) -> dict: the adapter a render would use.
#[pyfunction]
#[pyo3(signature = (backend = None))]
fn gpu_info<'py>(py: Python<'py>, backend: Obj<'_, 'py>) -> PyResult<Bound<'py, PyDict>> {
    let name = backend.map(|b| text("backend", b)).transpose().map_err(to_py)?;
    let choice = BackendChoice::resolve(name.as_deref()).map_err(to_py)?;
    let ctx = without_gil(py, || crate::render::context::context(choice))?;
    info_dict(py, &ctx.info)
}

/// encode_png(color: uint8 (H, W, 4)) -> bytes
#[pyfunction]
fn encode_png_rgba<'py>(py: Python<'py>, color: &Bound<'py, PyAny>) -> PyResult<Bound<'py, PyBytes>> {
    let a: PyReadonlyArray3<'py, u8> = color
        .extract()
        .map_err(|_| to_py(Error::wrong_type("color", "expected a uint8 array of shape (H, W, 4)")))?;
    let shape = a.shape().to_vec();
    if shape[2] != 4 {
        return Err(to_py(Error::invalid("color", format!("expected shape (H, W, 4), got {shape:?}"))));
    }
    let pixels: Vec<u8> = a.as_array().iter().copied().collect();
    let png = without_gil(py, || encode_png(shape[1] as u32, shape[0] as u32, &pixels))?;
    Ok(PyBytes::new(py, &png))
}

/// _shadow_truth(vertices, faces, view_proj, width, height, toward_light) -> (H, W) float32
///
/// The ray-cast truth of the shadow output (`render::passes::shadow::raycast`): for a mesh in
/// world space seen through `view_proj` ((4, 4) world -> clip, as `projection @ view_matrix`),
/// 1 where the pixel's surface sees the light along `toward_light` (or no surface), else 0.
#[pyfunction]
fn _shadow_truth<'py>(
    py: Python<'py>,
    vertices: &Bound<'py, PyAny>,
    faces_arr: &Bound<'py, PyAny>,
    view_proj: PyReadonlyArray2<'py, f64>,
    width: &Bound<'py, PyAny>,
    height: &Bound<'py, PyAny>,
    toward_light: &Bound<'py, PyAny>,
) -> PyResult<Bound<'py, PyArray2<f32>>> {
    use crate::render::passes::shadow::raycast::{shadow_truth, Triangles};
    use glam::{DMat4, DVec3};
    let (w, h) = (pixels("width", width).map_err(to_py)?, pixels("height", height).map_err(to_py)?);
    let toward =
        DVec3::from_array(super::args::triple("toward_light", toward_light).map_err(to_py)?).normalize();
    let m = view_proj.as_array();
    if m.shape() != [4, 4] {
        return Err(to_py(Error::invalid(
            "view_proj",
            format!("expected shape (4, 4), got {:?}", m.shape()),
        )));
    }
    let rows: Vec<f64> = m.iter().copied().collect();
    let vp = DMat4::from_cols_slice(&rows).transpose();
    let p: Vec<DVec3> = match positions("vertices", vertices).map_err(to_py)? {
        Positions::F32(v) => v.iter().map(|q| DVec3::new(q[0] as f64, q[1] as f64, q[2] as f64)).collect(),
        Positions::F64(v) => v.iter().map(|q| DVec3::from_array(*q)).collect(),
    };
    let f = faces("faces", faces_arr, p.len()).map_err(to_py)?;
    let tris = Triangles::new(f.iter().map(|t| t.map(|i| p[i as usize])).collect());
    let vis = without_gil(py, || {
        Ok(crate::parallel::install(|| shadow_truth(&tris, vp, w as usize, h as usize, toward)))
    })?;
    Ok(Array2::from_shape_vec((h as usize, w as usize), vis).expect("one value a pixel").into_pyarray(py))
}

pub fn register(m: &Bound<'_, PyModule>) -> PyResult<()> {
    m.add_function(wrap_pyfunction!(_shadow_truth, m)?)?;
    m.add_function(wrap_pyfunction!(_normal_mode, m)?)?;
    m.add_class::<PyRenderer>()?;
    m.add_function(wrap_pyfunction!(gpu_info, m)?)?;
    m.add_function(wrap_pyfunction!(encode_png_rgba, m)?)?;
    Ok(())
}

//! Python bindings for `crate::render`: a `Renderer` class holding meshes on the device, and
//! `gpu_info`. Scene descriptions arrive as plain dicts built by `python/toonmesh/_render.py`;
//! every value is checked here or in the core, and errors name the argument.

use numpy::ndarray::{Array2, Array3};
use numpy::{IntoPyArray, PyReadonlyArray3};
use pyo3::prelude::*;
use pyo3::types::{PyBytes, PyDict, PyList};

use super::convert::{faces, positions, Positions};
use super::errors::to_py;
use super::runtime::catching_panics;
use crate::error::{Error, Result};
use crate::render::camera::{Camera, Placement, Projection};
use crate::render::color::rgb_to_linear;
use crate::render::gpu_mesh::NormalMode;
use crate::render::image_out::encode_png;
use crate::render::light::{Light, LightKind, Space};
use crate::render::material::{Highlight, Material, Model};
use crate::render::scene::{FrameSpec, Outputs, Scene, SceneItem, IDENTITY};
use crate::render::{BackendChoice, GpuInfo, RenderOutput, Renderer};

/// Runs GPU work with the GIL released, catching panics. Not in the compute pool: a render
/// mostly waits on the device, and concurrent renders should not queue behind each other there.
fn without_gil<T: Send>(py: Python<'_>, work: impl FnOnce() -> Result<T> + Send) -> PyResult<T> {
    py.detach(|| catching_panics(work)).map_err(to_py)
}

fn get<'py>(d: &Bound<'py, PyDict>, key: &str) -> Result<Option<Bound<'py, PyAny>>> {
    d.get_item(key).map(|v| v.filter(|v| !v.is_none())).map_err(|e| Error::invalid(key, e.to_string()))
}

fn number(arg: &str, v: &Bound<'_, PyAny>) -> Result<f64> {
    v.extract::<f64>().map_err(|_| Error::wrong_type(arg, format!("expected a number, got {}", type_name(v))))
}

fn type_name(v: &Bound<'_, PyAny>) -> String {
    v.get_type().name().map(|n| n.to_string()).unwrap_or_else(|_| "?".into())
}

fn numbers(arg: &str, v: &Bound<'_, PyAny>) -> Result<Vec<f64>> {
    v.extract::<Vec<f64>>()
        .map_err(|_| Error::wrong_type(arg, format!("expected a sequence of numbers, got {}", type_name(v))))
}

fn triple(arg: &str, v: &Bound<'_, PyAny>) -> Result<[f64; 3]> {
    let x = numbers(arg, v)?;
    <[f64; 3]>::try_from(x.as_slice())
        .map_err(|_| Error::invalid(arg, format!("expected 3 numbers, got {}", x.len())))
}

fn text(arg: &str, v: &Bound<'_, PyAny>) -> Result<String> {
    v.extract::<String>()
        .map_err(|_| Error::wrong_type(arg, format!("expected a string, got {}", type_name(v))))
}

fn number_or(d: &Bound<'_, PyDict>, arg: &str, key: &str, default: f64) -> Result<f64> {
    get(d, key)?.map(|v| number(&format!("{arg}.{key}"), &v)).transpose().map(|v| v.unwrap_or(default))
}

/// An sRGB colour in [0, 1] as linear light.
fn color(arg: &str, v: &Bound<'_, PyAny>) -> Result<[f32; 3]> {
    let c = triple(arg, v)?;
    if !c.iter().all(|x| x.is_finite() && *x >= 0.0) {
        return Err(Error::invalid(arg, format!("channels must be finite and >= 0, got {c:?}")));
    }
    Ok(rgb_to_linear(c))
}

fn color_or(d: &Bound<'_, PyDict>, arg: &str, key: &str, default: [f32; 3]) -> Result<[f32; 3]> {
    get(d, key)?.map(|v| color(&format!("{arg}.{key}"), &v)).transpose().map(|v| v.unwrap_or(default))
}

fn dict<'a, 'py>(arg: &str, v: &'a Bound<'py, PyAny>) -> Result<&'a Bound<'py, PyDict>> {
    v.cast::<PyDict>().map_err(|_| Error::wrong_type(arg, format!("expected a dict, got {}", type_name(v))))
}

fn material(arg: &str, obj: &Bound<'_, PyAny>) -> Result<Material> {
    let d = dict(arg, obj)?;
    let name = get(d, "model")?
        .map(|v| text(&format!("{arg}.model"), &v))
        .transpose()?
        .unwrap_or_else(|| "bands".into());
    let floats = |key: &str| -> Result<Option<Vec<f32>>> {
        get(d, key)?
            .map(|v| numbers(&format!("{arg}.{key}"), &v).map(|x| x.into_iter().map(|f| f as f32).collect()))
            .transpose()
    };
    let model = match name.as_str() {
        "lambert" => Model::Lambert,
        "phong" => Model::Phong { shininess: number_or(d, arg, "shininess", 32.0)? as f32 },
        "thresholded_phong" => Model::ThresholdedPhong {
            t_h: number_or(d, arg, "t_h", 0.0)? as f32,
            t_s: number_or(d, arg, "t_s", 0.95)? as f32,
            highlight: match get(d, "highlight")?
                .map(|v| text(&format!("{arg}.highlight"), &v))
                .transpose()?
                .as_deref()
            {
                None | Some("blinn") => Highlight::Blinn,
                Some("paper") => Highlight::Paper,
                Some(o) => {
                    return Err(Error::invalid(
                        format!("{arg}.highlight"),
                        format!("must be 'paper' or 'blinn', got {o:?}"),
                    ))
                }
            },
        },
        "bands" => Model::Bands {
            thresholds: floats("thresholds")?
                .unwrap_or_else(|| crate::render::material::PAPER_BAND_THRESHOLDS.to_vec()),
            values: floats("values")?.unwrap_or_else(|| crate::render::material::PAPER_BAND_VALUES.to_vec()),
        },
        "lut" => Model::Lut {
            table: match get(d, "table")? {
                None => crate::render::material::kang_table(),
                Some(t) => t
                    .extract::<Vec<Vec<f64>>>()
                    .map_err(|_| Error::wrong_type(format!("{arg}.table"), "expected rows of 3 numbers"))?
                    .into_iter()
                    .map(|r| <[f64; 3]>::try_from(r.as_slice()).map(|c| c.map(|x| x as f32)))
                    .collect::<std::result::Result<_, _>>()
                    .map_err(|_| Error::invalid(format!("{arg}.table"), "rows must have 3 numbers"))?,
            },
        },
        other => {
            return Err(Error::invalid(
                format!("{arg}.model"),
                format!(
                    "unknown shading model {other:?}; use lambert, phong, thresholded_phong, bands or lut"
                ),
            ))
        }
    };
    let per_vertex = get(d, "per_vertex")?
        .map(|v| {
            v.extract::<bool>().map_err(|_| Error::wrong_type(format!("{arg}.per_vertex"), "expected a bool"))
        })
        .transpose()?
        .unwrap_or(false);
    let m = Material {
        model,
        ambient: color_or(d, arg, "ambient", [0.0; 3])?,
        diffuse: color_or(d, arg, "diffuse", [0.8; 3])?,
        specular: color_or(d, arg, "specular", [0.0; 3])?,
        per_vertex,
    };
    m.validate(arg)?;
    Ok(m)
}

fn transform(arg: &str, v: Option<Bound<'_, PyAny>>) -> Result<[[f64; 4]; 4]> {
    let Some(v) = v else { return Ok(IDENTITY) };
    let rows = v
        .extract::<Vec<Vec<f64>>>()
        .map_err(|_| Error::wrong_type(arg, "expected a 4x4 array of numbers"))?;
    if rows.len() != 4 || rows.iter().any(|r| r.len() != 4) {
        return Err(Error::invalid(arg, "expected shape (4, 4)"));
    }
    Ok(std::array::from_fn(|i| std::array::from_fn(|j| rows[i][j])))
}

fn camera_of(obj: Option<Bound<'_, PyAny>>) -> Result<Camera> {
    let Some(obj) = obj else {
        return Ok(Camera::default());
    };
    let d = dict("camera", &obj)?;
    let defaults = Camera::default();
    let opt_triple = |key: &str, default: [f64; 3]| -> Result<[f64; 3]> {
        get(d, key)?.map(|v| triple(&format!("camera.{key}"), &v)).transpose().map(|v| v.unwrap_or(default))
    };
    let projection =
        match get(d, "projection")?.map(|v| text("camera.projection", &v)).transpose()?.as_deref() {
            None | Some("perspective") => {
                Projection::Perspective { fov_y_deg: number_or(d, "camera", "fov_y", 35.0)? }
            }
            Some("orthographic") => {
                Projection::Orthographic { height: number_or(d, "camera", "height", 2.0)? }
            }
            Some(o) => {
                return Err(Error::invalid(
                    "camera.projection",
                    format!("must be 'perspective' or 'orthographic', got {o:?}"),
                ))
            }
        };
    let placement = match get(d, "kind")?.map(|v| text("camera.kind", &v)).transpose()?.as_deref() {
        None | Some("fit") => {
            let Placement::Fit { direction, up, margin } = defaults.placement else { unreachable!() };
            Placement::Fit {
                direction: opt_triple("direction", direction)?,
                up: opt_triple("up", up)?,
                margin: number_or(d, "camera", "margin", margin)?,
            }
        }
        Some("look_at") => Placement::LookAt {
            eye: opt_triple("eye", [0.0, 0.0, 5.0])?,
            target: opt_triple("target", [0.0; 3])?,
            up: opt_triple("up", [0.0, 1.0, 0.0])?,
        },
        Some(o) => {
            return Err(Error::invalid("camera.kind", format!("must be 'fit' or 'look_at', got {o:?}")))
        }
    };
    let near = get(d, "near")?.map(|v| number("camera.near", &v)).transpose()?;
    let far = get(d, "far")?.map(|v| number("camera.far", &v)).transpose()?;
    let cam = Camera { placement, projection, near, far };
    cam.validate()?;
    Ok(cam)
}

fn light(arg: &str, obj: &Bound<'_, PyAny>) -> Result<Light> {
    let d = dict(arg, obj)?;
    let kind = match get(d, "kind")?.map(|v| text(&format!("{arg}.kind"), &v)).transpose()?.as_deref() {
        None | Some("directional") => LightKind::Directional {
            direction: get(d, "direction")?
                .map(|v| triple(&format!("{arg}.direction"), &v))
                .transpose()?
                .unwrap_or([0.0, 0.0, -1.0]),
        },
        Some("point") => LightKind::Point {
            position: get(d, "position")?
                .map(|v| triple(&format!("{arg}.position"), &v))
                .transpose()?
                .ok_or_else(|| Error::invalid(format!("{arg}.position"), "a point light needs a position"))?,
        },
        Some(o) => {
            return Err(Error::invalid(
                format!("{arg}.kind"),
                format!("must be 'directional' or 'point', got {o:?}"),
            ))
        }
    };
    let space = match get(d, "space")?.map(|v| text(&format!("{arg}.space"), &v)).transpose()?.as_deref() {
        None | Some("world") => Space::World,
        Some("camera") => Space::Camera,
        Some(o) => {
            return Err(Error::invalid(
                format!("{arg}.space"),
                format!("must be 'world' or 'camera', got {o:?}"),
            ))
        }
    };
    let intensity = number_or(d, arg, "intensity", 1.0)?;
    if !(intensity.is_finite() && intensity >= 0.0) {
        return Err(Error::invalid(
            format!("{arg}.intensity"),
            format!("must be finite and >= 0, got {intensity}"),
        ));
    }
    let c = color_or(d, arg, "color", [1.0; 3])?;
    let l = Light { kind, space, color: c.map(|x| x * intensity as f32) };
    l.validate(arg)?;
    Ok(l)
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
    Ok(d)
}

fn matrix<'py>(py: Python<'py>, m: [[f64; 4]; 4]) -> Bound<'py, PyAny> {
    Array2::from_shape_vec((4, 4), m.iter().flatten().copied().collect())
        .expect("16 values")
        .into_pyarray(py)
        .into_any()
}

fn output_dict<'py>(py: Python<'py>, out: RenderOutput) -> PyResult<Bound<'py, PyDict>> {
    let (h, w) = (out.height as usize, out.width as usize);
    let d = PyDict::new(py);
    let shape = "the readback has one value per pixel";
    d.set_item(
        "color",
        out.color.map(|c| Array3::from_shape_vec((h, w, 4), c).expect(shape).into_pyarray(py)),
    )?;
    d.set_item(
        "normal",
        out.normal.map(|n| Array3::from_shape_vec((h, w, 3), n).expect(shape).into_pyarray(py)),
    )?;
    d.set_item("depth", out.depth.map(|z| Array2::from_shape_vec((h, w), z).expect(shape).into_pyarray(py)))?;
    d.set_item("timings", out.timings)?;
    d.set_item("view", matrix(py, out.view))?;
    d.set_item("proj", matrix(py, out.proj))?;
    d.set_item("near", out.near)?;
    d.set_item("far", out.far)?;
    Ok(d)
}

/// The device-side half of `toonmesh.Renderer` (see python/toonmesh/_render.py).
#[pyclass(name = "Renderer", module = "toonmesh._core", frozen)]
struct PyRenderer {
    inner: Renderer,
}

#[pymethods]
impl PyRenderer {
    #[new]
    #[pyo3(signature = (backend = None))]
    fn new(py: Python<'_>, backend: Option<&str>) -> PyResult<Self> {
        let choice = BackendChoice::resolve(backend).map_err(to_py)?;
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

    #[pyo3(signature = (vertices, faces, normals = "smooth"))]
    fn add_mesh(
        &self,
        py: Python<'_>,
        vertices: &Bound<'_, PyAny>,
        faces: &Bound<'_, PyAny>,
        normals: &str,
    ) -> PyResult<u64> {
        let mode = NormalMode::parse("normals", normals).map_err(to_py)?;
        let p = positions("vertices", vertices).map_err(to_py)?;
        let f = self::faces("faces", faces, p.len()).map_err(to_py)?;
        let inner = &self.inner;
        without_gil(py, || match &p {
            Positions::F32(v) => inner.add_mesh(v, &f, mode),
            Positions::F64(v) => inner.add_mesh(v, &f, mode),
        })
    }

    fn remove_mesh(&self, mesh: u64) -> bool {
        self.inner.remove_mesh(mesh)
    }

    /// items: [(mesh id, material dict, transform or None)], outputs: names of the outputs.
    #[pyo3(signature = (items, *, camera = None, lights = None, ambient = None, background = None,
                        width = 512, height = 512, outputs = None, msaa = 1, supersample = 1))]
    #[allow(clippy::too_many_arguments)]
    fn render<'py>(
        &self,
        py: Python<'py>,
        items: &Bound<'py, PyList>,
        camera: Option<Bound<'py, PyAny>>,
        lights: Option<Bound<'py, PyList>>,
        ambient: Option<Bound<'py, PyAny>>,
        background: Option<Bound<'py, PyAny>>,
        width: i64,
        height: i64,
        outputs: Option<Vec<String>>,
        msaa: i64,
        supersample: i64,
    ) -> PyResult<Bound<'py, PyDict>> {
        let (scene, frame) = (|| -> Result<(Scene, FrameSpec)> {
            let mut scene_items = Vec::with_capacity(items.len());
            for (i, item) in items.iter().enumerate() {
                let arg = format!("meshes[{i}]");
                let (id, mat, tf): (u64, Bound<'_, PyAny>, Option<Bound<'_, PyAny>>) = item
                    .extract()
                    .map_err(|_| Error::wrong_type(&arg, "expected (mesh id, material, transform)"))?;
                scene_items.push(SceneItem {
                    mesh: self.inner.mesh(id)?,
                    material: material(&format!("{arg}.material"), &mat)?,
                    transform: transform(&format!("{arg}.transform"), tf.filter(|t| !t.is_none()))?,
                });
            }
            let lights = match lights {
                None => vec![Light::default()],
                Some(l) => l
                    .iter()
                    .enumerate()
                    .map(|(i, x)| light(&format!("lights[{i}]"), &x))
                    .collect::<Result<_>>()?,
            };
            let ambient = match ambient.filter(|a| !a.is_none()) {
                None => [1.0; 3],
                Some(a) => color("ambient", &a)?,
            };
            let background = match background.filter(|b| !b.is_none()) {
                None => [1.0; 4],
                Some(b) => {
                    let x = numbers("background", &b)?;
                    match x.len() {
                        3 => [x[0] as f32, x[1] as f32, x[2] as f32, 1.0],
                        4 => [x[0] as f32, x[1] as f32, x[2] as f32, x[3] as f32],
                        n => {
                            return Err(Error::invalid(
                                "background",
                                format!("expected 3 or 4 channels, got {n}"),
                            ))
                        }
                    }
                }
            };
            let mut outs = Outputs::default();
            for name in outputs.unwrap_or_else(|| vec!["color".into()]) {
                match name.as_str() {
                    "color" => outs.color = true,
                    "normal" => outs.normal = true,
                    "depth" => outs.depth = true,
                    o => {
                        return Err(Error::invalid(
                            "outputs",
                            format!("unknown output {o:?}; use 'color', 'normal', 'depth'"),
                        ))
                    }
                }
            }
            let size = |arg: &str, v: i64| -> Result<u32> {
                if v < 1 {
                    return Err(Error::invalid(arg, format!("must be at least 1 pixel, got {v}")));
                }
                u32::try_from(v).map_err(|_| Error::invalid(arg, format!("{v} pixels is too large")))
            };
            let small = |arg: &str, v: i64| {
                u32::try_from(v).map_err(|_| Error::invalid(arg, format!("invalid value {v}")))
            };
            let frame = FrameSpec {
                width: size("width", width)?,
                height: size("height", height)?,
                outputs: outs,
                msaa: small("msaa", msaa)?,
                supersample: small("supersample", supersample)?,
                background,
            };
            Ok((Scene { items: scene_items, camera: camera_of(camera)?, lights, ambient }, frame))
        })()
        .map_err(to_py)?;
        let inner = &self.inner;
        let out = without_gil(py, || inner.render(&scene, &frame))?;
        output_dict(py, out)
    }
}

/// gpu_info(backend=None) -> dict: the adapter a render would use.
#[pyfunction]
#[pyo3(signature = (backend = None))]
fn gpu_info<'py>(py: Python<'py>, backend: Option<&str>) -> PyResult<Bound<'py, PyDict>> {
    let choice = BackendChoice::resolve(backend).map_err(to_py)?;
    let ctx = without_gil(py, || crate::render::context::context(choice))?;
    info_dict(py, &ctx.info)
}

/// encode_png(color: uint8 (H, W, 4)) -> bytes
#[pyfunction]
fn encode_png_rgba<'py>(py: Python<'py>, color: &Bound<'py, PyAny>) -> PyResult<Bound<'py, PyBytes>> {
    let a: PyReadonlyArray3<'py, u8> = color
        .extract()
        .map_err(|_| to_py(Error::wrong_type("color", "expected a uint8 array of shape (H, W, 4)")))?;
    let shape = a.as_array().shape().to_vec();
    if shape[2] != 4 {
        return Err(to_py(Error::invalid("color", format!("expected shape (H, W, 4), got {shape:?}"))));
    }
    let pixels: Vec<u8> = a.as_array().iter().copied().collect();
    let png = without_gil(py, || encode_png(shape[1] as u32, shape[0] as u32, &pixels))?;
    Ok(PyBytes::new(py, &png))
}

pub fn register(m: &Bound<'_, PyModule>) -> PyResult<()> {
    m.add_class::<PyRenderer>()?;
    m.add_function(wrap_pyfunction!(gpu_info, m)?)?;
    m.add_function(wrap_pyfunction!(encode_png_rgba, m)?)?;
    Ok(())
}

//! `RenderOptions`: everything a render takes besides its meshes, as one object whose defaults
//! live in the core (`render::scene::options`). `render`, `Renderer.render`,
//! `Renderer.render_many`, the command line and batch rendering all hand one to the core.

use numpy::{PyArrayDescrMethods, PyUntypedArray, PyUntypedArrayMethods};
use pyo3::prelude::*;
use pyo3::types::{PyDict, PyString};

use super::camera::PyCamera;
use super::light::PyLight;
use super::material::{material_arg, PyMaterial};
use super::outlines::{outlines_arg, PyOutlines};
use super::{getters, settings_class};
use crate::error::{closest, Error, Result};
use crate::py::args::{flag, integer, numbers, refuse_text, rgb, rgba, text, type_name};
use crate::py::errors::to_py;
use crate::render::scene::light::Light;
use crate::render::scene::options::RenderOptions;
use crate::render::scene::{Output, Outputs};

/// The keywords: the fields of the core's `RenderOptions`.
fn keywords() -> Vec<String> {
    match serde_json::to_value(RenderOptions::default()) {
        Ok(serde_json::Value::Object(fields)) => fields.keys().cloned().collect(),
        _ => Vec::new(),
    }
}

/// Every render setting besides the meshes, checked, with the core's defaults: made from the
/// keywords of :class:`RenderKeywords` (``RenderOptions(width=640, outlines="mesh")``), which
/// lists them; ``replace(**keywords)`` makes a changed copy. Compared by value, hashable and
/// picklable, so a batch sends one to its workers.
#[pyclass(name = "RenderOptions", module = "toonmesh._core", frozen, eq)]
#[derive(Clone, PartialEq)]
pub struct PyRenderOptions {
    pub inner: RenderOptions,
}

settings_class!(PyRenderOptions, RenderOptions, "RenderOptions", |_| Ok(()));

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

/// A 4x4 matrix of numbers (`arg` in errors): an array of integers or floats, or nested
/// sequences of numbers (never bools, strings or complex numbers, which are refused rather than
/// cast). The core checks its values.
pub fn transform(arg: &str, obj: &Bound<'_, PyAny>) -> Result<[[f64; 4]; 4]> {
    let wrong = || Error::wrong_type(arg, format!("expected a 4x4 array of numbers, got {}", type_name(obj)));
    refuse_text(arg, obj, "a 4x4 array of numbers")?;
    if let Ok(a) = obj.cast::<PyUntypedArray>() {
        if !matches!(a.dtype().kind(), b'i' | b'u' | b'f') {
            return Err(wrong());
        }
    }
    let rows: Vec<Bound<'_, PyAny>> =
        obj.try_iter().map_err(|_| wrong())?.collect::<PyResult<_>>().map_err(|_| wrong())?;
    let rows: Vec<Vec<f64>> = rows.iter().map(|r| numbers(arg, r)).collect::<Result<_>>()?;
    if rows.iter().any(|r| r.len() != rows[0].len()) {
        return Err(wrong());
    }
    if rows.len() != 4 || rows[0].len() != 4 {
        let cols = rows.first().map_or(0, |r| r.len());
        return Err(Error::invalid(arg, format!("expected shape (4, 4), got ({}, {cols})", rows.len())));
    }
    Ok(std::array::from_fn(|i| std::array::from_fn(|j| rows[i][j])))
}

fn outputs(obj: &Bound<'_, PyAny>) -> Result<Outputs> {
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
    let mut o = Outputs::default();
    for n in &names {
        o.insert(Output::parse("outputs", &text("outputs", n)?)?);
    }
    o.validate()?;
    Ok(o)
}

/// The items of the sequence `obj` (argument `name`), each read by `read` (None: the item is
/// not `item`, a TypeError naming `name[i]`); `expected` describes the whole.
pub fn each<T>(
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

fn lights(obj: &Bound<'_, PyAny>) -> Result<Vec<Light>> {
    if let Ok(l) = obj.cast::<PyLight>() {
        return Ok(vec![l.get().inner]);
    }
    each(obj, "lights", "a toonmesh.Light or a list of them", "a toonmesh.Light", |l| {
        l.cast::<PyLight>().ok().map(|l| l.get().inner)
    })
}

/// A camera argument called `name`.
pub fn camera_arg(name: &str, obj: &Bound<'_, PyAny>) -> Result<crate::render::scene::camera::Camera> {
    obj.cast::<PyCamera>()
        .map(|c| c.get().inner)
        .map_err(|_| Error::wrong_type(name, format!("expected a toonmesh.Camera, got {}", type_name(obj))))
}

impl PyRenderOptions {
    /// `base` with the keywords of `kwargs` set (a keyword given as None: its default).
    pub fn with(base: &RenderOptions, kwargs: Option<&Bound<'_, PyDict>>) -> Result<RenderOptions> {
        let mut o = base.clone();
        let d = RenderOptions::default();
        let Some(kwargs) = kwargs else { return Ok(o) };
        for (key, value) in kwargs.iter() {
            let key: String =
                key.extract().map_err(|_| Error::wrong_type("options", "keywords must be strings"))?;
            let none = value.is_none();
            match key.as_str() {
                "material" => {
                    o.material = if none { d.material.clone() } else { material_arg("material", &value)? }
                }
                "transform" => o.transform = if none { d.transform } else { transform("transform", &value)? },
                "camera" => o.camera = if none { d.camera } else { camera_arg("camera", &value)? },
                "lights" => o.lights = if none { d.lights.clone() } else { lights(&value)? },
                "ambient" => o.ambient = if none { d.ambient } else { rgb("ambient", &value)? },
                "background" => {
                    o.frame.background =
                        if none { d.frame.background } else { rgba("background", &value)?.map(|c| c as f32) }
                }
                "outputs" => o.frame.outputs = if none { d.frame.outputs } else { outputs(&value)? },
                "outlines" => o.outlines = if none { None } else { Some(outlines_arg(&value)?) },
                "width" => o.frame.width = pixels("width", &value)?,
                "height" => o.frame.height = pixels("height", &value)?,
                "msaa" => o.frame.msaa = small("msaa", &value)?,
                "supersample" => o.frame.supersample = small("supersample", &value)?,
                "band_antialias" => {
                    o.frame.band_antialias =
                        if none { d.frame.band_antialias } else { flag("band_antialias", &value)? }
                }
                other => {
                    let known = keywords();
                    let names: Vec<&str> = known.iter().map(String::as_str).collect();
                    let hint =
                        closest(other, &names).map_or(String::new(), |k| format!("; did you mean '{k}'?"));
                    let why = format!("not a render option{hint} (they are: {})", names.join(", "));
                    return Err(Error::wrong_type(other, why));
                }
            }
        }
        Ok(o)
    }
}

#[pymethods]
impl PyRenderOptions {
    #[new]
    #[pyo3(signature = (**options))]
    fn new(options: Option<&Bound<'_, PyDict>>) -> PyResult<Self> {
        Self::with(&RenderOptions::default(), options).map(|inner| PyRenderOptions { inner }).map_err(to_py)
    }

    /// These options with the given keywords changed.
    #[pyo3(signature = (**options))]
    fn replace(&self, options: Option<&Bound<'_, PyDict>>) -> PyResult<Self> {
        Self::with(&self.inner, options).map(|inner| PyRenderOptions { inner }).map_err(to_py)
    }

    /// The keywords that differ from the defaults (their values elided).
    fn __repr__(&self) -> String {
        let fields = |o: &RenderOptions| match serde_json::to_value(o) {
            Ok(serde_json::Value::Object(m)) => m,
            _ => Default::default(),
        };
        let (now, default) = (fields(&self.inner), fields(&RenderOptions::default()));
        let changed: Vec<String> = keywords()
            .iter()
            .filter(|k| now.get(*k) != default.get(*k))
            .map(|k| match &now[k] {
                serde_json::Value::Number(n) => format!("{k}={n}"),
                _ => format!("{k}=..."),
            })
            .collect();
        format!("RenderOptions({})", changed.join(", "))
    }
}

getters!(PyRenderOptions {
    material -> PyMaterial = |o| PyMaterial { inner: o.material.clone() };
    transform -> [[f64; 4]; 4] = |o| o.transform;
    camera -> PyCamera = |o| PyCamera { inner: o.camera };
    lights -> Vec<PyLight> = |o| o.lights.iter().map(|&inner| PyLight { inner }).collect();
    ambient -> (f64, f64, f64) = |o| super::tup(o.ambient);
    background -> (f32, f32, f32, f32) = |o| o.frame.background.into();
    width -> u32 = |o| o.frame.width;
    height -> u32 = |o| o.frame.height;
    outputs -> Vec<&'static str> = |o| o.frame.outputs.iter().map(|o| o.name()).collect();
    msaa -> u32 = |o| o.frame.msaa;
    band_antialias -> bool = |o| o.frame.band_antialias;
    supersample -> u32 = |o| o.frame.supersample;
    outlines -> Option<PyOutlines> = |o| o.outlines.clone().map(|inner| PyOutlines { inner });
});

//! A mesh's colour, texture coordinates and texture read from NumPy: the colour keywords of
//! `Renderer.add_mesh` converted as the core takes them (`render::albedo::given`, which checks
//! them and decodes colours and texels, sRGB codes or floats in [0, 1], to linear light).

use numpy::{PyReadonlyArrayDyn, PyUntypedArrayMethods};
use pyo3::prelude::*;
use pyo3::types::PyDict;

use super::args::{flag, number, text};
use super::convert::{array_values, by_dtype, dtype_name, native_order, rows, untyped, ToPython, FLOATS};
use crate::error::{Error, Result};
use crate::render::albedo::given::{Channels, Given, Values};
use crate::render::albedo::Albedo;
use crate::render::color::linear_to_srgb;

/// An sRGB array (the argument `arg`): uint8 codes, or float32 or float64 values.
pub(super) fn channels(arg: &str, obj: &Bound<'_, PyAny>) -> Result<Channels> {
    let obj = &native_order(obj)?;
    let a = untyped(arg, obj)?;
    let wrong_dtype =
        || Error::wrong_type(arg, format!("dtype must be uint8, float32 or float64, got {}", dtype_name(a)));
    let values = match obj.extract::<PyReadonlyArrayDyn<'_, u8>>() {
        Ok(x) => Values::Codes(x.as_array().iter().copied().collect()),
        Err(_) => Values::Unit(
            by_dtype!(obj, PyReadonlyArrayDyn<f32, f64>, |x| x.as_array().iter().map(|&v| v.into()).collect())
                .ok_or_else(wrong_dtype)?,
        ),
    };
    Ok(Channels { shape: a.shape().to_vec(), values })
}

/// (N, 2) float texture coordinates.
fn uv(obj: &Bound<'_, PyAny>) -> Result<Vec<[f32; 2]>> {
    // read as float64 (no overflow in NumPy's cast); the core checks the narrowed values
    let uv: Vec<f64> = array_values("uv", obj, FLOATS, (&[None, Some(2)], "(N, 2)"))?.0;
    Ok(rows(&uv.into_iter().map(|c| c as f32).collect::<Vec<f32>>()))
}

/// The colour keywords of `Renderer.add_mesh` (`Given::KEYWORDS`; None or absent: not given),
/// read into an `Albedo` (None: no colour).
pub fn albedo(keywords: Option<&Bound<'_, PyDict>>) -> Result<Option<Albedo>> {
    let mut given: [Option<Bound<'_, PyAny>>; 8] = Default::default();
    for (k, v) in keywords.into_iter().flat_map(|d| d.iter()) {
        let k = k.to_string();
        let i = Given::KEYWORDS.iter().position(|n| *n == k);
        let i = i.ok_or_else(|| Error::wrong_type(&k, "not a keyword of Renderer.add_mesh"))?;
        given[i] = (!v.is_none()).then_some(v);
    }
    let [vertex_colors, face_colors, uv_obj, texture, filter, wrap, alpha_cutoff, alpha_blend] = given;
    let read = |arg, obj: Option<Bound<'_, PyAny>>| obj.map(|o| channels(arg, &o)).transpose();
    Given {
        vertex_colors: read("vertex_colors", vertex_colors)?,
        face_colors: read("face_colors", face_colors)?,
        uv: uv_obj.as_ref().map(uv).transpose()?,
        texture: read("texture", texture)?,
        texture_filter: filter.map(|f| text("texture_filter", &f)).transpose()?,
        texture_wrap: wrap.map(|w| text("texture_wrap", &w)).transpose()?,
        alpha_cutoff: alpha_cutoff.map(|c| number("alpha_cutoff", &c)).transpose()?,
        alpha_blend: alpha_blend.map(|b| flag("alpha_blend", &b)).transpose()?,
    }
    .albedo()
}

/// _srgb_from_linear(values) -> float64 array: linear-light colour channels as sRGB (clamped to
/// [0, 1] first).
#[pyfunction]
pub fn _srgb_from_linear<'py>(
    py: Python<'py>,
    values: numpy::PyReadonlyArray1<'py, f64>,
) -> PyResult<Bound<'py, PyAny>> {
    values.as_array().iter().map(|&c| linear_to_srgb(c)).collect::<Vec<_>>().to_python(py)
}

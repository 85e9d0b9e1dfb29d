//! A mesh's colour, texture coordinates and texture read from NumPy (`render::albedo`): colours
//! and texels as uint8 codes or floats in [0, 1], sRGB, decoded to linear light here.

use numpy::{PyReadonlyArrayDyn, PyUntypedArrayMethods};
use pyo3::prelude::*;
use pyo3::types::PyDict;

use super::args::{number, text};
use super::convert::{array_values, dtype_name, float_values, native_order, rows, untyped, FLOATS};
use crate::error::{Error, Result};
use crate::render::albedo::texture::Texture;
use crate::render::albedo::{check_unit_floats, linear_colors, Albedo, Colors, Filter, Sampling, Wrap};

/// An array's values as floats in [0, 1] (uint8 codes divided by 255) and its shape, checked
/// as the argument `arg`: `channels` the allowed sizes of its last axis, `rank` its axes.
fn unit_values(arg: &str, obj: &Bound<'_, PyAny>, rank: usize, what: &str) -> Result<(Vec<f32>, Vec<usize>)> {
    let obj = &native_order(obj)?;
    let a = untyped(arg, obj)?;
    let shape = a.shape().to_vec();
    if shape.len() != rank || !matches!(shape[rank - 1], 3 | 4) || shape.contains(&0) {
        return Err(Error::invalid(arg, format!("expected shape {what}, got {shape:?}")));
    }
    let wrong_dtype =
        || Error::wrong_type(arg, format!("dtype must be uint8, float32 or float64, got {}", dtype_name(a)));
    let values: Vec<f32> = if let Ok(x) = obj.extract::<PyReadonlyArrayDyn<'_, u8>>() {
        x.as_array().iter().map(|&c| c as f32 / 255.0).collect()
    } else {
        let v = float_values(obj).ok_or_else(wrong_dtype)?;
        check_unit_floats(arg, &v)?;
        v.into_iter().map(|x| x as f32).collect()
    };
    Ok((values, shape))
}

/// (H, W, 3|4) sRGB image, top row first, as 8-bit codes (floats rounded to the nearest code).
fn texture(obj: &Bound<'_, PyAny>) -> Result<Texture> {
    // uint8 codes are copied as they are (no float copy of a large image)
    match native_order(obj)?.extract::<PyReadonlyArrayDyn<'_, u8>>() {
        Ok(x) if x.ndim() == 3 && matches!(x.shape()[2], 3 | 4) && !x.shape().contains(&0) => {
            Texture::from_codes(x.shape(), &x.as_array().iter().copied().collect::<Vec<_>>())
        }
        _ => {
            let (v, shape) = unit_values("texture", obj, 3, "(H, W, 3) or (H, W, 4)")?;
            Texture::from_unit(&shape, &v)
        }
    }
}

/// (K, 3|4) sRGB colours as linear RGBA (alpha 1 when absent).
fn colors(arg: &str, obj: &Bound<'_, PyAny>, what: &str) -> Result<Vec<[f32; 4]>> {
    let (v, shape) = unit_values(arg, obj, 2, what)?;
    Ok(linear_colors(&v, shape[1]))
}

/// (N, 2) float texture coordinates.
fn uv(obj: &Bound<'_, PyAny>) -> Result<Vec<[f32; 2]>> {
    // read as float64 (no overflow in NumPy's cast); the core checks the narrowed values
    let uv: Vec<f64> = array_values("uv", obj, FLOATS, (&[None, Some(2)], "(N, 2)"))?.0;
    Ok(rows(&uv.into_iter().map(|c| c as f32).collect::<Vec<f32>>()))
}

/// The colour keywords of `Renderer.add_mesh`, in the order `albedo` reads them.
const KEYWORDS: [&str; 7] =
    ["vertex_colors", "face_colors", "uv", "texture", "texture_filter", "texture_wrap", "alpha_cutoff"];

/// The colour keywords of `Renderer.add_mesh` (`KEYWORDS`; None or absent: not given), read into
/// an `Albedo` (None: no colour).
pub fn albedo(keywords: Option<&Bound<'_, PyDict>>) -> Result<Option<Albedo>> {
    let mut given: [Option<Bound<'_, PyAny>>; 7] = Default::default();
    for (k, v) in keywords.into_iter().flat_map(|d| d.iter()) {
        let k = k.to_string();
        let i = KEYWORDS.iter().position(|n| *n == k);
        let i = i.ok_or_else(|| Error::wrong_type(&k, "not a keyword of Renderer.add_mesh"))?;
        given[i] = (!v.is_none()).then_some(v);
    }
    let [vertex_colors, face_colors, uv_obj, texture_obj, filter, wrap, alpha_cutoff] = given;
    let sampling = Sampling {
        filter: filter
            .map(|f| Filter::parse("texture_filter", &text("texture_filter", &f)?))
            .transpose()?
            .unwrap_or_default(),
        wrap: wrap
            .map(|w| Wrap::parse("texture_wrap", &text("texture_wrap", &w)?))
            .transpose()?
            .unwrap_or_default(),
        alpha_cutoff: alpha_cutoff.map(|c| number("alpha_cutoff", &c).map(|c| c as f32)).transpose()?,
    };
    sampling.check()?;
    let colors = match (vertex_colors, face_colors) {
        (Some(_), Some(_)) => {
            return Err(Error::invalid("vertex_colors, face_colors", "give one of them, not both"))
        }
        (Some(c), None) => Some(Colors::Vertex(colors("vertex_colors", &c, "(N, 3) or (N, 4)")?)),
        (None, Some(c)) => Some(Colors::Face(colors("face_colors", &c, "(M, 3) or (M, 4)")?)),
        (None, None) => None,
    };
    let a = Albedo {
        colors,
        uv: uv_obj.as_ref().map(uv).transpose()?,
        texture: texture_obj.as_ref().map(texture).transpose()?,
        sampling,
    };
    Ok((a.is_used() || a.uv.is_some()).then_some(a))
}

/// _srgb_from_linear(values) -> float64 array: linear-light colour channels as sRGB (clamped to
/// [0, 1] first).
#[pyfunction]
pub fn _srgb_from_linear<'py>(
    py: Python<'py>,
    values: numpy::PyReadonlyArray1<'py, f64>,
) -> Bound<'py, numpy::PyArray1<f64>> {
    use numpy::IntoPyArray;
    let v: Vec<f64> = values.as_array().iter().map(|&c| crate::render::color::linear_to_srgb(c)).collect();
    v.into_pyarray(py)
}

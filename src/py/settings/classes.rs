//! The settings classes: each a described core type with its constructors (`settings_class!`),
//! their docstrings the core's (`render/settings/docs`, which its description holds too), and the
//! few read-only views that are not fields.

use pyo3::prelude::*;
use pyo3::types::{PyDict, PyTuple};

use super::settings_class;
use crate::render::effects::dither::Dither;
use crate::render::effects::outlines::settings::{kind_names, LineStyle, Outlines};
use crate::render::effects::shadows::settings::Shadows;
use crate::render::scene::camera::Camera;
use crate::render::scene::light::Light;
use crate::render::scene::material::Material;
use crate::render::scene::model;
use crate::render::scene::options::RenderOptions;

settings_class! {
    #[doc = include_str!("../../render/settings/docs/Material.md")]
    PyMaterial(Material, "Material") {
        #[doc = include_str!("../../render/settings/docs/Material.lambert.md")]
        fn lambert;
        #[doc = include_str!("../../render/settings/docs/Material.phong.md")]
        fn phong;
        #[doc = include_str!("../../render/settings/docs/Material.thresholded_phong.md")]
        fn thresholded_phong;
        #[doc = include_str!("../../render/settings/docs/Material.bands.md")]
        fn bands;
        #[doc = include_str!("../../render/settings/docs/Material.hatching.md")]
        fn hatching;
        #[doc = include_str!("../../render/settings/docs/Material.lut.md")]
        fn lut;
    }
}

settings_class! {
    #[doc = include_str!("../../render/settings/docs/Dither.md")]
    PyDither(Dither, "Dither") {
        new;
    }
}

settings_class! {
    #[doc = include_str!("../../render/settings/docs/Light.md")]
    PyLight(Light, "Light") {
        #[doc = include_str!("../../render/settings/docs/Light.directional.md")]
        fn directional;
        #[doc = include_str!("../../render/settings/docs/Light.point.md")]
        fn point;
        #[doc = include_str!("../../render/settings/docs/Light.key.md")]
        fn key;
    }
}

settings_class! {
    #[doc = include_str!("../../render/settings/docs/Shadows.md")]
    PyShadows(Shadows, "Shadows") {
        new;
    }
}

settings_class! {
    #[doc = include_str!("../../render/settings/docs/Camera.md")]
    PyCamera(Camera, "Camera") {
        #[doc = include_str!("../../render/settings/docs/Camera.fit.md")]
        fn fit;
        #[doc = include_str!("../../render/settings/docs/Camera.look_at.md")]
        fn look_at;
        #[doc = include_str!("../../render/settings/docs/Camera.orthographic.md")]
        fn orthographic;
    }
}

settings_class! {
    #[doc = include_str!("../../render/settings/docs/LineStyle.md")]
    PyLineStyle(LineStyle, "LineStyle") {
        new;
    }
}

settings_class! {
    #[doc = include_str!("../../render/settings/docs/Outlines.md")]
    PyOutlines(Outlines, "Outlines") {
        new;
    }
}

settings_class! {
    #[doc = include_str!("../../render/settings/docs/RenderOptions.md")]
    PyRenderOptions(RenderOptions, "RenderOptions") {
        new;
    }
}

#[pymethods]
impl PyOutlines {
    /// Each ink kind's :class:`LineStyle`, or None where it is not drawn.
    #[getter]
    fn styles<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyDict>> {
        let d = PyDict::new(py);
        for (name, s) in kind_names().iter().zip(&self.inner.styles) {
            d.set_item(name, s.map(|inner| PyLineStyle { inner }))?;
        }
        Ok(d)
    }
}

#[pymethods]
impl PyMaterial {
    /// A hatching material's ink (sRGB), spacing and width in pixels and mode ("field" or
    /// "triplanar") as a dict; None for others.
    #[getter]
    fn hatch_style<'py>(&self, py: Python<'py>) -> PyResult<Option<Bound<'py, PyDict>>> {
        let Some(h) = &self.inner.effects.hatching else { return Ok(None) };
        let d = PyDict::new(py);
        d.set_item("ink", (h.ink[0], h.ink[1], h.ink[2]))?;
        d.set_item("spacing", h.spacing)?;
        d.set_item("width", h.width)?;
        d.set_item("mode", h.mode.name())?;
        Ok(Some(d))
    }
}

/// kang_table() -> ndarray
///
/// Kang et al.'s 256-to-3-level lookup table as (256,) float64: 0.3, 0.65 and 1.0 in thirds.
/// The paper maps 256 Phong intensities to three tones without giving numbers; these split the
/// range in thirds.
#[pyfunction]
pub fn kang_table(py: Python<'_>) -> Bound<'_, numpy::PyArray1<f64>> {
    use numpy::IntoPyArray;
    model::kang_table().into_iter().map(|c| c[0] as f64).collect::<Vec<_>>().into_pyarray(py)
}

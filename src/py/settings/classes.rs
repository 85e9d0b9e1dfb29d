//! The settings classes: one per entry of the core's list (`python_classes!`), their docstrings
//! the core's (which its description holds too), and the few read-only views that are not
//! fields.

use pyo3::prelude::*;
use pyo3::types::{PyDict, PyTuple};

use crate::render::effects::outlines::settings::kind_names;
use crate::render::scene::model;
use crate::render::settings::{settings_classes, CLASSES};

use super::python_classes;
settings_classes!(python_classes);

/// Adds every settings class, and their names as `SETTINGS_CLASSES`.
pub fn register(m: &Bound<'_, PyModule>) -> PyResult<()> {
    macro_rules! add {
        ($($class:ident($docs:literal) = $core:path { $($ctors:tt)* })*) => {
            $(m.add_class::<$class>()?;)*
        };
    }
    settings_classes!(add);
    m.add("SETTINGS_CLASSES", PyTuple::new(m.py(), CLASSES)?)
}

#[pymethods]
impl Outlines {
    /// Each ink kind's :class:`LineStyle`, or None where it is not drawn.
    #[getter]
    fn styles<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyDict>> {
        let d = PyDict::new(py);
        for (name, s) in kind_names().iter().zip(&self.inner.styles) {
            d.set_item(name, s.map(|inner| LineStyle { inner }))?;
        }
        Ok(d)
    }
}

#[pymethods]
impl Material {
    /// A hatching material's ink (sRGB), spacing and width in pixels and mode ("field" or
    /// "triplanar") as a dict; None for others.
    #[getter]
    fn hatch_style<'py>(&self, py: Python<'py>) -> PyResult<Option<Bound<'py, PyAny>>> {
        self.inner.effects.hatching.as_ref().map(|h| crate::py::convert::python(py, h)).transpose()
    }
}

/// Kang et al.'s 256-to-3-level lookup table, for ``Material.lut``.
///
/// The paper maps 256 Phong intensities to three tones without giving numbers; these split the
/// range in thirds.
///
/// Returns:
///     (256,) float64: 0.3, 0.65 and 1.0 in thirds.
#[pyfunction]
pub fn kang_table(py: Python<'_>) -> Bound<'_, numpy::PyArray1<f64>> {
    use numpy::IntoPyArray;
    model::kang_table().into_iter().map(|c| c[0] as f64).collect::<Vec<_>>().into_pyarray(py)
}

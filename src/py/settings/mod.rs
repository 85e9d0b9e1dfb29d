//! The scene's settings as frozen Python classes around the core's typed objects: `Material`,
//! `Dither`, `Light`, `Shadows`, `Camera`, `LineStyle`, `Outlines` and `RenderOptions`, one file
//! each. Defaults and checks live in the core (`crate::render::scene`, `crate::render::effects`);
//! these classes convert arguments (naming them in errors), expose the fields read-only, compare
//! by value, and pickle through the core's serde form (for sending to worker processes): the
//! `settings_class!` line of each gives it hashing and pickling.

mod camera;
mod dither;
mod light;
mod material;
pub mod options;
mod outlines;

use std::hash::{Hash, Hasher};

use pyo3::prelude::*;
use pyo3::IntoPyObjectExt;
use serde::de::DeserializeOwned;
use serde::Serialize;

use super::errors::to_py;
use crate::error::{Error, Result};

pub use camera::PyCamera;
pub use dither::PyDither;
pub use light::{PyLight, PyShadows};
pub use material::PyMaterial;
pub use options::PyRenderOptions;
pub use outlines::{PyLineStyle, PyOutlines};

/// A settings class: the core value it wraps, its Python name, and the check a value restored
/// from a pickle passes.
pub trait Wraps: Sized {
    type Core: Serialize + DeserializeOwned;
    const CLASS: &'static str;
    fn wrap(inner: Self::Core) -> Self;
    fn check(inner: &Self::Core) -> Result<()>;
}

/// Gives a settings class `Wraps`, `__hash__` (of its value) and `__reduce__` (its value in
/// the core's text form, rebuilt and checked again by `_restore`).
macro_rules! settings_class {
    ($py:ident, $core:ty, $class:literal, $check:expr) => {
        impl $crate::py::settings::Wraps for $py {
            type Core = $core;
            const CLASS: &'static str = $class;
            fn wrap(inner: $core) -> Self {
                $py { inner }
            }
            fn check(inner: &$core) -> $crate::error::Result<()> {
                let check: fn(&$core) -> $crate::error::Result<()> = $check;
                check(inner)
            }
        }

        #[pyo3::pymethods]
        impl $py {
            fn __hash__(&self) -> u64 {
                $crate::py::settings::hash_of(&self.inner)
            }

            fn __reduce__<'py>(
                &self,
                py: pyo3::Python<'py>,
            ) -> pyo3::PyResult<(pyo3::Bound<'py, pyo3::PyAny>, (&'static str, String))> {
                $crate::py::settings::reduce::<$py>(py, &self.inner)
            }
        }
    };
}
pub(crate) use settings_class;

/// Read-only properties of a settings class, each computed from its core value: `name -> type
/// = |value| expression;`, doc comments allowed.
macro_rules! getters {
    ($py:ident { $($(#[$doc:meta])* $name:ident -> $ty:ty = |$v:ident| $body:expr;)* }) => {
        #[pyo3::pymethods]
        impl $py {
            $(
                $(#[$doc])*
                #[getter]
                fn $name(&self) -> $ty {
                    let $v = &self.inner;
                    $body
                }
            )*
        }
    };
}
pub(crate) use getters;

fn state<T: Serialize>(x: &T) -> String {
    serde_json::to_string(x).expect("settings serialise")
}

pub fn hash_of<T: Serialize>(x: &T) -> u64 {
    let mut h = std::collections::hash_map::DefaultHasher::new();
    state(x).hash(&mut h);
    h.finish()
}

pub fn reduce<'py, W: Wraps>(
    py: Python<'py>,
    inner: &W::Core,
) -> PyResult<(Bound<'py, PyAny>, (&'static str, String))> {
    Ok((py.import("toonmesh._core")?.getattr("_restore")?, (W::CLASS, state(inner))))
}

fn restore<'py, W: Wraps + IntoPyObjectExt<'py>>(py: Python<'py>, state: &str) -> PyResult<Py<PyAny>> {
    let inner: W::Core =
        serde_json::from_str(state).map_err(|e| to_py(Error::invalid("state", format!("{e}"))))?;
    W::check(&inner).map_err(to_py)?;
    W::wrap(inner).into_py_any(py)
}

/// _restore(cls, state): a pickled setting, checked again.
#[pyfunction]
fn _restore(py: Python<'_>, cls: &str, state: &str) -> PyResult<Py<PyAny>> {
    macro_rules! classes {
        ($($py:ty),*) => {
            match cls {
                $(c if c == <$py as Wraps>::CLASS => restore::<$py>(py, state),)*
                other => Err(to_py(Error::invalid("cls", format!("no settings class {other:?}")))),
            }
        };
    }
    classes!(PyMaterial, PyDither, PyLight, PyShadows, PyCamera, PyLineStyle, PyOutlines, PyRenderOptions)
}

/// A triple as a Python tuple.
fn tup(v: [f64; 3]) -> (f64, f64, f64) {
    (v[0], v[1], v[2])
}

/// The names the core accepts, for Python to take rather than repeat.
fn add_names(m: &Bound<'_, PyModule>) -> PyResult<()> {
    use crate::edges::outlines::LineKind;
    use crate::render::effects::dither::{DitherPattern, DitherSpace};
    use crate::render::effects::outlines::settings::{kind_names, ContourRule, ImageRule, Outlines};
    use crate::render::effects::shadows::settings::ShadowFilter;
    use crate::render::scene::model::{Highlight, Model};
    use crate::render::scene::Output;
    let py = m.py();
    let names = |v: &[&str]| pyo3::types::PyTuple::new(py, v.iter().copied());
    let outputs: Vec<&str> = Output::ALL.iter().map(|o| o.name()).collect();
    let images: Vec<&str> = Output::ALL.iter().filter(|o| o.pixel().is_some()).map(|o| o.name()).collect();
    m.add("OUTPUTS", names(&outputs)?)?;
    m.add("IMAGE_OUTPUTS", names(&images)?)?;
    m.add("LINE_KINDS", names(&LineKind::ALL.map(|k| k.name()))?)?;
    m.add("INK_KINDS", names(&kind_names())?)?;
    m.add("OUTLINE_KINDS", names(&Outlines::KINDS)?)?;
    m.add("CONTOUR_RULES", names(ContourRule::NAMES)?)?;
    m.add("IMAGE_RULES", names(ImageRule::NAMES)?)?;
    m.add("MODELS", names(&Model::NAMES)?)?;
    m.add("HIGHLIGHTS", names(&Highlight::NAMES)?)?;
    m.add("DITHER_PATTERNS", names(&DitherPattern::NAMES)?)?;
    m.add("DITHER_SPACES", names(&DitherSpace::NAMES)?)?;
    m.add("SHADOW_FILTERS", names(&ShadowFilter::NAMES)?)?;
    Ok(())
}

pub fn register(m: &Bound<'_, PyModule>) -> PyResult<()> {
    add_names(m)?;
    m.add_class::<PyMaterial>()?;
    m.add_class::<PyDither>()?;
    m.add_class::<PyLight>()?;
    m.add_class::<PyShadows>()?;
    m.add_class::<PyCamera>()?;
    m.add_class::<PyLineStyle>()?;
    m.add_class::<PyOutlines>()?;
    m.add_class::<PyRenderOptions>()?;
    m.add_function(wrap_pyfunction!(_restore, m)?)?;
    m.add_function(wrap_pyfunction!(material::kang_table, m)?)?;
    Ok(())
}

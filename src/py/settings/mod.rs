//! The scene's settings as frozen Python classes, each derived from the core's description of
//! its type (`render::settings`): its constructors, a getter per field, `replace`, `__repr__`
//! (which evaluates back to an equal object), `__eq__`, `__hash__`, pickling through the core's
//! serde form, and `describe()` for front ends. A field added to the core's description reaches
//! all of them with no edit here; a class added to the core's list (`settings_classes!`) gets
//! its Python class with none.

mod classes;
pub mod values;

use pyo3::prelude::*;
use pyo3::types::{IntoPyDict, PyDict, PyTuple};

use crate::error::{Error, Result};
use crate::render::settings::{self as described, Declared, Described, Setting, Value};

pub use classes::{kang_table, Camera as PyCamera, Material as PyMaterial, RenderOptions as PyRenderOptions};

/// The Python classes, one per entry of the core's list (`render::settings::settings_classes`):
/// the wrapper (named as the class), its docstring and its constructors' (from the core's
/// docs), and the methods every settings class has. Where it is used, PyO3's prelude and
/// `PyDict`, `PyTuple` are in scope.
macro_rules! python_classes {
    ($(
        $class:ident($docs:literal) = $core:path {
            $(new $(#[$ndoc:meta])*;)?
            $(fn $ctor:ident;)*
        }
    )*) => {$(
        #[doc = include_str!(concat!("../../render/", $docs, "/", stringify!($class), ".md"))]
        #[pyclass(module = "toonmesh._core", frozen, eq)]
        #[derive(Clone, PartialEq)]
        pub struct $class {
            pub inner: $core,
        }

        #[pymethods]
        impl $class {
            $(
                $(#[$ndoc])*
                #[new]
                #[pyo3(signature = (*args, **kwargs))]
                fn new(args: &Bound<'_, PyTuple>, kwargs: Option<&Bound<'_, PyDict>>) -> PyResult<Self> {
                    $crate::py::settings::make("", args, kwargs).map(|inner| $class { inner })
                }
            )?

            $(
                #[doc = include_str!(concat!(
                    "../../render/", $docs, "/", stringify!($class), ".", stringify!($ctor), ".md"
                ))]
                #[staticmethod]
                #[pyo3(signature = (*args, **kwargs))]
                fn $ctor(args: &Bound<'_, PyTuple>, kwargs: Option<&Bound<'_, PyDict>>) -> PyResult<Self> {
                    $crate::py::settings::make(stringify!($ctor), args, kwargs).map(|inner| $class { inner })
                }
            )*

            fn __getattr__<'py>(&self, py: Python<'py>, name: &str) -> PyResult<Bound<'py, PyAny>> {
                $crate::py::settings::getattr(py, &self.inner, name)
            }

            fn __dir__(slf: &Bound<'_, Self>) -> PyResult<Vec<String>> {
                $crate::py::settings::dir::<$core>(slf.as_any())
            }

            fn __hash__(&self) -> u64 {
                $crate::render::settings::state::hash(&self.inner)
            }

            fn __repr__(&self, py: Python<'_>) -> PyResult<String> {
                $crate::py::settings::repr(py, &self.inner)
            }

            fn __reduce__<'py>(&self, py: Python<'py>) -> PyResult<(Bound<'py, PyAny>, (&'static str, String))> {
                let state = $crate::render::settings::state::state(&self.inner);
                Ok((py.import("toonmesh._core")?.getattr("_restore")?, (stringify!($class), state)))
            }

            /// A copy with only the fields named changed (None: the field's default), checked as
            /// the constructor checks.
            #[pyo3(signature = (**changes))]
            fn replace(&self, changes: Option<&Bound<'_, PyDict>>) -> PyResult<Self> {
                $crate::py::settings::replace(&self.inner, changes).map(|inner| $class { inner })
            }

            /// The class described for front ends: its fields (name, kind, choices or a
            /// number's rule: min, max, exclusive, slider and rule; help) and constructors
            /// (their parameters, with the default of each).
            #[staticmethod]
            fn describe(py: Python<'_>) -> PyResult<Bound<'_, PyAny>> {
                $crate::py::settings::values::to_py(py, &$crate::render::settings::describe::<$core>())
            }
        }
    )*};
}
pub(crate) use python_classes;

/// The arguments of a call to `constructor`, by parameter (None: the default, so left out);
/// the core checks which it takes and needs.
pub fn make<T: Described>(
    constructor: &str,
    args: &Bound<'_, PyTuple>,
    kwargs: Option<&Bound<'_, PyDict>>,
) -> PyResult<T> {
    let ctor = described::constructor::<T>(constructor);
    let (mut keywords, mut given) = (Vec::new(), args.iter().collect::<Vec<_>>());
    for (k, v) in kwargs.into_iter().flat_map(|d| d.iter()) {
        keywords.push(k.extract().map_err(|_| Error::wrong_type("kwargs", "keywords must be strings"))?);
        given.push(v);
    }
    let params = described::bind::<T>(ctor, args.len(), keywords)?;
    let given = params.into_iter().zip(given).filter(|(_, v)| !v.is_none());
    let values = given.map(|(p, v)| Ok((p.name, values::from_py(p.name, p, &v)?))).collect::<Result<_>>()?;
    Ok(T::construct(constructor, values)?)
}

pub fn replace<T: Described>(value: &T, changes: Option<&Bound<'_, PyDict>>) -> PyResult<T> {
    let mut out = Vec::new();
    for (k, v) in changes.into_iter().flat_map(|d| d.iter()) {
        let k: String = k.extract().map_err(|_| Error::wrong_type("changes", "keywords must be strings"))?;
        let field = T::FIELDS.iter().find(|f| f.name == k);
        let value = match field {
            Some(f) if !v.is_none() => Some(values::from_py(&k, f, &v)?),
            _ => None,
        };
        // an unknown name is refused by the core, which lists the fields
        out.push((k, value));
    }
    Ok(described::replace(value, out)?)
}

pub fn getattr<'py, T: Described>(py: Python<'py>, value: &T, name: &str) -> PyResult<Bound<'py, PyAny>> {
    if T::FIELDS.iter().any(|f| f.name == name) {
        return values::to_py(py, &value.get(name));
    }
    Err(pyo3::exceptions::PyAttributeError::new_err(format!(
        "'{}' object has no attribute '{name}'",
        T::CLASS
    )))
}

pub fn dir<T: Described>(obj: &Bound<'_, PyAny>) -> PyResult<Vec<String>> {
    let mut names: Vec<String> = obj.get_type().dir()?.extract()?;
    names.extend(T::FIELDS.iter().map(|f| f.name.to_string()));
    names.sort();
    Ok(names)
}

/// `Class.constructor(required, ..., name=value, ...)`: what makes the value again.
pub fn repr<T: Described>(py: Python<'_>, value: &T) -> PyResult<String> {
    described::call(value, |v| {
        let obj = values::to_py(py, v)?;
        if !matches!(v, Value::Image(_)) {
            return Ok(obj.repr()?.to_string());
        }
        // an image's numbers in full (NumPy prints 8 digits, which do not make its float32s again)
        let options = py.import("numpy")?.call_method(
            "printoptions",
            (),
            Some(&[("floatmode", "unique")].into_py_dict(py)?),
        )?;
        options.call_method0("__enter__")?;
        let text = obj.repr().map(|r| r.to_string());
        options.call_method1("__exit__", (py.None(), py.None(), py.None()))?;
        text
    })
}

/// _restore(cls, state): a pickled setting, checked again.
#[pyfunction]
pub(super) fn _restore<'py>(py: Python<'py>, cls: &str, state: &str) -> PyResult<Bound<'py, PyAny>> {
    values::to_py(py, &Value::setting(Setting::restore(cls, state)?))
}

/// The names the core accepts, for Python to take rather than repeat.
fn add_names(m: &Bound<'_, PyModule>) -> PyResult<()> {
    for (name, names) in crate::render::accepted_names() {
        m.add(name, PyTuple::new(m.py(), names)?)?;
    }
    m.add("DEFAULT_CREASE_ANGLE", crate::edges::DEFAULT_CREASE_ANGLE)?;
    let up = crate::render::scene::up::FILE_UP_AXES.iter().map(|(suffix, axis)| (suffix, axis.name()));
    m.add("FILE_UP_AXES", up.into_py_dict(m.py())?)?;
    m.add("DEFAULT_UP_AXIS", crate::render::scene::up::DEFAULT_UP.name())
}

/// `RenderKeywords`: the render keywords as a TypedDict for `**options` in the public API, with
/// each keyword's help and default in its docstring. Its keys are in `__optional_keys__`; its
/// annotations are left empty, as no documentation tool finds a source line for them.
fn render_keywords(m: &Bound<'_, PyModule>) -> PyResult<()> {
    use crate::render::scene::options::RenderOptions;
    let py = m.py();
    let typing = py.import("typing")?;
    let keys = PyDict::new(py);
    let start = RenderOptions::default();
    let mut doc = String::from(
        "The keywords of :class:`RenderOptions`, and so of :func:`render`, :meth:`Renderer.render` and \
         :meth:`Renderer.render_many`. Each has its default in the core; a keyword given as None takes it.\n",
    );
    for f in RenderOptions::FIELDS {
        keys.set_item(f.name, typing.getattr("Any")?)?;
        let default = values::to_py(py, &start.get(f.name))?.repr()?;
        doc += &format!("\n- ``{}``: {} (default ``{default}``);", f.name, f.help);
    }
    let total = PyDict::new(py);
    total.set_item("total", false)?;
    let keywords = typing.getattr("TypedDict")?.call(("RenderKeywords", keys), Some(&total))?;
    keywords.setattr("__annotations__", PyDict::new(py))?;
    keywords.setattr("__doc__", doc)?;
    m.add("_RenderKeywords", keywords)
}

pub fn register(m: &Bound<'_, PyModule>) -> PyResult<()> {
    add_names(m)?;
    render_keywords(m)?;
    classes::register(m)
}

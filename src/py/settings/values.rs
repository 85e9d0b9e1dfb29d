//! Python objects to a field's value and back, by the field's kind (`render::settings::Kind`):
//! the only place that knows how each kind is spelt in Python.

use numpy::{PyArrayDescrMethods, PyUntypedArray, PyUntypedArrayMethods};
use pyo3::prelude::*;
use pyo3::types::{IntoPyDict, PyString};
use pyo3::IntoPyObjectExt;

use super::classes::{self, Light as PyLight, LineStyle as PyLineStyle};
use crate::error::{Error, Result};
use crate::py::args::{flag, integer, items, number, numbers, rgb, rgba, text, triple, type_name};
use crate::py::convert::shaped_to_numpy;
use crate::render::scene::light::Light;
use crate::render::settings::settings_classes;
use crate::render::settings::{Field, GreyImage, Kind, Setting, Value};

/// The value of `obj` for `field` (named `name` in errors).
pub fn from_py(name: &str, field: &Field, obj: &Bound<'_, PyAny>) -> Result<Value> {
    Ok(match field.kind {
        Kind::Bool => Value::Bool(flag(name, obj)?),
        Kind::Int { .. } => Value::Int(integer(name, obj)?),
        Kind::Float { .. } => Value::Float(number(name, obj)?),
        Kind::Choice(_) => Value::Text(text(name, obj)?),
        Kind::Color => Value::Triple(rgb(name, obj)?),
        Kind::Rgba => Value::Rgba(rgba(name, obj)?),
        Kind::Vec3 => Value::Triple(triple(name, obj)?),
        Kind::Floats => Value::Floats(numbers(name, obj)?),
        Kind::Table => Value::Rows(table(name, obj)?),
        Kind::Matrix => Value::Matrix(transform(name, obj)?),
        Kind::Names(_) => Value::Names(names(name, obj)?),
        Kind::Style => style(name, obj)?,
        Kind::Setting(class) => setting(name, class, obj)?,
        Kind::Lights => Value::Lights(lights(name, obj)?),
        Kind::Image => Value::Image(image(name, obj)?),
    })
}

/// A field's value as Python gives it back.
pub fn to_py<'py>(py: Python<'py>, value: &Value) -> PyResult<Bound<'py, PyAny>> {
    let triple = |t: &[f64; 3]| (t[0], t[1], t[2]);
    match value {
        Value::None => Ok(py.None().into_bound(py)),
        Value::Bool(b) => b.into_bound_py_any(py),
        Value::Int(i) => i.into_bound_py_any(py),
        Value::Float(x) => x.into_bound_py_any(py),
        Value::Text(s) => s.into_bound_py_any(py),
        Value::Triple(t) => triple(t).into_bound_py_any(py),
        Value::Rgba(c) => (c[0], c[1], c[2], c[3]).into_bound_py_any(py),
        Value::Floats(v) => v.clone().into_bound_py_any(py),
        Value::Rows(rows) => rows.iter().map(triple).collect::<Vec<_>>().into_bound_py_any(py),
        Value::Matrix(m) => m.iter().map(|r| r.to_vec()).collect::<Vec<_>>().into_bound_py_any(py),
        Value::Names(n) => n.clone().into_bound_py_any(py),
        Value::Image(g) => shaped_to_numpy(py, vec![g.height as usize, g.width as usize], g.values.clone()),
        Value::Lights(l) => {
            l.iter().map(|&inner| PyLight { inner }).collect::<Vec<_>>().into_bound_py_any(py)
        }
        Value::Map(items) => {
            let items = items.iter().map(|(k, v)| Ok((*k, to_py(py, v)?))).collect::<PyResult<Vec<_>>>()?;
            Ok(items.into_py_dict(py)?.into_any())
        }
        Value::List(items) => {
            items.iter().map(|v| to_py(py, v)).collect::<PyResult<Vec<_>>>()?.into_bound_py_any(py)
        }
        Value::Setting(s) => {
            macro_rules! wrap {
                ($($class:ident($docs:literal) = $core:path { $($ctors:tt)* })*) => {
                    match &**s {
                        $(Setting::$class(inner) => classes::$class { inner: inner.clone() }.into_bound_py_any(py),)*
                    }
                };
            }
            settings_classes!(wrap)
        }
    }
}

/// A settings object of `class`, or the other forms its field takes (a name or a flag).
fn setting(name: &str, class: &str, obj: &Bound<'_, PyAny>) -> Result<Value> {
    macro_rules! cast {
        ($($class:ident($docs:literal) = $core:path { $($ctors:tt)* })*) => {
            match class {
                $(stringify!($class) => {
                    obj.cast::<classes::$class>().ok().map(|o| Setting::$class(o.get().inner.clone()))
                })*
                _ => None,
            }
        };
    }
    let found = settings_classes!(cast);
    if let Some(s) = found {
        return Ok(Value::setting(s));
    }
    let expected = match class {
        "Dither" if obj.is_instance_of::<PyString>() => return Ok(Value::Text(text(name, obj)?)),
        "Outlines" if obj.is_instance_of::<PyString>() => return Ok(Value::Text(text(name, obj)?)),
        "Shadows" if flag(name, obj).is_ok() => return Ok(Value::Bool(flag(name, obj)?)),
        "Dither" => "a pattern name or a toonmesh.Dither".to_string(),
        "Outlines" => "None, 'mesh', 'image', 'both' or a toonmesh.Outlines".to_string(),
        "Shadows" => "True, False or a toonmesh.Shadows".to_string(),
        other => format!("a toonmesh.{other}"),
    };
    Err(Error::wrong_type(name, format!("expected {expected}, got {}", type_name(obj))))
}

/// An ink kind's style: True or False, a LineStyle, or a colour.
fn style(name: &str, obj: &Bound<'_, PyAny>) -> Result<Value> {
    if let Ok(s) = obj.cast::<PyLineStyle>() {
        return Ok(Value::setting(Setting::LineStyle(s.get().inner)));
    }
    if let Ok(on) = flag(name, obj) {
        return Ok(Value::Bool(on));
    }
    rgb(name, obj).map(Value::Triple).map_err(|e| match e {
        Error::WrongType { .. } => Error::wrong_type(
            name,
            format!("expected True, False, a LineStyle or a colour, got {}", type_name(obj)),
        ),
        other => other,
    })
}

/// The items of a sequence, each read by `read` (None: the wrong type for an item).
pub fn each<T>(
    obj: &Bound<'_, PyAny>,
    name: &str,
    expected: &str,
    item: &str,
    read: impl Fn(&Bound<'_, PyAny>) -> Option<T>,
) -> Result<Vec<T>> {
    let wrong = |i, x: &Bound<'_, PyAny>| {
        Error::wrong_type(format!("{name}[{i}]"), format!("expected {item}, got {}", type_name(x)))
    };
    items(name, obj, expected)?.iter().enumerate().map(|(i, x)| read(x).ok_or_else(|| wrong(i, x))).collect()
}

fn lights(name: &str, obj: &Bound<'_, PyAny>) -> Result<Vec<Light>> {
    if let Ok(l) = obj.cast::<PyLight>() {
        return Ok(vec![l.get().inner]);
    }
    each(obj, name, "a toonmesh.Light or a list of them", "a toonmesh.Light", |l| {
        l.cast::<PyLight>().ok().map(|l| l.get().inner)
    })
}

fn names(name: &str, obj: &Bound<'_, PyAny>) -> Result<Vec<String>> {
    if obj.is_instance_of::<PyString>() {
        return Ok(vec![text(name, obj)?]);
    }
    let expected = "a name or a sequence of names";
    each(obj, name, expected, "a name", |n| n.extract::<String>().ok())
}

/// A lookup table: (N,) grey factors or (N, 3) RGB factors.
fn table(name: &str, obj: &Bound<'_, PyAny>) -> Result<Vec<[f64; 3]>> {
    // how many entries a table may have is the core's check
    items(name, obj, "(N,) or (N, 3) numbers")?
        .iter()
        .enumerate()
        .map(|(i, r)| {
            let arg = format!("{name}[{i}]");
            if r.try_iter().is_ok() && !r.is_instance_of::<PyString>() {
                triple(&arg, r)
            } else {
                Ok([number(&arg, r)?; 3])
            }
        })
        .collect()
}

/// A grey image: an (H, W) or (H, W, C) array of 8-bit integers or of numbers in [0, 1] (the
/// core checks the shape and values, `GreyImage::from_pixels`).
fn image(name: &str, obj: &Bound<'_, PyAny>) -> Result<GreyImage> {
    let wrong = |what: &str| Error::wrong_type(name, format!("expected {what}, got {}", type_name(obj)));
    let a = obj.cast::<PyUntypedArray>().map_err(|_| wrong("an (H, W) or (H, W, C) NumPy array"))?;
    let full = match a.dtype().kind() {
        b'u' | b'i' => 255.0,
        b'f' => 1.0,
        _ => return Err(wrong("an array of integers (0 to 255) or floats (0 to 1)")),
    };
    let shape = a.shape().to_vec();
    let values = obj
        .call_method1("astype", ("float64",))
        .and_then(|x| x.extract::<numpy::PyReadonlyArrayDyn<'_, f64>>().map_err(PyErr::from))
        .map_err(|e| Error::invalid(name, e.to_string()))?
        .as_array()
        .iter()
        .copied()
        .collect::<Vec<f64>>();
    GreyImage::from_pixels(name, &shape, &values, full)
}

/// A 4x4 matrix of numbers.
pub fn transform(arg: &str, obj: &Bound<'_, PyAny>) -> Result<[[f64; 4]; 4]> {
    let expected = "a 4x4 array of numbers";
    let wrong = || Error::wrong_type(arg, format!("expected {expected}, got {}", type_name(obj)));
    if obj.cast::<PyUntypedArray>().is_ok_and(|a| !matches!(a.dtype().kind(), b'i' | b'u' | b'f')) {
        return Err(wrong());
    }
    let rows: Vec<Vec<f64>> =
        items(arg, obj, expected)?.iter().map(|r| numbers(arg, r)).collect::<Result<_>>()?;
    if rows.iter().any(|r| r.len() != rows[0].len()) {
        return Err(wrong());
    }
    if rows.len() != 4 || rows[0].len() != 4 {
        let cols = rows.first().map_or(0, |r| r.len());
        return Err(Error::invalid(arg, format!("expected shape (4, 4), got ({}, {cols})", rows.len())));
    }
    Ok(std::array::from_fn(|i| std::array::from_fn(|j| rows[i][j])))
}

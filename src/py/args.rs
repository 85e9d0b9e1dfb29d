//! Python scalars and small vectors as Rust values, with the type rules every public function
//! shares:
//!
//! - a flag takes True or False (or a NumPy bool), nothing else: `"no"` and `1` are refused;
//! - a number takes an int or a float (or a NumPy number, or any `numbers.Real`), never a bool
//!   or a string;
//! - an integer takes an int (or a NumPy integer, or any `numbers.Integral`), never a bool or a
//!   float;
//! - a name takes a str.
//!
//! A wrong type is a `TypeError` that names the argument and shows what was given; an integer
//! beyond 64 bits, or one too large for a float, is a `ValueError` naming it. Ranges (and NaN,
//! which no range admits) are checked by the core, where each rule lives.

use numpy::{PyArrayDescrMethods, PyUntypedArray, PyUntypedArrayMethods};
use pyo3::prelude::*;
use pyo3::sync::PyOnceLock;
use pyo3::types::{PyBool, PyFloat, PyInt, PyString, PyType};

use crate::error::{Error, Result};

/// `type value`, for messages: "str '30'", "bool True", "NoneType None".
fn shown(obj: &Bound<'_, PyAny>) -> String {
    let ty = obj.get_type().name().map(|n| n.to_string()).unwrap_or_else(|_| "object".into());
    let repr = obj.repr().map(|r| r.to_string()).unwrap_or_else(|_| "?".into());
    let repr = if repr.chars().count() > 40 {
        format!("{}...", repr.chars().take(40).collect::<String>())
    } else {
        repr
    };
    format!("{ty} {repr}")
}

fn abstract_type<'py>(
    py: Python<'py>,
    cell: &'static PyOnceLock<Py<PyType>>,
    module: &str,
    name: &str,
) -> Result<&'py Bound<'py, PyType>> {
    cell.import(py, module, name).map_err(|e| Error::Internal(format!("cannot import {module}.{name}: {e}")))
}

/// True for Python's bool and NumPy's bool, which count as flags, not numbers.
fn is_bool(obj: &Bound<'_, PyAny>) -> bool {
    if obj.is_instance_of::<PyBool>() {
        return true;
    }
    let ty = obj.get_type();
    ty.module().is_ok_and(|m| m == "numpy") && ty.name().is_ok_and(|n| n == "bool_" || n == "bool")
}

/// True or False (or a NumPy bool).
pub fn flag(arg: &str, obj: &Bound<'_, PyAny>) -> Result<bool> {
    if is_bool(obj) {
        return obj.is_truthy().map_err(|e| Error::wrong_type(arg, format!("expected True or False ({e})")));
    }
    Err(Error::wrong_type(arg, format!("expected True or False, got {}", shown(obj))))
}

/// An int or float (or NumPy number, or `numbers.Real`) as f64. NaN and inf pass: the core's
/// range checks refuse them where they are not allowed.
pub fn number(arg: &str, obj: &Bound<'_, PyAny>) -> Result<f64> {
    static REAL: PyOnceLock<Py<PyType>> = PyOnceLock::new();
    let numeric = obj.is_instance_of::<PyFloat>()
        || obj.is_instance_of::<PyInt>()
        || obj.is_instance(abstract_type(obj.py(), &REAL, "numbers", "Real")?).unwrap_or(false);
    if is_bool(obj) || !numeric {
        return Err(Error::wrong_type(arg, format!("expected a number, got {}", shown(obj))));
    }
    obj.extract::<f64>().map_err(|_| Error::invalid(arg, format!("{} is too large for a float", shown(obj))))
}

/// An int (or NumPy integer, or `numbers.Integral`) that fits in 64 bits.
pub fn integer(arg: &str, obj: &Bound<'_, PyAny>) -> Result<i64> {
    static INTEGRAL: PyOnceLock<Py<PyType>> = PyOnceLock::new();
    let integral = obj.is_instance_of::<PyInt>()
        || obj.is_instance(abstract_type(obj.py(), &INTEGRAL, "numbers", "Integral")?).unwrap_or(false);
    if is_bool(obj) || !integral {
        return Err(Error::wrong_type(arg, format!("expected an integer, got {}", shown(obj))));
    }
    obj.extract::<i64>().map_err(|_| {
        Error::invalid(arg, format!("{} is out of range (it does not fit in 64 bits)", shown(obj)))
    })
}

/// A non-negative integer below 2^64 (a seed).
pub fn unsigned(arg: &str, obj: &Bound<'_, PyAny>) -> Result<u64> {
    static INTEGRAL: PyOnceLock<Py<PyType>> = PyOnceLock::new();
    let integral = obj.is_instance_of::<PyInt>()
        || obj.is_instance(abstract_type(obj.py(), &INTEGRAL, "numbers", "Integral")?).unwrap_or(false);
    if is_bool(obj) || !integral {
        return Err(Error::wrong_type(arg, format!("expected an integer, got {}", shown(obj))));
    }
    obj.extract::<u64>()
        .map_err(|_| Error::invalid(arg, format!("must be in [0, 2**64), got {}", shown(obj))))
}

/// A str.
pub fn name(arg: &str, obj: &Bound<'_, PyAny>) -> Result<String> {
    match obj.cast::<PyString>() {
        Ok(s) => Ok(s.to_string()),
        Err(_) => Err(Error::wrong_type(arg, format!("expected a string, got {}", shown(obj)))),
    }
}

/// `None` (use the default) or a value read by `read`.
pub fn optional<T>(
    arg: &str,
    obj: Option<&Bound<'_, PyAny>>,
    read: impl FnOnce(&str, &Bound<'_, PyAny>) -> Result<T>,
) -> Result<Option<T>> {
    match obj {
        Some(o) if !o.is_none() => read(arg, o).map(Some),
        _ => Ok(None),
    }
}

/// Three numbers: a sequence of three Python or NumPy numbers, or a (3,) numeric array.
pub fn vec3(arg: &str, obj: &Bound<'_, PyAny>) -> Result<[f64; 3]> {
    if let Ok(a) = obj.cast::<PyUntypedArray>() {
        let kind = a.dtype().kind();
        if !matches!(kind, b'i' | b'u' | b'f') {
            return Err(Error::wrong_type(
                arg,
                format!(
                    "expected 3 numbers, got an array of dtype {}",
                    a.dtype().str().map(|s| s.to_string()).unwrap_or_default()
                ),
            ));
        }
        if a.shape() != [3] {
            return Err(Error::invalid(
                arg,
                format!("expected 3 numbers, got an array of shape {:?}", a.shape()),
            ));
        }
    } else if obj.is_instance_of::<PyString>() || obj.len().is_err() {
        return Err(Error::wrong_type(arg, format!("expected 3 numbers, got {}", shown(obj))));
    }
    let n = obj.len().unwrap_or(0);
    if n != 3 {
        return Err(Error::invalid(arg, format!("expected 3 numbers, got {n}")));
    }
    let mut out = [0.0; 3];
    for (k, o) in out.iter_mut().enumerate() {
        let item = obj
            .get_item(k)
            .map_err(|_| Error::wrong_type(arg, format!("expected 3 numbers, got {}", shown(obj))))?;
        *o = number(arg, &item).map_err(|e| match e {
            Error::WrongType { .. } => {
                Error::wrong_type(arg, format!("expected 3 numbers, got {} at position {k}", shown(&item)))
            }
            other => other,
        })?;
    }
    Ok(out)
}

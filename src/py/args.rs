//! Strict conversion of Python arguments, each error naming the argument: booleans take bools
//! (and NumPy bools), numbers take numbers (not bools, not strings), integers take integers (not
//! floats), colours take '#rrggbb' or three numbers in [0, 1]. A wrong type is a TypeError; an
//! integer beyond 64 bits, or one too large for a float, a ValueError. Ranges (and NaN, which no
//! range admits) are checked by the core, where each rule lives.

use pyo3::prelude::*;
use pyo3::types::{PyBool, PyByteArray, PyBytes, PyFloat, PyInt, PyString};

use crate::error::{Error, Result};
use crate::render::color;

pub fn type_name(obj: &Bound<'_, PyAny>) -> String {
    obj.get_type().name().map(|n| n.to_string()).unwrap_or_else(|_| "an unknown type".into())
}

fn numpy_kind(obj: &Bound<'_, PyAny>) -> Option<String> {
    let t = obj.get_type();
    let module = t.getattr("__module__").ok()?.extract::<String>().ok()?;
    (module == "numpy").then(|| type_name(obj))
}

fn is_bool(obj: &Bound<'_, PyAny>) -> bool {
    obj.is_instance_of::<PyBool>() || numpy_kind(obj).is_some_and(|k| k == "bool" || k == "bool_")
}

/// A bool (True/False or a NumPy bool).
pub fn flag(name: &str, obj: &Bound<'_, PyAny>) -> Result<bool> {
    if is_bool(obj) {
        return obj.is_truthy().map_err(|e| Error::wrong_type(name, e.to_string()));
    }
    Err(Error::wrong_type(name, format!("expected a bool (True or False), got {}", type_name(obj))))
}

/// A real number (int, float or NumPy number; not a bool or a string). NaN and inf pass: range
/// checks decide.
pub fn number(name: &str, obj: &Bound<'_, PyAny>) -> Result<f64> {
    if is_bool(obj) || obj.is_instance_of::<PyString>() {
        return Err(Error::wrong_type(name, format!("expected a number, got {}", type_name(obj))));
    }
    obj.extract::<f64>().map_err(|e| {
        if obj.is_instance_of::<PyInt>() {
            Error::invalid(name, format!("{} is too large for a float ({e})", obj))
        } else {
            Error::wrong_type(name, format!("expected a number, got {}", type_name(obj)))
        }
    })
}

/// An integer (int or NumPy integer; not a bool or a float), within i64.
pub fn integer(name: &str, obj: &Bound<'_, PyAny>) -> Result<i64> {
    integer_type(name, obj)?;
    obj.extract::<i64>().map_err(|_| Error::invalid(name, format!("{obj} is out of range")))
}

/// A non-negative integer below 2^64 (a seed).
pub fn unsigned(name: &str, obj: &Bound<'_, PyAny>) -> Result<u64> {
    integer_type(name, obj)?;
    obj.extract::<u64>().map_err(|_| Error::invalid(name, format!("must be in [0, 2**64), got {obj}")))
}

fn integer_type(name: &str, obj: &Bound<'_, PyAny>) -> Result<()> {
    let integral = obj.is_instance_of::<PyInt>()
        || (numpy_kind(obj).is_some() && obj.hasattr("__index__").unwrap_or(false));
    if is_bool(obj) || !integral || obj.is_instance_of::<PyFloat>() {
        return Err(Error::wrong_type(name, format!("expected an integer, got {}", type_name(obj))));
    }
    Ok(())
}

/// `None` (or absent: use the default) or a value read by `read`.
pub fn optional<T>(
    name: &str,
    obj: Option<&Bound<'_, PyAny>>,
    read: impl FnOnce(&str, &Bound<'_, PyAny>) -> Result<T>,
) -> Result<Option<T>> {
    match obj {
        Some(o) if !o.is_none() => read(name, o).map(Some),
        _ => Ok(None),
    }
}

/// A text argument.
pub fn text(name: &str, obj: &Bound<'_, PyAny>) -> Result<String> {
    obj.extract::<String>()
        .map_err(|_| Error::wrong_type(name, format!("expected a string, got {}", type_name(obj))))
}

/// The items of a sequence, `expected` saying what it should be. Text (str, bytes, bytearray)
/// is refused: it iterates, but as characters or byte codes, never as numbers or items.
pub fn items<'py>(name: &str, obj: &Bound<'py, PyAny>, expected: &str) -> Result<Vec<Bound<'py, PyAny>>> {
    let wrong = || Error::wrong_type(name, format!("expected {expected}, got {}", type_name(obj)));
    if obj.is_instance_of::<PyString>()
        || obj.is_instance_of::<PyBytes>()
        || obj.is_instance_of::<PyByteArray>()
    {
        return Err(wrong());
    }
    obj.try_iter()
        .map_err(|_| wrong())?
        .map(|item| item.map_err(|e| Error::invalid(name, e.to_string())))
        .collect()
}

/// A sequence of numbers (list, tuple, 1-D array).
pub fn numbers(name: &str, obj: &Bound<'_, PyAny>) -> Result<Vec<f64>> {
    let items = items(name, obj, "a sequence of numbers")?;
    items.iter().enumerate().map(|(i, item)| number(&format!("{name}[{i}]"), item)).collect()
}

/// Three finite numbers.
pub fn triple(name: &str, obj: &Bound<'_, PyAny>) -> Result<[f64; 3]> {
    crate::real::finite3(name, &numbers(name, obj)?)
}

/// Channels of a colour: '#rrggbb' ('#rrggbbaa') or numbers.
fn channels(name: &str, obj: &Bound<'_, PyAny>) -> Result<Vec<f64>> {
    if obj.is_instance_of::<PyString>() {
        return color::parse_hex(name, &text(name, obj)?);
    }
    numbers(name, obj).map_err(|e| match e {
        Error::WrongType { .. } => Error::wrong_type(
            name,
            format!("expected a colour: '#rrggbb' or 3 numbers in [0, 1], got {}", type_name(obj)),
        ),
        other => other,
    })
}

/// An sRGB colour: '#rrggbb' or 3 numbers in [0, 1].
pub fn rgb(name: &str, obj: &Bound<'_, PyAny>) -> Result<color::Srgb> {
    color::from_channels(name, &channels(name, obj)?)
}

/// An sRGB colour with alpha: '#rrggbb', '#rrggbbaa', or 3 or 4 numbers in [0, 1] (alpha 1
/// when not given).
pub fn rgba(name: &str, obj: &Bound<'_, PyAny>) -> Result<[f64; 4]> {
    color::rgba_from_channels(name, &channels(name, obj)?)
}

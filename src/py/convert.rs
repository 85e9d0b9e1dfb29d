//! NumPy arrays <-> core types. Inputs are copied (so they are never modified and any memory
//! order works); outputs are handed to NumPy without a copy.

use numpy::{
    IntoPyArray, PyArrayDescrMethods, PyReadonlyArray1, PyReadonlyArrayDyn, PyUntypedArray,
    PyUntypedArrayMethods,
};
use pyo3::prelude::*;
use pyo3::types::PyTuple;
use pyo3::IntoPyObjectExt;

use super::args::type_name;
use crate::edges::views::Lines;
use crate::error::{Error, Result};
use crate::mesh::{check_mask, flag_vertices, Positions};
use crate::names::listed;

/// `$body` on the first of the element types `$t` that `$obj` reads as, bound to `$x` as a
/// `$array` of it; None when it reads as none of them. NumPy dtypes match exactly (no casts).
macro_rules! by_dtype {
    ($obj:expr, $array:ident<$($t:ty),+>, |$x:ident| $body:expr) => {
        None $(.or_else(|| $obj.extract::<$array<'_, $t>>().ok().map(|$x| $body)))+
    };
}
pub(crate) use by_dtype;

/// The array in native byte order: `obj` itself when it already is (or is no array), else one
/// converted copy, so that big-endian input ('>f8', '>i4') is read like any other.
pub fn native_order<'py>(obj: &Bound<'py, PyAny>) -> Result<Bound<'py, PyAny>> {
    if let Ok(a) = obj.cast::<PyUntypedArray>() {
        if a.dtype().is_native_byteorder() == Some(false) {
            return a
                .dtype()
                .call_method1("newbyteorder", ("=",))
                .and_then(|native| obj.call_method1("astype", (native,)))
                .map_err(|e| Error::Internal(format!("byte-order conversion failed: {e}")));
        }
    }
    Ok(obj.clone())
}

pub fn untyped<'a, 'py>(arg: &str, obj: &'a Bound<'py, PyAny>) -> Result<&'a Bound<'py, PyUntypedArray>> {
    obj.cast::<PyUntypedArray>()
        .map_err(|_| Error::wrong_type(arg, format!("expected a NumPy array, got {}", type_name(obj))))
}

pub fn dtype_name(a: &Bound<'_, PyUntypedArray>) -> String {
    a.dtype().str().map(|s| s.to_string()).unwrap_or_else(|_| "?".into())
}

/// The float dtypes array arguments take.
pub const FLOATS: &[&str] = &["float32", "float64"];

/// An array argument in native byte order and its shape, checked: its dtype one of `dtypes`,
/// its shape `shape` (None: any length on that axis), written `what` in errors ("(K, 2)").
pub fn checked_array<'py>(
    arg: &str,
    obj: &Bound<'py, PyAny>,
    dtypes: &[&str],
    (shape, what): (&[Option<usize>], &str),
) -> Result<(Bound<'py, PyAny>, Vec<usize>)> {
    let obj = native_order(obj)?;
    let a = untyped(arg, &obj)?;
    let dtype = dtype_name(a);
    if !dtypes.contains(&dtype.as_str()) {
        return Err(Error::wrong_type(arg, format!("dtype must be {}, got {dtype}", listed(dtypes))));
    }
    let got = a.shape().to_vec();
    if got.len() != shape.len() || shape.iter().zip(&got).any(|(s, g)| s.is_some_and(|s| s != *g)) {
        return Err(Error::invalid(arg, format!("expected shape {what}, got {got:?}")));
    }
    Ok((obj, got))
}

/// The values of an array argument checked as `checked_array` does, converted to `T`, in
/// row-major order, and its shape.
pub fn array_values<T: numpy::Element + Copy>(
    arg: &str,
    obj: &Bound<'_, PyAny>,
    dtypes: &[&str],
    shape: (&[Option<usize>], &str),
) -> Result<(Vec<T>, Vec<usize>)> {
    let (obj, shape) = checked_array(arg, obj, dtypes, shape)?;
    let x = obj.call_method1("astype", (numpy::dtype::<T>(obj.py()),));
    let x = x
        .and_then(|x| Ok(x.extract::<PyReadonlyArrayDyn<'_, T>>()?))
        .map_err(|e| Error::Internal(e.to_string()))?;
    Ok((x.as_array().iter().copied().collect(), shape))
}

/// Row-major values as rows of `K`.
pub fn rows<T: Copy, const K: usize>(flat: &[T]) -> Vec<[T; K]> {
    flat.chunks_exact(K).map(|c| std::array::from_fn(|i| c[i])).collect()
}

/// Reads an optional 1-D array of vertex indices (any integer dtype, either byte order) or a
/// boolean mask of length `n_vertices`, returning a per-vertex flag.
pub fn vertex_mask(
    arg: &str,
    obj: Option<&Bound<'_, PyAny>>,
    n_vertices: usize,
) -> Result<Option<Vec<bool>>> {
    let Some(obj) = obj.filter(|o| !o.is_none()) else { return Ok(None) };
    let expected = "expected vertex indices or an (N,) boolean mask";
    let obj = &if obj.cast::<PyUntypedArray>().is_ok() {
        native_order(obj)?
    } else {
        // A list or tuple of indices or booleans.
        let np = obj.py().import("numpy");
        let arr = np.and_then(|np| np.call_method1("asarray", (obj,))).ok();
        arr.filter(|a| a.cast::<PyUntypedArray>().is_ok_and(|a| a.ndim() == 1))
            .ok_or_else(|| Error::wrong_type(arg, format!("{expected}, got {}", type_name(obj))))?
    };
    let a = untyped(arg, obj)?;
    if a.ndim() != 1 {
        return Err(Error::invalid(arg, format!("{expected}: a 1-D array, got shape {:?}", a.shape())));
    }
    if a.len() == 0 {
        return Ok(None); // an empty list pins nothing, whatever dtype NumPy gave it
    }
    let flags = match obj.extract::<PyReadonlyArray1<'_, bool>>() {
        Ok(mask) => check_mask(arg, mask.as_array().to_vec(), n_vertices),
        Err(_) => by_dtype!(obj, PyReadonlyArray1<i8, i16, i32, i64, u8, u16, u32, u64>, |x| {
            flag_vertices(arg, x.as_array().iter().copied(), n_vertices)
        })
        .unwrap_or_else(|| {
            let why = "expected vertex indices of an integer dtype or an (N,) boolean mask, got dtype";
            Err(Error::wrong_type(arg, format!("{why} {}", dtype_name(a))))
        }),
    };
    flags.map(Some)
}

/// A core result as Python receives it: a vector as a 1-D array and a vector of rows as a 2-D
/// one, handed to NumPy without a copy; vertex indices (u32) as int64, NumPy's index type; an
/// option as the value or None, and a tuple as a tuple of these.
pub trait ToPython<'py> {
    fn to_python(self, py: Python<'py>) -> PyResult<Bound<'py, PyAny>>;
}

macro_rules! arrays {
    ($($t:ty),*) => {$(
        impl<'py> ToPython<'py> for Vec<$t> {
            fn to_python(self, py: Python<'py>) -> PyResult<Bound<'py, PyAny>> {
                Ok(self.into_pyarray(py).into_any())
            }
        }

        impl<'py, const K: usize> ToPython<'py> for Vec<[$t; K]> {
            fn to_python(self, py: Python<'py>) -> PyResult<Bound<'py, PyAny>> {
                shaped_to_numpy(py, vec![self.len(), K], self.into_flattened())
            }
        }
    )*};
}
arrays!(f64, f32, bool, i8, i64);

impl<'py> ToPython<'py> for Vec<u32> {
    fn to_python(self, py: Python<'py>) -> PyResult<Bound<'py, PyAny>> {
        self.into_iter().map(i64::from).collect::<Vec<_>>().to_python(py)
    }
}

impl<'py, const K: usize> ToPython<'py> for Vec<[u32; K]> {
    fn to_python(self, py: Python<'py>) -> PyResult<Bound<'py, PyAny>> {
        self.into_iter().map(|r| r.map(i64::from)).collect::<Vec<_>>().to_python(py)
    }
}

impl<'py, T> ToPython<'py> for Bound<'py, T> {
    fn to_python(self, _: Python<'py>) -> PyResult<Bound<'py, PyAny>> {
        Ok(self.into_any())
    }
}

impl<'py, T: ToPython<'py>> ToPython<'py> for Option<T> {
    fn to_python(self, py: Python<'py>) -> PyResult<Bound<'py, PyAny>> {
        self.map_or_else(|| Ok(py.None().into_bound(py)), |x| x.to_python(py))
    }
}

macro_rules! tuples {
    ($(($($x:ident),+))*) => {$(
        impl<'py, $($x: ToPython<'py>),+> ToPython<'py> for ($($x,)+) {
            #[allow(non_snake_case)]
            fn to_python(self, py: Python<'py>) -> PyResult<Bound<'py, PyAny>> {
                let ($($x,)+) = self;
                PyTuple::new(py, [$($x.to_python(py)?),+])?.into_bound_py_any(py)
            }
        }
    )*};
}
tuples!((A, B)(A, B, C)(A, B, C, D, E, F));

/// Positions as (N, 3), in their precision.
impl<'py> ToPython<'py> for Positions {
    fn to_python(self, py: Python<'py>) -> PyResult<Bound<'py, PyAny>> {
        match self {
            Positions::F32(v) => v.to_python(py),
            Positions::F64(v) => v.to_python(py),
        }
    }
}

/// Edges as (K, 2) int64; polylines as their flat (P, 3) points and int64 line starts.
impl<'py> ToPython<'py> for Lines {
    fn to_python(self, py: Python<'py>) -> PyResult<Bound<'py, PyAny>> {
        match self {
            Lines::Edges(e) => e.to_python(py),
            Lines::Polylines(l) => (l.points, l.starts).to_python(py),
        }
    }
}

/// A core value through its serde form: a struct as a dict, an array or tuple as a tuple.
pub fn python<'py>(py: Python<'py>, value: &impl serde::Serialize) -> PyResult<Bound<'py, PyAny>> {
    pythonize::pythonize(py, value).map_err(|e| Error::Internal(e.to_string()).into())
}

/// Hands row-major values of any `shape` to NumPy without copying.
pub fn shaped_to_numpy<T: numpy::Element>(
    py: Python<'_>,
    shape: Vec<usize>,
    flat: Vec<T>,
) -> PyResult<Bound<'_, PyAny>> {
    let a =
        numpy::ndarray::ArrayD::from_shape_vec(shape, flat).map_err(|e| Error::Internal(e.to_string()))?;
    Ok(a.into_pyarray(py).into_any())
}

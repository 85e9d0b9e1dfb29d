//! The one place where core errors become Python exceptions.

use pyo3::exceptions::{PyIndexError, PyKeyboardInterrupt, PyRuntimeError, PyTypeError, PyValueError};
use pyo3::prelude::*;

use crate::error::Error;

pyo3::create_exception!(
    toonmesh,
    ConvergenceError,
    PyRuntimeError,
    "An iterative solver did not reach its tolerance."
);
pyo3::create_exception!(
    toonmesh,
    GpuUnavailableError,
    PyRuntimeError,
    "No GPU adapter (hardware, or Mesa's lavapipe/llvmpipe) could be found."
);
pyo3::create_exception!(toonmesh, GpuError, PyRuntimeError, "The GPU device failed while rendering.");

/// The one mapping from a core error to a Python exception.
impl From<Error> for PyErr {
    fn from(e: Error) -> PyErr {
        let msg = e.to_string();
        match e {
            Error::InvalidValue { .. } => PyValueError::new_err(msg),
            Error::IndexOutOfRange { .. } => PyIndexError::new_err(msg),
            Error::WrongType { .. } => PyTypeError::new_err(msg),
            Error::NotConverged(_) => ConvergenceError::new_err(msg),
            Error::NoAdapter(_) => GpuUnavailableError::new_err(msg),
            Error::Gpu(_) => GpuError::new_err(msg),
            Error::Interrupted => PyKeyboardInterrupt::new_err(msg),
            Error::Internal(_) => PyRuntimeError::new_err(msg),
        }
    }
}

pub fn register(m: &Bound<'_, PyModule>) -> PyResult<()> {
    let py = m.py();
    m.add("ConvergenceError", py.get_type::<ConvergenceError>())?;
    m.add("GpuUnavailableError", py.get_type::<GpuUnavailableError>())?;
    m.add("GpuError", py.get_type::<GpuError>())?;
    Ok(())
}

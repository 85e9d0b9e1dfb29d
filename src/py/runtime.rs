//! Running core work from Python: outside the GIL, inside the thread pool, with panics caught
//! so that none reaches Python.

use pyo3::prelude::*;

use super::errors::to_py;
use crate::error::{Error, Result};
use crate::parallel;

/// Runs compute work with the GIL released, inside the thread pool, and maps its error (or a
/// panic) to a Python exception.
pub fn detached<T: Send>(py: Python<'_>, work: impl FnOnce() -> Result<T> + Send) -> PyResult<T> {
    py.detach(|| catching_panics(|| parallel::install(work))).map_err(to_py)
}

/// Runs `work`, turning a panic into `Error::Internal` so that none reaches Python.
pub fn catching_panics<T>(work: impl FnOnce() -> Result<T>) -> Result<T> {
    std::panic::catch_unwind(std::panic::AssertUnwindSafe(work)).unwrap_or_else(|p| {
        let what = p
            .downcast_ref::<&str>()
            .map(|s| s.to_string())
            .or_else(|| p.downcast_ref::<String>().cloned())
            .unwrap_or_else(|| "unknown panic".into());
        Err(Error::Internal(what))
    })
}

/// set_num_threads(n: int) -> None
///
/// Sets how many worker threads toonmesh's parallel work uses, from the next call on.
///
/// n: a count from 1 to 1024, or 0 to restore the default (the ``TOONMESH_NUM_THREADS``
/// environment variable if set, else the number of cores). Results are the same bits for any
/// count. Raises ValueError below 0 or above 1024.
#[pyfunction]
fn set_num_threads(n: i64) -> PyResult<()> {
    let n = usize::try_from(n)
        .map_err(|_| Error::invalid("n", format!("must be >= 0 (0 restores the default), got {n}")))
        .map_err(to_py)?;
    parallel::set_num_threads(n).map_err(to_py)
}

/// get_num_threads() -> int
///
/// The number of worker threads the next parallel call will use (see ``set_num_threads``).
#[pyfunction]
fn get_num_threads() -> usize {
    parallel::num_threads()
}

pub fn register(m: &Bound<'_, PyModule>) -> PyResult<()> {
    m.add_function(wrap_pyfunction!(set_num_threads, m)?)?;
    m.add_function(wrap_pyfunction!(get_num_threads, m)?)?;
    Ok(())
}

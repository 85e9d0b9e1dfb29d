//! Running core work from Python: outside the GIL, inside the thread pool, with panics caught
//! so that none reaches Python, and (for long work) stopped by Ctrl-C.

use std::time::Duration;

use pyo3::prelude::*;

use super::args;
use crate::cancel::Cancel;
use crate::error::Result;
use crate::parallel::{self, catching_panics};

/// How often the calling thread looks for a pending signal while work runs: often enough that
/// Ctrl-C stops the work within a fraction of a second, rarely enough to cost nothing.
const SIGNAL_POLL: Duration = Duration::from_millis(5);

/// Runs compute work with the GIL released, inside the thread pool, and maps its error (or a
/// panic) to a Python exception.
pub fn detached<T: Send>(py: Python<'_>, work: impl FnOnce() -> Result<T> + Send) -> PyResult<T> {
    py.detach(|| catching_panics(|| parallel::install(work))).map_err(PyErr::from)
}

/// Runs long compute work as `detached` does, and stops it on Ctrl-C.
///
/// Python runs signal handlers only on its main thread, so the work is handed to the pool and
/// the calling thread, if it is the main thread, waits for it in short slices; after each
/// slice it re-attaches to the interpreter and runs `check_signals`. When that raises (a
/// KeyboardInterrupt, or whatever the handler raised), the work's `Cancel` is raised, the work
/// stops at its next check, and that exception is what the call raises. On any other thread
/// signals cannot be handled, and the work simply runs.
pub fn detached_cancellable<T: Send>(
    py: Python<'_>,
    work: impl FnOnce(&Cancel) -> Result<T> + Send,
) -> PyResult<T> {
    if !on_main_thread(py) {
        return detached(py, || work(Cancel::never()));
    }
    let mut raised: Option<PyErr> = None;
    let outcome = py.detach(|| {
        parallel::watched(work, SIGNAL_POLL, || {
            raised = Python::attach(|py| py.check_signals()).err();
            raised.is_some()
        })
    });
    // A signal that was taken must be raised, whatever the work returned meanwhile.
    match raised {
        Some(e) => Err(e),
        None => outcome.map_err(PyErr::from),
    }
}

/// Whether this is the thread Python runs signal handlers on.
fn on_main_thread(py: Python<'_>) -> bool {
    let threading = py.import("threading");
    let main =
        threading.and_then(|t| Ok(t.call_method0("main_thread")?.is(&t.call_method0("current_thread")?)));
    main.unwrap_or(false)
}

/// Sets how many worker threads toonmesh's parallel work uses, from the next call on.
/// Results are the same bits for any count.
///
/// Args:
///     n: a count from 1 to 1024, or 0 to restore the default (the ``TOONMESH_NUM_THREADS``
///         environment variable if set, else the number of cores).
///
/// Raises:
///     TypeError: anything but an int (or NumPy integer; bools are refused).
///     ValueError: below 0 or above 1024.
#[pyfunction]
pub(super) fn set_num_threads(n: &Bound<'_, PyAny>) -> PyResult<()> {
    Ok(parallel::set_num_threads(args::integer("n", n)?)?)
}

/// The number of worker threads the next parallel call will use (see :func:`set_num_threads`).
///
/// Returns:
///     The count, an int.
#[pyfunction]
pub(super) fn get_num_threads() -> usize {
    parallel::num_threads()
}

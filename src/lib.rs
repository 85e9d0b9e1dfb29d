//! toonmesh: mesh smoothing, outline extraction and headless toon rendering.
//!
//! Everything except `py` is a pure-Rust core that knows nothing of Python; `py` is the PyO3
//! glue, and this file only registers it.

pub mod cancel;
pub mod edges;
pub mod error;
pub mod huge_pages;
pub mod mesh;
pub mod names;
pub mod parallel;
pub mod points;
pub mod real;
pub mod render;
pub mod smooth;

#[cfg(feature = "python")]
mod py;

#[cfg(feature = "python")]
#[pyo3::pymodule]
fn _core(m: &pyo3::Bound<'_, pyo3::types::PyModule>) -> pyo3::PyResult<()> {
    py::register(m)
}

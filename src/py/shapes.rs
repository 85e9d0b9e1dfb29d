//! Procedural meshes, exposed for examples, tests and benchmarks.

use numpy::{PyArray2};
use pyo3::prelude::*;

use super::convert::{faces_to_numpy, rows3_to_numpy};
use super::runtime::detached;
use crate::mesh::shapes;

type MeshOut<'py> = (Bound<'py, PyArray2<f64>>, Bound<'py, PyArray2<i64>>);

#[pyfunction]
#[pyo3(signature = (subdivisions = 3, noise = 0.0, seed = 0))]
fn icosphere(py: Python<'_>, subdivisions: u32, noise: f64, seed: u64) -> PyResult<MeshOut<'_>> {
    let (v, f) = detached(py, || shapes::icosphere(subdivisions, noise, seed))?;
    Ok((rows3_to_numpy(py, v), faces_to_numpy(py, f)))
}

#[pyfunction]
#[pyo3(signature = (n = 32, noise = 0.0, seed = 0))]
fn grid(py: Python<'_>, n: u32, noise: f64, seed: u64) -> PyResult<MeshOut<'_>> {
    let (v, f) = detached(py, || shapes::grid(n, noise, seed))?;
    Ok((rows3_to_numpy(py, v), faces_to_numpy(py, f)))
}

pub fn register(m: &Bound<'_, PyModule>) -> PyResult<()> {
    m.add_function(wrap_pyfunction!(icosphere, m)?)?;
    m.add_function(wrap_pyfunction!(grid, m)?)?;
    Ok(())
}

//! Procedural meshes, exposed for examples, tests and benchmarks. The defaults live in the
//! Python wrappers (`toonmesh/shapes.py`), which pass every argument.

use numpy::PyArray2;
use pyo3::prelude::*;

use super::args;
use super::convert::{index_rows_to_numpy, rows_to_numpy};
use super::runtime::detached;
use crate::error::Result;
use crate::mesh::shapes;

type MeshOut<'py> = (Bound<'py, PyArray2<f64>>, Bound<'py, PyArray2<i64>>);

/// The mesh `make` builds from its size (the argument `size_name`), noise and seed, each read
/// and checked here.
fn procedural<'py>(
    py: Python<'py>,
    (size_name, size): (&str, &Bound<'py, PyAny>),
    noise: &Bound<'py, PyAny>,
    seed: &Bound<'py, PyAny>,
    make: impl FnOnce(i64, f64, u64) -> Result<shapes::Shape> + Send,
) -> PyResult<MeshOut<'py>> {
    let size = args::integer(size_name, size)?;
    let noise = args::number("noise", noise)?;
    let seed = args::unsigned("seed", seed)?;
    let (v, f) = detached(py, || make(size, noise, seed))?;
    Ok((rows_to_numpy(py, v), index_rows_to_numpy(py, f)))
}

#[pyfunction]
fn icosphere<'py>(
    py: Python<'py>,
    subdivisions: &Bound<'py, PyAny>,
    noise: &Bound<'py, PyAny>,
    seed: &Bound<'py, PyAny>,
) -> PyResult<MeshOut<'py>> {
    procedural(py, ("subdivisions", subdivisions), noise, seed, shapes::icosphere)
}

#[pyfunction]
fn grid<'py>(
    py: Python<'py>,
    n: &Bound<'py, PyAny>,
    noise: &Bound<'py, PyAny>,
    seed: &Bound<'py, PyAny>,
) -> PyResult<MeshOut<'py>> {
    procedural(py, ("n", n), noise, seed, shapes::grid)
}

pub fn register(m: &Bound<'_, PyModule>) -> PyResult<()> {
    m.add_function(wrap_pyfunction!(icosphere, m)?)?;
    m.add_function(wrap_pyfunction!(grid, m)?)?;
    Ok(())
}

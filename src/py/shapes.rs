//! Procedural meshes, exposed for examples, tests and benchmarks. The defaults live in the
//! Python wrappers (`toonmesh/shapes.py`), which pass every argument.

use numpy::PyArray2;
use pyo3::prelude::*;

use super::args;
use super::convert::{faces_to_numpy, rows3_to_numpy};
use super::errors::to_py;
use super::runtime::detached;
use crate::mesh::shapes;

type MeshOut<'py> = (Bound<'py, PyArray2<f64>>, Bound<'py, PyArray2<i64>>);

#[pyfunction]
fn icosphere<'py>(
    py: Python<'py>,
    subdivisions: &Bound<'py, PyAny>,
    noise: &Bound<'py, PyAny>,
    seed: &Bound<'py, PyAny>,
) -> PyResult<MeshOut<'py>> {
    let subdivisions = args::integer("subdivisions", subdivisions).map_err(to_py)?;
    let noise = args::number("noise", noise).map_err(to_py)?;
    let seed = args::unsigned("seed", seed).map_err(to_py)?;
    let (v, f) = detached(py, || shapes::icosphere(subdivisions, noise, seed))?;
    Ok((rows3_to_numpy(py, v), faces_to_numpy(py, f)))
}

#[pyfunction]
fn grid<'py>(
    py: Python<'py>,
    n: &Bound<'py, PyAny>,
    noise: &Bound<'py, PyAny>,
    seed: &Bound<'py, PyAny>,
) -> PyResult<MeshOut<'py>> {
    let n = args::integer("n", n).map_err(to_py)?;
    let noise = args::number("noise", noise).map_err(to_py)?;
    let seed = args::unsigned("seed", seed).map_err(to_py)?;
    let (v, f) = detached(py, || shapes::grid(n, noise, seed))?;
    Ok((rows3_to_numpy(py, v), faces_to_numpy(py, f)))
}

pub fn register(m: &Bound<'_, PyModule>) -> PyResult<()> {
    m.add_function(wrap_pyfunction!(icosphere, m)?)?;
    m.add_function(wrap_pyfunction!(grid, m)?)?;
    Ok(())
}

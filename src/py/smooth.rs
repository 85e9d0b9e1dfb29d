//! Python bindings for `crate::smooth`: one entry point, `_smooth`, that the public wrappers in
//! `toonmesh/smooth.py` call with their own signatures and docstrings.

use pyo3::prelude::*;

use super::convert::{rows3_to_numpy, vertex_mask};
use super::errors::to_py;
use super::mesh_input::{MeshInput, PositionsRef};
use crate::error::Error;
use crate::smooth::{self, Args, Method};

fn method(name: &str) -> Result<Method, Error> {
    match name {
        "laplacian" => Ok(Method::Laplacian),
        "taubin" => Ok(Method::Taubin),
        "hc" => Ok(Method::Hc),
        "implicit" => Ok(Method::Implicit),
        _ => Err(Error::invalid("method", format!("unknown smoothing method '{name}'"))),
    }
}

#[pyfunction]
#[pyo3(signature = (
    method_name, vertices, faces_arr, *, iterations=None, lamb=None, mu=None, alpha=None, beta=None,
    step=None, tol=None, max_iter=None, weights=None, boundary=None, pinned=None,
    volume_constraint=None, preset=None, weld=false
))]
#[allow(clippy::too_many_arguments)]
fn _smooth<'py>(
    py: Python<'py>,
    method_name: &str,
    vertices: &Bound<'py, PyAny>,
    faces_arr: &Bound<'py, PyAny>,
    iterations: Option<i64>,
    lamb: Option<f64>,
    mu: Option<f64>,
    alpha: Option<f64>,
    beta: Option<f64>,
    step: Option<f64>,
    tol: Option<f64>,
    max_iter: Option<i64>,
    weights: Option<String>,
    boundary: Option<String>,
    pinned: Option<&Bound<'py, PyAny>>,
    volume_constraint: Option<bool>,
    preset: Option<String>,
    weld: bool,
) -> PyResult<Bound<'py, PyAny>> {
    let m = method(method_name).map_err(to_py)?;
    let args = Args {
        iterations,
        lamb,
        mu,
        alpha,
        beta,
        step,
        tol,
        max_iter,
        weights,
        boundary,
        volume_constraint,
        preset,
        weld: Some(weld),
    };
    let plan = smooth::resolve(m, &args).map_err(to_py)?;
    let mesh = MeshInput::read(vertices, faces_arr).map_err(to_py)?;
    let pin = vertex_mask("pinned", pinned, mesh.n_vertices()).map_err(to_py)?;
    let pin = pin.as_deref();
    let out = mesh.run(py, faces_arr, |p, f| {
        Ok(match p {
            PositionsRef::F32(v) => Smoothed::F32(smooth::smooth(v, f, &plan, pin)?),
            PositionsRef::F64(v) => Smoothed::F64(smooth::smooth(v, f, &plan, pin)?),
        })
    })?;
    Ok(match out {
        Smoothed::F32(v) => rows3_to_numpy(py, v).into_any(),
        Smoothed::F64(v) => rows3_to_numpy(py, v).into_any(),
    })
}

/// Smoothed positions, in the input's precision.
enum Smoothed {
    F32(Vec<[f32; 3]>),
    F64(Vec<[f64; 3]>),
}

pub fn register(m: &Bound<'_, PyModule>) -> PyResult<()> {
    m.add_function(wrap_pyfunction!(_smooth, m)?)?;
    Ok(())
}

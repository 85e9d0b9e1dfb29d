//! Python bindings for `crate::smooth`: one entry point, `_smooth`, that the public wrappers in
//! `toonmesh/smooth.py` call with their own signatures and docstrings.

use pyo3::prelude::*;

use super::convert::{faces, positions, rows3_to_numpy, vertex_mask, Positions};
use super::errors::to_py;
use super::runtime::detached;
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
    volume_constraint=None, preset=None
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
    };
    let plan = smooth::resolve(m, &args).map_err(to_py)?;
    let v = positions("vertices", vertices).map_err(to_py)?;
    let f = faces("faces", faces_arr, v.len()).map_err(to_py)?;
    let pin = vertex_mask("pinned", pinned, v.len()).map_err(to_py)?;
    Ok(match v {
        Positions::F32(v) => {
            let out = detached(py, || smooth::smooth(&v, &f, &plan, pin.as_deref()))?;
            rows3_to_numpy(py, out).into_any()
        }
        Positions::F64(v) => {
            let out = detached(py, || smooth::smooth(&v, &f, &plan, pin.as_deref()))?;
            rows3_to_numpy(py, out).into_any()
        }
    })
}

pub fn register(m: &Bound<'_, PyModule>) -> PyResult<()> {
    m.add_function(wrap_pyfunction!(_smooth, m)?)?;
    Ok(())
}

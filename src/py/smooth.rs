//! Python bindings for `crate::smooth`: one entry point, `_smooth`, that the public wrappers in
//! `toonmesh/smooth.py` call with their own signatures and docstrings.

use pyo3::prelude::*;

use super::args;
use super::convert::{rows3_to_numpy, vertex_mask};
use super::errors::to_py;
use super::mesh_input::{MeshInput, PositionsRef};
use crate::error::Error;
use crate::smooth::denoise::{self, Filter};
use crate::smooth::{self, Args};

#[pyfunction]
#[pyo3(signature = (
    method_name, vertices, faces_arr, *, iterations=None, lamb=None, mu=None, alpha=None, beta=None,
    step=None, tol=None, max_iter=None, weights=None, boundary=None, pinned=None,
    volume_constraint=None, preset=None, weld
))]
#[allow(clippy::too_many_arguments)]
fn _smooth<'py>(
    py: Python<'py>,
    method_name: &str,
    vertices: &Bound<'py, PyAny>,
    faces_arr: &Bound<'py, PyAny>,
    iterations: Option<&Bound<'py, PyAny>>,
    lamb: Option<&Bound<'py, PyAny>>,
    mu: Option<&Bound<'py, PyAny>>,
    alpha: Option<&Bound<'py, PyAny>>,
    beta: Option<&Bound<'py, PyAny>>,
    step: Option<&Bound<'py, PyAny>>,
    tol: Option<&Bound<'py, PyAny>>,
    max_iter: Option<&Bound<'py, PyAny>>,
    weights: Option<&Bound<'py, PyAny>>,
    boundary: Option<&Bound<'py, PyAny>>,
    pinned: Option<&Bound<'py, PyAny>>,
    volume_constraint: Option<&Bound<'py, PyAny>>,
    preset: Option<&Bound<'py, PyAny>>,
    weld: &Bound<'py, PyAny>,
) -> PyResult<Bound<'py, PyAny>> {
    let m = smooth::options::parse_method(method_name).map_err(to_py)?;
    // None means "the preset's default" for every option.
    let args = (|| -> Result<Args, Error> {
        Ok(Args {
            iterations: args::optional("iterations", iterations, args::integer)?,
            lamb: args::optional("lamb", lamb, args::number)?,
            mu: args::optional("mu", mu, args::number)?,
            alpha: args::optional("alpha", alpha, args::number)?,
            beta: args::optional("beta", beta, args::number)?,
            step: args::optional("step", step, args::number)?,
            tol: args::optional("tol", tol, args::number)?,
            max_iter: args::optional("max_iter", max_iter, args::integer)?,
            weights: args::optional("weights", weights, args::text)?,
            boundary: args::optional("boundary", boundary, args::text)?,
            volume_constraint: args::optional("volume_constraint", volume_constraint, args::flag)?,
            preset: args::optional("preset", preset, args::text)?,
            weld: Some(args::flag("weld", weld)?),
        })
    })()
    .map_err(to_py)?;
    let plan = smooth::resolve(m, &args).map_err(to_py)?;
    let mesh = MeshInput::read(vertices, faces_arr).map_err(to_py)?;
    let pin = vertex_mask("pinned", pinned, mesh.n_vertices()).map_err(to_py)?;
    let (pin, largest) = (pin.as_deref(), mesh.largest_coordinate());
    let out = mesh.run(py, faces_arr, |p, f, cancel| {
        Ok(match p {
            PositionsRef::F32(v) => {
                Smoothed::F32(smooth::smooth_cancellable(v, f, &plan, pin, cancel, largest)?)
            }
            PositionsRef::F64(v) => {
                Smoothed::F64(smooth::smooth_cancellable(v, f, &plan, pin, cancel, largest)?)
            }
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

fn filter(name: &str) -> Result<Filter, Error> {
    match name {
        "bilateral" => Ok(Filter::Bilateral),
        "guided" => Ok(Filter::Guided),
        _ => Err(Error::invalid("method", format!("unknown normal filter '{name}'"))),
    }
}

/// The feature-preserving smoothers (`crate::smooth::denoise`); None means the default.
#[pyfunction]
#[pyo3(signature = (
    method_name, vertices, faces_arr, *, iterations=None, vertex_iterations=None, sigma_s=None,
    sigma_r=None, pinned=None, weld
))]
#[allow(clippy::too_many_arguments)]
fn _denoise<'py>(
    py: Python<'py>,
    method_name: &str,
    vertices: &Bound<'py, PyAny>,
    faces_arr: &Bound<'py, PyAny>,
    iterations: Option<&Bound<'py, PyAny>>,
    vertex_iterations: Option<&Bound<'py, PyAny>>,
    sigma_s: Option<&Bound<'py, PyAny>>,
    sigma_r: Option<&Bound<'py, PyAny>>,
    pinned: Option<&Bound<'py, PyAny>>,
    weld: &Bound<'py, PyAny>,
) -> PyResult<Bound<'py, PyAny>> {
    let f = filter(method_name).map_err(to_py)?;
    let opts = (|| -> Result<denoise::Options, Error> {
        denoise::resolve(
            f,
            &denoise::Args {
                iterations: args::optional("iterations", iterations, args::integer)?,
                vertex_iterations: args::optional("vertex_iterations", vertex_iterations, args::integer)?,
                sigma_s: args::optional("sigma_s", sigma_s, args::number)?,
                sigma_r: args::optional("sigma_r", sigma_r, args::number)?,
                weld: args::flag("weld", weld)?,
            },
        )
    })()
    .map_err(to_py)?;
    let mesh = MeshInput::read(vertices, faces_arr).map_err(to_py)?;
    let pin = vertex_mask("pinned", pinned, mesh.n_vertices()).map_err(to_py)?;
    let (pin, largest) = (pin.as_deref(), mesh.largest_coordinate());
    let out = mesh.run(py, faces_arr, |p, faces, cancel| {
        Ok(match p {
            PositionsRef::F32(v) => Smoothed::F32(denoise::denoise(v, faces, &opts, pin, cancel, largest)?),
            PositionsRef::F64(v) => Smoothed::F64(denoise::denoise(v, faces, &opts, pin, cancel, largest)?),
        })
    })?;
    Ok(match out {
        Smoothed::F32(v) => rows3_to_numpy(py, v).into_any(),
        Smoothed::F64(v) => rows3_to_numpy(py, v).into_any(),
    })
}

pub fn register(m: &Bound<'_, PyModule>) -> PyResult<()> {
    m.add_function(wrap_pyfunction!(_smooth, m)?)?;
    m.add_function(wrap_pyfunction!(_denoise, m)?)?;
    Ok(())
}

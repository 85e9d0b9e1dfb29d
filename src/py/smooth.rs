//! Python bindings for `crate::smooth`: one entry point, `_smooth`, that the public functions
//! of `toonmesh/smooth.py` call with their own signatures and docstrings (their keywords are
//! written there only; None means the default, and each is checked here and in the core).

use pyo3::prelude::*;
use pyo3::types::PyDict;

use super::args;
use super::convert::{vertex_mask, ToPython};
use super::mesh_input::MeshInput;
use crate::error::{Error, Result};
use crate::mesh::{Positions, PositionsRef};
use crate::smooth::denoise::{self, Filter};
use crate::smooth::{self, Args, Run};

/// The options a public function passed, taken one by one; what is left was not expected.
struct Options<'a, 'py>(&'a Bound<'py, PyDict>);

impl<'py> Options<'_, 'py> {
    /// The value given for `name`, None included (absent: None).
    fn given(&self, name: &str) -> Option<Bound<'py, PyAny>> {
        let v = self.0.get_item(name).ok().flatten();
        let _ = self.0.del_item(name);
        v
    }

    /// An option whose None means its default.
    fn take<T>(&self, name: &str, read: impl Fn(&str, &Bound<'_, PyAny>) -> Result<T>) -> Result<Option<T>> {
        args::optional(name, self.given(name).as_ref(), read)
    }

    fn rest(&self, method: &str) -> Result<()> {
        match self.0.keys().iter().next() {
            Some(k) => Err(Error::wrong_type(k.to_string(), format!("not an option of {method}"))),
            None => Ok(()),
        }
    }
}

fn plan(method: &str, o: &Options<'_, '_>) -> Result<Run> {
    let iterations = o.take("iterations", args::integer)?;
    // weld is always given (False by default), so None is refused as a non-bool
    let weld = o.given("weld").map(|w| args::flag("weld", &w)).transpose()?;
    let run = match Filter::of_method(method) {
        Some(f) => Run::Normals(denoise::resolve(
            f,
            &denoise::Args {
                iterations,
                vertex_iterations: o.take("vertex_iterations", args::integer)?,
                sigma_s: o.take("sigma_s", args::number)?,
                sigma_r: o.take("sigma_r", args::number)?,
                weld: weld.unwrap_or(false),
            },
        )?),
        None => Run::Laplacian(smooth::resolve(
            smooth::options::parse_method(method)?,
            &Args {
                iterations,
                lamb: o.take("lamb", args::number)?,
                mu: o.take("mu", args::number)?,
                alpha: o.take("alpha", args::number)?,
                beta: o.take("beta", args::number)?,
                step: o.take("step", args::number)?,
                tol: o.take("tol", args::number)?,
                max_iter: o.take("max_iter", args::integer)?,
                weights: o.take("weights", args::text)?,
                boundary: o.take("boundary", args::text)?,
                volume_constraint: o.take("volume_constraint", args::flag)?,
                preset: o.take("preset", args::text)?,
                weld,
            },
        )?),
    };
    o.rest(method)?;
    Ok(run)
}

#[pyfunction]
#[pyo3(signature = (method_name, mesh, **options))]
pub(super) fn _smooth<'py>(
    py: Python<'py>,
    method_name: &str,
    mesh: &Bound<'py, PyAny>,
    options: Option<&Bound<'py, PyDict>>,
) -> PyResult<Bound<'py, PyAny>> {
    let options = options.map_or_else(|| PyDict::new(py), |d| d.copy().expect("a dict copies"));
    let o = Options(&options);
    let pinned = o.given("pinned").filter(|p| !p.is_none());
    // `_as`: {option: the caller's name for it}, for errors
    let names: Vec<(String, String)> = o.given("_as").map_or(Ok(Vec::new()), |d| d.extract())?;
    let rename = |e: Error| names.iter().fold(e, |e, (from, to)| e.renamed(from, to));
    let run = plan(method_name, &o).map_err(rename)?;
    let mesh = MeshInput::of(mesh)?;
    let pin = vertex_mask("pinned", pinned.as_ref(), mesh.n_vertices())?;
    let (pin, largest) = (pin.as_deref(), mesh.largest_coordinate());
    let out = mesh.run(py, |p, f, cancel| {
        Ok(match p {
            PositionsRef::F32(v) => Positions::F32(run.run(v, f, pin, cancel, largest)?),
            PositionsRef::F64(v) => Positions::F64(run.run(v, f, pin, cancel, largest)?),
        })
    })?;
    out.to_python(py)
}

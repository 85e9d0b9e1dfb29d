//! Python bindings for `crate::smooth`: one entry point, `_smooth`, that the public functions
//! of `toonmesh/smooth.py` call with their own signatures and docstrings. The keywords are read
//! by the kinds the core describes (`smooth::keywords`); None means the default, and each is
//! checked here for its type and in the core for its value.

use pyo3::prelude::*;
use pyo3::types::PyDict;

use super::args;
use super::convert::{vertex_mask, ToPython};
use super::mesh_input::MeshInput;
use crate::error::{Error, Result};
use crate::mesh::{Positions, PositionsRef};
use crate::smooth::keywords::{Given, Kind, Smoother};
use crate::smooth::Run;

/// How `method` runs with the keywords in `options`, each read by its kind; a keyword the
/// method does not take is refused.
fn plan(method: &str, options: &Bound<'_, PyDict>) -> Result<Run> {
    let smoother = Smoother::parse(method)?;
    let mut given = Vec::new();
    for k in smoother.keywords() {
        let Some(v) = options.get_item(k.name).ok().flatten() else { continue };
        let _ = options.del_item(k.name);
        if v.is_none() && k.takes_none {
            continue;
        }
        given.push((
            k.name,
            match k.kind {
                Kind::Int => Given::Int(args::integer(k.name, &v)?),
                Kind::Float => Given::Float(args::number(k.name, &v)?),
                Kind::Name => Given::Name(args::text(k.name, &v)?),
                Kind::Bool => Given::Bool(args::flag(k.name, &v)?),
            },
        ));
    }
    if let Some(k) = options.keys().iter().next() {
        return Err(Error::wrong_type(k.to_string(), format!("not an option of {method}")));
    }
    smoother.plan(given)
}

#[pyfunction]
#[pyo3(signature = (method_name, mesh, **options))]
pub(super) fn _smooth<'py>(
    py: Python<'py>,
    method_name: &str,
    mesh: &Bound<'py, PyAny>,
    options: Option<&Bound<'py, PyDict>>,
) -> PyResult<Bound<'py, PyAny>> {
    let options = options.map_or_else(|| Ok(PyDict::new(py)), |d| d.copy())?;
    let pinned = options.get_item("pinned")?.filter(|p| !p.is_none());
    // `_as`: {option: the caller's name for it}, for errors
    let names: Vec<(String, String)> = options.get_item("_as")?.map_or(Ok(Vec::new()), |d| d.extract())?;
    let (_, _) = (options.del_item("pinned"), options.del_item("_as"));
    let rename = |e: Error| names.iter().fold(e, |e, (from, to)| e.renamed(from, to));
    let run = plan(method_name, &options).map_err(rename)?;
    let mesh = MeshInput::of(mesh)?;
    let pin = vertex_mask("pinned", pinned.as_ref(), mesh.vertices.count())?;
    let (pin, largest) = (pin.as_deref(), Some(mesh.vertices.largest));
    let out = mesh.run(py, |p, f, cancel| {
        Ok(match p {
            PositionsRef::F32(v) => Positions::F32(run.run(v, &f, pin, cancel, largest)?),
            PositionsRef::F64(v) => Positions::F64(run.run(v, &f, pin, cancel, largest)?),
        })
    })?;
    out.to_python(py)
}

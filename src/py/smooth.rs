//! Python bindings for `crate::smooth`: one entry point, `_smooth`, that the public functions
//! of `toonmesh/smooth.py` call, and the methods' description, `_smoothing_description`, that
//! their signatures, docstrings and TypedDicts and the command line's flags are made from. The
//! keywords are read by the kinds the core describes (`smooth::described`); None means the
//! default, and each is checked here for its type and in the core for its value.

use pyo3::prelude::*;
use pyo3::types::{PyDict, PyList};
use pyo3::IntoPyObjectExt;

use super::args;
use super::convert::{vertex_mask, ToPython};
use super::mesh_input::MeshInput;
use crate::error::{Error, Result};
use crate::mesh::{Positions, PositionsRef};
use crate::smooth::described::{self, Keyword, Rule, Value, METHODS};
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

/// A described value as Python holds it (None for no value: no preset, or measured).
fn value<'py>(py: Python<'py>, v: Value) -> PyResult<Bound<'py, PyAny>> {
    match v {
        Value::Int(n) => n.into_bound_py_any(py),
        Value::Float(x) => x.into_bound_py_any(py),
        Value::Name(s) => s.into_bound_py_any(py),
        Value::Bool(b) => b.into_bound_py_any(py),
        Value::Unset | Value::Measured(_) => Ok(py.None().into_bound(py)),
    }
}

/// A rule's keys: `min`, `max` (floats, infinite where unbounded) and `exclusive` for a range,
/// `choices` for names; none for a flag.
fn rule<'py>(py: Python<'py>, r: Rule, into: &Bound<'py, PyDict>) -> PyResult<()> {
    match r {
        Rule::Range { min, max, exclusive } => {
            into.set_item("min", min)?;
            into.set_item("max", max)?;
            into.set_item("exclusive", PyList::new(py, exclusive)?)?;
        }
        Rule::Choices(names) => into.set_item("choices", PyList::new(py, names)?)?,
        Rule::Flag => {}
    }
    Ok(())
}

fn keyword<'py>(py: Python<'py>, k: &Keyword) -> PyResult<Bound<'py, PyDict>> {
    let d = PyDict::new(py);
    d.set_item("name", k.name)?;
    let kind = match k.kind {
        Kind::Int => "int",
        Kind::Float => "float",
        Kind::Name => "choice",
        Kind::Bool => "bool",
    };
    d.set_item("kind", kind)?;
    rule(py, k.rule, &d)?;
    d.set_item("optional", k.takes_none)?;
    d.set_item("default", value(py, k.default)?)?;
    let words = match k.default {
        Value::Measured(words) => Some(words()),
        _ => None,
    };
    d.set_item("default_words", words)?;
    let presets = PyDict::new(py);
    for (p, v) in k.presets {
        presets.set_item(described::preset_name(*p), value(py, *v)?)?;
    }
    d.set_item("presets", presets)?;
    let ranges = PyDict::new(py);
    for (p, r) in k.preset_rules {
        let range = PyDict::new(py);
        rule(py, *r, &range)?;
        ranges.set_item(described::preset_name(*p), range)?;
    }
    d.set_item("preset_ranges", ranges)?;
    d.set_item("help", k.help)?;
    Ok(d)
}

/// Every smoothing method as the core describes it: a list of
/// `{"method", "help", "keywords": [...], "presets": [...]}`, each keyword a dict of `name`,
/// `kind` ("int", "float", "choice" or "bool"), `min`/`max`/`exclusive` (a range) or `choices`,
/// `optional` (None means the default), `default` (without a preset; None where there is none
/// or it is measured from the mesh, as `default_words` then says), `presets` (the presets whose
/// default differs), `preset_ranges` (those whose range differs) and `help`.
#[pyfunction]
pub(super) fn _smoothing_description(py: Python<'_>) -> PyResult<Bound<'_, PyList>> {
    let methods = PyList::empty(py);
    for m in &METHODS {
        let d = PyDict::new(py);
        d.set_item("method", m.name)?;
        d.set_item("help", m.help)?;
        let keywords = PyList::empty(py);
        for k in m.keywords {
            keywords.append(keyword(py, k)?)?;
        }
        d.set_item("keywords", keywords)?;
        d.set_item("presets", PyList::new(py, m.presets())?)?;
        methods.append(d)?;
    }
    Ok(methods)
}

//! PyO3 glue: NumPy in and out, argument checks, GIL release, error mapping.

mod albedo;
mod args;
mod convert;
mod edges;
mod errors;
mod mesh_input;
mod render;
mod runtime;
mod settings;
mod shapes;
mod smooth;
mod strokes;

use pyo3::prelude::*;

pub fn register(m: &Bound<'_, PyModule>) -> PyResult<()> {
    errors::register(m)?;
    edges::register(m)?;
    runtime::register(m)?;
    shapes::register(m)?;
    smooth::register(m)?;
    strokes::register(m)?;
    settings::register(m)?;
    render::register(m)?;
    m.add("__version__", env!("CARGO_PKG_VERSION"))?;
    Ok(())
}

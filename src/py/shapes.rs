//! Procedural meshes, exposed for examples, tests and benchmarks. The defaults live in the
//! Python wrappers (`toonmesh/shapes.py`), which pass every argument.

use pyo3::prelude::*;

use super::args;
use super::convert::ToPython;
use super::runtime::detached;
use crate::error::Result;
use crate::mesh::shapes;

/// The mesh `make` builds from its size (the argument `size_name`), noise and seed, each read
/// and checked here.
fn procedural<'py>(
    py: Python<'py>,
    (size_name, size): (&str, &Bound<'py, PyAny>),
    noise: &Bound<'py, PyAny>,
    seed: &Bound<'py, PyAny>,
    make: impl FnOnce(i64, f64, u64) -> Result<shapes::Shape> + Send,
) -> PyResult<Bound<'py, PyAny>> {
    let size = args::integer(size_name, size)?;
    let noise = args::number("noise", noise)?;
    let seed = args::unsigned("seed", seed)?;
    detached(py, || make(size, noise, seed))?.to_python(py)
}

/// `$shape(size, noise, seed)`: `shapes::$shape`, its size argument called `$size`.
macro_rules! procedural {
    ($($shape:ident($size:ident)),*) => {$(
        #[pyfunction]
        pub(super) fn $shape<'py>(
            py: Python<'py>,
            $size: &Bound<'py, PyAny>,
            noise: &Bound<'py, PyAny>,
            seed: &Bound<'py, PyAny>,
        ) -> PyResult<Bound<'py, PyAny>> {
            procedural(py, (stringify!($size), $size), noise, seed, shapes::$shape)
        }
    )*};
}
procedural!(icosphere(subdivisions), grid(n));

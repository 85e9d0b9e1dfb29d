//! Python bindings for point clouds: `_point_normals` (`toonmesh.points.normals`) and
//! `Renderer.add_points`, which uploads a cloud as splats (`render::splats`).

use numpy::{PyUntypedArray, PyUntypedArrayMethods};
use pyo3::prelude::*;

use super::albedo::channels;
use super::args::{self, number};
use super::convert::{array_values, ToPython, FLOATS};
use super::mesh_input::PositionsIn;
use super::render::{without_gil, PyRenderer};
use super::runtime::detached;
use crate::error::{Error, Result};
use crate::mesh::normals::given_unit_normals;
use crate::mesh::positions::on_positions;
use crate::points::local::{check_neighbours, neighbourhoods, DEFAULT_NEIGHBOURS};
use crate::real::{to_f64, Real};
use crate::render::albedo::given::Given;
use crate::render::albedo::Colors;
use crate::render::splats::Radius;

/// (N, 3) float positions as float64 rows.
fn points(arg: &str, obj: &Bound<'_, PyAny>) -> Result<Vec<[f64; 3]>> {
    let p = PositionsIn::read(arg, obj)?;
    Ok(on_positions!(p.get(), v => v.iter().map(|x| to_f64(*x)).collect()))
}

/// `k`: an int, 3 to `MAX_NEIGHBOURS`; None: `DEFAULT_NEIGHBOURS`.
fn neighbours(k: &Bound<'_, PyAny>) -> Result<usize> {
    if k.is_none() {
        return Ok(DEFAULT_NEIGHBOURS);
    }
    let k = args::integer("k", k)?;
    let k = usize::try_from(k).map_err(|_| Error::invalid("k", format!("must be >= 3, got {k}")))?;
    check_neighbours("k", k)?;
    Ok(k)
}

/// _point_normals(positions, k) -> (N, 3) array of the positions' dtype: each point's unit
/// normal from its k nearest neighbours (`points::local`; k None: `DEFAULT_NEIGHBOURS`).
#[pyfunction]
pub(super) fn _point_normals<'py>(
    py: Python<'py>,
    positions: &Bound<'py, PyAny>,
    k: &Bound<'py, PyAny>,
) -> PyResult<Bound<'py, PyAny>> {
    let p = PositionsIn::read("positions", positions)?;
    let k = neighbours(k)?;
    fn typed<T: Real>(v: &[[T; 3]], k: usize) -> Vec<[T; 3]> {
        let points: Vec<[f64; 3]> = v.iter().map(|x| to_f64(*x)).collect();
        neighbourhoods(&points, k).into_iter().map(|l| l.normal.map(T::from_f64)).collect()
    }
    match p.get() {
        crate::mesh::positions::PositionsRef::F32(v) => detached(py, || Ok(typed(v, k)))?.to_python(py),
        crate::mesh::positions::PositionsRef::F64(v) => detached(py, || Ok(typed(v, k)))?.to_python(py),
    }
}

/// The argument `radius`: None (from the spacing), a number, or an (N,) float array.
fn radii(obj: &Bound<'_, PyAny>) -> Result<Radius> {
    if obj.is_none() {
        return Ok(Radius::Spacing);
    }
    if obj.cast::<PyUntypedArray>().is_ok_and(|a| a.ndim() == 1) {
        return Ok(Radius::Each(array_values("radius", obj, FLOATS, (&[None], "(N,)"))?.0));
    }
    Ok(Radius::All(number("radius", obj)?))
}

#[pymethods]
impl PyRenderer {
    /// add_points(positions, normals, colors, radius, k) -> mesh id: a point cloud uploaded as
    /// splats; see `toonmesh.Points`.
    #[pyo3(signature = (positions, normals, colors, radius, k))]
    fn add_points(
        &self,
        py: Python<'_>,
        positions: &Bound<'_, PyAny>,
        normals: &Bound<'_, PyAny>,
        colors: &Bound<'_, PyAny>,
        radius: &Bound<'_, PyAny>,
        k: &Bound<'_, PyAny>,
    ) -> PyResult<u64> {
        let p = points("positions", positions)?;
        let k = neighbours(k)?;
        let normals = if normals.is_none() {
            None
        } else {
            let n = PositionsIn::read("normals", normals)?;
            let unit = on_positions!(n.get(), v => given_unit_normals("normals", v, p.len()))?;
            Some(unit.into_iter().map(|x| x.map(f64::from)).collect())
        };
        let colors = if colors.is_none() {
            None
        } else {
            let given = Given { vertex_colors: Some(channels("colors", colors)?), ..Given::default() };
            match given.albedo().map_err(|e| e.renamed("vertex_colors", "colors"))? {
                Some(a) => match a.colors {
                    Some(Colors::Vertex(c)) => Some(c),
                    _ => None,
                },
                None => None,
            }
        };
        let radius = radii(radius)?;
        let inner = &self.inner;
        without_gil(py, || inner.add_points(&p, normals, colors, &radius, k))
    }
}

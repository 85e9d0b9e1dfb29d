//! Mesh input read straight from NumPy's buffers when they are C-contiguous (the usual case),
//! so a million-face mesh is not copied and checked serially before the parallel work starts.
//! Anything else, and every error message, goes through the general readers in `convert`.
//! Arrays in the other byte order are converted once, on entry.

use numpy::{PyReadonlyArray2, PyUntypedArrayMethods};
use pyo3::prelude::*;

use super::args::type_name;
use super::convert::{faces, native_order, positions};
use super::runtime::detached_cancellable;
use crate::cancel::Cancel;
use crate::error::{Error, Result};
use crate::mesh::positions::on_positions;
use crate::mesh::{faces_from_flat, rows_of, Positions, PositionsRef};
use crate::real::Real;
use crate::smooth::range::largest_if_finite;

/// Vertices and faces as read from Python: borrowed when possible, owned otherwise.
pub struct MeshInput<'py> {
    vertices: VerticesIn<'py>,
    faces: FacesIn<'py>,
    n_vertices: usize,
    /// The largest absolute coordinate, when the fast path computed it.
    largest: Option<f64>,
}

/// NumPy's own buffer when it is C-contiguous and finite, else a checked copy.
enum VerticesIn<'py> {
    F32(PyReadonlyArray2<'py, f32>),
    F64(PyReadonlyArray2<'py, f64>),
    Copied(Positions),
}

/// NumPy's own int64 or int32 buffer when it is C-contiguous (its indices are checked as they
/// are converted, in `run`), else a checked copy.
enum FacesIn<'py> {
    I64(PyReadonlyArray2<'py, i64>),
    I32(PyReadonlyArray2<'py, i32>),
    Checked(Vec<[u32; 3]>),
}

fn contiguous_rows3<'py, T: numpy::Element>(obj: &Bound<'py, PyAny>) -> Option<PyReadonlyArray2<'py, T>> {
    let x = obj.extract::<PyReadonlyArray2<'py, T>>().ok()?;
    let shape = x.shape();
    (shape[1] == 3 && shape[0] > 0 && x.is_c_contiguous()).then_some(x)
}

/// The largest absolute value in `x`, or None if any is not finite.
fn largest_of<T: Real + numpy::Element>(x: &PyReadonlyArray2<'_, T>) -> Option<f64> {
    largest_if_finite(x.as_slice().ok()?)
}

fn slice<'a, T: numpy::Element>(x: &'a PyReadonlyArray2<'_, T>) -> &'a [T] {
    x.as_slice().expect("checked contiguous")
}

/// `$body` run on the mesh argument `$mesh` (see `MeshInput::of`, `MeshInput::run`), with `$v`
/// its positions in their own precision, `$f` its faces and `$cancel` Ctrl-C's flag.
macro_rules! on_mesh {
    ($py:expr, $mesh:expr, |$v:ident, $f:ident, $cancel:pat_param| $body:expr) => {
        $crate::py::mesh_input::MeshInput::of($mesh)?
            .run($py, |p, $f, $cancel| $crate::mesh::positions::on_positions!(p, $v => $body))
    };
}
pub(crate) use on_mesh;

impl<'py> MeshInput<'py> {
    /// A mesh argument: the pair (vertices, faces) the Python wrappers pass, read as `read` reads
    /// them.
    pub fn of(mesh: &Bound<'py, PyAny>) -> Result<Self> {
        let (vertices, faces) = mesh.extract::<(Bound<'py, PyAny>, Bound<'py, PyAny>)>().map_err(|_| {
            Error::wrong_type("mesh", format!("expected (vertices, faces), got {}", type_name(mesh)))
        })?;
        Self::read(&vertices, &faces)
    }

    pub fn read(vertices: &Bound<'py, PyAny>, faces_obj: &Bound<'py, PyAny>) -> Result<Self> {
        let (vertices, faces_obj) = (&native_order(vertices)?, &native_order(faces_obj)?);
        // One pass checks finiteness and finds the scale (which smoothing needs).
        let borrowed = match contiguous_rows3::<f32>(vertices) {
            Some(x) => largest_of(&x).map(|m| (VerticesIn::F32(x), m)),
            None => contiguous_rows3::<f64>(vertices)
                .and_then(|x| largest_of(&x).map(|m| (VerticesIn::F64(x), m))),
        };
        let (vertices, largest) = match borrowed {
            Some((v, m)) => (v, Some(m)),
            None => (VerticesIn::Copied(positions("vertices", vertices)?), None),
        };
        let mut me = MeshInput { vertices, faces: FacesIn::Checked(Vec::new()), n_vertices: 0, largest };
        me.n_vertices = on_positions!(me.positions(), v => v.len());
        me.faces = match contiguous_rows3::<i64>(faces_obj) {
            Some(x) => FacesIn::I64(x),
            None => match contiguous_rows3::<i32>(faces_obj) {
                Some(x) => FacesIn::I32(x),
                None => FacesIn::Checked(faces("faces", faces_obj, me.n_vertices)?),
            },
        };
        Ok(me)
    }

    pub fn n_vertices(&self) -> usize {
        self.n_vertices
    }

    /// The largest absolute coordinate, if reading found it.
    pub fn largest_coordinate(&self) -> Option<f64> {
        self.largest
    }

    pub fn positions(&self) -> PositionsRef<'_> {
        match &self.vertices {
            VerticesIn::F32(x) => PositionsRef::F32(rows_of(slice(x))),
            VerticesIn::F64(x) => PositionsRef::F64(rows_of(slice(x))),
            VerticesIn::Copied(p) => p.slices(),
        }
    }

    /// Runs `work` on the mesh with the GIL released, stopping on Ctrl-C when `work` checks its
    /// `Cancel` (see `runtime::detached_cancellable`). NumPy's faces are converted to u32
    /// inside, in parallel, and checked as the general reader checks them.
    pub fn run<R: Send>(
        &self,
        py: Python<'_>,
        work: impl Fn(PositionsRef<'_>, &[[u32; 3]], &Cancel) -> Result<R> + Send + Sync,
    ) -> PyResult<R> {
        let (positions, n) = (self.positions(), self.n_vertices);
        let faces = match &self.faces {
            FacesIn::Checked(f) => FacesRef::Checked(f),
            FacesIn::I64(x) => FacesRef::I64(slice(x)),
            FacesIn::I32(x) => FacesRef::I32(slice(x)),
        };
        detached_cancellable(py, |cancel| match faces {
            FacesRef::Checked(f) => work(positions, f, cancel),
            FacesRef::I64(flat) => work(positions, &faces_from_flat("faces", flat, n)?, cancel),
            FacesRef::I32(flat) => work(positions, &faces_from_flat("faces", flat, n)?, cancel),
        })
    }
}

#[derive(Clone, Copy)]
enum FacesRef<'a> {
    I64(&'a [i64]),
    I32(&'a [i32]),
    Checked(&'a [[u32; 3]]),
}

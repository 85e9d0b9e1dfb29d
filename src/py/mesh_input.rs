//! Mesh input read straight from NumPy's buffers, so that a million-face mesh is not copied
//! and checked serially before the parallel work starts. An array in another memory order or
//! byte order is converted once, on entry; every check after its dtype and shape is the core's.

use numpy::PyReadonlyArray2;
use pyo3::prelude::*;

use super::args::type_name;
use super::convert::{checked_array, FLOATS};
use super::runtime::detached_cancellable;
use crate::cancel::Cancel;
use crate::error::{Error, Result};
use crate::mesh::positions::on_positions;
use crate::mesh::{rows_of, Faces, FacesRef, PositionsRef};
use crate::smooth::range::checked_scale;

/// A C-contiguous (N, 3) array borrowed from NumPy, of an element type a mesh takes.
enum Rows3<'py> {
    F32(PyReadonlyArray2<'py, f32>),
    F64(PyReadonlyArray2<'py, f64>),
    I32(PyReadonlyArray2<'py, i32>),
    I64(PyReadonlyArray2<'py, i64>),
    U32(PyReadonlyArray2<'py, u32>),
    U64(PyReadonlyArray2<'py, u64>),
}

fn flat<'a, T: numpy::Element>(x: &'a PyReadonlyArray2<'_, T>) -> &'a [T] {
    x.as_slice().expect("made C-contiguous")
}

impl<'py> Rows3<'py> {
    /// The argument `arg`, checked for one of `dtypes` and the shape `what` ("(N, 3)"), and made
    /// C-contiguous in native byte order.
    fn read(arg: &str, obj: &Bound<'py, PyAny>, dtypes: &[&str], what: &str) -> Result<Self> {
        let (obj, _) = checked_array(arg, obj, dtypes, (&[None, Some(3)], what))?;
        let numpy = obj.py().import("numpy");
        let obj = numpy.and_then(|np| np.call_method1("ascontiguousarray", (obj,)));
        let obj = obj.map_err(|e| Error::Internal(format!("{arg}: {e}")))?;
        let x = None
            .or_else(|| obj.extract().ok().map(Rows3::F32))
            .or_else(|| obj.extract().ok().map(Rows3::F64))
            .or_else(|| obj.extract().ok().map(Rows3::I32))
            .or_else(|| obj.extract().ok().map(Rows3::I64))
            .or_else(|| obj.extract().ok().map(Rows3::U32))
            .or_else(|| obj.extract().ok().map(Rows3::U64));
        x.ok_or_else(|| Error::Internal(format!("{arg}: an array NumPy did not hand over")))
    }

    fn positions(&self) -> Option<PositionsRef<'_>> {
        match self {
            Rows3::F32(x) => Some(PositionsRef::F32(rows_of(flat(x)))),
            Rows3::F64(x) => Some(PositionsRef::F64(rows_of(flat(x)))),
            _ => None,
        }
    }

    fn faces(&self) -> Option<FacesRef<'_>> {
        match self {
            Rows3::I32(x) => Some(FacesRef::I32(flat(x))),
            Rows3::I64(x) => Some(FacesRef::I64(flat(x))),
            Rows3::U32(x) => Some(FacesRef::U32(flat(x))),
            Rows3::U64(x) => Some(FacesRef::U64(flat(x))),
            _ => None,
        }
    }
}

/// (N, 3) float32 or float64 positions borrowed from NumPy, checked finite and not empty.
pub struct PositionsIn<'py> {
    rows: Rows3<'py>,
    /// The largest absolute coordinate (smoothing scales by it).
    pub largest: f64,
}

impl<'py> PositionsIn<'py> {
    pub fn read(arg: &str, obj: &Bound<'py, PyAny>) -> Result<Self> {
        let rows = Rows3::read(arg, obj, FLOATS, "(N, 3)")?;
        let largest = on_positions!(rows.positions().expect("a float dtype"), v => checked_scale(arg, v))?;
        Ok(PositionsIn { rows, largest })
    }

    pub fn get(&self) -> PositionsRef<'_> {
        self.rows.positions().expect("a float dtype")
    }

    pub fn count(&self) -> usize {
        on_positions!(self.get(), v => v.len())
    }
}

/// Vertices and faces as read from Python, borrowed.
pub struct MeshInput<'py> {
    pub vertices: PositionsIn<'py>,
    faces: Rows3<'py>,
}

/// `$body` run on the mesh argument `$mesh` (see `MeshInput::of`, `MeshInput::run`), with `$v`
/// its positions in their own precision, `$f` its faces and `$cancel` Ctrl-C's flag.
macro_rules! on_mesh {
    ($py:expr, $mesh:expr, |$v:ident, $f:ident, $cancel:pat_param| $body:expr) => {
        $crate::py::mesh_input::MeshInput::of($mesh)?.run($py, |p, faces, $cancel| {
            let $f = &faces;
            $crate::mesh::positions::on_positions!(p, $v => $body)
        })
    };
}
pub(crate) use on_mesh;

impl<'py> MeshInput<'py> {
    /// A mesh argument: the pair (vertices, faces) the Python wrappers pass.
    pub fn of(mesh: &Bound<'py, PyAny>) -> Result<Self> {
        let (vertices, faces) = mesh.extract::<(Bound<'py, PyAny>, Bound<'py, PyAny>)>().map_err(|_| {
            Error::wrong_type("mesh", format!("expected (vertices, faces), got {}", type_name(mesh)))
        })?;
        Self::read(&vertices, &faces)
    }

    /// (N, 3) float32 or float64 vertices and (M, 3) int32, int64, uint32 or uint64 faces, in
    /// either byte order and any memory order; the faces' indices are checked in `run`.
    pub fn read(vertices: &Bound<'py, PyAny>, faces: &Bound<'py, PyAny>) -> Result<Self> {
        let vertices = PositionsIn::read("vertices", vertices)?;
        let faces = Rows3::read("faces", faces, &["int32", "int64", "uint32", "uint64"], "(M, 3)")?;
        Ok(MeshInput { vertices, faces })
    }

    /// The positions and the faces as borrowed (the faces' indices not yet checked: see
    /// `FacesRef::checked`), to work on several meshes with the GIL released at once.
    pub fn parts(&self) -> (PositionsRef<'_>, FacesRef<'_>) {
        (self.vertices.get(), self.faces.faces().expect("an integer dtype"))
    }

    /// Runs `work` on the mesh with the GIL released, stopping on Ctrl-C when `work` checks its
    /// `Cancel` (see `runtime::detached_cancellable`). The faces are converted to u32 inside, in
    /// parallel, each index checked against the vertices.
    pub fn run<R: Send>(
        &self,
        py: Python<'_>,
        work: impl FnOnce(PositionsRef<'_>, Faces, &Cancel) -> Result<R> + Send,
    ) -> PyResult<R> {
        let (positions, n) = (self.vertices.get(), self.vertices.count());
        let faces = self.faces.faces().expect("an integer dtype");
        detached_cancellable(py, |cancel| work(positions, faces.checked("faces", n)?, cancel))
    }
}

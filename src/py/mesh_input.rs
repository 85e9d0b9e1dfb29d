//! Mesh input read straight from NumPy's buffers when they are C-contiguous (the usual case),
//! so a million-face mesh is not copied and checked serially before the parallel work starts.
//! Anything else, and every error message, goes through the general readers in `convert`.
//! Arrays in the other byte order are converted once, on entry.

use numpy::{PyReadonlyArray2, PyUntypedArrayMethods};
use pyo3::prelude::*;

use super::convert::{faces, native_order, on_positions, positions, Positions, PositionsRef};
use super::runtime::detached_cancellable;
use crate::cancel::Cancel;
use crate::error::{Error, Result};
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

#[derive(Clone, Copy)]
pub enum FacesRef<'a> {
    I64(&'a [i64]),
    I32(&'a [i32]),
    Checked(&'a [[u32; 3]]),
}

fn rows_of<T>(flat: &[T]) -> &[[T; 3]] {
    // SAFETY: [T; 3] has T's alignment and is three Ts laid out contiguously; the caller
    // checked that the length is a multiple of 3.
    unsafe { std::slice::from_raw_parts(flat.as_ptr() as *const [T; 3], flat.len() / 3) }
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

impl<'py> MeshInput<'py> {
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
            VerticesIn::F32(x) => PositionsRef::F32(rows_of(x.as_slice().expect("checked contiguous"))),
            VerticesIn::F64(x) => PositionsRef::F64(rows_of(x.as_slice().expect("checked contiguous"))),
            VerticesIn::Copied(p) => p.slices(),
        }
    }

    fn faces(&self) -> FacesRef<'_> {
        match &self.faces {
            FacesIn::I64(x) => FacesRef::I64(x.as_slice().expect("checked contiguous")),
            FacesIn::I32(x) => FacesRef::I32(x.as_slice().expect("checked contiguous")),
            FacesIn::Checked(f) => FacesRef::Checked(f),
        }
    }

    /// Runs `work` on the mesh with the GIL released, stopping on Ctrl-C when `work` checks its
    /// `Cancel` (see `runtime::detached_cancellable`). Faces are converted to u32 inside, in
    /// parallel; if any index is bad, the general reader produces the error message.
    pub fn run<R: Send>(
        &self,
        py: Python<'_>,
        faces_obj: &Bound<'_, PyAny>,
        work: impl Fn(PositionsRef<'_>, &[[u32; 3]], &Cancel) -> Result<R> + Send + Sync,
    ) -> PyResult<R> {
        let (positions, faces_ref, n) = (self.positions(), self.faces(), self.n_vertices);
        let outcome = detached_cancellable(py, |cancel| {
            let converted = match faces_ref {
                FacesRef::Checked(f) => return work(positions, f, cancel).map(Some),
                FacesRef::I64(flat) => faces_to_u32(flat, n),
                FacesRef::I32(flat) => faces_to_u32(flat, n),
            };
            match converted {
                Some(f) => work(positions, &f, cancel).map(Some),
                None => Ok(None),
            }
        })?;
        match outcome {
            Some(r) => Ok(r),
            // Some index is out of range: let the general reader say which one.
            None => Err(faces("faces", faces_obj, n)
                .err()
                .unwrap_or_else(|| {
                    Error::Internal("faces: rejected by the fast reader but not by the general one".into())
                })
                .into()),
        }
    }
}

/// Faces as u32 rows, or None if any index is outside [0, n).
fn faces_to_u32<I: Copy + Into<i64> + Sync>(flat: &[I], n: usize) -> Option<Vec<[u32; 3]>> {
    use rayon::prelude::*;
    let rows = rows_of(flat);
    let mut out: Vec<[u32; 3]> = crate::huge_pages::with_capacity(rows.len());
    let ok = out.spare_capacity_mut()[..rows.len()].par_chunks_mut(16384).zip(rows.par_chunks(16384)).all(
        |(o, r)| {
            let mut ok = true;
            for (o, r) in o.iter_mut().zip(r) {
                let row = r.map(|i| {
                    let i: i64 = i.into();
                    ok &= i >= 0 && (i as u64) < n as u64;
                    i as u32
                });
                o.write(row);
            }
            ok
        },
    );
    if ok {
        // SAFETY: `all` returned true, so every chunk ran and wrote each of its elements.
        unsafe { out.set_len(rows.len()) };
    }
    ok.then_some(out)
}

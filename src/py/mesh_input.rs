//! Mesh input read straight from NumPy's buffers when they are C-contiguous (the usual case),
//! so a million-face mesh is not copied and checked serially before the parallel work starts.
//! Anything else, and every error message, goes through the general readers in `convert`.
//! Arrays in the other byte order are converted once, on entry.

use numpy::{PyReadonlyArray2, PyUntypedArrayMethods};
use pyo3::prelude::*;

use super::convert::{faces, native_order, positions, Positions, PositionsRef};
use super::runtime::detached_cancellable;
use crate::cancel::Cancel;
use crate::error::{Error, Result};
use crate::smooth::range::largest_if_finite;

/// Vertices and faces as read from Python: borrowed when possible, owned otherwise.
pub struct MeshInput<'py> {
    v32: Option<PyReadonlyArray2<'py, f32>>,
    v64: Option<PyReadonlyArray2<'py, f64>>,
    owned: Option<Positions>,
    faces64: Option<PyReadonlyArray2<'py, i64>>,
    faces32: Option<PyReadonlyArray2<'py, i32>>,
    owned_faces: Option<Vec<[u32; 3]>>,
    n_vertices: usize,
    /// The largest absolute coordinate, when the fast path computed it.
    largest: Option<f64>,
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

impl<'py> MeshInput<'py> {
    pub fn read(vertices: &Bound<'py, PyAny>, faces_obj: &Bound<'py, PyAny>) -> Result<Self> {
        let (vertices, faces_obj) = (&native_order(vertices)?, &native_order(faces_obj)?);
        let mut me = MeshInput {
            v32: contiguous_rows3::<f32>(vertices),
            v64: None,
            owned: None,
            faces64: None,
            faces32: None,
            owned_faces: None,
            n_vertices: 0,
            largest: None,
        };
        if me.v32.is_none() {
            me.v64 = contiguous_rows3::<f64>(vertices);
        }
        // One pass checks finiteness and finds the scale (which smoothing needs).
        me.largest = match (&me.v32, &me.v64) {
            (Some(x), _) => largest_if_finite(x.as_slice().unwrap_or(&[f32::NAN])),
            (_, Some(x)) => largest_if_finite(x.as_slice().unwrap_or(&[f64::NAN])),
            _ => None,
        };
        if me.largest.is_some() {
            me.n_vertices =
                me.v32.as_ref().map(|x| x.shape()[0]).or(me.v64.as_ref().map(|x| x.shape()[0])).unwrap_or(0);
        } else {
            me.v32 = None;
            me.v64 = None;
            let p = positions("vertices", vertices)?;
            me.n_vertices = p.len();
            me.owned = Some(p);
        }
        me.faces64 = contiguous_rows3::<i64>(faces_obj);
        if me.faces64.is_none() {
            me.faces32 = contiguous_rows3::<i32>(faces_obj);
        }
        if me.faces64.is_none() && me.faces32.is_none() {
            me.owned_faces = Some(faces("faces", faces_obj, me.n_vertices)?);
        }
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
        if let Some(x) = &self.v32 {
            return PositionsRef::F32(rows_of(x.as_slice().expect("checked contiguous")));
        }
        if let Some(x) = &self.v64 {
            return PositionsRef::F64(rows_of(x.as_slice().expect("checked contiguous")));
        }
        self.owned.as_ref().expect("one of the three is set").slices()
    }

    fn faces(&self) -> FacesRef<'_> {
        if let Some(x) = &self.faces64 {
            return FacesRef::I64(x.as_slice().expect("checked contiguous"));
        }
        if let Some(x) = &self.faces32 {
            return FacesRef::I32(x.as_slice().expect("checked contiguous"));
        }
        FacesRef::Checked(self.owned_faces.as_deref().expect("one of the three is set"))
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

//! Checks on mesh input that every public function shares.
//!
//! Positions must be finite; faces must index existing vertices. Unreferenced vertices are
//! allowed. Faces are stored as u32, which bounds a mesh at 2^32 - 1 vertices.

use crate::error::{Error, Result};
use crate::real::{Real, Vec3};

pub type Faces = Vec<[u32; 3]>;

/// Checks positions: at least one vertex and every coordinate finite.
pub fn check_positions<T: Real>(arg: &str, positions: &[Vec3<T>]) -> Result<()> {
    if positions.is_empty() {
        return Err(Error::invalid(arg, "the mesh has no vertices (shape (0, 3))"));
    }
    if let Some(i) =
        positions.iter().position(|p| !(p[0].is_finite() && p[1].is_finite() && p[2].is_finite()))
    {
        let p = positions[i];
        return Err(Error::invalid(
            arg,
            format!(
                "vertex {i} is not finite ({:?}, {:?}, {:?}); NaN and inf are not allowed",
                p[0], p[1], p[2]
            ),
        ));
    }
    Ok(())
}

/// Converts face rows of any integer type to u32, checking each index against `n_vertices`.
pub fn check_faces<I>(arg: &str, rows: impl Iterator<Item = [I; 3]>, n_vertices: usize) -> Result<Faces>
where
    I: Copy + TryInto<i64> + std::fmt::Display,
{
    let mut faces = Vec::with_capacity(rows.size_hint().0);
    for (f, row) in rows.enumerate() {
        let mut out = [0u32; 3];
        for k in 0..3 {
            // An index beyond i64 (from uint64 faces) is out of range too, and named as given.
            match row[k].try_into().ok() {
                Some(idx) if idx < 0 => {
                    return Err(Error::out_of_range(
                        arg,
                        format!("face {f} has a negative vertex index {idx}"),
                    ));
                }
                Some(idx) if (idx as u64) < n_vertices as u64 => out[k] = idx as u32,
                _ => {
                    return Err(Error::out_of_range(
                        arg,
                        format!(
                            "face {f} refers to vertex {}, but there are only {n_vertices} vertices",
                            row[k]
                        ),
                    ));
                }
            }
        }
        faces.push(out);
    }
    if faces.is_empty() {
        return Err(Error::invalid(arg, "the mesh has no faces (shape (0, 3))"));
    }
    Ok(faces)
}

/// Vertices flagged by index (the argument `arg`): each index in [0, `n_vertices`).
pub fn flag_vertices<I>(
    arg: &str,
    indices: impl IntoIterator<Item = I>,
    n_vertices: usize,
) -> Result<Vec<bool>>
where
    I: Copy + TryInto<u64> + std::fmt::Display,
{
    let mut flags = vec![false; n_vertices];
    for i in indices {
        match i.try_into().ok().filter(|&j| j < n_vertices as u64) {
            Some(j) => flags[j as usize] = true,
            None => {
                return Err(Error::out_of_range(
                    arg,
                    format!("vertex index {i} is outside [0, {n_vertices})"),
                ))
            }
        }
    }
    Ok(flags)
}

/// A boolean mask of vertices (the argument `arg`): one entry per vertex.
pub fn check_mask(arg: &str, mask: Vec<bool>, n_vertices: usize) -> Result<Vec<bool>> {
    if mask.len() != n_vertices {
        return Err(Error::invalid(
            arg,
            format!("a boolean mask needs {n_vertices} entries, got {}", mask.len()),
        ));
    }
    Ok(mask)
}

/// Flat values as rows of three.
pub fn rows_of<T>(flat: &[T]) -> &[[T; 3]] {
    assert!(flat.len() % 3 == 0, "rows of three");
    // SAFETY: [T; 3] has T's alignment and is three Ts laid out contiguously, and the length is
    // a multiple of 3.
    unsafe { std::slice::from_raw_parts(flat.as_ptr() as *const [T; 3], flat.len() / 3) }
}

/// Faces borrowed as flat rows of three indices, in the caller's integer type.
#[derive(Clone, Copy)]
pub enum FacesRef<'a> {
    I32(&'a [i32]),
    I64(&'a [i64]),
    U32(&'a [u32]),
    U64(&'a [u64]),
}

impl FacesRef<'_> {
    /// The faces as rows of u32, each index checked against `n_vertices` (`faces_from_flat`).
    pub fn checked(self, arg: &str, n_vertices: usize) -> Result<Faces> {
        match self {
            FacesRef::I32(flat) => faces_from_flat(arg, flat, n_vertices),
            FacesRef::I64(flat) => faces_from_flat(arg, flat, n_vertices),
            FacesRef::U32(flat) => faces_from_flat(arg, flat, n_vertices),
            FacesRef::U64(flat) => faces_from_flat(arg, flat, n_vertices),
        }
    }
}

/// Faces held as flat rows of three indices, converted to u32 in parallel (in huge pages) and
/// checked as `check_faces` checks them, which names the first bad index.
pub fn faces_from_flat<I>(arg: &str, flat: &[I], n_vertices: usize) -> Result<Faces>
where
    I: Copy + TryInto<i64> + Sync + std::fmt::Display,
{
    use rayon::prelude::*;
    let rows = rows_of(flat);
    let mut out: Faces = crate::huge_pages::with_capacity(rows.len());
    let ok = out.spare_capacity_mut()[..rows.len()].par_chunks_mut(16384).zip(rows.par_chunks(16384)).all(
        |(o, r)| {
            let mut ok = true;
            for (o, r) in o.iter_mut().zip(r) {
                let row = r.map(|i| {
                    // an index beyond i64 (from uint64 faces) is out of range, as a negative one
                    let i: i64 = i.try_into().unwrap_or(-1);
                    ok &= i >= 0 && (i as u64) < n_vertices as u64;
                    i as u32
                });
                o.write(row);
            }
            ok
        },
    );
    if !ok || rows.is_empty() {
        let checked = check_faces(arg, rows.iter().copied(), n_vertices);
        return Err(checked.err().unwrap_or_else(|| {
            Error::Internal(format!("{arg}: rejected by the fast reader but not by the general one"))
        }));
    }
    // SAFETY: `all` returned true, so every chunk ran and wrote each of its elements.
    unsafe { out.set_len(rows.len()) };
    Ok(out)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn rejects_nan_and_empty() {
        assert!(check_positions::<f64>("vertices", &[]).is_err());
        let e = check_positions("vertices", &[[0.0, f64::NAN, 0.0]]).unwrap_err();
        assert!(e.to_string().contains("vertex 0"));
    }

    #[test]
    fn rejects_bad_indices() {
        let e = check_faces("faces", [[0i64, 1, 5]].into_iter(), 3).unwrap_err();
        assert!(matches!(e, Error::IndexOutOfRange { .. }));
        let e = check_faces("faces", [[0i32, -1, 2]].into_iter(), 3).unwrap_err();
        assert!(e.to_string().contains("negative"));
        assert!(check_faces::<i32>("faces", std::iter::empty(), 3).is_err());
        assert_eq!(check_faces("faces", [[0u32, 1, 2]].into_iter(), 3).unwrap(), vec![[0, 1, 2]]);
        assert_eq!(faces_from_flat("faces", &[0i64, 1, 2, 2, 1, 0], 3).unwrap(), vec![[0, 1, 2], [2, 1, 0]]);
        let e = faces_from_flat("faces", &[0i32, 1, 3], 3).unwrap_err();
        let huge = FacesRef::U64(&[0, 1, u64::MAX]).checked("faces", 3).unwrap_err();
        assert!(huge.to_string().contains(&format!("refers to vertex {}", u64::MAX)));
        assert!(flag_vertices("pinned", [2i64, -1], 3).unwrap_err().to_string().contains("index -1"));
        assert_eq!(flag_vertices("pinned", [2u64], 3).unwrap(), vec![false, false, true]);
        assert!(e.to_string().contains("refers to vertex 3"));
    }
}

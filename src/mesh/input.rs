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
    }
}

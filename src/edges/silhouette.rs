//! Which side of each face the viewer is on, per view: the run-time half of silhouette finding.
//!
//! With V the view vector from the eye to the face (perspective: p - eye for any point p of the
//! face's plane, so the answer is exact per face and not one global direction; orthographic:
//! the view direction), a face is *front-facing* when n . V < 0 and *back-facing* otherwise:
//! a face exactly edge-on (n . V = 0) counts as back-facing, as back-face culling would. A
//! degenerate face faces neither way. An edge is a silhouette when its faces include at least
//! one front-facing and one back-facing face, which for a manifold edge is the paper's
//! (n1 . V)(n2 . V) <= 0 with the tie broken that way. Boundary edges (one face) and edges next
//! to a degenerate face are never silhouettes; a non-manifold edge is one when its faces
//! disagree as above.

use rayon::prelude::*;

use crate::error::{Error, Result};

#[derive(Debug, Clone, Copy, PartialEq)]
pub enum View {
    /// Perspective: the eye position.
    Eye([f64; 3]),
    /// Orthographic: the direction the camera looks in (from the eye into the scene).
    Direction([f64; 3]),
}

impl View {
    /// The view from exactly one of an eye (perspective) or a direction (orthographic), checked.
    pub fn of(eye: Option<[f64; 3]>, direction: Option<[f64; 3]>) -> Result<View> {
        match (eye, direction) {
            (Some(e), None) => View::Eye(e).check(),
            (None, Some(d)) => View::Direction(d).check(),
            _ => Err(Error::invalid(
                "eye, direction",
                "give exactly one of eye= (perspective) or direction= (orthographic)",
            )),
        }
    }

    pub fn check(self) -> Result<View> {
        match self {
            View::Eye(e) if e.iter().all(|x| x.is_finite()) => Ok(self),
            View::Eye(e) => Err(Error::invalid("eye", format!("must be finite, got {e:?}"))),
            View::Direction(d) if d.iter().all(|x| x.is_finite()) && d.iter().any(|&x| x != 0.0) => Ok(self),
            View::Direction(d) => {
                Err(Error::invalid("direction", format!("must be finite and non-zero, got {d:?}")))
            }
        }
    }
}

pub const BACK: u8 = 0;
pub const FRONT: u8 = 1;
pub const NO_NORMAL: u8 = 2;

/// Which side of a face (unit normal `n`, zero when degenerate, plane offset `d` = n . p) the
/// viewer is on: FRONT, BACK or NO_NORMAL.
#[inline]
pub fn face_side(n: &[f64; 3], d: f64, view: View) -> u8 {
    // n . V with V = p - eye equals d - n . eye.
    let toward = match view {
        View::Eye(e) => d - (n[0] * e[0] + n[1] * e[1] + n[2] * e[2]),
        View::Direction(v) => n[0] * v[0] + n[1] * v[1] + n[2] * v[2],
    };
    let defined = n[0] != 0.0 || n[1] != 0.0 || n[2] != 0.0;
    if !defined {
        NO_NORMAL
    } else if toward < 0.0 {
        FRONT
    } else {
        BACK
    }
}

/// Per face: FRONT, BACK or NO_NORMAL, given unit normals (zero when degenerate) and each face's
/// plane offset n . p.
pub fn facing(normals: &[[f64; 3]], offsets: &[f64], view: View) -> Vec<u8> {
    let mut out = vec![0u8; normals.len()];
    out.par_chunks_mut(16384).zip(normals.par_chunks(16384).zip(offsets.par_chunks(16384))).for_each(
        |(o, (n, d))| {
            for ((o, n), &d) in o.iter_mut().zip(n).zip(d) {
                *o = face_side(n, d, view);
            }
        },
    );
    out
}

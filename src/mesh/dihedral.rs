//! The dihedral angle between two faces and the crease rule on it, shared by the crease
//! outlines (`edges::feature`) and the shading normals that split at creases
//! (`mesh::crease_normals`), so both see the same edges.

use crate::error::{Error, Result};

/// Checks a crease threshold in degrees.
pub fn check_crease_angle(degrees: f64) -> Result<()> {
    if !(0.0..=180.0).contains(&degrees) {
        return Err(Error::invalid("crease_angle", format!("must be in [0, 180] degrees, got {degrees}")));
    }
    Ok(())
}

/// The crease rule on the unit normals of an edge's two faces: their dihedral angle exceeds
/// the threshold (strictly). Shared by the crease outlines and the shading normals that split
/// at creases (`mesh::crease_normals`), so both see the same edges.
#[derive(Debug, Clone, Copy)]
pub struct CreaseTest {
    crease_angle: f64,
    /// Cheap pre-test on n1 . n2 alone: a pair whose cosine is clearly above the threshold's
    /// cannot be a crease (rounding in the dot product is ~1e-16, far below the slack), so
    /// only the few survivors pay for the cross product and the exact atan2.
    skip_above: f64,
}

impl CreaseTest {
    /// The test for a threshold in degrees (checked as `crease_angle`).
    pub fn new(crease_angle: f64) -> Result<Self> {
        check_crease_angle(crease_angle)?;
        Ok(CreaseTest { crease_angle, skip_above: crease_angle.to_radians().cos() + 1e-9 })
    }

    /// The dihedral angle in degrees and the convexity (see `dihedral`) when the faces meet at
    /// a crease; `along()` (the direction the first face walks the edge) is only asked for then.
    #[inline]
    pub fn crease(
        &self,
        n1: [f64; 3],
        n2: [f64; 3],
        along: impl FnOnce() -> [f64; 3],
    ) -> Option<(f64, bool)> {
        let cos = n1[0] * n2[0] + n1[1] * n2[1] + n1[2] * n2[2];
        if cos >= self.skip_above {
            return None;
        }
        let (angle, convex) = dihedral(n1, n2, along());
        (angle > self.crease_angle).then_some((angle, convex))
    }

    /// Whether the faces meet at a crease.
    #[inline]
    pub fn is_crease(&self, n1: [f64; 3], n2: [f64; 3]) -> bool {
        self.crease(n1, n2, || [0.0; 3]).is_some()
    }
}

/// The angle between two unit normals in degrees and whether the fold is convex, given the
/// direction `along` in which the first face walks the edge.
#[inline]
pub fn dihedral(n1: [f64; 3], n2: [f64; 3], along: [f64; 3]) -> (f64, bool) {
    let c = [n1[1] * n2[2] - n1[2] * n2[1], n1[2] * n2[0] - n1[0] * n2[2], n1[0] * n2[1] - n1[1] * n2[0]];
    let sin = (c[0] * c[0] + c[1] * c[1] + c[2] * c[2]).sqrt();
    let cos = n1[0] * n2[0] + n1[1] * n2[1] + n1[2] * n2[2];
    let convex = c[0] * along[0] + c[1] * along[1] + c[2] * along[2] >= 0.0;
    (sin.atan2(cos).to_degrees(), convex)
}

//! Faces in small spatial clusters, each with a bound on its vertices' normals (a cone) and
//! positions (a ball), so that a view's contour pass skips every cluster where n . v has one
//! sign at all its vertices (the silhouette clusters of Sander et al. 2000, with the cone test
//! of Johannsen and Carter 1998). On a smooth mesh a view then visits the faces near its
//! contours, not the whole mesh.
//!
//! The test is exact, not a guess: a cluster is skipped only when no vertex value can change
//! sign inside it. With v the unit vector from a point to the eye, the angle between a vertex's
//! normal n and v is at most theta + alpha + beta, where theta is the angle between the cone's
//! axis and the direction from the ball's centre to the eye, alpha the cone's half-angle, and
//! beta = asin(r / D) the most the direction to the eye turns over a ball of radius r at
//! distance D; so n . v > 0 everywhere when that sum is below 90 degrees, and n . v < 0 when
//! theta - alpha - beta is above.

use rayon::prelude::*;

use super::silhouette::View;
use crate::mesh::reorder::Reordering;
use crate::real::{dot, norm, sub};

/// Faces per cluster: small enough that a contour's clusters hold few faces it does not
/// cross, large enough that testing the clusters costs little beside them.
const CLUSTER: usize = 32;

/// Angles within this of the test's limit count as undecided, so rounding never skips a
/// cluster the contour crosses.
const MARGIN: f64 = 1e-9;

#[derive(Clone, Copy, Debug)]
struct Bound {
    centre: [f64; 3],
    radius: f64,
    axis: [f64; 3],
    /// Sine and cosine of the cone's half-angle plus MARGIN (cosine -1: no bound).
    sin_spread: f64,
    cos_spread: f64,
}

/// Which signs n . v may take over a cluster's vertices for a view.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Sides {
    Front,
    Back,
    Both,
}

pub struct FaceClusters {
    /// The faces, in spatial order (Morton order of their centroids).
    pub faces: Vec<[u32; 3]>,
    bounds: Vec<Bound>,
}

impl FaceClusters {
    /// Clusters of `faces` over `positions` with vertex `normals` (unit, or zero where
    /// undefined: a cluster with such a vertex is never skipped).
    pub fn build(positions: &[[f64; 3]], normals: &[[f64; 3]], faces: &[[u32; 3]]) -> FaceClusters {
        let centroids: Vec<[f64; 3]> = faces
            .par_iter()
            .map(|f| {
                let [a, b, c] = f.map(|v| positions[v as usize]);
                std::array::from_fn(|k| (a[k] + b[k] + c[k]) / 3.0)
            })
            .collect();
        let order = Reordering::spatial(&centroids);
        let faces: Vec<[u32; 3]> = order.order().par_iter().map(|&i| faces[i as usize]).collect();
        let bounds = faces.par_chunks(CLUSTER).map(|chunk| bound(positions, normals, chunk)).collect();
        FaceClusters { faces, bounds }
    }

    /// The signs n . v may take over each cluster for `view`.
    pub fn sides(&self, view: View) -> Vec<Sides> {
        self.bounds.par_iter().map(|b| sides(b, view)).collect()
    }

    /// The faces of the clusters whose sides `keep` accepts, as slices of `faces`.
    pub fn select(&self, view: View, keep: impl Fn(Sides) -> bool) -> Vec<&[[u32; 3]]> {
        self.faces.chunks(CLUSTER).zip(self.sides(view)).filter(|(_, s)| keep(*s)).map(|(c, _)| c).collect()
    }
}

fn bound(positions: &[[f64; 3]], normals: &[[f64; 3]], faces: &[[u32; 3]]) -> Bound {
    let corners = || faces.iter().flatten().map(|&v| v as usize);
    let (mut lo, mut hi) = ([f64::INFINITY; 3], [f64::NEG_INFINITY; 3]);
    let mut sum = [0.0; 3];
    let mut undefined = false;
    for v in corners() {
        let (p, n) = (positions[v], normals[v]);
        for k in 0..3 {
            lo[k] = lo[k].min(p[k]);
            hi[k] = hi[k].max(p[k]);
            sum[k] += n[k];
        }
        undefined |= !(dot(n, n) > 0.5);
    }
    let centre: [f64; 3] = std::array::from_fn(|k| 0.5 * lo[k] + 0.5 * hi[k]);
    let radius = corners().map(|v| norm(sub(positions[v], centre))).fold(0.0, f64::max);
    let length = norm(sum);
    let axis = sum.map(|x| x / length);
    let spread = if undefined || !(length > 0.0) || !axis.iter().all(|x| x.is_finite()) {
        std::f64::consts::PI
    } else {
        corners().map(|v| dot(normals[v], axis).clamp(-1.0, 1.0).acos()).fold(0.0, f64::max) + MARGIN
    };
    Bound { centre, radius, axis, sin_spread: spread.sin(), cos_spread: spread.cos() }
}

/// The module comment's test in cosines, without an inverse trigonometric function per
/// cluster: with reach = alpha + beta below 90 degrees, theta + reach < 90 degrees is
/// cos(theta) > sin(reach), and theta - reach > 90 degrees is cos(theta) < -sin(reach).
fn sides(b: &Bound, view: View) -> Sides {
    if !(b.cos_spread > 0.0) || !b.radius.is_finite() {
        return Sides::Both;
    }
    let (toward, sin_beta) = match view {
        View::Direction(d) => ([-d[0], -d[1], -d[2]], 0.0),
        View::Eye(e) => {
            let v = sub(e, b.centre);
            let distance = norm(v);
            if !(distance > b.radius) {
                return Sides::Both;
            }
            (v, b.radius / distance)
        }
    };
    let length = norm(toward);
    if !(length > 0.0) {
        return Sides::Both;
    }
    let cos_beta = (1.0 - sin_beta * sin_beta).max(0.0).sqrt();
    let cos_reach = b.cos_spread * cos_beta - b.sin_spread * sin_beta;
    if !(cos_reach > 0.0) {
        return Sides::Both;
    }
    let sin_reach = b.sin_spread * cos_beta + b.cos_spread * sin_beta;
    let cos_theta = dot(toward, b.axis) / length;
    if cos_theta > sin_reach {
        Sides::Front
    } else if cos_theta < -sin_reach {
        Sides::Back
    } else {
        Sides::Both
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::mesh::normals::vertex_normals;
    use crate::mesh::shapes::icosphere;

    #[test]
    fn a_skipped_cluster_has_one_sign_at_every_vertex() {
        let (v, f) = icosphere(6, 0.0, 0).unwrap();
        let n = vertex_normals(&v, &f);
        let clusters = FaceClusters::build(&v, &n, &f);
        let mut sorted = clusters.faces.clone();
        sorted.sort_unstable();
        let mut original = f.clone();
        original.sort_unstable();
        assert_eq!(sorted, original);
        for view in
            [View::Eye([0.0, 0.3, 3.0]), View::Eye([1.2, 0.0, 0.1]), View::Direction([0.2, -1.0, 0.4])]
        {
            let sides = clusters.sides(view);
            let both = sides.iter().filter(|s| **s == Sides::Both).count();
            assert!(both * 4 < sides.len(), "{both} of {} clusters undecided", sides.len());
            for (chunk, s) in clusters.faces.chunks(CLUSTER).zip(&sides) {
                for &i in chunk.iter().flatten() {
                    let p = v[i as usize];
                    let to_eye = match view {
                        View::Eye(e) => sub(e, p),
                        View::Direction(d) => d.map(|x| -x),
                    };
                    let side = dot(n[i as usize], to_eye);
                    match s {
                        Sides::Front => assert!(side > 0.0),
                        Sides::Back => assert!(side < 0.0),
                        Sides::Both => {}
                    }
                }
            }
        }
    }
}

//! A smooth field of principal directions per vertex, for strokes that follow the form
//! (Hertzmann and Zorin 2000).
//!
//! The direction of largest curvature is a line (d1 and -d1 are the same), reliable only where
//! the surface bends more one way than the other. Each vertex is held to its own direction with
//! the weight of its anisotropy |k1 - k2| / (|k1| + |k2| + 1/size) (0 on flats and umbilic
//! regions such as a sphere, near 1 on a cylinder) and pulled toward the mean of its neighbours'
//! lines (each turned into its tangent plane and its sign matched first: a 2-RoSy average).
//! A faint pull toward a fixed axis projected on the tangent plane settles regions that no
//! curvature reaches, so the field is the same from run to run and on every view. Last, signs
//! are propagated breadth-first so that neighbours agree wherever the line field allows it:
//! stripes need a vector field.

use rayon::prelude::*;

use crate::cancel::Cancel;
use crate::error::Result;
use crate::mesh::curvature::curvature;
use crate::mesh::{Adjacency, Bounds};
use crate::real::{dot, norm};

/// Jacobi sweeps of the smoothing: the field's directions spread about sqrt(sweeps) edges
/// into regions without a reliable direction, beyond which the fixed axis decides.
pub const LINE_FIELD_SWEEPS: usize = 200;
/// The weight of a vertex's own direction where the surface is clearly anisotropic, beside a
/// neighbour's 1.
const OWN_PULL: f64 = 1.0;
/// The weight, beside a neighbour's 1, of the fixed axis (only breaks ties).
const AXIS_PULL: f64 = 1e-3;

fn scale(a: [f64; 3], s: f64) -> [f64; 3] {
    a.map(|x| x * s)
}

fn add(a: [f64; 3], b: [f64; 3]) -> [f64; 3] {
    std::array::from_fn(|k| a[k] + b[k])
}

/// `v` without its component along the unit `n`.
fn tangent(v: [f64; 3], n: [f64; 3]) -> [f64; 3] {
    add(v, scale(n, -dot(v, n)))
}

fn unit(v: [f64; 3]) -> Option<[f64; 3]> {
    let l = norm(v);
    (l > 1e-12).then(|| scale(v, 1.0 / l))
}

/// `v` with its sign turned to agree with `like`.
fn aligned(v: [f64; 3], like: [f64; 3]) -> [f64; 3] {
    if dot(v, like) < 0.0 {
        scale(v, -1.0)
    } else {
        v
    }
}

/// The fixed axis's line on the tangent plane of `n`: y, or x where the plane faces y.
fn axis_line(n: [f64; 3]) -> [f64; 3] {
    unit(tangent([0.0, 1.0, 0.0], n))
        .filter(|t| norm(tangent([0.0, 1.0, 0.0], n)) > 0.1 && t.iter().all(|x| x.is_finite()))
        .or_else(|| unit(tangent([1.0, 0.0, 0.0], n)))
        .unwrap_or([1.0, 0.0, 0.0])
}

/// Per vertex: the unit normal and a unit tangent along the smoothed direction of largest
/// curvature (strokes along it run around a cylinder), signs agreeing between neighbours
/// wherever the field has no odd singularity.
pub struct LineField {
    pub normals: Vec<[f64; 3]>,
    pub directions: Vec<[f64; 3]>,
}

/// The smoothed field of `positions` and `faces` (checked indices); see the module comment.
pub fn principal_line_field(
    positions: &[[f64; 3]],
    faces: &[[u32; 3]],
    cancel: &Cancel,
) -> Result<LineField> {
    let c = curvature(positions, faces, 0.0, cancel)?;
    let adj = Adjacency::build(positions.len(), faces)?;
    let size = Bounds::of(positions).diagonal().max(1e-300);
    let normals = c.normals.clone();
    let weight: Vec<f64> =
        c.k1.iter()
            .zip(&c.k2)
            .map(|(a, b)| {
                let w = (a - b).abs() / (a.abs() + b.abs() + 1.0 / size);
                if w.is_finite() {
                    w
                } else {
                    0.0
                }
            })
            .collect();
    let axis: Vec<[f64; 3]> = normals.par_iter().map(|&n| axis_line(n)).collect();
    let own: Vec<[f64; 3]> = (0..positions.len())
        .into_par_iter()
        .map(|i| unit(tangent(c.d1[i], normals[i])).unwrap_or(axis[i]))
        .collect();
    let mut field: Vec<[f64; 3]> =
        (0..positions.len()).map(|i| if weight[i] > 0.5 { own[i] } else { axis[i] }).collect();
    let mut next = field.clone();
    for _ in 0..LINE_FIELD_SWEEPS {
        cancel.check()?;
        next.par_iter_mut().enumerate().for_each(|(i, out)| {
            let (n, v) = (normals[i], field[i]);
            let ring = adj.neighbours(i);
            // the own direction weighs as much as OWN_PULL neighbours where the surface is
            // clearly anisotropic: scanned meshes' small bumps are smoothed over
            let mut acc = scale(aligned(own[i], v), weight[i] * OWN_PULL);
            acc = add(acc, scale(aligned(axis[i], v), AXIS_PULL * ring.len().max(1) as f64));
            for &j in ring {
                acc = add(acc, aligned(tangent(field[j as usize], n), v));
            }
            *out = unit(tangent(acc, n)).unwrap_or(v);
        });
        std::mem::swap(&mut field, &mut next);
    }
    orient(&adj, &mut field);
    Ok(LineField { normals, directions: field })
}

/// Flips directions so that each vertex agrees with the one it was reached from, breadth-first
/// from the lowest index of each connected part.
fn orient(adj: &Adjacency, field: &mut [[f64; 3]]) {
    adj.breadth_first(|i, j| field[j] = aligned(field[j], field[i]));
}

#[cfg(test)]
pub(crate) mod tests {
    use super::*;

    /// An open cylinder of radius 1 and height 2 along z: `around` segments, `rows` rows.
    pub(crate) fn cylinder(around: u32, rows: u32) -> (Vec<[f64; 3]>, Vec<[u32; 3]>) {
        let mut v = vec![];
        for r in 0..=rows {
            for k in 0..around {
                let a = std::f64::consts::TAU * k as f64 / around as f64;
                v.push([a.cos(), a.sin(), -1.0 + 2.0 * r as f64 / rows as f64]);
            }
        }
        let mut f = vec![];
        for r in 0..rows {
            for k in 0..around {
                let (a, b) = (r * around + k, r * around + (k + 1) % around);
                let (c, d) = (a + around, b + around);
                f.push([a, b, d]);
                f.push([a, d, c]);
            }
        }
        (v, f)
    }

    #[test]
    fn runs_around_a_cylinder_and_agrees_in_sign() {
        let (v, f) = cylinder(48, 24);
        let field = principal_line_field(&v, &f, Cancel::never()).unwrap();
        for (i, d) in field.directions.iter().enumerate() {
            assert!(d[2].abs() < 0.05, "vertex {i}: {d:?} is not around the axis");
            assert!((norm(*d) - 1.0).abs() < 1e-9);
        }
        // one sense of rotation all around: neighbours agree
        let adj = Adjacency::build(v.len(), &f).unwrap();
        for i in 0..v.len() {
            for &j in adj.neighbours(i) {
                assert!(dot(field.directions[i], field.directions[j as usize]) > 0.9);
            }
        }
    }

    #[test]
    fn a_sphere_gets_a_smooth_field_and_the_same_one_every_time() {
        let (v, f) = crate::mesh::shapes::icosphere(3, 0.0, 0).unwrap();
        let a = principal_line_field(&v, &f, Cancel::never()).unwrap();
        let b = principal_line_field(&v, &f, Cancel::never()).unwrap();
        assert_eq!(a.directions, b.directions);
        // away from the axis's poles neighbours' lines are nearly parallel
        let adj = Adjacency::build(v.len(), &f).unwrap();
        let (mut smooth, mut all) = (0, 0);
        for i in 0..v.len() {
            if v[i][1].abs() > 0.9 {
                continue;
            }
            for &j in adj.neighbours(i) {
                all += 1;
                smooth += (dot(a.directions[i], a.directions[j as usize]).abs() > 0.95) as usize;
            }
        }
        assert!(smooth as f64 > 0.97 * all as f64, "{smooth} of {all}");
    }
}

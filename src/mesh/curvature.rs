//! Principal curvatures and directions per vertex, and the derivatives of the curvature, from
//! the second fundamental form of each face (Rusinkiewicz, "Estimating curvatures and their
//! derivatives on triangle meshes", 2004).
//!
//! Each face fits the 2x2 tensor II that maps a step along an edge to the change of the vertex
//! normals along it (least squares over its three edges); each vertex averages the tensors of
//! its faces, turned into its own tangent plane and weighted by its Voronoi share of each face
//! (Meyer et al. 2003), then diagonalises it. The derivative of II (a symmetric 2x2x2 tensor, four
//! numbers) is fitted per face the same way from the vertex tensors and averaged per vertex.
//!
//! Sign: with outward normals (counter-clockwise faces seen from outside), a surface that bends
//! away from its normal has positive curvature: a sphere of radius r gives k1 = k2 = +1/r.
//! Scaling a mesh by s scales k by 1/s and the derivatives by 1/s^2. The work is done in
//! coordinates centred on the bounding box and divided by its size, so any scale or offset
//! that f64 can hold gives the same relative answer.
//!
//! Faces without area, and vertices without a face with area, get curvature 0 and some tangent
//! frame: every output is finite.

use glam::DVec3;
use rayon::prelude::*;

use crate::cancel::Cancel;
use crate::error::{Error, Result};
use crate::mesh::buckets::{Buckets, RingCorner};
use crate::mesh::diffuse::Patches;
use crate::mesh::edge_length::mean_edge_length;
use crate::mesh::normals::DEGENERATE_RELATIVE_AREA;
use crate::mesh::Bounds;
use crate::real::{Real, Vec3};

/// Per vertex: the principal curvatures (k1 >= k2), their unit directions (d1, d2, with
/// d1 x d2 = n), the unit normal the estimate used, and the derivative of the second
/// fundamental form in the (d1, d2) frame: `[C111, C112, C122, C222]`, the rate of change of
/// II(d1, d1) along d1, of II(d1, d1) along d2 (= of II(d1, d2) along d1), and so on.
#[derive(Clone, Debug, Default)]
pub struct Curvature {
    pub k1: Vec<f64>,
    pub k2: Vec<f64>,
    pub d1: Vec<[f64; 3]>,
    pub d2: Vec<[f64; 3]>,
    pub normals: Vec<[f64; 3]>,
    pub derivatives: Vec<[f64; 4]>,
}

impl Curvature {
    pub fn mean(&self) -> Vec<f64> {
        self.k1.iter().zip(&self.k2).map(|(a, b)| 0.5 * (a + b)).collect()
    }

    pub fn gaussian(&self) -> Vec<f64> {
        self.k1.iter().zip(&self.k2).map(|(a, b)| a * b).collect()
    }
}

/// A face's tangent frame (t along its first edge, b = n x t, n its normal) and its corners'
/// Voronoi areas (all 0 for a face without area).
#[derive(Clone, Copy, Default)]
struct FaceFrame {
    t: DVec3,
    b: DVec3,
    corner_area: [f64; 3],
}

impl FaceFrame {
    fn defined(&self) -> bool {
        self.corner_area.iter().any(|&a| a > 0.0)
    }
}

/// The edge opposite corner j: from corner j+1 to corner j+2.
fn edge(p: &[DVec3; 3], j: usize) -> DVec3 {
    p[(j + 2) % 3] - p[(j + 1) % 3]
}

fn face_frame(p: &[DVec3; 3]) -> FaceFrame {
    let e = [edge(p, 0), edge(p, 1), edge(p, 2)];
    let cross = e[0].cross(e[1]);
    let l2 = [e[0].length_squared(), e[1].length_squared(), e[2].length_squared()];
    let longest = l2[0].max(l2[1]).max(l2[2]);
    if !(cross.length() > DEGENERATE_RELATIVE_AREA * longest) {
        return FaceFrame::default();
    }
    let area = 0.5 * cross.length();
    let n = cross.normalize();
    let t = e[0].normalize();
    // Voronoi shares (Meyer et al.): the circumcentre's split where no angle is obtuse (weight[j]
    // is its barycentric weight on corner j, up to a factor, not positive at an obtuse corner); half
    // the face to an obtuse corner and a quarter to each other one otherwise.
    let weight = [0, 1, 2].map(|j| l2[j] * (l2[(j + 1) % 3] + l2[(j + 2) % 3] - l2[j]));
    let corner_area = if let Some(obtuse) = (0..3).find(|&j| weight[j] <= 0.0) {
        std::array::from_fn(|j| if j == obtuse { 0.5 * area } else { 0.25 * area })
    } else {
        let total: f64 = weight.iter().sum();
        // corner j's share: the parts of the two edges meeting at j (edges j+1 and j+2)
        std::array::from_fn(|j| 0.5 * area * (weight[(j + 1) % 3] + weight[(j + 2) % 3]) / total)
    };
    FaceFrame { t, b: n.cross(t), corner_area }
}

/// Turns the frame (u, v) about u x v onto the plane with normal `n` (the smallest rotation).
fn rotate_frame(u: DVec3, v: DVec3, n: DVec3) -> (DVec3, DVec3) {
    let old_n = u.cross(v);
    let ndot = old_n.dot(n);
    if ndot <= -1.0 {
        return (-u, -v);
    }
    let perp = n - ndot * old_n;
    let dperp = (old_n + n) / (1.0 + ndot);
    (u - dperp * perp.dot(u), v - dperp * perp.dot(v))
}

/// The tensor `[ku, kuv, kv]` in frame (u, v) rewritten in frame (nu, nv) of a nearby plane.
fn project_tensor(u: DVec3, v: DVec3, k: [f64; 3], nu: DVec3, nv: DVec3) -> [f64; 3] {
    let (ru, rv) = rotate_frame(nu, nv, u.cross(v));
    let (u1, v1, u2, v2) = (ru.dot(u), ru.dot(v), rv.dot(u), rv.dot(v));
    let [ku, kuv, kv] = k;
    [
        ku * u1 * u1 + kuv * 2.0 * u1 * v1 + kv * v1 * v1,
        ku * u1 * u2 + kuv * (u1 * v2 + u2 * v1) + kv * v1 * v2,
        ku * u2 * u2 + kuv * 2.0 * u2 * v2 + kv * v2 * v2,
    ]
}

/// The derivative tensor `[a, b, c, d]` in frame (u, v) rewritten in frame (nu, nv).
fn project_derivative(u: DVec3, v: DVec3, c: [f64; 4], nu: DVec3, nv: DVec3) -> [f64; 4] {
    let (ru, rv) = rotate_frame(nu, nv, u.cross(v));
    let (u1, v1, u2, v2) = (ru.dot(u), ru.dot(v), rv.dot(u), rv.dot(v));
    let [a, b, cc, d] = c;
    [
        a * u1 * u1 * u1 + b * 3.0 * u1 * u1 * v1 + cc * 3.0 * u1 * v1 * v1 + d * v1 * v1 * v1,
        a * u1 * u1 * u2
            + b * (u1 * u1 * v2 + 2.0 * u2 * u1 * v1)
            + cc * (u2 * v1 * v1 + 2.0 * u1 * v1 * v2)
            + d * v1 * v1 * v2,
        a * u1 * u2 * u2
            + b * (u2 * u2 * v1 + 2.0 * u1 * u2 * v2)
            + cc * (u1 * v2 * v2 + 2.0 * u2 * v1 * v2)
            + d * v1 * v2 * v2,
        a * u2 * u2 * u2 + b * 3.0 * u2 * u2 * v2 + cc * 3.0 * u2 * v2 * v2 + d * v2 * v2 * v2,
    ]
}

/// Solves the normal equations `A x = y` (A symmetric positive definite, N <= 4) by Cholesky;
/// None when A is singular (a face whose edges do not span its plane).
fn solve<const N: usize>(a: [[f64; N]; N], y: [f64; N]) -> Option<[f64; N]> {
    let mut l = [[0.0; N]; N];
    for i in 0..N {
        for j in 0..=i {
            let s = a[i][j] - (0..j).map(|k| l[i][k] * l[j][k]).sum::<f64>();
            if i == j {
                if !(s > 1e-14 * a[i][i].abs().max(f64::MIN_POSITIVE)) {
                    return None;
                }
                l[i][i] = s.sqrt();
            } else {
                l[i][j] = s / l[j][j];
            }
        }
    }
    let mut z = [0.0; N];
    for i in 0..N {
        z[i] = (y[i] - (0..i).map(|k| l[i][k] * z[k]).sum::<f64>()) / l[i][i];
    }
    let mut x = [0.0; N];
    for i in (0..N).rev() {
        x[i] = (z[i] - (i + 1..N).map(|k| l[k][i] * x[k]).sum::<f64>()) / l[i][i];
    }
    x.iter().all(|v| v.is_finite()).then_some(x)
}

/// Least squares over rows `(row, target)`: the x minimising the sum of (row . x - target)^2.
fn least_squares<const N: usize>(rows: impl Iterator<Item = ([f64; N], f64)>) -> Option<[f64; N]> {
    let mut a = [[0.0; N]; N];
    let mut y = [0.0; N];
    for (r, t) in rows {
        for i in 0..N {
            y[i] += r[i] * t;
            for j in 0..N {
                a[i][j] += r[i] * r[j];
            }
        }
    }
    solve(a, y)
}

/// A unit vector perpendicular to the unit `n`.
fn any_tangent(n: DVec3) -> DVec3 {
    let axis = if n.x.abs() < 0.6 { DVec3::X } else { DVec3::Y };
    n.cross(axis).normalize()
}

/// Curvature per vertex; see the module comment. `faces` are checked indices. `smoothing` > 0
/// measures it at that feature size instead of the one-ring's: the normals, then the tensors
/// are averaged over patches a bell `smoothing` mean edge lengths wide (`mesh::diffuse`) before
/// the next is fitted from them. The derivatives, fitted from the smoothed tensors, are not
/// averaged again: on the Stanford bunny that pass costs as much as the other two together
/// and changes its suggestive contours little (24 lines against 25).
pub fn curvature<T: Real>(
    positions: &[Vec3<T>],
    faces: &[[u32; 3]],
    smoothing: f64,
    cancel: &Cancel,
) -> Result<Curvature> {
    let n_vertices = positions.len();
    let p = normalized_positions(positions);
    let scale = p.1;
    let p = p.0;
    let corners = p_faces(&p, faces);
    let frames: Vec<FaceFrame> = corners.par_iter().map(face_frame).collect();
    cancel.check()?;
    let normals = vertex_normals(n_vertices, faces, &corners);
    let ring = Buckets::<RingCorner>::corners_with_ids(n_vertices, faces)?;
    // each vertex's Voronoi area, for the patches' weights (only when smoothing)
    let areas: Vec<f64> = if smoothing > 0.0 {
        (0..n_vertices)
            .into_par_iter()
            .map(|v| {
                ring.at(v)
                    .iter()
                    .map(|&[_, _, id]| frames[id as usize / 3].corner_area[id as usize % 3])
                    .sum()
            })
            .collect()
    } else {
        Vec::new()
    };
    let patches = (smoothing > 0.0).then(|| {
        let arrays: Vec<[f64; 3]> = p.iter().map(|q| q.to_array()).collect();
        let sigma = smoothing * mean_edge_length(&arrays, faces);
        Patches { positions: &p, normals: &normals, areas: &areas, ring: &ring, sigma }
    });
    let smoothed_normals;
    let normals: &[DVec3] = match &patches {
        Some(patches) => {
            let mean = patches.average(|_, u| normals[u].to_array(), cancel)?;
            smoothed_normals = mean
                .iter()
                .zip(normals.iter())
                .map(|(m, &raw)| DVec3::from(*m).try_normalize().unwrap_or(raw))
                .collect::<Vec<_>>();
            &smoothed_normals
        }
        None => &normals,
    };

    // Each face's second fundamental form in its own frame, from the normals' change along
    // each edge.
    let face_ii: Vec<[f64; 3]> = (faces, &corners, &frames)
        .into_par_iter()
        .map(|(f, c, fr)| {
            if !fr.defined() {
                return [0.0; 3];
            }
            let rows = (0..3).flat_map(|j| {
                let e = edge(c, j);
                let dn = normals[f[(j + 2) % 3] as usize] - normals[f[(j + 1) % 3] as usize];
                let (u, v) = (e.dot(fr.t), e.dot(fr.b));
                [([u, v, 0.0], dn.dot(fr.t)), ([0.0, u, v], dn.dot(fr.b))]
            });
            least_squares(rows).unwrap_or([0.0; 3])
        })
        .collect();
    cancel.check()?;

    // Each vertex: the area-weighted mean of its faces' tensors in its tangent plane (then, when
    // smoothing, averaged over its patch), diagonalised.
    let frame = |v: usize| {
        let u0 = any_tangent(normals[v]);
        (u0, normals[v].cross(u0))
    };
    let tensor = |v: usize, (u0, v0): (DVec3, DVec3)| {
        corner_mean(ring.at(v), &frames, |face, fr| project_tensor(fr.t, fr.b, face_ii[face], u0, v0))
            .unwrap_or([0.0; 3])
    };
    let principal: Vec<(f64, f64, DVec3, DVec3)> = match &patches {
        // one pass: the tensor in a frame, diagonalised
        None => (0..n_vertices)
            .into_par_iter()
            .map(|v| {
                let (u0, v0) = frame(v);
                diagonalize(u0, v0, tensor(v, (u0, v0)))
            })
            .collect(),
        Some(patches) => {
            let frames_v: Vec<(DVec3, DVec3)> = (0..n_vertices).into_par_iter().map(frame).collect();
            let tensors: Vec<[f64; 3]> =
                (0..n_vertices).into_par_iter().map(|v| tensor(v, frames_v[v])).collect();
            cancel.check()?;
            let tensors = patches.average(
                |at, from| {
                    let ((u, v), (nu, nv)) = (frames_v[from], frames_v[at]);
                    project_tensor(u, v, tensors[from], nu, nv)
                },
                cancel,
            )?;
            (0..n_vertices)
                .into_par_iter()
                .map(|v| {
                    let (u0, v0) = frames_v[v];
                    diagonalize(u0, v0, tensors[v])
                })
                .collect()
        }
    };
    cancel.check()?;

    // Each face's derivative of the tensor, from its vertices' tensors along its edges; then
    // each vertex's area-weighted mean in its principal frame.
    let face_dii: Vec<[f64; 4]> = (faces, &corners, &frames)
        .into_par_iter()
        .map(|(f, c, fr)| {
            if !fr.defined() {
                return [0.0; 4];
            }
            let at = |i: u32| {
                let (k1, k2, d1, d2) = principal[i as usize];
                project_tensor(d1, d2, [k1, 0.0, k2], fr.t, fr.b)
            };
            let k = f.map(at);
            let rows = (0..3).flat_map(|j| {
                let e = edge(c, j);
                let (u, v) = (e.dot(fr.t), e.dot(fr.b));
                let (from, to) = (k[(j + 1) % 3], k[(j + 2) % 3]);
                let dk = [to[0] - from[0], to[1] - from[1], to[2] - from[2]];
                [([u, v, 0.0, 0.0], dk[0]), ([0.0, u, v, 0.0], dk[1]), ([0.0, 0.0, u, v], dk[2])]
            });
            least_squares(rows).unwrap_or([0.0; 4])
        })
        .collect();
    cancel.check()?;

    let derivatives: Vec<[f64; 4]> = (0..n_vertices)
        .into_par_iter()
        .map(|v| {
            let (_, _, d1, d2) = principal[v];
            let s = scale * scale;
            corner_mean(ring.at(v), &frames, |face, fr| {
                project_derivative(fr.t, fr.b, face_dii[face], d1, d2)
            })
            .map_or([0.0; 4], |c| c.map(|x| x / s))
        })
        .collect();

    // in the normalised coordinates every value is finite; only the scale can push them out of
    // range (a mesh below about 1e-154 units across, whose derivatives exceed f64)
    let k_max = principal.iter().map(|p| p.0.abs().max(p.1.abs())).fold(0.0, f64::max);
    if !(k_max / scale).is_finite() || derivatives.iter().flatten().any(|x| !x.is_finite()) {
        return Err(Error::invalid(
            "vertices",
            format!(
                "the mesh is {scale:e} units across: its curvature (about 1/size) or the curvature's \
                 derivatives (1/size^2) are beyond float64's range; scale it up first"
            ),
        ));
    }
    let arr = |d: DVec3| d.to_array();
    Ok(Curvature {
        k1: principal.iter().map(|p| p.0 / scale).collect(),
        k2: principal.iter().map(|p| p.1 / scale).collect(),
        d1: principal.iter().map(|p| arr(p.2)).collect(),
        d2: principal.iter().map(|p| arr(p.3)).collect(),
        normals: normals.iter().copied().map(arr).collect(),
        derivatives,
    })
}

/// The mean of `of(face, frame)` over a vertex's corners, weighted by their Voronoi areas; None
/// when no corner has area.
fn corner_mean<const K: usize>(
    corners: &[RingCorner],
    frames: &[FaceFrame],
    of: impl Fn(usize, &FaceFrame) -> [f64; K],
) -> Option<[f64; K]> {
    let (mut sum, mut weight) = ([0.0; K], 0.0);
    for &[_, _, id] in corners {
        let (face, corner) = (id as usize / 3, id as usize % 3);
        let a = frames[face].corner_area[corner];
        if a > 0.0 {
            let x = of(face, &frames[face]);
            (0..K).for_each(|i| sum[i] += a * x[i]);
            weight += a;
        }
    }
    (weight > 0.0).then(|| sum.map(|x| x / weight))
}

/// Positions in f64, centred on the bounding box and divided by its largest extent, and that
/// extent (1 for a mesh of one point).
fn normalized_positions<T: Real>(positions: &[Vec3<T>]) -> (Vec<DVec3>, f64) {
    let b = Bounds::of(positions);
    let (lo, hi) = (DVec3::from(b.min), DVec3::from(b.max));
    let p = positions.par_iter().map(|q| DVec3::new(q[0].to_f64(), q[1].to_f64(), q[2].to_f64()));
    // halves first, so that extents near f64::MAX do not overflow
    let centre = lo * 0.5 + hi * 0.5;
    let extent = (hi * 0.5 - lo * 0.5).max_element() * 2.0;
    let scale = if extent > 0.0 && extent.is_finite() { extent } else { 1.0 };
    (p.map(|q| (q - centre) / scale).collect(), scale)
}

fn p_faces(p: &[DVec3], faces: &[[u32; 3]]) -> Vec<[DVec3; 3]> {
    faces.par_iter().map(|f| f.map(|i| p[i as usize])).collect()
}

/// Vertex normals weighted for curvature (Max 1999): each face's cross product at a corner
/// divided by the squared lengths of the corner's two edges, exact for vertices on a sphere.
fn vertex_normals(n: usize, faces: &[[u32; 3]], corners: &[[DVec3; 3]]) -> Vec<DVec3> {
    let mut acc = vec![DVec3::ZERO; n];
    for (f, c) in faces.iter().zip(corners) {
        let e = [edge(c, 0), edge(c, 1), edge(c, 2)];
        let cross = e[0].cross(e[1]);
        for j in 0..3 {
            let w = e[(j + 1) % 3].length_squared() * e[(j + 2) % 3].length_squared();
            if w > 0.0 && w.is_finite() {
                acc[f[j] as usize] += cross / w;
            }
        }
    }
    acc.into_par_iter()
        .map(|a| {
            let n = a.normalize_or_zero();
            if n == DVec3::ZERO {
                DVec3::Z
            } else {
                n
            }
        })
        .collect()
}

/// Principal curvatures and directions of the tensor `[ku, kuv, kv]` in frame (u, v):
/// (k1, k2, d1, d2) with k1 >= k2 and d1 x d2 = u x v.
fn diagonalize(u: DVec3, v: DVec3, k: [f64; 3]) -> (f64, f64, DVec3, DVec3) {
    let [ku, kuv, kv] = k;
    let (mut c, mut s, mut tt) = (1.0, 0.0, 0.0);
    if kuv != 0.0 {
        // a Jacobi rotation zeroing the off-diagonal term
        let h = 0.5 * (kv - ku) / kuv;
        tt = if h < 0.0 { 1.0 / (h - (1.0 + h * h).sqrt()) } else { 1.0 / (h + (1.0 + h * h).sqrt()) };
        c = 1.0 / (1.0 + tt * tt).sqrt();
        s = tt * c;
    }
    let (a, b) = (ku - tt * kuv, kv + tt * kuv);
    let (da, db) = (c * u - s * v, s * u + c * v);
    let n = u.cross(v);
    let (k1, k2, d1) = if a >= b { (a, b, da) } else { (b, a, db) };
    let d1 = d1.normalize_or_zero();
    let d1 = if d1 == DVec3::ZERO { u } else { d1 };
    (k1, k2, d1, n.cross(d1))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::mesh::shapes::icosphere;

    fn median(mut x: Vec<f64>) -> f64 {
        x.sort_by(|a, b| a.total_cmp(b));
        x[x.len() / 2]
    }

    #[test]
    fn sphere_curvature_is_one_over_radius_at_any_scale() {
        let (v, f) = icosphere(4, 0.0, 0).unwrap();
        for r in [1e-3, 1.0, 250.0] {
            let vs: Vec<[f64; 3]> = v.iter().map(|p| p.map(|x| x * r)).collect();
            let c = curvature(&vs, &f, 0.0, Cancel::never()).unwrap();
            let rel1 = median(c.k1.iter().map(|k| (k * r - 1.0).abs()).collect());
            let rel2 = median(c.k2.iter().map(|k| (k * r - 1.0).abs()).collect());
            assert!(rel1 < 0.02 && rel2 < 0.02, "r {r}: {rel1} {rel2}");
            // umbilic: no derivative to speak of
            let d = median(
                c.derivatives.iter().map(|d| d.iter().map(|x| x.abs()).fold(0.0, f64::max) * r * r).collect(),
            );
            assert!(d < 0.05, "derivative {d}");
        }
    }

    #[test]
    fn degenerate_and_lonely_vertices_are_finite() {
        let v = vec![[0.0, 0.0, 0.0], [1.0, 0.0, 0.0], [2.0, 0.0, 0.0], [0.0, 1.0, 0.0], [5.0, 5.0, 5.0]];
        let f = vec![[0, 1, 2], [0, 1, 3], [0, 0, 3]];
        let c = curvature(&v, &f, 0.0, Cancel::never()).unwrap();
        assert!(c.k1.iter().chain(&c.k2).all(|k| k.is_finite()));
        assert!(c.d1.iter().chain(&c.d2).flatten().all(|x| x.is_finite()));
        assert!(c.derivatives.iter().flatten().all(|x| x.is_finite()));
        assert_eq!(c.k1[4], 0.0);
    }

    #[test]
    fn smoothing_finds_the_shape_under_noise_and_keeps_a_clean_one() {
        // noise of a fifth of an edge along the normals: the one-ring estimate scatters
        let (v, f) = icosphere(5, 0.01, 3).unwrap();
        let spread = |c: &Curvature| median(c.k1.iter().chain(&c.k2).map(|k| (k - 1.0).abs()).collect());
        let raw = curvature(&v, &f, 0.0, Cancel::never()).unwrap();
        let smooth = curvature(&v, &f, 2.0, Cancel::never()).unwrap();
        assert!(spread(&smooth) < 0.25 * spread(&raw), "{} against {}", spread(&smooth), spread(&raw));
        // no saddles left to draw suggestive contours on
        let saddles = |c: &Curvature| c.k2.iter().filter(|&&k| k <= 0.0).count();
        assert!(
            saddles(&smooth) * 20 < saddles(&raw).max(1),
            "{} against {}",
            saddles(&smooth),
            saddles(&raw)
        );
        // a clean sphere stays at 1/r, at any scale
        let (v, f) = icosphere(4, 0.0, 0).unwrap();
        for r in [1e-3, 250.0] {
            let vs: Vec<[f64; 3]> = v.iter().map(|p| p.map(|x| x * r)).collect();
            let c = curvature(&vs, &f, 2.0, Cancel::never()).unwrap();
            assert!(
                spread(&Curvature {
                    k1: c.k1.iter().map(|k| k * r).collect(),
                    k2: c.k2.iter().map(|k| k * r).collect(),
                    ..c
                }) < 0.02
            );
        }
    }
}

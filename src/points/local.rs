//! What each point's neighbourhood tells of the surface the cloud samples: its normal, the
//! direction in which the point and its k nearest neighbours spread least (PCA: the covariance's
//! eigenvector of the smallest eigenvalue), and its reach, the distance to the k-th neighbour
//! (the cloud's spacing, in its own units).
//!
//! Normals point away from the cloud's centroid (one consistent side for closed shapes such as a
//! scan of an object; shading is two-sided, so a normal pointing in draws the same). Where the
//! neighbourhood does not span a plane the normal is still unit and finite: on a line, some
//! direction across it; where every neighbour coincides with the point (duplicates, a cloud of
//! one point), the direction from the centroid, else +z.

use rayon::prelude::*;

use super::kd_tree::KdTree;
use crate::error::{Error, Result};

/// Neighbours per point when the caller names no number: enough for a stable plane fit on a
/// noisy scan, few enough to keep thin features.
pub const DEFAULT_NEIGHBOURS: usize = 12;

/// The largest number of neighbours a point may take.
pub const MAX_NEIGHBOURS: usize = 256;

/// Checks `k` (the argument `arg`): 3 to `MAX_NEIGHBOURS` (a plane needs three points).
pub fn check_neighbours(arg: &str, k: usize) -> Result<()> {
    if !(3..=MAX_NEIGHBOURS).contains(&k) {
        return Err(Error::invalid(arg, format!("must be 3 to {MAX_NEIGHBOURS} neighbours, got {k}")));
    }
    Ok(())
}

/// A point's neighbourhood: its unit normal and its reach.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Local {
    pub normal: [f64; 3],
    /// The distance to its k-th nearest neighbour (to its farthest, in a cloud of k or fewer).
    pub reach: f64,
    /// The distance to its nearest neighbour.
    pub nearest: f64,
}

/// Each point's `Local`, from its `k` nearest neighbours (the point itself left out); in
/// parallel, the same bits for any thread count.
pub fn neighbourhoods(points: &[[f64; 3]], k: usize) -> Vec<Local> {
    let tree = KdTree::new(points);
    let centroid = centroid(points);
    crate::parallel::install(|| {
        points
            .par_iter()
            .enumerate()
            .map(|(i, &p)| {
                let near = tree.nearest(p, k, Some(i as u32));
                let reach = near.last().map_or(0.0, |n| n.1.sqrt());
                let nearest = near.first().map_or(0.0, |n| n.1.sqrt());
                let normal = plane_normal(p, near.iter().map(|n| points[n.0 as usize]), centroid);
                Local { normal, reach, nearest }
            })
            .collect()
    })
}

/// The cloud's centroid (summed in order: the same bits every time).
fn centroid(points: &[[f64; 3]]) -> [f64; 3] {
    let n = points.len().max(1) as f64;
    let mut c = [0.0; 3];
    for p in points {
        for a in 0..3 {
            c[a] += p[a] / n;
        }
    }
    c
}

/// The normal of the plane through `p` and its neighbours, turned away from `centroid`.
fn plane_normal(p: [f64; 3], near: impl Iterator<Item = [f64; 3]>, centroid: [f64; 3]) -> [f64; 3] {
    // about p, not the origin: a cloud far from the origin keeps its precision
    let d: Vec<[f64; 3]> = std::iter::once([0.0; 3]).chain(near.map(|q| sub(q, p))).collect();
    let n = d.len() as f64;
    let mean = [0, 1, 2].map(|a| d.iter().map(|v| v[a]).sum::<f64>() / n);
    let mut cov = [[0.0; 3]; 3];
    for v in &d {
        let c = sub(*v, mean);
        for a in 0..3 {
            for b in 0..3 {
                cov[a][b] += c[a] * c[b];
            }
        }
    }
    let outward = sub(p, centroid);
    let (values, vectors) = symmetric_eigen(cov);
    let largest = values.iter().fold(0.0f64, |m, v| m.max(v.abs()));
    let normal = if largest > 0.0 {
        let smallest = (0..3).min_by(|&a, &b| values[a].total_cmp(&values[b])).unwrap_or(2);
        unit(vectors[smallest]).unwrap_or([0.0, 0.0, 1.0])
    } else {
        unit(outward).unwrap_or([0.0, 0.0, 1.0])
    };
    if dot(normal, outward) < 0.0 {
        normal.map(|x| -x)
    } else {
        normal
    }
}

/// Eigenvalues and unit eigenvectors of a symmetric 3x3 matrix, by cyclic Jacobi rotations.
pub fn symmetric_eigen(m: [[f64; 3]; 3]) -> ([f64; 3], [[f64; 3]; 3]) {
    let mut a = m;
    // columns of v are the eigenvectors
    let mut v = [[1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]];
    for _sweep in 0..32 {
        let off = a[0][1] * a[0][1] + a[0][2] * a[0][2] + a[1][2] * a[1][2];
        let diag = a[0][0] * a[0][0] + a[1][1] * a[1][1] + a[2][2] * a[2][2];
        if off <= 1e-30 * diag || off == 0.0 {
            break;
        }
        for (p, q) in [(0, 1), (0, 2), (1, 2)] {
            if a[p][q] == 0.0 {
                continue;
            }
            let theta = (a[q][q] - a[p][p]) / (2.0 * a[p][q]);
            let t = theta.signum() / (theta.abs() + (theta * theta + 1.0).sqrt());
            let t = if theta == 0.0 { 1.0 } else { t };
            let c = 1.0 / (t * t + 1.0).sqrt();
            let s = t * c;
            // a <- J^T a J, v <- v J, with J the rotation in the (p, q) plane
            for k in 0..3 {
                let (akp, akq) = (a[k][p], a[k][q]);
                a[k][p] = c * akp - s * akq;
                a[k][q] = s * akp + c * akq;
            }
            for k in 0..3 {
                let (apk, aqk) = (a[p][k], a[q][k]);
                a[p][k] = c * apk - s * aqk;
                a[q][k] = s * apk + c * aqk;
            }
            for row in &mut v {
                let (vp, vq) = (row[p], row[q]);
                row[p] = c * vp - s * vq;
                row[q] = s * vp + c * vq;
            }
        }
    }
    let vectors = [0, 1, 2].map(|j| [v[0][j], v[1][j], v[2][j]]);
    ([a[0][0], a[1][1], a[2][2]], vectors)
}

fn sub(a: [f64; 3], b: [f64; 3]) -> [f64; 3] {
    [a[0] - b[0], a[1] - b[1], a[2] - b[2]]
}

fn dot(a: [f64; 3], b: [f64; 3]) -> f64 {
    a[0] * b[0] + a[1] * b[1] + a[2] * b[2]
}

fn unit(v: [f64; 3]) -> Option<[f64; 3]> {
    let l = dot(v, v).sqrt();
    (l > 0.0 && l.is_finite()).then(|| v.map(|x| x / l))
}

#[cfg(test)]
mod tests {
    use super::*;

    fn sphere(n: usize) -> Vec<[f64; 3]> {
        // a Fibonacci sphere
        (0..n)
            .map(|i| {
                let y = 1.0 - 2.0 * (i as f64 + 0.5) / n as f64;
                let r = (1.0 - y * y).sqrt();
                let t = i as f64 * std::f64::consts::PI * (3.0 - 5f64.sqrt());
                [r * t.cos(), y, r * t.sin()]
            })
            .collect()
    }

    #[test]
    fn sphere_normals_are_radial_and_outward() {
        let p = sphere(2000);
        for (l, q) in neighbourhoods(&p, DEFAULT_NEIGHBOURS).iter().zip(&p) {
            assert!(dot(l.normal, *q) > 0.99, "{:?} at {q:?}", l.normal);
            assert!(l.reach > 0.0 && l.reach < 0.2);
        }
    }

    #[test]
    fn same_for_any_offset_and_scale() {
        let p = sphere(500);
        let moved: Vec<[f64; 3]> = p.iter().map(|q| q.map(|x| x * 1e-3 + 1e3)).collect();
        let (a, b) = (neighbourhoods(&p, 10), neighbourhoods(&moved, 10));
        for (x, y) in a.iter().zip(&b) {
            assert!(dot(x.normal, y.normal) > 0.999);
            assert!((x.reach * 1e-3 - y.reach).abs() < 1e-6 * x.reach);
        }
    }

    #[test]
    fn hard_cases_give_unit_normals() {
        let line: Vec<[f64; 3]> = (0..20).map(|i| [i as f64, 2.0 * i as f64, 0.0]).collect();
        let dupes = vec![[1.0, 2.0, 3.0]; 30];
        let one = vec![[5.0, 5.0, 5.0]];
        let two = vec![[0.0; 3], [1.0, 0.0, 0.0]];
        let plane: Vec<[f64; 3]> = (0..100).map(|i| [(i % 10) as f64, (i / 10) as f64, 7.0]).collect();
        for cloud in [&line, &dupes, &one, &two, &plane] {
            for l in neighbourhoods(cloud, 12) {
                let len = dot(l.normal, l.normal).sqrt();
                assert!((len - 1.0).abs() < 1e-9 && l.reach.is_finite(), "{l:?}");
            }
        }
        for l in neighbourhoods(&plane, 12) {
            assert!(l.normal[2].abs() > 0.999999);
        }
        for (l, p) in neighbourhoods(&line, 12).iter().zip(&line) {
            assert!(dot(l.normal, [1.0, 2.0, 0.0]).abs() < 1e-9, "across the line at {p:?}");
        }
    }

    #[test]
    fn eigen_of_a_diagonal_and_a_rotated_matrix() {
        let (values, vectors) = symmetric_eigen([[2.0, 1.0, 0.0], [1.0, 2.0, 0.0], [0.0, 0.0, 5.0]]);
        let mut sorted = values;
        sorted.sort_by(f64::total_cmp);
        assert!((sorted[0] - 1.0).abs() < 1e-12 && (sorted[1] - 3.0).abs() < 1e-12);
        let i = (0..3).find(|&i| (values[i] - 1.0).abs() < 1e-9).unwrap();
        assert!((vectors[i][0] + vectors[i][1]).abs() < 1e-9);
    }
}

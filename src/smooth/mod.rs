//! Mesh smoothing: Laplacian (uniform, cotangent, inverse distance), Taubin, HC (Vollmer et al.
//! 1999) and implicit (backward Euler), with presets that reproduce trimesh and pymeshlab.
//!
//! Every method is a Jacobi iteration over an averaging operator A (see `operator`): all
//! vertices of step t+1 are computed from step t, in parallel, each row in a fixed order, so the
//! result is the same bits for any thread count. Positions are kept in the caller's precision
//! between steps; sums are taken in f64.

pub mod bicgstab;
pub mod clean;
pub mod meshlab;
pub mod operator;
pub mod options;
pub mod trimesh;
pub mod volume;

use rayon::prelude::*;

use crate::error::Result;
use crate::mesh::reorder::{self, Reordering};
use crate::mesh::Adjacency;
use crate::real::{self, Real, Vec3};
use operator::{from_f64, par_rows, par_rows_f64, Operator};
pub use options::{resolve, Args, Boundary, Method, Plan, Preset, Weights};
use volume::VolumeConstraint;

/// Where each step's operator comes from: fixed once, or rebuilt from the current positions
/// when the weights depend on the geometry.
enum Source {
    Fixed(Operator),
    Clean { weights: Weights, boundary: Boundary, frozen: Vec<bool>, is_boundary: Vec<bool> },
    MeshlabCotangent { boundary: bool, pinned: Option<Vec<bool>> },
}

impl Source {
    /// The operator for positions `x`. Rebuilt operators reuse `scratch`'s buffers; `slot`
    /// holds the current one so that it can be recycled at the next step.
    fn at<'a, T: Real>(
        &'a self,
        adj: &Adjacency,
        x: &[Vec3<T>],
        faces: &[[u32; 3]],
        scratch: &mut clean::Scratch,
        slot: &'a mut Option<Operator>,
    ) -> &'a Operator {
        if let Some(old) = slot.take() {
            scratch.recycle(old);
        }
        let fresh = match self {
            Source::Fixed(op) => return op,
            Source::Clean { weights, boundary, frozen, is_boundary } => {
                clean::operator(adj, x, faces, *weights, *boundary, frozen, is_boundary, scratch)
            }
            Source::MeshlabCotangent { boundary, pinned } => {
                meshlab::laplacian(adj, x, true, *boundary, pinned.as_deref())
            }
        };
        slot.insert(fresh)
    }
}

/// Smooths `x0` as `plan` says. `pinned` marks vertices that must not move.
pub fn smooth<T: Real>(
    x0: &[Vec3<T>],
    faces: &[[u32; 3]],
    plan: &Plan,
    pinned: Option<&[bool]>,
) -> Result<Vec<Vec3<T>>> {
    if x0.len() < reorder::MIN_VERTICES || plan.iterations == 0 {
        return smooth_in_order(x0, faces, plan, pinned);
    }
    let r = Reordering::spatial(x0);
    let pinned = pinned.map(|p| r.mask(p));
    let out = smooth_in_order(&r.positions(x0), &r.faces(faces), plan, pinned.as_deref())?;
    Ok(r.restore(out))
}

pub fn smooth_in_order<T: Real>(
    x0: &[Vec3<T>],
    faces: &[[u32; 3]],
    plan: &Plan,
    pinned: Option<&[bool]>,
) -> Result<Vec<Vec3<T>>> {
    let mut adj = Adjacency::build(x0.len(), faces)?;
    if plan.weights == Weights::Cotangent {
        adj = adj.with_corners(faces);
    }
    let mut x = x0.to_vec();
    if plan.iterations == 0 {
        return Ok(x);
    }
    // Which vertices the volume constraint may rescale (None: all, as trimesh does).
    let mut rescale_mask: Option<Vec<bool>> = None;
    let source = match plan.preset {
        Preset::Clean | Preset::Paper => {
            let is_boundary = adj.boundary_vertices();
            let frozen = clean::frozen_vertices(&adj, plan.boundary, &is_boundary, pinned);
            rescale_mask = Some(frozen.iter().map(|f| !f).collect());
            if plan.weights == Weights::Uniform {
                Source::Fixed(clean::operator(
                    &adj,
                    x0,
                    faces,
                    plan.weights,
                    plan.boundary,
                    &frozen,
                    &is_boundary,
                    &mut clean::Scratch::default(),
                ))
            } else {
                Source::Clean { weights: plan.weights, boundary: plan.boundary, frozen, is_boundary }
            }
        }
        Preset::Trimesh => Source::Fixed(match plan.weights {
            Weights::Distance => trimesh::distance(&adj, x0, pinned),
            _ => trimesh::uniform(&adj, faces, pinned),
        }),
        Preset::Pymeshlab => {
            let boundary = plan.boundary == Boundary::Slide;
            match plan.method {
                Method::Laplacian if plan.weights == Weights::Cotangent => {
                    Source::MeshlabCotangent { boundary, pinned: pinned.map(|p| p.to_vec()) }
                }
                Method::Laplacian => Source::Fixed(meshlab::laplacian(&adj, x0, false, boundary, pinned)),
                Method::Taubin => Source::Fixed(meshlab::taubin_average(&adj, x0, pinned)),
                _ => Source::Fixed(meshlab::hc_average(&adj, pinned)),
            }
        }
    };
    let volume = if plan.volume_constraint { VolumeConstraint::new(x0, faces) } else { None };
    let mut y = vec![[T::zero(); 3]; x.len()];
    let mut scratch = clean::Scratch::default();
    let mut slot: Option<Operator> = None;
    let mut hc_buf = HcBuffers::default();
    for it in 0..plan.iterations {
        match plan.method {
            Method::Laplacian => {
                let op = source.at(&adj, &x, faces, &mut scratch, &mut slot);
                explicit_step(&adj, op, &x, &mut y, plan.lamb);
                std::mem::swap(&mut x, &mut y);
            }
            Method::Taubin => {
                let factors: Vec<f64> = taubin_factors(plan, it);
                for f in factors {
                    let op = source.at(&adj, &x, faces, &mut scratch, &mut slot);
                    explicit_step(&adj, op, &x, &mut y, f);
                    std::mem::swap(&mut x, &mut y);
                }
            }
            Method::Hc => {
                let op = source.at(&adj, &x, faces, &mut scratch, &mut slot);
                if plan.preset == Preset::Pymeshlab {
                    hc_meshlab_step(&adj, op, &x, &mut y, plan.beta, &mut hc_buf);
                } else {
                    hc_step(&adj, op, x0, &x, &mut y, plan.alpha, plan.beta, &mut hc_buf);
                }
                std::mem::swap(&mut x, &mut y);
            }
            Method::Implicit => {
                let op = source.at(&adj, &x, faces, &mut scratch, &mut slot);
                implicit_step(&adj, op, &mut x, plan.step, plan.tol, plan.max_iter)?;
            }
        }
        if let Some(vc) = &volume {
            if let Some(s) = vc.factor(&x, faces) {
                rescale(&mut x, vc.center, s, rescale_mask.as_deref());
            }
        }
    }
    Ok(x)
}

/// The step factors of one Taubin iteration: a shrink then an inflate pass, except that
/// trimesh counts passes (even passes shrink, odd passes inflate).
fn taubin_factors(plan: &Plan, it: u32) -> Vec<f64> {
    if plan.preset == Preset::Trimesh {
        vec![if it % 2 == 0 { plan.lamb } else { plan.mu }]
    } else {
        vec![plan.lamb, plan.mu]
    }
}

/// x' = x + f (A x - x).
fn explicit_step<T: Real>(adj: &Adjacency, op: &Operator, x: &[Vec3<T>], out: &mut [Vec3<T>], f: f64) {
    par_rows(out, |i| {
        let a = op.row(adj, x, i);
        let xi = real::to_f64(x[i]);
        from_f64([xi[0] + f * (a[0] - xi[0]), xi[1] + f * (a[1] - xi[1]), xi[2] + f * (a[2] - xi[2])])
    });
}

/// The two f64 fields an HC step needs, kept from step to step.
#[derive(Default)]
struct HcBuffers {
    p: Vec<[f64; 3]>,
    b: Vec<[f64; 3]>,
}

impl HcBuffers {
    fn get(&mut self, n: usize) -> (&mut Vec<[f64; 3]>, &mut Vec<[f64; 3]>) {
        self.p.resize(n, [0.0; 3]);
        self.b.resize(n, [0.0; 3]);
        (&mut self.p, &mut self.b)
    }
}

/// Vollmer et al.: p = A x; b = p - (alpha o + (1 - alpha) x); x' = p - (beta b + (1 - beta) A b).
#[allow(clippy::too_many_arguments)]
fn hc_step<T: Real>(
    adj: &Adjacency,
    op: &Operator,
    o: &[Vec3<T>],
    x: &[Vec3<T>],
    out: &mut [Vec3<T>],
    alpha: f64,
    beta: f64,
    buf: &mut HcBuffers,
) {
    let (p, b) = buf.get(x.len());
    par_rows_f64(p, |i| op.row(adj, x, i));
    let p: &[[f64; 3]] = p;
    par_rows_f64(b, |i| {
        let (oi, xi) = (real::to_f64(o[i]), real::to_f64(x[i]));
        std::array::from_fn(|k| p[i][k] - (alpha * oi[k] + (1.0 - alpha) * xi[k]))
    });
    par_rows(out, |i| {
        if op.is_identity(adj, i) {
            return x[i]; // exactly, rather than x - b with b rounding to 1e-16
        }
        let ab = op.row(adj, b, i);
        from_f64(std::array::from_fn(|k| p[i][k] - (beta * b[i][k] + (1.0 - beta) * ab[k])))
    });
}

/// pymeshlab's HC: q = A x; d = A (q - x); x' = q - beta (q - x) + (1 - beta) d.
fn hc_meshlab_step<T: Real>(
    adj: &Adjacency,
    op: &Operator,
    x: &[Vec3<T>],
    out: &mut [Vec3<T>],
    beta: f64,
    buf: &mut HcBuffers,
) {
    let (q, qx) = buf.get(x.len());
    par_rows_f64(q, |i| op.row(adj, x, i));
    let q: &[[f64; 3]] = q;
    par_rows_f64(qx, |i| {
        let xi = real::to_f64(x[i]);
        std::array::from_fn(|k| q[i][k] - xi[k])
    });
    par_rows(out, |i| {
        if op.is_identity(adj, i) {
            return x[i];
        }
        let d = op.row(adj, qx, i);
        from_f64(std::array::from_fn(|k| q[i][k] - beta * qx[i][k] + (1.0 - beta) * d[k]))
    });
}

/// Backward Euler: solve ((1 + s) I - s A) x' = x, written for the displacement
/// d = x' - x: ((1 + s) I - s A) d = s (A x - x). Solving for d keeps the tolerance relative to
/// the motion rather than to the coordinates, so offset meshes converge just as well.
fn implicit_step<T: Real>(
    adj: &Adjacency,
    op: &Operator,
    x: &mut [Vec3<T>],
    s: f64,
    tol: f64,
    max_iter: u32,
) -> Result<()> {
    let n = x.len();
    let inv_diag: Vec<f64> =
        (0..n).into_par_iter().map(|i| 1.0 / ((1.0 + s) - s * op.diagonal(adj, i))).collect();
    let mut rhs = vec![[0.0f64; 3]; n];
    {
        let xr: &[Vec3<T>] = x;
        par_rows_f64(&mut rhs, |i| {
            let a = op.row(adj, xr, i);
            let xi = real::to_f64(xr[i]);
            std::array::from_fn(|k| s * (a[k] - xi[k]))
        });
    }
    let matvec = |v: &[[f64; 3]], out: &mut [[f64; 3]]| {
        par_rows_f64(out, |i| {
            let a = op.row(adj, v, i);
            std::array::from_fn(|k| (1.0 + s) * v[i][k] - s * a[k])
        });
    };
    let mut d = vec![[0.0f64; 3]; n];
    bicgstab::solve(matvec, &inv_diag, &rhs, &mut d, tol, max_iter)?;
    // A vertex that never moves has the equation d_i = 0 exactly; the iterative solution
    // only approximates it, so such rows are left untouched.
    x.par_iter_mut().zip(d.par_iter()).enumerate().for_each(|(i, (p, di))| {
        if !op.is_identity(adj, i) {
            *p = from_f64(std::array::from_fn(|k| p[k].to_f64() + di[k]));
        }
    });
    Ok(())
}

/// x <- (x - c) s + c, for the vertices `mask` allows (all when None).
fn rescale<T: Real>(x: &mut [Vec3<T>], c: [f64; 3], s: f64, mask: Option<&[bool]>) {
    x.par_iter_mut().enumerate().for_each(|(i, p)| {
        if mask.is_none_or(|m| m[i]) {
            let q = real::to_f64(*p);
            *p = from_f64(std::array::from_fn(|k| (q[k] - c[k]) * s + c[k]));
        }
    });
}

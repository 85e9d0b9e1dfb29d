//! Mesh smoothing: Laplacian (uniform, cotangent, inverse distance), Taubin, HC (Vollmer et al.
//! 1999) and implicit (backward Euler), with presets that reproduce trimesh and pymeshlab; and
//! feature-preserving smoothing by normal filtering (`denoise`: bilateral and guided).
//!
//! Every method is a Jacobi iteration over an averaging operator A (see `operator`): all
//! vertices of step t+1 are computed from step t, in parallel, each row in a fixed order, so the
//! result is the same bits for any thread count. Positions are kept in the caller's precision
//! between steps; sums are taken in f64.

pub mod bicgstab;
pub mod clean;
pub mod denoise;
pub mod described;
pub mod given;
pub mod keywords;
pub mod meshlab;
pub mod operator;
pub mod options;
pub mod preset;
pub mod range;
pub mod trimesh;
pub mod volume;

use rayon::prelude::*;

use crate::cancel::Cancel;
use crate::error::{Error, Result};
use crate::huge_pages;
use crate::mesh::reorder;
use crate::mesh::weld::on_welded;
use crate::mesh::Adjacency;
use crate::real::{self, Real, Vec3};
use operator::{from_f64, par_rows_gathering, Operator};
pub use options::{resolve, Args, Boundary, Method, Plan, Preset, Weights};
use volume::VolumeConstraint;

/// Where each step's operator comes from: fixed once, or rebuilt from the current positions
/// when the weights depend on the geometry.
enum Source {
    Fixed(Operator),
    Clean(clean::Rules),
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
            Source::Clean(rules) => clean::operator(adj, x, faces, rules, scratch),
            Source::MeshlabCotangent { boundary, pinned } => {
                meshlab::laplacian(adj, x, faces, true, *boundary, pinned.as_deref(), scratch)
            }
        };
        slot.insert(fresh)
    }

    /// out = x + f (A x - x) with the operator at `x`. Clean rows are built and used at once,
    /// never stored.
    #[allow(clippy::too_many_arguments)]
    fn explicit_step<T: Real>(
        &self,
        adj: &Adjacency,
        x: &[Vec3<T>],
        out: &mut [Vec3<T>],
        f: f64,
        faces: &[[u32; 3]],
        scratch: &mut clean::Scratch,
        slot: &mut Option<Operator>,
    ) {
        match self {
            Source::Clean(rules) => {
                clean::map_averages(adj, x, faces, rules, scratch, out, |i, a| relax(x[i], a, f))
            }
            Source::MeshlabCotangent { pinned, .. } => {
                let op = self.at(adj, x, faces, scratch, slot);
                explicit_step(adj, op, x, out, f);
                // VCG's x' = (x + S) / (C + 1) exactly where collinear faces make it depend
                // on the order of the sums (the preset has no step size: f is 1).
                for (v, p) in
                    meshlab::exact_at_collinear_faces(adj, x, faces, &scratch.face_cot, pinned.as_deref())
                {
                    out[v as usize] = from_f64(p);
                }
            }
            _ => {
                let op = self.at(adj, x, faces, scratch, slot);
                explicit_step(adj, op, x, out, f)
            }
        }
    }
}

/// Smooths `x0` as `plan` says. `pinned` marks vertices that must not move.
///
/// With `plan.weld`, the mesh smoothed is the welded one (`mesh::weld::Merged`): vertices at
/// equal positions are one vertex, so seams are neither boundaries nor cracks, a position is
/// pinned when any of its copies is, and every copy gets its position's result.
pub fn smooth<T: Real>(
    x0: &[Vec3<T>],
    faces: &[[u32; 3]],
    plan: &Plan,
    pinned: Option<&[bool]>,
) -> Result<Vec<Vec3<T>>> {
    smooth_cancellable(x0, faces, plan, pinned, Cancel::never(), None)
}

/// How a smoother runs: the Laplacian family's plan, or a normal filter's options.
pub enum Run {
    Laplacian(Plan),
    Normals(denoise::Options),
}

impl Run {
    /// `x0` smoothed as this run says, stopping with `Error::Interrupted` at the next step (or
    /// solver iteration, or filtering pass) after `cancel` is raised. Meshes of any scale are
    /// handled (see `range`), welded first where the run says so (`mesh::weld::on_welded`); a
    /// result that is not finite in the input's dtype is refused rather than returned.
    /// `largest` is the largest absolute coordinate of `x0` if the caller already has it (it
    /// saves a pass over `x0`).
    pub fn run<T: Real>(
        &self,
        x0: &[Vec3<T>],
        faces: &[[u32; 3]],
        pinned: Option<&[bool]>,
        cancel: &Cancel,
        largest: Option<f64>,
    ) -> Result<Vec<Vec3<T>>> {
        let (steps, weld) = match self {
            Run::Laplacian(plan) => (plan.iterations, plan.weld),
            Run::Normals(opts) => (opts.vertex_iterations, opts.weld),
        };
        if steps == 0 {
            return Ok(x0.to_vec());
        }
        // `scale` serves the one rule stated in absolute units (trimesh's distance floor)
        let out = range::at_fitted_scale(x0, largest, |x, scale| {
            on_welded(x, faces, pinned, weld, |x, f, pinned| match self {
                Run::Laplacian(plan) => reorder::on_best_order(x, f, pinned, |x, f, pinned| {
                    smooth_in_order(x, f, plan, pinned, cancel, scale)
                }),
                Run::Normals(opts) => denoise::denoise_mesh(x, f, opts, pinned, cancel),
            })
        })?;
        match self {
            Run::Laplacian(plan) if may_grow(plan) && !range::all_finite(&out) => Err(overflow_error::<T>(x0, plan)),
            Run::Normals(_) if !range::all_finite(&out) => Err(Error::invalid(
                "vertices",
                "the smoothed positions overflow the dtype: coordinates must stay well below its largest value",
            )),
            _ => Ok(out),
        }
    }
}

/// `smooth`, stopping on `cancel` (see `Run::run`).
pub fn smooth_cancellable<T: Real>(
    x0: &[Vec3<T>],
    faces: &[[u32; 3]],
    plan: &Plan,
    pinned: Option<&[bool]>,
    cancel: &Cancel,
    largest: Option<f64>,
) -> Result<Vec<Vec3<T>>> {
    Run::Laplacian(plan.clone()).run(x0, faces, pinned, cancel, largest)
}

/// Whether a result can leave the input's bounding box (and so, in principle, the dtype's
/// range). The clean and paper Laplacians cannot: each step is a convex combination of
/// neighbours (see `clean`), so they skip the final check.
fn may_grow(plan: &Plan) -> bool {
    !(plan.method == Method::Laplacian
        && matches!(plan.preset, Preset::Clean | Preset::Paper)
        && !plan.volume_constraint)
}

/// The error for a result that overflowed the dtype: the input was too close to its largest
/// value, or (Taubin, HC, implicit with a volume constraint) very many iterations let it grow.
fn overflow_error<T: Real>(x0: &[Vec3<T>], plan: &Plan) -> Error {
    let largest = T::max_value().to_f64();
    let dtype = if largest > f32::MAX as f64 { "float64" } else { "float32" };
    if range::largest_coordinate(x0) > largest / 16.0 {
        Error::invalid(
            "vertices",
            format!(
                "the smoothed positions overflow {dtype}: coordinates must stay below about \
                 {:.0e} (1/16 of the largest {dtype})",
                largest / 16.0
            ),
        )
    } else {
        Error::invalid(
            "iterations",
            format!(
                "the smoothed positions grew past the largest {dtype} after {} iterations \
                 (Taubin and HC amplify the lowest frequencies slightly at every step): use \
                 fewer iterations",
                plan.iterations
            ),
        )
    }
}

fn smooth_in_order<T: Real>(
    x0: &[Vec3<T>],
    faces: &[[u32; 3]],
    plan: &Plan,
    pinned: Option<&[bool]>,
    cancel: &Cancel,
    scale: Option<range::Pow2>,
) -> Result<Vec<Vec3<T>>> {
    let adj = if plan.weights == Weights::Cotangent {
        Adjacency::build_with_corners(x0.len(), faces)?
    } else {
        Adjacency::build(x0.len(), faces)?
    };
    // Which vertices the volume constraint may rescale (None: all, as trimesh does).
    let mut rescale_mask: Option<Vec<bool>> = None;
    let source = match plan.preset {
        Preset::Clean | Preset::Paper => {
            let rules = clean::Rules::new(&adj, plan.weights, plan.boundary, pinned);
            if plan.volume_constraint {
                rescale_mask = Some(rules.frozen.par_iter().map(|f| !f).collect());
            }
            if plan.weights == Weights::Uniform {
                Source::Fixed(clean::operator(&adj, x0, faces, &rules, &mut clean::Scratch::default()))
            } else {
                Source::Clean(rules)
            }
        }
        Preset::Trimesh => Source::Fixed(match plan.weights {
            Weights::Distance => {
                let floor = scale.map_or(trimesh::DISTANCE_FLOOR, |s| s.length(trimesh::DISTANCE_FLOOR));
                trimesh::distance(&adj, x0, pinned, floor)
            }
            _ => trimesh::uniform(&adj, faces, pinned),
        }),
        Preset::Pymeshlab => {
            let boundary = plan.boundary == Boundary::Slide;
            match plan.method {
                Method::Laplacian if plan.weights == Weights::Cotangent => {
                    Source::MeshlabCotangent { boundary, pinned: pinned.map(|p| p.to_vec()) }
                }
                Method::Laplacian => Source::Fixed(meshlab::laplacian(
                    &adj,
                    x0,
                    faces,
                    false,
                    boundary,
                    pinned,
                    &mut clean::Scratch::default(),
                )),
                Method::Taubin => Source::Fixed(meshlab::taubin_average(&adj, pinned)),
                _ => Source::Fixed(meshlab::hc_average(&adj, pinned)),
            }
        }
    };
    let rule = if plan.preset == Preset::Trimesh { volume::Rule::Trimesh } else { volume::Rule::Enclosed };
    let volume = if plan.volume_constraint { VolumeConstraint::new(x0, faces, rule) } else { None };
    let mut x = Steps::new(x0);
    let mut scratch = clean::Scratch::default();
    let mut slot: Option<Operator> = None;
    let mut hc_buf = HcBuffers::default();
    for it in 0..plan.iterations {
        cancel.check()?;
        match plan.method {
            Method::Laplacian => {
                x.step(|src, out| {
                    source.explicit_step(&adj, src, out, plan.lamb, faces, &mut scratch, &mut slot)
                });
            }
            Method::Taubin => {
                for f in taubin_factors(plan, it) {
                    cancel.check()?;
                    x.step(|src, out| {
                        source.explicit_step(&adj, src, out, f, faces, &mut scratch, &mut slot)
                    });
                }
            }
            Method::Hc => {
                let op = source.at(&adj, x.current(), faces, &mut scratch, &mut slot);
                if plan.preset == Preset::Pymeshlab {
                    x.step(|src, out| hc_meshlab_step(&adj, op, src, out, plan.beta, &mut hc_buf));
                } else {
                    x.step(|src, out| hc_step(&adj, op, x0, src, out, plan.alpha, plan.beta, &mut hc_buf));
                }
            }
            Method::Implicit => {
                let op = source.at(&adj, x.current(), faces, &mut scratch, &mut slot);
                implicit_step(&adj, op, x.owned(), plan.step, plan.tol, plan.max_iter, cancel)?;
            }
        }
        if let Some(vc) = &volume {
            if let Some(s) = vc.factor(x.current(), faces) {
                rescale(x.owned(), vc.center, s, rescale_mask.as_deref());
            }
        }
    }
    Ok(x.into_result())
}

/// The positions between steps: the caller's input until the first step (so it is never
/// copied), then two buffers that trade places at every explicit step.
struct Steps<'a, T> {
    initial: &'a [Vec3<T>],
    x: Vec<Vec3<T>>,
    spare: Vec<Vec3<T>>,
}

impl<'a, T: Real> Steps<'a, T> {
    fn new(initial: &'a [Vec3<T>]) -> Self {
        Steps { initial, x: Vec::new(), spare: Vec::new() }
    }

    fn current(&self) -> &[Vec3<T>] {
        if self.x.is_empty() {
            self.initial
        } else {
            &self.x
        }
    }

    /// out = f(current); out becomes current.
    fn step(&mut self, f: impl FnOnce(&[Vec3<T>], &mut [Vec3<T>])) {
        let mut out = std::mem::take(&mut self.spare);
        if out.len() != self.initial.len() {
            out = huge_pages::filled_vec(self.initial.len(), [T::zero(); 3]);
        }
        f(self.current(), &mut out);
        self.spare = std::mem::replace(&mut self.x, out);
    }

    /// The current positions, to change in place.
    fn owned(&mut self) -> &mut Vec<Vec3<T>> {
        if self.x.is_empty() {
            self.x = self.initial.to_vec();
        }
        &mut self.x
    }

    fn into_result(mut self) -> Vec<Vec3<T>> {
        self.owned();
        self.x
    }
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
    par_rows_gathering(out, adj, x, |i| relax(x[i], op.row(adj, x, i), f));
}

/// x + f (a - x), a vertex moved part of the way to its average a.
#[inline]
fn relax<T: Real>(x: Vec3<T>, a: [f64; 3], f: f64) -> Vec3<T> {
    let x = real::to_f64(x);
    from_f64([x[0] + f * (a[0] - x[0]), x[1] + f * (a[1] - x[1]), x[2] + f * (a[2] - x[2])])
}

/// The f64 field an HC step keeps between its two passes, reused from step to step.
#[derive(Default)]
struct HcBuffers {
    b: Vec<[f64; 3]>,
}

impl HcBuffers {
    fn get(&mut self, n: usize) -> &mut Vec<[f64; 3]> {
        if self.b.len() != n {
            self.b = huge_pages::filled_vec(n, [0.0; 3]);
        }
        &mut self.b
    }
}

/// Vollmer et al.: p = A x; b = p - (alpha o + (1 - alpha) x); x' = p - (beta b + (1 - beta) A b).
/// Two passes: the first stores only b, the second gathers A b and recovers p from b.
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
    let anchor = |i: usize| -> [f64; 3] {
        let (oi, xi) = (real::to_f64(o[i]), real::to_f64(x[i]));
        std::array::from_fn(|k| alpha * oi[k] + (1.0 - alpha) * xi[k])
    };
    let b = buf.get(x.len());
    par_rows_gathering(b, adj, x, |i| {
        let (p, q) = (op.row(adj, x, i), anchor(i));
        std::array::from_fn(|k| p[k] - q[k])
    });
    let b: &[[f64; 3]] = b;
    par_rows_gathering(out, adj, b, |i| {
        if op.is_identity(adj, i) {
            return x[i]; // exactly, rather than x - b with b rounding to 1e-16
        }
        let (ab, q) = (op.row(adj, b, i), anchor(i));
        from_f64(std::array::from_fn(|k| (b[i][k] + q[k]) - (beta * b[i][k] + (1.0 - beta) * ab[k])))
    });
}

/// pymeshlab's HC: q = A x; d = A (q - x); x' = q - beta (q - x) + (1 - beta) d. Two passes:
/// the first stores q - x, the second gathers d and recovers q.
fn hc_meshlab_step<T: Real>(
    adj: &Adjacency,
    op: &Operator,
    x: &[Vec3<T>],
    out: &mut [Vec3<T>],
    beta: f64,
    buf: &mut HcBuffers,
) {
    let qx = buf.get(x.len());
    par_rows_gathering(qx, adj, x, |i| {
        let (q, xi) = (op.row(adj, x, i), real::to_f64(x[i]));
        std::array::from_fn(|k| q[k] - xi[k])
    });
    let qx: &[[f64; 3]] = qx;
    par_rows_gathering(out, adj, qx, |i| {
        if op.is_identity(adj, i) {
            return x[i];
        }
        let (d, xi) = (op.row(adj, qx, i), real::to_f64(x[i]));
        from_f64(std::array::from_fn(|k| (qx[i][k] + xi[k]) - beta * qx[i][k] + (1.0 - beta) * d[k]))
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
    cancel: &Cancel,
) -> Result<()> {
    let n = x.len();
    let inv_diag: Vec<f64> =
        (0..n).into_par_iter().map(|i| 1.0 / ((1.0 + s) - s * op.diagonal(adj, i))).collect();
    let mut rhs = vec![[0.0f64; 3]; n];
    {
        let xr: &[Vec3<T>] = x;
        par_rows_gathering(&mut rhs, adj, xr, |i| {
            let a = op.row(adj, xr, i);
            let xi = real::to_f64(xr[i]);
            std::array::from_fn(|k| s * (a[k] - xi[k]))
        });
    }
    let matvec = |v: &[[f64; 3]], out: &mut [[f64; 3]]| {
        par_rows_gathering(out, adj, v, |i| {
            let a = op.row(adj, v, i);
            std::array::from_fn(|k| (1.0 + s) * v[i][k] - s * a[k])
        });
    };
    let mut d = vec![[0.0f64; 3]; n];
    bicgstab::solve(matvec, &inv_diag, &rhs, &mut d, tol, max_iter, cancel)?;
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

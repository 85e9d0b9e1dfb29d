//! Jacobi-preconditioned BiCGSTAB for three right-hand sides at once (x, y and z).
//!
//! The implicit systems here, (1 + s) I - s A with A a row-averaging operator, are diagonally
//! dominant but not symmetric under every preset, so BiCGSTAB rather than CG. The three
//! coordinates share one traversal of the adjacency per product, each with its own scalars and
//! its own stopping test. Dot products are summed in fixed chunks, so the iterates are the same
//! bits for any thread count.

use rayon::prelude::*;

use crate::cancel::Cancel;
use crate::error::{Error, Result};
use crate::parallel::REDUCE_CHUNK;

type Col3 = [f64; 3];

fn dot3(a: &[Col3], b: &[Col3]) -> Col3 {
    let partial: Vec<Col3> = a
        .par_chunks(REDUCE_CHUNK)
        .zip(b.par_chunks(REDUCE_CHUNK))
        .map(|(ca, cb)| {
            let mut s = [0.0; 3];
            for (x, y) in ca.iter().zip(cb) {
                for k in 0..3 {
                    s[k] += x[k] * y[k];
                }
            }
            s
        })
        .collect();
    partial.iter().fold([0.0; 3], |acc, p| [acc[0] + p[0], acc[1] + p[1], acc[2] + p[2]])
}

fn map3(out: &mut [Col3], f: impl Fn(usize) -> Col3 + Sync) {
    out.par_chunks_mut(REDUCE_CHUNK).enumerate().for_each(|(c, ch)| {
        for (k, o) in ch.iter_mut().enumerate() {
            *o = f(c * REDUCE_CHUNK + k);
        }
    });
}

fn norms(a: &[Col3]) -> Col3 {
    dot3(a, a).map(f64::sqrt)
}

/// Solves M x = b (three columns) to a relative residual of `tol` per column, starting from
/// `x`. Returns the number of iterations. Stops with `Error::Interrupted` at the first
/// iteration after `cancel` is raised.
pub fn solve(
    matvec: impl Fn(&[Col3], &mut [Col3]) + Sync,
    inv_diag: &[f64],
    b: &[Col3],
    x: &mut [Col3],
    tol: f64,
    max_iter: u32,
    cancel: &Cancel,
) -> Result<u32> {
    let n = b.len();
    let goal = norms(b).map(|v| tol * v);
    let mut tmp = vec![[0.0; 3]; n];
    matvec(x, &mut tmp);
    let mut r = vec![[0.0; 3]; n];
    map3(&mut r, |i| std::array::from_fn(|k| b[i][k] - tmp[i][k]));
    let mut done = [false; 3];
    let rn = norms(&r);
    for k in 0..3 {
        done[k] = rn[k] <= goal[k];
    }
    if done.iter().all(|&d| d) {
        return Ok(0);
    }
    let r_hat = r.clone();
    let (mut rho, mut alpha, mut omega) = ([1.0f64; 3], [1.0f64; 3], [1.0f64; 3]);
    let mut v = vec![[0.0; 3]; n];
    let mut p = vec![[0.0; 3]; n];
    let mut y = vec![[0.0; 3]; n];
    let mut s = vec![[0.0; 3]; n];
    let mut z = vec![[0.0; 3]; n];
    let mut t = vec![[0.0; 3]; n];
    let mut res = rn;
    // Coefficients of finished columns are zero, so their values stop changing.
    let live =
        |done: &[bool; 3], c: Col3| -> Col3 { std::array::from_fn(|k| if done[k] { 0.0 } else { c[k] }) };
    for it in 1..=max_iter {
        cancel.check()?;
        let rho_new = dot3(&r_hat, &r);
        let mut beta = [0.0; 3];
        for k in 0..3 {
            beta[k] = if done[k] { 0.0 } else { (rho_new[k] / rho[k]) * (alpha[k] / omega[k]) };
            if !(done[k] || (beta[k].is_finite() && rho_new[k] != 0.0)) {
                return Err(Error::NotConverged(format!("implicit solve broke down after {it} iterations")));
            }
        }
        map3(&mut tmp, |i| std::array::from_fn(|k| r[i][k] + beta[k] * (p[i][k] - omega[k] * v[i][k])));
        std::mem::swap(&mut p, &mut tmp);
        map3(&mut y, |i| p[i].map(|c| c * inv_diag[i]));
        matvec(&y, &mut v);
        let rv = dot3(&r_hat, &v);
        alpha = live(&done, std::array::from_fn(|k| rho_new[k] / rv[k]));
        if alpha.iter().any(|a| !a.is_finite()) {
            return Err(Error::NotConverged(format!("implicit solve broke down after {it} iterations")));
        }
        map3(&mut s, |i| std::array::from_fn(|k| r[i][k] - alpha[k] * v[i][k]));
        // Columns whose half-step residual is small enough finish here.
        let sn = norms(&s);
        let half_done: [bool; 3] = std::array::from_fn(|k| !done[k] && sn[k] <= goal[k]);
        map3(&mut z, |i| s[i].map(|c| c * inv_diag[i]));
        matvec(&z, &mut t);
        let ts = dot3(&t, &s);
        let tt = dot3(&t, &t);
        omega =
            std::array::from_fn(
                |k| if done[k] || half_done[k] || tt[k] == 0.0 { 0.0 } else { ts[k] / tt[k] },
            );
        let (yr, zr) = (&y, &z);
        x.par_chunks_mut(REDUCE_CHUNK).enumerate().for_each(|(c, ch)| {
            for (j, xi) in ch.iter_mut().enumerate() {
                let i = c * REDUCE_CHUNK + j;
                for k in 0..3 {
                    xi[k] += alpha[k] * yr[i][k] + omega[k] * zr[i][k];
                }
            }
        });
        map3(&mut r, |i| std::array::from_fn(|k| s[i][k] - omega[k] * t[i][k]));
        res = norms(&r);
        for k in 0..3 {
            if !done[k] && (half_done[k] || res[k] <= goal[k]) {
                done[k] = true;
            } else if !done[k] && omega[k] == 0.0 {
                return Err(Error::NotConverged(format!("implicit solve stagnated after {it} iterations")));
            }
        }
        if done.iter().all(|&d| d) {
            return Ok(it);
        }
        rho = rho_new;
    }
    let worst = (0..3).filter(|&k| !done[k]).map(|k| res[k] / (goal[k] / tol)).fold(0.0, f64::max);
    Err(Error::NotConverged(format!(
        "implicit solve reached max_iter={max_iter} with relative residual {worst:.3e} > tol={tol:.1e}; \
         raise max_iter or tol, or take a smaller step"
    )))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn solves_a_small_nonsymmetric_system_per_column() {
        // [[3, 1], [0.5, 2]] x = b for three right-hand sides, one of them zero.
        let m = |v: &[Col3], out: &mut [Col3]| {
            for k in 0..3 {
                out[0][k] = 3.0 * v[0][k] + v[1][k];
                out[1][k] = 0.5 * v[0][k] + 2.0 * v[1][k];
            }
        };
        let b = [[1.0, 0.0, -4.0], [2.0, 0.0, 7.0]];
        let mut x = vec![[0.0; 3]; 2];
        solve(m, &[1.0 / 3.0, 0.5], &b, &mut x, 1e-14, 100, Cancel::never()).unwrap();
        for k in 0..3 {
            assert!((3.0 * x[0][k] + x[1][k] - b[0][k]).abs() < 1e-12);
            assert!((0.5 * x[0][k] + 2.0 * x[1][k] - b[1][k]).abs() < 1e-12);
        }
        assert_eq!(x[0][1], 0.0);
    }

    #[test]
    fn stops_when_cancelled() {
        let m = |v: &[Col3], out: &mut [Col3]| out.copy_from_slice(v);
        let cancel = Cancel::new();
        cancel.request();
        let mut x = vec![[0.0; 3]; 1];
        assert_eq!(solve(m, &[1.0], &[[1.0; 3]], &mut x, 1e-14, 100, &cancel), Err(Error::Interrupted));
    }
}

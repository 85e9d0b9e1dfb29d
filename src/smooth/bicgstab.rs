//! Jacobi-preconditioned BiCGSTAB for one right-hand side.
//!
//! The implicit systems here, (1 + s) I - s A with A a row-averaging operator, are diagonally
//! dominant but not symmetric under every preset, so BiCGSTAB rather than CG. Dot products are
//! summed in fixed chunks, so the iterates are the same bits for any thread count.

use rayon::prelude::*;

use crate::error::{Error, Result};
use crate::parallel::deterministic_sum;

const CHUNK: usize = 4096;

fn dot(a: &[f64], b: &[f64]) -> f64 {
    deterministic_sum(a.len(), |i| a[i] * b[i])
}

fn zip_map(out: &mut [f64], f: impl Fn(usize) -> f64 + Sync) {
    out.par_chunks_mut(CHUNK).enumerate().for_each(|(c, ch)| {
        for (k, o) in ch.iter_mut().enumerate() {
            *o = f(c * CHUNK + k);
        }
    });
}

/// Solves M x = b to a relative residual of `tol`, starting from `x`. Returns the iterations.
pub fn solve(
    matvec: impl Fn(&[f64], &mut [f64]) + Sync,
    inv_diag: &[f64],
    b: &[f64],
    x: &mut [f64],
    tol: f64,
    max_iter: u32,
) -> Result<u32> {
    let n = b.len();
    let b_norm = dot(b, b).sqrt();
    if b_norm == 0.0 {
        x.fill(0.0);
        return Ok(0);
    }
    let goal = tol * b_norm;
    let mut tmp = vec![0.0; n];
    matvec(x, &mut tmp);
    let mut r = vec![0.0; n];
    zip_map(&mut r, |i| b[i] - tmp[i]);
    if dot(&r, &r).sqrt() <= goal {
        return Ok(0);
    }
    let mut r_hat = r.clone();
    let (mut rho, mut alpha, mut omega) = (1.0f64, 1.0f64, 1.0f64);
    let mut v = vec![0.0; n];
    let mut p = vec![0.0; n];
    let mut y = vec![0.0; n];
    let mut s = vec![0.0; n];
    let mut z = vec![0.0; n];
    let mut t = vec![0.0; n];
    let mut res = f64::INFINITY;
    for it in 1..=max_iter {
        let mut rho_new = dot(&r_hat, &r);
        if rho_new == 0.0 || !rho_new.is_finite() {
            // Breakdown: restart the shadow residual from the current residual.
            r_hat.copy_from_slice(&r);
            rho_new = dot(&r_hat, &r);
            p.fill(0.0);
            v.fill(0.0);
            rho = 1.0;
            alpha = 1.0;
            omega = 1.0;
        }
        let beta = (rho_new / rho) * (alpha / omega);
        {
            let (pr, vr) = (&p, &v);
            zip_map(&mut tmp, |i| r[i] + beta * (pr[i] - omega * vr[i]));
        }
        std::mem::swap(&mut p, &mut tmp);
        zip_map(&mut y, |i| p[i] * inv_diag[i]);
        matvec(&y, &mut v);
        let rv = dot(&r_hat, &v);
        if rv == 0.0 || !rv.is_finite() {
            return Err(Error::NotConverged(format!("implicit solve broke down after {it} iterations")));
        }
        alpha = rho_new / rv;
        zip_map(&mut s, |i| r[i] - alpha * v[i]);
        let s_norm = dot(&s, &s).sqrt();
        if s_norm <= goal {
            x.par_iter_mut().zip(y.par_iter()).for_each(|(xi, yi)| *xi += alpha * yi);
            return Ok(it);
        }
        zip_map(&mut z, |i| s[i] * inv_diag[i]);
        matvec(&z, &mut t);
        let tt = dot(&t, &t);
        omega = if tt > 0.0 { dot(&t, &s) / tt } else { 0.0 };
        {
            let (yr, zr) = (&y, &z);
            x.par_chunks_mut(CHUNK).enumerate().for_each(|(c, ch)| {
                for (k, xi) in ch.iter_mut().enumerate() {
                    let i = c * CHUNK + k;
                    *xi += alpha * yr[i] + omega * zr[i];
                }
            });
        }
        zip_map(&mut r, |i| s[i] - omega * t[i]);
        res = dot(&r, &r).sqrt();
        if res <= goal {
            return Ok(it);
        }
        if omega == 0.0 {
            return Err(Error::NotConverged(format!("implicit solve stagnated after {it} iterations")));
        }
        rho = rho_new;
    }
    Err(Error::NotConverged(format!(
        "implicit solve reached max_iter={max_iter} with relative residual {:.3e} > tol={tol:.1e}; raise max_iter or tol, or take a smaller step",
        res / b_norm
    )))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn solves_a_small_nonsymmetric_system() {
        // [[3, 1], [0.5, 2]] x = [1, 2]
        let m = |v: &[f64], out: &mut [f64]| {
            out[0] = 3.0 * v[0] + v[1];
            out[1] = 0.5 * v[0] + 2.0 * v[1];
        };
        let mut x = vec![0.0; 2];
        solve(m, &[1.0 / 3.0, 0.5], &[1.0, 2.0], &mut x, 1e-14, 100).unwrap();
        assert!((3.0 * x[0] + x[1] - 1.0).abs() < 1e-12);
        assert!((0.5 * x[0] + 2.0 * x[1] - 2.0).abs() < 1e-12);
    }
}

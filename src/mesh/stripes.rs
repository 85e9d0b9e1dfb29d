//! A stripe pattern along a tangent vector field: per vertex a unit complex number psi whose
//! argument (the phase) grows by 2 pi per `period` along the field (Knöppel, Crane, Pinkall and
//! Schröder 2015, "Stripe Patterns on Surfaces"). Stripes (phase near 0 mod 2 pi) then run
//! across the field.
//!
//! Along each edge ij the phase should turn by w_ij = 2 pi / period * (p_j - p_i) . X_ij, X_ij
//! the mean of the two ends' field: psi_j = e^(i w_ij) psi_i. The paper finds the psi that
//! satisfies this best over the whole mesh as the smallest eigenvector of the energy; here the
//! same energy is lowered by Jacobi sweeps (each psi moved to the normalised mean of its own
//! value and what each neighbour predicts), started from the phase integrated breadth-first.
//! That keeps the work linear and deterministic; where the integrated phase does not close
//! (around a cylinder when its circumference is not a whole number of periods) the sweeps
//! spread the mismatch over a band instead of a seam, or gather it into isolated zeros of psi.
//!
//! A renderer interpolates psi over each triangle and takes its argument: a phase that is
//! continuous everywhere (no cut, no seam) except at the zeros.

use rayon::prelude::*;

use crate::cancel::Cancel;
use crate::error::Result;
use crate::mesh::Adjacency;
use crate::real::{dot, sub};

/// Jacobi sweeps of the stripe energy.
pub const STRIPE_SWEEPS: usize = 96;

type Complex = [f64; 2];

fn mul(a: Complex, b: Complex) -> Complex {
    [a[0] * b[0] - a[1] * b[1], a[0] * b[1] + a[1] * b[0]]
}

fn turn(angle: f64) -> Complex {
    [angle.cos(), angle.sin()]
}

/// The phase's turn from vertex i to vertex j, radians.
fn edge_turn(p: &[[f64; 3]], x: &[[f64; 3]], i: usize, j: usize, frequency: f64) -> f64 {
    let mean: [f64; 3] = std::array::from_fn(|k| 0.5 * (x[i][k] + x[j][k]));
    frequency * dot(sub(p[j], p[i]), mean)
}

/// The stripe pattern of `positions` (one-rings `adj`) along the tangent field `x` (per vertex,
/// unit or zero), one stripe per `period` (in the positions' units). Returns psi per vertex:
/// unit complex numbers, phase in radians = arg(psi).
pub fn stripe_phase(
    positions: &[[f64; 3]],
    adj: &Adjacency,
    x: &[[f64; 3]],
    period: f64,
    cancel: &Cancel,
) -> Result<Vec<Complex>> {
    let n = positions.len();
    let frequency = std::f64::consts::TAU / period;
    // the phase integrated along a breadth-first tree, from the lowest index of each part
    let mut psi = vec![[1.0, 0.0]; n];
    adj.breadth_first(|i, j| psi[j] = mul(psi[i], turn(edge_turn(positions, x, i, j, frequency))));
    cancel.check()?;
    // each edge's turn, once (per one-ring slot), for the sweeps
    let turns: Vec<Complex> = (0..n)
        .into_par_iter()
        .flat_map_iter(|i| {
            adj.neighbours(i).iter().map(move |&j| turn(edge_turn(positions, x, j as usize, i, frequency)))
        })
        .collect();
    let mut next = psi.clone();
    for _ in 0..STRIPE_SWEEPS {
        cancel.check()?;
        next.par_iter_mut().enumerate().for_each(|(i, out)| {
            let ring = adj.neighbours(i);
            let slots = adj.slots(i);
            let own = psi[i];
            let mut acc = [own[0] * ring.len() as f64, own[1] * ring.len() as f64];
            for (&j, t) in ring.iter().zip(&turns[slots]) {
                let predicted = mul(psi[j as usize], *t);
                acc[0] += predicted[0];
                acc[1] += predicted[1];
            }
            let l = acc[0].hypot(acc[1]);
            *out = if l > 1e-12 { [acc[0] / l, acc[1] / l] } else { own };
        });
        std::mem::swap(&mut psi, &mut next);
    }
    Ok(psi)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn phase_step(psi: &[Complex], i: usize, j: usize) -> f64 {
        let (a, b) = (psi[i], psi[j]);
        // arg(b / a)
        (a[0] * b[1] - a[1] * b[0]).atan2(a[0] * b[0] + a[1] * b[1])
    }

    #[test]
    fn on_a_plane_the_phase_grows_along_the_field_at_the_frequency() {
        let (v, f) = crate::mesh::shapes::grid(20, 0.0, 0).unwrap();
        let adj = Adjacency::build(v.len(), &f).unwrap();
        let x = vec![[1.0, 0.0, 0.0]; v.len()];
        let period = 0.4;
        let psi = stripe_phase(&v, &adj, &x, period, Cancel::never()).unwrap();
        for i in 0..v.len() {
            for &j in adj.neighbours(i) {
                let j = j as usize;
                let want = std::f64::consts::TAU / period * (v[j][0] - v[i][0]);
                assert!((phase_step(&psi, i, j) - want).abs() < 1e-9, "edge {i}-{j}");
            }
        }
    }

    #[test]
    fn around_a_cylinder_the_stripes_close_without_a_seam() {
        // 2 pi around, a period that does not divide it: the pattern must adapt
        let (v, f) = crate::mesh::line_field::tests::cylinder(64, 16);
        let adj = Adjacency::build(v.len(), &f).unwrap();
        let x: Vec<[f64; 3]> = v.iter().map(|p| [-p[1], p[0], 0.0]).collect();
        let psi = stripe_phase(&v, &adj, &x, 2.0 * std::f64::consts::PI / 7.4, Cancel::never()).unwrap();
        // every edge turns the phase by close to the asked amount: no edge holds the mismatch
        let want = std::f64::consts::TAU / 64.0 * 7.4;
        let mut worst: f64 = 0.0;
        for i in 0..v.len() {
            for &j in adj.neighbours(i) {
                let j = j as usize;
                let around = x[i][0] * (v[j][0] - v[i][0]) + x[i][1] * (v[j][1] - v[i][1]);
                if around.abs() > 0.05 {
                    let step = phase_step(&psi, i, j) * around.signum();
                    worst = worst.max((step - want).abs() / want);
                }
            }
        }
        assert!(worst < 0.35, "an edge's phase step is off by {worst} of the asked step");
    }
}

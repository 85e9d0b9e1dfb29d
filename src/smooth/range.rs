//! Smoothing at any scale. Every method commutes with x -> 2^k x: the weights are scale-free,
//! the volume constraint is a ratio and the solver's tolerance is relative. Their intermediate
//! quantities are not: squared lengths and cross products grow as L^2 (L the largest
//! coordinate), |cross|^2 and the centre of mass's sums as L^4, and the neighbour sums as the
//! valence times L, so beyond about 1e75 or below 1e-75 they overflow or underflow in f64.
//! A mesh whose largest coordinate is outside [2^-200, 2^200] is therefore scaled by a power of
//! two so that it lies in [1, 2), smoothed, and scaled back. Scaling by a power of two is exact,
//! so the result is the same bits as an f64 with unlimited range would give (until the scaled
//! back result itself under- or overflows the dtype); vertices that did not move get their
//! input value back exactly. Float32 input never needs it: f32's whole range, squared twice,
//! fits in f64.

use rayon::prelude::*;

use crate::error::{Error, Result};
use crate::mesh::check_positions;
use crate::real::{Real, Vec3};

/// Largest coordinates below or above these are rescaled.
pub const LOW: f64 = pow2(-200);
pub const HIGH: f64 = pow2(200);

/// The largest absolute coordinate of `positions`, the scale smoothing works at, from one fast
/// pass that also checks them as every mesh argument is checked (`check_positions`, whose error
/// names what is wrong when the pass fails).
pub fn checked_scale<T: Real>(arg: &str, positions: &[Vec3<T>]) -> Result<f64> {
    match largest_if_finite(positions.as_flattened()).filter(|_| !positions.is_empty()) {
        Some(largest) => Ok(largest),
        None => check_positions(arg, positions).and_then(|()| {
            Err(Error::Internal(format!("{arg}: refused by the fast check but not by check_positions")))
        }),
    }
}

/// The largest absolute value in `flat`, or None if any value is NaN or infinite. One pass,
/// eight lanes at a time so that it vectorises: a finiteness check that also gives the scale.
pub fn largest_if_finite<T: Real>(flat: &[T]) -> Option<f64> {
    let (mut largest, mut finite) = ([0.0f64; 8], [true; 8]);
    let mut blocks = flat.chunks_exact(8);
    for block in &mut blocks {
        for l in 0..8 {
            let a = Real::to_f64(block[l]).abs();
            finite[l] &= a <= f64::MAX;
            largest[l] = if a > largest[l] { a } else { largest[l] };
        }
    }
    let mut ok = finite.iter().all(|&f| f);
    let mut m = largest.iter().fold(0.0f64, |m, &v| m.max(v));
    for &c in blocks.remainder() {
        let a = Real::to_f64(c).abs();
        ok &= a <= f64::MAX;
        m = m.max(a);
    }
    ok.then_some(m)
}

/// The largest absolute coordinate of finite positions, in parallel.
pub fn largest_coordinate<T: Real>(x: &[Vec3<T>]) -> f64 {
    x.as_flattened()
        .par_chunks(3 * 8192)
        .map(|c| largest_if_finite(c).unwrap_or(f64::INFINITY))
        .reduce(|| 0.0, f64::max)
}

/// A power-of-two scale 2^k, applied as two factors so that every |k| up to 1074 works.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Pow2 {
    k: i32,
}

/// 2^k for k in [-1022, 1023].
const fn pow2(k: i32) -> f64 {
    f64::from_bits(((k + 1023) as u64) << 52)
}

/// e with m = f 2^e, f in [1, 2), for any finite m > 0 (subnormals included).
fn exponent(m: f64) -> i32 {
    let bits = m.to_bits();
    match ((bits >> 52) & 0x7ff) as i32 {
        0 => 63 - bits.leading_zeros() as i32 - 1074,
        biased => biased - 1023,
    }
}

impl Pow2 {
    /// The scale that brings `x` into [1, 2) when its largest coordinate is outside
    /// [LOW, HIGH] (and not zero), or None when no scaling is needed. `largest` is that
    /// coordinate if the caller already has it (it saves a pass over `x`).
    pub fn to_fit<T: Real>(x: &[Vec3<T>], largest: Option<f64>) -> Option<Pow2> {
        if T::max_value().to_f64() < HIGH {
            return None; // f32: see the module docs
        }
        let m = largest.unwrap_or_else(|| largest_coordinate(x));
        if m == 0.0 || (LOW..=HIGH).contains(&m) {
            return None;
        }
        Some(Pow2 { k: -exponent(m) })
    }

    /// A length given at the input's scale, at the scaled mesh's scale (at most f64::MAX).
    pub fn length(self, v: f64) -> f64 {
        self.apply(v, 1).min(f64::MAX)
    }

    #[inline]
    fn apply(self, v: f64, sign: i32) -> f64 {
        let k = sign * self.k;
        let (a, b) = (k / 2, k - k / 2);
        v * pow2(a) * pow2(b)
    }

    pub fn scale<T: Real>(self, x: &[Vec3<T>]) -> Vec<Vec3<T>> {
        x.par_iter().map(|p| p.map(|c| T::from_f64(self.apply(c.to_f64(), 1)))).collect()
    }

    /// The result back at the input's scale: `out` was smoothed from `scaled`, the scaled
    /// `input`. A vertex that did not move gets its input value back exactly.
    pub fn restore<T: Real>(self, input: &[Vec3<T>], scaled: &[Vec3<T>], out: &mut [Vec3<T>]) {
        out.par_iter_mut().zip(scaled.par_iter().zip(input.par_iter())).for_each(|(o, (s, x))| {
            *o = if *o == *s { *x } else { o.map(|c| T::from_f64(self.apply(c.to_f64(), -1))) };
        });
    }
}

/// `smooth` run on `x` brought into range (see `Pow2::to_fit`, which takes `largest`), its result
/// back at `x`'s scale; `smooth` is told the scale it runs at, if any.
pub fn at_fitted_scale<T: Real>(
    x: &[Vec3<T>],
    largest: Option<f64>,
    smooth: impl FnOnce(&[Vec3<T>], Option<Pow2>) -> Result<Vec<Vec3<T>>>,
) -> Result<Vec<Vec3<T>>> {
    let Some(s) = Pow2::to_fit(x, largest) else { return smooth(x, None) };
    let scaled = s.scale(x);
    let mut out = smooth(&scaled, Some(s))?;
    s.restore(x, &scaled, &mut out);
    Ok(out)
}

/// Whether every coordinate is finite, in parallel.
pub fn all_finite<T: Real>(x: &[Vec3<T>]) -> bool {
    x.as_flattened().par_chunks(3 * 8192).all(|c| largest_if_finite(c).is_some())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn fits_extreme_meshes_into_one_to_two_exactly() {
        for m in [1e-320, 1e-300, 1e-61, 1e61, 1e300, f64::MAX] {
            let x = vec![[m, -m / 3.0, 0.0], [0.5 * m, 0.0, 1e-310]];
            let s = Pow2::to_fit(&x, None).expect("outside the safe range");
            let y = s.scale(&x);
            let top = largest_coordinate(&y);
            assert!((1.0..2.0).contains(&top), "{m}: {top}");
            let mut back = y.iter().map(|p| p.map(|c| c * 0.5)).collect::<Vec<_>>();
            s.restore(&x, &y, &mut back);
            assert_eq!(back[0][0], 0.5 * m, "{m}");
        }
        assert_eq!(Pow2::to_fit(&[[1e60f64, 0.0, 0.0]], None), None);
        assert_eq!(Pow2::to_fit(&[[0.0f64; 3]], None), None);
        assert_eq!(Pow2::to_fit(&[[f32::MAX, 0.0, 0.0]], None), None);
        for m in [f64::MIN_POSITIVE, 5e-324, 1e-310, 0.75, 1.0, 3.0, f64::MAX] {
            let e = exponent(m);
            assert!(m / 2f64.powi(e) >= 1.0 && m / 2f64.powi(e) < 2.0 || e < -1022, "{m}: {e}");
        }
        assert_eq!(exponent(5e-324), -1074);
    }

    #[test]
    fn largest_if_finite_sees_every_lane_and_the_tail() {
        for n in [1, 7, 8, 9, 17, 100] {
            for at in [0, n / 2, n - 1] {
                let mut v = vec![1.0f64; n];
                v[at] = -3.0;
                assert_eq!(largest_if_finite(&v), Some(3.0));
                for bad in [f64::NAN, f64::INFINITY, f64::NEG_INFINITY] {
                    v[at] = bad;
                    assert_eq!(largest_if_finite(&v), None, "{n} {at} {bad}");
                }
            }
        }
        assert_eq!(largest_if_finite::<f32>(&[]), Some(0.0));
    }

    #[test]
    fn unmoved_vertices_keep_their_exact_input() {
        // 1e-310 is lost when scaled down from 1e300, but a vertex that does not move is restored.
        let x = vec![[1e300, 0.0, 0.0], [1e-310, 2.0, 3.0]];
        let s = Pow2::to_fit(&x, None).unwrap();
        let y = s.scale(&x);
        let mut out = y.clone();
        s.restore(&x, &y, &mut out);
        assert_eq!(out, x);
    }
}

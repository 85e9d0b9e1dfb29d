//! The floating-point types the core computes in. Results keep the caller's precision, so every
//! numeric routine is generic over `Real` (f32 or f64).

use num_traits::Float;

use crate::error::{Error, Result};

pub trait Real: Float + Send + Sync + Default + std::fmt::Debug + std::iter::Sum + 'static {
    fn from_f64(x: f64) -> Self;
    fn to_f64(self) -> f64;
    /// Machine epsilon as f64, for tolerances stated relative to the dtype.
    const EPS: f64;
}

impl Real for f32 {
    fn from_f64(x: f64) -> Self {
        x as f32
    }
    fn to_f64(self) -> f64 {
        self as f64
    }
    const EPS: f64 = f32::EPSILON as f64;
}

impl Real for f64 {
    fn from_f64(x: f64) -> Self {
        x
    }
    fn to_f64(self) -> f64 {
        self
    }
    const EPS: f64 = f64::EPSILON;
}

pub type Vec3<T> = [T; 3];

#[inline]
pub fn sub<T: Real>(a: Vec3<T>, b: Vec3<T>) -> Vec3<T> {
    [a[0] - b[0], a[1] - b[1], a[2] - b[2]]
}

#[inline]
pub fn add<T: Real>(a: Vec3<T>, b: Vec3<T>) -> Vec3<T> {
    [a[0] + b[0], a[1] + b[1], a[2] + b[2]]
}

#[inline]
pub fn scale<T: Real>(a: Vec3<T>, s: T) -> Vec3<T> {
    [a[0] * s, a[1] * s, a[2] * s]
}

#[inline]
pub fn dot<T: Real>(a: Vec3<T>, b: Vec3<T>) -> T {
    a[0] * b[0] + a[1] * b[1] + a[2] * b[2]
}

#[inline]
pub fn cross<T: Real>(a: Vec3<T>, b: Vec3<T>) -> Vec3<T> {
    [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]]
}

#[inline]
pub fn norm<T: Real>(a: Vec3<T>) -> T {
    dot(a, a).sqrt()
}

/// Three finite numbers (a point or a direction): the argument `arg`, given as `v`.
pub fn finite3(arg: &str, v: &[f64]) -> Result<[f64; 3]> {
    let t: [f64; 3] =
        v.try_into().map_err(|_| Error::invalid(arg, format!("expected 3 numbers, got {}", v.len())))?;
    if !t.iter().all(|x| x.is_finite()) {
        return Err(Error::invalid(arg, format!("must be finite, got {t:?}")));
    }
    Ok(t)
}

/// Converts a position to f64 for accumulations that need the headroom.
#[inline]
pub fn to_f64<T: Real>(a: Vec3<T>) -> [f64; 3] {
    [a[0].to_f64(), a[1].to_f64(), a[2].to_f64()]
}

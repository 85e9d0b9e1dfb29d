//! 3x3 Sobel filters on 2-D images, in one pass per output row.
//!
//! Two conventions:
//! - `Skimage` (as `skimage.filters`): kernels [1, 0, -1] x [1, 2, 1] / 4, border 'reflect'
//!   (d c b a | a b c d), magnitude sqrt((h^2 + v^2) / 2) computed as sqrt(h^2 + v^2) / sqrt(2).
//! - `OpenCv` (as `cv2.Sobel` with ksize=3 and its default border): unnormalised kernels, border
//!   BORDER_REFLECT_101 (d c b | a b c d), magnitude sqrt(h^2 + v^2) as `cv2.magnitude`.
//!
//! `h` is the derivative along axis 0 (rows: the row below minus the row above, smoothed along
//! the row), `v` along axis 1 (the right neighbour minus the left). For each output row, the
//! vertical smoothing and difference of three input rows go into two row buffers, and the
//! horizontal pass reads them: one read of the image, one write of the result, loops the
//! compiler vectorises, and row bands in parallel.
//!
//! Range: h and v are finite whenever the image's values are below a quarter of the dtype's
//! largest value (beyond that the [1, 2, 1] sums overflow). The magnitude's squares overflow
//! for gradients above about 1e154 (float64) or 1.8e19 (float32) and lose digits below about
//! 1e-154 or 1e-19; a row where that happens is recomputed with a scaled hypot, so the
//! magnitude is finite and accurate wherever h and v are (scikit-image returns inf there).

use rayon::prelude::*;

use crate::error::{Error, Result};
use crate::real::Real;

#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Convention {
    Skimage,
    OpenCv,
}

impl Convention {
    pub fn parse(name: &str) -> Result<Self> {
        match name {
            "skimage" => Ok(Convention::Skimage),
            "opencv" => Ok(Convention::OpenCv),
            _ => Err(Error::invalid("convention", format!("must be 'skimage' or 'opencv', got {name:?}"))),
        }
    }
}

#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Output {
    /// Gradient magnitude.
    Magnitude,
    /// Derivative along axis 0 (`sobel_h`).
    AlongRows,
    /// Derivative along axis 1 (`sobel_v`).
    AlongColumns,
}

impl Output {
    /// "magnitude", "h" (`sobel_h`) or "v" (`sobel_v`).
    pub fn parse(name: &str) -> Result<Self> {
        match name {
            "magnitude" => Ok(Output::Magnitude),
            "h" => Ok(Output::AlongRows),
            "v" => Ok(Output::AlongColumns),
            _ => Err(Error::invalid("output", format!("unknown output {name:?}"))),
        }
    }
}

impl Convention {
    /// Where index -1 and index n land for an axis of length n.
    #[inline]
    fn borders(self, n: usize) -> (usize, usize) {
        match (self, n) {
            (_, 1) => (0, 0),
            (Convention::Skimage, _) => (0, n - 1),
            (Convention::OpenCv, _) => (1, n - 2),
        }
    }
}

/// Output rows per parallel task: big enough to amortise the row buffers, small enough to
/// balance two to many cores.
const BAND_ROWS: usize = 16;

/// Filters an `height` x `width` row-major image into `out` (same size).
pub fn sobel<T: Real>(
    image: &[T],
    height: usize,
    width: usize,
    out: &mut [T],
    output: Output,
    convention: Convention,
) -> Result<()> {
    if height == 0 || width == 0 {
        return Err(Error::invalid("image", format!("must not be empty, got shape ({height}, {width})")));
    }
    if image.len() != height * width || out.len() != height * width {
        return Err(Error::Internal("sobel: buffer sizes do not match the shape".into()));
    }
    let (up_border, down_border) = convention.borders(height);
    let (left_border, right_border) = convention.borders(width);
    let (scale, mag_div) = match convention {
        Convention::Skimage => (T::from_f64(0.25), T::from_f64(2f64.sqrt())),
        Convention::OpenCv => (T::one(), T::one()),
    };
    let k = Kernel { width, left_border, right_border, output, scale, mag_div };
    out.par_chunks_mut(BAND_ROWS * width).enumerate().for_each(|(band, out_band)| {
        let mut smooth = vec![T::zero(); width + 2];
        let mut diff = vec![T::zero(); width + 2];
        for (i, out_row) in out_band.chunks_exact_mut(width).enumerate() {
            let r = band * BAND_ROWS + i;
            let above = if r == 0 { up_border } else { r - 1 };
            let below = if r + 1 == height { down_border } else { r + 1 };
            let row = |i: usize| &image[i * width..(i + 1) * width];
            k.run(row(above), row(r), row(below), &mut smooth, &mut diff, out_row);
        }
    });
    Ok(())
}

/// One output row's work, with everything that is fixed per image.
struct Kernel<T> {
    width: usize,
    left_border: usize,
    right_border: usize,
    output: Output,
    scale: T,
    mag_div: T,
}

impl<T: Real> Kernel<T> {
    fn run(&self, above: &[T], mid: &[T], below: &[T], smooth: &mut [T], diff: &mut [T], out: &mut [T]) {
        #[cfg(target_arch = "x86_64")]
        {
            if std::arch::is_x86_feature_detected!("avx2") {
                // SAFETY: the CPU supports AVX2, checked just above.
                return unsafe { self.row_avx2(above, mid, below, smooth, diff, out) };
            }
        }
        self.row(above, mid, below, smooth, diff, out)
    }

    /// The same loops compiled for 8-wide f32 vectors. FMA stays off, so the rounding is the
    /// same as on the baseline path.
    #[cfg(target_arch = "x86_64")]
    #[target_feature(enable = "avx2")]
    unsafe fn row_avx2(
        &self,
        above: &[T],
        mid: &[T],
        below: &[T],
        smooth: &mut [T],
        diff: &mut [T],
        out: &mut [T],
    ) {
        self.row(above, mid, below, smooth, diff, out)
    }

    /// Vertical smoothing [1, 2, 1] and difference [-1, 0, 1] into padded row buffers, then the
    /// horizontal pass.
    #[inline(always)]
    fn row(&self, above: &[T], mid: &[T], below: &[T], smooth: &mut [T], diff: &mut [T], out: &mut [T]) {
        let w = self.width;
        let (above, mid, below, out) = (&above[..w], &mid[..w], &below[..w], &mut out[..w]);
        for (((s, d), (&a, &m)), &b) in
            smooth[1..w + 1].iter_mut().zip(diff[1..w + 1].iter_mut()).zip(above.iter().zip(mid)).zip(below)
        {
            *s = a + (m + m) + b;
            *d = b - a;
        }
        smooth[0] = smooth[1 + self.left_border];
        diff[0] = diff[1 + self.left_border];
        smooth[w + 1] = smooth[1 + self.right_border];
        diff[w + 1] = diff[1 + self.right_border];
        let (s0, s2) = (&smooth[0..w], &smooth[2..w + 2]);
        let (d0, d1, d2) = (&diff[0..w], &diff[1..w + 1], &diff[2..w + 2]);
        let (scale, mag_div) = (self.scale, self.mag_div);
        match self.output {
            Output::Magnitude => {
                let (tiny, huge) = (T::min_positive_value() / T::epsilon(), T::max_value());
                let mut out_of_range = false;
                for ((o, (&s0, &s2)), ((&d0, &d1), &d2)) in
                    out.iter_mut().zip(s0.iter().zip(s2)).zip(d0.iter().zip(d1).zip(d2))
                {
                    let v = (s2 - s0) * scale;
                    let h = (d0 + (d1 + d1) + d2) * scale;
                    let m2 = h * h + v * v;
                    // Squares that overflowed (from finite h and v) or lost digits to underflow.
                    out_of_range |= (m2 > huge) & (h.abs() <= huge) & (v.abs() <= huge)
                        | (m2 < tiny) & ((h != T::zero()) | (v != T::zero()));
                    *o = m2.sqrt() / mag_div;
                }
                if out_of_range {
                    self.scaled_magnitudes(s0, s2, d0, d1, d2, out);
                }
            }
            Output::AlongRows => {
                for (o, ((&d0, &d1), &d2)) in out.iter_mut().zip(d0.iter().zip(d1).zip(d2)) {
                    *o = (d0 + (d1 + d1) + d2) * scale;
                }
            }
            Output::AlongColumns => {
                for (o, (&s0, &s2)) in out.iter_mut().zip(s0.iter().zip(s2)) {
                    *o = (s2 - s0) * scale;
                }
            }
        }
    }
}

impl<T: Real> Kernel<T> {
    /// The magnitudes of one row as hypot(h, v) / mag_div with h and v scaled by their larger
    /// absolute value first, so that no square overflows or underflows. Rarely needed.
    #[cold]
    fn scaled_magnitudes(&self, s0: &[T], s2: &[T], d0: &[T], d1: &[T], d2: &[T], out: &mut [T]) {
        for (k, o) in out.iter_mut().enumerate() {
            let v = (s2[k] - s0[k]) * self.scale;
            let h = (d0[k] + (d1[k] + d1[k]) + d2[k]) * self.scale;
            let m = h.abs().max(v.abs());
            if m > T::zero() && m.is_finite() {
                let (h, v) = (h / m, v / m);
                *o = m * (h * h + v * v).sqrt() / self.mag_div;
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn unit_step_gives_known_values() {
        // 4x4, left half 0, right half 1
        let img: Vec<f64> = (0..16).map(|i| if i % 4 >= 2 { 1.0 } else { 0.0 }).collect();
        let mut out = vec![0.0; 16];
        sobel(&img, 4, 4, &mut out, Output::AlongColumns, Convention::Skimage).unwrap();
        assert_eq!(&out[0..4], &[0.0, 1.0, 1.0, 0.0]);
        sobel(&img, 4, 4, &mut out, Output::Magnitude, Convention::Skimage).unwrap();
        assert!((out[1] - 0.5f64.sqrt()).abs() < 1e-15);
        sobel(&img, 4, 4, &mut out, Output::AlongColumns, Convention::OpenCv).unwrap();
        assert_eq!(&out[0..4], &[0.0, 4.0, 4.0, 0.0]);
        sobel(&img, 4, 4, &mut out, Output::AlongRows, Convention::OpenCv).unwrap();
        assert!(out.iter().all(|&x| x == 0.0));
    }

    #[test]
    fn magnitude_stays_finite_and_accurate_where_squares_would_not() {
        let step = |s: f64| -> Vec<f64> { (0..16).map(|i| if i % 4 >= 2 { s } else { 0.0 }).collect() };
        for s in [1e-300, 1e-160, 1.0, 1e160, 1e300] {
            let mut out = vec![0.0; 16];
            sobel(&step(s), 4, 4, &mut out, Output::Magnitude, Convention::Skimage).unwrap();
            let want = 0.5f64.sqrt() * s;
            assert!((out[1] - want).abs() <= 4.0 * f64::EPSILON * want, "{s}: {} vs {want}", out[1]);
        }
        let img: Vec<f32> = (0..16).map(|i| if i % 4 >= 2 { 1e30 } else { 0.0 }).collect();
        let mut out = vec![0.0f32; 16];
        sobel(&img, 4, 4, &mut out, Output::Magnitude, Convention::OpenCv).unwrap();
        assert_eq!(out[1], 4e30);
    }

    #[test]
    fn single_row_and_column() {
        let img = [0.0f32, 1.0, 3.0];
        let mut out = [0.0f32; 3];
        sobel(&img, 1, 3, &mut out, Output::AlongColumns, Convention::Skimage).unwrap();
        assert_eq!(out, [1.0, 3.0, 2.0]);
        sobel(&img, 3, 1, &mut out, Output::AlongColumns, Convention::Skimage).unwrap();
        assert_eq!(out, [0.0; 3]);
        assert!(sobel(&[] as &[f32], 0, 3, &mut [], Output::Magnitude, Convention::Skimage).is_err());
    }
}

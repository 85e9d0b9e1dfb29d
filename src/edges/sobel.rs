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

use rayon::prelude::*;

use crate::error::{Error, Result};
use crate::real::Real;

#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Convention {
    Skimage,
    OpenCv,
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
        return Err(Error::invalid(
            "image",
            format!("must not be empty, got shape ({height}, {width})"),
        ));
    }
    if image.len() != height * width || out.len() != height * width {
        return Err(Error::Internal(
            "sobel: buffer sizes do not match the shape".into(),
        ));
    }
    let (up_border, down_border) = convention.borders(height);
    let (left_border, right_border) = convention.borders(width);
    let (scale, mag_div) = match convention {
        Convention::Skimage => (T::from_f64(0.25), T::from_f64(2f64.sqrt())),
        Convention::OpenCv => (T::one(), T::one()),
    };
    out.par_chunks_mut(BAND_ROWS * width)
        .enumerate()
        .for_each(|(band, out_band)| {
            let mut smooth = vec![T::zero(); width + 2];
            let mut diff = vec![T::zero(); width + 2];
            for (k, out_row) in out_band.chunks_exact_mut(width).enumerate() {
                let r = band * BAND_ROWS + k;
                let above = if r == 0 { up_border } else { r - 1 };
                let below = if r + 1 == height { down_border } else { r + 1 };
                let row = |i: usize| &image[i * width..(i + 1) * width];
                let (a, m, b) = (row(above), row(r), row(below));
                for (((s, d), (&a, &m)), &b) in smooth[1..width + 1]
                    .iter_mut()
                    .zip(diff[1..width + 1].iter_mut())
                    .zip(a.iter().zip(m))
                    .zip(b)
                {
                    *s = a + (m + m) + b;
                    *d = b - a;
                }
                smooth[0] = smooth[1 + left_border];
                diff[0] = diff[1 + left_border];
                smooth[width + 1] = smooth[1 + right_border];
                diff[width + 1] = diff[1 + right_border];
                let (s0, s2) = (&smooth[0..width], &smooth[2..width + 2]);
                let (d0, d1, d2) = (&diff[0..width], &diff[1..width + 1], &diff[2..width + 2]);
                match output {
                    Output::Magnitude => {
                        for ((o, (&s0, &s2)), ((&d0, &d1), &d2)) in out_row
                            .iter_mut()
                            .zip(s0.iter().zip(s2))
                            .zip(d0.iter().zip(d1).zip(d2))
                        {
                            let v = (s2 - s0) * scale;
                            let h = (d0 + (d1 + d1) + d2) * scale;
                            *o = (h * h + v * v).sqrt() / mag_div;
                        }
                    }
                    Output::AlongRows => {
                        for (o, ((&d0, &d1), &d2)) in
                            out_row.iter_mut().zip(d0.iter().zip(d1).zip(d2))
                        {
                            *o = (d0 + (d1 + d1) + d2) * scale;
                        }
                    }
                    Output::AlongColumns => {
                        for (o, (&s0, &s2)) in out_row.iter_mut().zip(s0.iter().zip(s2)) {
                            *o = (s2 - s0) * scale;
                        }
                    }
                }
            }
        });
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn unit_step_gives_known_values() {
        // 4x4, left half 0, right half 1
        let img: Vec<f64> = (0..16)
            .map(|i| if i % 4 >= 2 { 1.0 } else { 0.0 })
            .collect();
        let mut out = vec![0.0; 16];
        sobel(
            &img,
            4,
            4,
            &mut out,
            Output::AlongColumns,
            Convention::Skimage,
        )
        .unwrap();
        assert_eq!(&out[0..4], &[0.0, 1.0, 1.0, 0.0]);
        sobel(&img, 4, 4, &mut out, Output::Magnitude, Convention::Skimage).unwrap();
        assert!((out[1] - 0.5f64.sqrt()).abs() < 1e-15);
        sobel(
            &img,
            4,
            4,
            &mut out,
            Output::AlongColumns,
            Convention::OpenCv,
        )
        .unwrap();
        assert_eq!(&out[0..4], &[0.0, 4.0, 4.0, 0.0]);
        sobel(&img, 4, 4, &mut out, Output::AlongRows, Convention::OpenCv).unwrap();
        assert!(out.iter().all(|&x| x == 0.0));
    }

    #[test]
    fn single_row_and_column() {
        let img = [0.0f32, 1.0, 3.0];
        let mut out = [0.0f32; 3];
        sobel(
            &img,
            1,
            3,
            &mut out,
            Output::AlongColumns,
            Convention::Skimage,
        )
        .unwrap();
        assert_eq!(out, [1.0, 3.0, 2.0]);
        sobel(
            &img,
            3,
            1,
            &mut out,
            Output::AlongColumns,
            Convention::Skimage,
        )
        .unwrap();
        assert_eq!(out, [0.0; 3]);
        assert!(sobel(
            &[] as &[f32],
            0,
            3,
            &mut [],
            Output::Magnitude,
            Convention::Skimage
        )
        .is_err());
    }
}

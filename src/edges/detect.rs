//! The image-space outline rule of Borquez and Yepez: 3x3 Sobel on a normal or depth buffer,
//! an edge where max(|Gx|, |Gy|) exceeds that buffer's own threshold.
//!
//! Gx and Gy use the paper's unnormalised kernels (a unit step gives 4) with the 'reflect'
//! border, so the image border never makes an edge by itself. For a buffer with several
//! channels the gradient is the largest over channels.
//!
//! Background: a pixel is background when any of its channels is not finite (an infinite or
//! NaN depth, a NaN normal). A pixel whose 3x3 window mixes background and foreground gets an
//! infinite gradient (the outline of the object against the background is always an edge); a
//! pixel whose window is all background gets 0.

use rayon::prelude::*;

/// Default thresholds of the rule: a normal threshold of 1 finds turns of about 15 degrees
/// between neighbouring pixels; a depth threshold of 0.1 finds steps of 0.025 depth units.
pub const DEFAULT_NORMAL_THRESHOLD: f64 = 1.0;
pub const DEFAULT_DEPTH_THRESHOLD: f64 = 0.1;

use crate::error::{Error, Result};
use crate::real::Real;

/// An edge mask: where the gradient exceeds `threshold`, which must be a finite number >= 0
/// (NaN would mark nothing and a negative threshold every pixel). `arg` names it in errors.
pub fn threshold_mask<T: Real>(arg: &str, gradient: &[T], threshold: f64) -> Result<Vec<bool>> {
    if !(threshold.is_finite() && threshold >= 0.0) {
        return Err(Error::invalid(arg, format!("must be a finite number >= 0, got {threshold}")));
    }
    Ok(gradient.par_iter().map(|&g| Real::to_f64(g) > threshold).collect())
}

/// max over channels of max(|Gx|, |Gy|) for an `height` x `width` x `channels` row-major buffer.
pub fn paper_gradient<T: Real>(buffer: &[T], height: usize, width: usize, channels: usize) -> Result<Vec<T>> {
    if height == 0 || width == 0 || channels == 0 {
        return Err(Error::invalid(
            "buffer",
            format!("must not be empty, got shape ({height}, {width}, {channels})"),
        ));
    }
    if buffer.len() != height * width * channels {
        return Err(Error::Internal("paper_gradient: buffer size does not match the shape".into()));
    }
    let reflect = |i: isize, n: usize| -> usize {
        if i < 0 {
            0
        } else if i as usize >= n {
            n - 1
        } else {
            i as usize
        }
    };
    let background: Vec<bool> =
        buffer.par_chunks(channels).map(|px| px.iter().any(|x| !x.is_finite())).collect();
    let mut out = vec![T::zero(); height * width];
    out.par_chunks_mut(width).enumerate().for_each(|(r, out_row)| {
        let rows = [reflect(r as isize - 1, height), r, reflect(r as isize + 1, height)];
        for (c, o) in out_row.iter_mut().enumerate() {
            let cols = [reflect(c as isize - 1, width), c, reflect(c as isize + 1, width)];
            let mut n_background = 0;
            for &rr in &rows {
                for &cc in &cols {
                    n_background += background[rr * width + cc] as usize;
                }
            }
            if n_background == 9 {
                continue;
            }
            if n_background > 0 {
                *o = T::infinity();
                continue;
            }
            let at = |rr: usize, cc: usize, k: usize| buffer[(rr * width + cc) * channels + k];
            let two = T::from_f64(2.0);
            let mut best = T::zero();
            for k in 0..channels {
                // Sx = [[1, 0, -1], [2, 0, -2], [1, 0, -1]], Sy = [[1, 2, 1], [0, 0, 0], [-1, -2, -1]]
                let gx = (at(rows[0], cols[0], k) - at(rows[0], cols[2], k))
                    + two * (at(rows[1], cols[0], k) - at(rows[1], cols[2], k))
                    + (at(rows[2], cols[0], k) - at(rows[2], cols[2], k));
                let gy = (at(rows[0], cols[0], k) - at(rows[2], cols[0], k))
                    + two * (at(rows[0], cols[1], k) - at(rows[2], cols[1], k))
                    + (at(rows[0], cols[2], k) - at(rows[2], cols[2], k));
                best = best.max(gx.abs()).max(gy.abs());
            }
            *o = best;
        }
    });
    Ok(out)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn step_and_background() {
        // 3x4 depth: 1 on the left, 2 on the right, inf in the last column
        let d = [1.0, 1.0, 2.0, f64::INFINITY].repeat(3);
        let g = paper_gradient(&d, 3, 4, 1).unwrap();
        assert_eq!(&g[0..4], &[0.0, 4.0, f64::INFINITY, f64::INFINITY]);
        let all_bg = [f64::NAN; 4];
        assert_eq!(paper_gradient(&all_bg, 2, 2, 1).unwrap(), vec![0.0; 4]);
        assert_eq!(threshold_mask("t", &g[0..4], 2.0).unwrap(), vec![false, true, true, true]);
        for bad in [f64::NAN, -1.0, f64::INFINITY] {
            assert!(threshold_mask("t", &g, bad).is_err());
        }
    }
}

//! A grey image a setting holds (a paper's grain): one value in [0, 1] a pixel, row by row.

use serde::{Deserialize, Serialize};

use crate::error::{Error, Result};

/// The largest side of an image a setting takes.
pub const MAX_IMAGE_SIDE: usize = 4096;

#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct GreyImage {
    pub width: u32,
    pub height: u32,
    /// Row by row, top row first.
    pub values: Vec<f32>,
}

impl GreyImage {
    /// From an (H, W) or (H, W, C) array's values in row-major order, each divided by `full`
    /// (255 for 8-bit images, 1 for floats). One or two channels (grey, alpha) give the first;
    /// three or four (RGB, alpha) the mean of the colour channels; alpha is not used.
    pub fn from_pixels(arg: &str, shape: &[usize], values: &[f64], full: f64) -> Result<GreyImage> {
        let channels = match shape.len() {
            2 => 1,
            3 => shape[2],
            n => {
                return Err(Error::invalid(
                    arg,
                    format!("expected an (H, W) or (H, W, C) array, got {n} dimensions"),
                ))
            }
        };
        let (height, width) = (shape[0], shape[1]);
        if !(1..=4).contains(&channels) {
            return Err(Error::invalid(arg, format!("expected 1 to 4 channels, got {channels}")));
        }
        if !(1..=MAX_IMAGE_SIDE).contains(&width) || !(1..=MAX_IMAGE_SIDE).contains(&height) {
            return Err(Error::invalid(
                arg,
                format!("expected sides of 1 to {MAX_IMAGE_SIDE} pixels, got {height} x {width}"),
            ));
        }
        if let Some(k) = values.iter().position(|v| !(v.is_finite() && (0.0..=full).contains(v))) {
            let (i, j) = (k / channels / width, k / channels % width);
            return Err(Error::invalid(
                format!("{arg}[{i}, {j}]"),
                format!("values must be in [0, {full}], got {}", values[k]),
            ));
        }
        let colour = if channels >= 3 { 3 } else { 1 };
        let values = values
            .chunks_exact(channels)
            .map(|px| (px[..colour].iter().sum::<f64>() / (colour as f64 * full)) as f32)
            .collect();
        Ok(GreyImage { width: width as u32, height: height as u32, values })
    }

    /// The value at column `x`, row `y`.
    pub fn at(&self, x: usize, y: usize) -> f32 {
        self.values[y * self.width as usize + x]
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn colour_channels_average_and_bad_values_are_placed() {
        let g = GreyImage::from_pixels(
            "grain",
            &[1, 2, 4],
            &[255.0, 0.0, 0.0, 9.0, 51.0, 51.0, 51.0, 0.0],
            255.0,
        )
        .unwrap();
        assert_eq!(g.values, vec![1.0 / 3.0, 0.2]);
        let e = GreyImage::from_pixels("grain", &[2, 2], &[0.0, 0.5, 1.5, 0.0], 1.0).unwrap_err();
        assert!(e.to_string().starts_with("grain[1, 0]: values must be in [0, 1]"), "{e}");
    }
}

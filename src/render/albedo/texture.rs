//! A texture image and its mip chain, made on the host with a 2x2 box filter in linear light
//! (the GPU samples these levels; `sampling` reads the same ones on the CPU).

use rayon::prelude::*;

use crate::error::{Error, Result};
use crate::render::color::{linear_to_srgb, srgb_to_linear};

/// An RGBA image of 8-bit sRGB codes (alpha linear), rows top first: v = 0 is the top row.
#[derive(Clone, Debug, PartialEq)]
pub struct Texture {
    pub width: u32,
    pub height: u32,
    pub texels: Vec<[u8; 4]>,
}

/// The linear value of each 8-bit sRGB code.
pub fn decode_table() -> &'static [f32; 256] {
    static TABLE: std::sync::OnceLock<[f32; 256]> = std::sync::OnceLock::new();
    TABLE.get_or_init(|| std::array::from_fn(|i| srgb_to_linear(i as f64 / 255.0) as f32))
}

/// A texel in linear light (alpha as stored).
pub fn linear(t: [u8; 4]) -> [f32; 4] {
    let d = decode_table();
    [d[t[0] as usize], d[t[1] as usize], d[t[2] as usize], t[3] as f32 / 255.0]
}

fn encode(c: [f32; 4]) -> [u8; 4] {
    let e = |x: f32| (linear_to_srgb(x as f64) * 255.0).round() as u8;
    [e(c[0]), e(c[1]), e(c[2]), (c[3].clamp(0.0, 1.0) * 255.0).round() as u8]
}

impl Texture {
    pub fn new(width: u32, height: u32, texels: Vec<[u8; 4]>) -> Result<Self> {
        if width == 0 || height == 0 {
            return Err(Error::invalid("texture", format!("is empty ({height} x {width} pixels)")));
        }
        if texels.len() != width as usize * height as usize {
            return Err(Error::Internal("texture: texel count does not match its size".into()));
        }
        Ok(Texture { width, height, texels })
    }

    /// An image of `shape` (H, W, 3 or 4 channels), rows top first, from its 8-bit codes (alpha
    /// 255 when absent).
    pub fn from_codes(shape: &[usize], codes: &[u8]) -> Result<Self> {
        let too_large = || Error::invalid("texture", format!("{shape:?} is too large"));
        let h = u32::try_from(shape[0]).map_err(|_| too_large())?;
        let w = u32::try_from(shape[1]).map_err(|_| too_large())?;
        let texels =
            codes.chunks_exact(shape[2]).map(|c| [c[0], c[1], c[2], c.get(3).copied().unwrap_or(255)]);
        Texture::new(w, h, texels.collect())
    }

    /// The same from channel values in [0, 1], each rounded to the nearest code.
    pub fn from_unit(shape: &[usize], values: &[f32]) -> Result<Self> {
        let codes: Vec<u8> = values.iter().map(|&x| (x * 255.0).round() as u8).collect();
        Texture::from_codes(shape, &codes)
    }

    pub fn at(&self, x: u32, y: u32) -> [u8; 4] {
        self.texels[(y * self.width + x) as usize]
    }

    /// The next level: half the size (rounded down, at least 1), each texel the mean of the
    /// 2x2 block it covers in linear light (the last row or column repeated on odd sizes).
    pub fn half(&self) -> Texture {
        let (w, h) = ((self.width / 2).max(1), (self.height / 2).max(1));
        let texels = (0..h)
            .into_par_iter()
            .flat_map_iter(|y| (0..w).map(move |x| (x, y)))
            .map(|(x, y)| {
                let mut sum = [0f32; 4];
                for (dx, dy) in [(0, 0), (1, 0), (0, 1), (1, 1)] {
                    let sx = (2 * x + dx).min(self.width - 1);
                    let sy = (2 * y + dy).min(self.height - 1);
                    let t = linear(self.at(sx, sy));
                    (0..4).for_each(|k| sum[k] += 0.25 * t[k]);
                }
                encode(sum)
            })
            .collect();
        Texture { width: w, height: h, texels }
    }

    /// Halved until both sides are at most `max` texels: a texture larger than the device holds.
    pub fn fitted(self, max: u32) -> Texture {
        let mut t = self;
        while t.width > max || t.height > max {
            t = t.half();
        }
        t
    }

    /// This image and every smaller level down to 1 x 1.
    pub fn mip_chain(&self) -> Vec<Texture> {
        let mut levels = vec![self.clone()];
        while let Some(last) = levels.last().filter(|t| t.width > 1 || t.height > 1) {
            let next = last.half();
            levels.push(next);
        }
        levels
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn mip_levels_halve_down_to_one_texel_and_average_in_linear_light() {
        let t = Texture::new(5, 2, vec![[255, 0, 0, 255], [0, 0, 0, 0]].repeat(5)).unwrap();
        let chain = t.mip_chain();
        let sizes: Vec<(u32, u32)> = chain.iter().map(|l| (l.width, l.height)).collect();
        assert_eq!(sizes, vec![(5, 2), (2, 1), (1, 1)]);
        // black and red side by side average to half the light, not half the code
        let mid = chain[1].at(0, 0);
        assert_eq!(mid[0], (linear_to_srgb(0.5) * 255.0).round() as u8);
        assert_eq!(mid[3], 128);
    }

    #[test]
    fn a_texture_too_large_is_halved_until_it_fits() {
        let t = Texture::new(300, 40, vec![[9, 9, 9, 9]; 12000]).unwrap().fitted(128);
        assert_eq!((t.width, t.height), (75, 10));
    }
}

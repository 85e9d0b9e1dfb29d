//! The grain: a tile of heights in [0, 1], wrapped around at its edges, read between texels
//! (`grain_at`, the CPU twin of paper.wgsl's) on the screen or on the three axis planes of the
//! surface (`surface_grain`). The built-in grain is value noise of three octaves, made once.

use std::sync::{Arc, OnceLock};

use glam::Vec3;

use crate::render::settings::GreyImage;

/// The built-in grain's side in texels (a multiple of its coarsest octave, so that it tiles).
pub const PROCEDURAL_SIDE: u32 = 256;
/// The noise's values below which the paper is all valley, and above which all peak (its median
/// is about 0.5).
const VALLEYS: f64 = 0.3;
const PEAKS: f64 = 0.5;
/// Its octaves: lattice spacing in texels, and weight (mostly the finest: a paper's tooth).
const OCTAVES: [(u32, f64); 3] = [(1, 0.45), (2, 0.35), (4, 0.2)];

/// A hash of a lattice point to [0, 1).
fn hash(x: u32, y: u32, octave: u32) -> f64 {
    let mut h = x.wrapping_mul(0x8da6_b343) ^ y.wrapping_mul(0xd816_3841) ^ octave.wrapping_mul(0xcb1a_b31f);
    h ^= h >> 15;
    h = h.wrapping_mul(0x2c1b_3c6d);
    h ^= h >> 12;
    h = h.wrapping_mul(0x297a_2d39);
    h ^= h >> 15;
    h as f64 / 4_294_967_296.0
}

/// The built-in grain: value noise (smoothly interpolated random heights on a lattice) of three
/// octaves, stretched to fill [0, 1], then a smooth step from `VALLEYS` to `PEAKS`: about half
/// the paper is peak, which takes all the pigment, and its valleys are narrow, as a paper's
/// tooth (so that ink stays ink, speckled, instead of turning grey).
pub fn procedural() -> Arc<GreyImage> {
    static TILE: OnceLock<Arc<GreyImage>> = OnceLock::new();
    TILE.get_or_init(|| {
        let n = PROCEDURAL_SIDE;
        let smooth = |t: f64| t * t * (3.0 - 2.0 * t);
        let mut values: Vec<f64> = (0..n * n)
            .map(|k| {
                let (x, y) = (k % n, k / n);
                OCTAVES
                    .iter()
                    .enumerate()
                    .map(|(o, &(step, weight))| {
                        let cells = n / step;
                        let (cx, cy) = (x / step, y / step);
                        let (fx, fy) = (
                            smooth((x % step) as f64 / step as f64),
                            smooth((y % step) as f64 / step as f64),
                        );
                        let at = |i: u32, j: u32| hash(i % cells, j % cells, o as u32);
                        let top = at(cx, cy) + (at(cx + 1, cy) - at(cx, cy)) * fx;
                        let bottom = at(cx, cy + 1) + (at(cx + 1, cy + 1) - at(cx, cy + 1)) * fx;
                        weight * (top + (bottom - top) * fy)
                    })
                    .sum()
            })
            .collect();
        let (lo, hi) = values.iter().fold((f64::MAX, f64::MIN), |(a, b), &v| (a.min(v), b.max(v)));
        let step = |v: f64| smooth(((v - VALLEYS) / (PEAKS - VALLEYS)).clamp(0.0, 1.0));
        values.iter_mut().for_each(|v| *v = step((*v - lo) / (hi - lo)));
        Arc::new(GreyImage { width: n, height: n, values: values.into_iter().map(|v| v as f32).collect() })
    })
    .clone()
}

/// The grain at (u, v) in texels (texel centres at half-integers), blended between the four
/// nearest texels and wrapped around the tile: `grain_at` in paper.wgsl, in the same f32 steps.
pub fn grain_at(tile: &GreyImage, u: f32, v: f32) -> f32 {
    let (w, h) = (tile.width as f32, tile.height as f32);
    // wrapped first, so that far coordinates keep their fraction
    let (su, sv) = (u - w * (u / w).floor() - 0.5, v - h * (v / h).floor() - 0.5);
    let (iu, iv) = (su.floor(), sv.floor());
    let (fu, fv) = (su - iu, sv - iv);
    let texel = |x: i32, y: i32| {
        let (tw, th) = (tile.width as i32, tile.height as i32);
        tile.at(x.rem_euclid(tw) as usize, y.rem_euclid(th) as usize)
    };
    let (x, y) = (iu as i32, iv as i32);
    let a = texel(x, y) + (texel(x + 1, y) - texel(x, y)) * fu;
    let b = texel(x, y + 1) + (texel(x + 1, y + 1) - texel(x, y + 1)) * fu;
    a + (b - a) * fv
}

/// The grain on a surface at `q` (grain texels from the scene's centre) with unit normal `n`
/// (world axes): the three axis planes' grain weighted by the normal's squared components
/// (which sum to 1). `surface_grain` in paper.wgsl.
pub fn surface_grain(tile: &GreyImage, q: Vec3, n: Vec3) -> f32 {
    let w = n * n;
    w.x * grain_at(tile, q.y, q.z) + w.y * grain_at(tile, q.z, q.x) + w.z * grain_at(tile, q.x, q.y)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_procedural_grain_fills_the_range_and_tiles() {
        let t = procedural();
        let (lo, hi) = t.values.iter().fold((1.0f32, 0.0f32), |(a, b), &v| (a.min(v), b.max(v)));
        assert!(lo == 0.0 && hi == 1.0);
        let mean = t.values.iter().sum::<f32>() / t.values.len() as f32;
        assert!((0.6..0.9).contains(&mean), "{mean}");
        // read across the tile's edge as inside it
        let n = PROCEDURAL_SIDE as f32;
        assert!((grain_at(&t, 0.2, 3.0) - grain_at(&t, n + 0.2, 3.0)).abs() < 1e-4);
        assert_eq!(grain_at(&t, 10.5, 20.5), t.at(10, 20));
    }
}

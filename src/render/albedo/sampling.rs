//! How a texture is read (glTF's sampler): the filter, the wrap mode and the alpha cutoff, and
//! the CPU twin of the GPU's sampling: wrap, nearest or bilinear texels, and the mip level from
//! the texture coordinates' change across a pixel (trilinear between two levels).

use serde::{Deserialize, Serialize};

use crate::error::{Error, Result};

use super::texture::{linear, Texture};

/// glTF's filters: `Linear` is LINEAR magnification with LINEAR_MIPMAP_LINEAR minification
/// (trilinear, the smooth default); `Nearest` reads the nearest texel of the full-size image
/// (NEAREST / NEAREST: hard texel edges, as pixel art wants).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash, Serialize, Deserialize)]
pub enum Filter {
    #[default]
    Linear,
    Nearest,
}

/// glTF's wrap modes, the same on both axes: REPEAT, CLAMP_TO_EDGE, MIRRORED_REPEAT.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash, Serialize, Deserialize)]
pub enum Wrap {
    #[default]
    Repeat,
    Clamp,
    Mirror,
}

impl Filter {
    pub const NAMES: [&'static str; 2] = ["linear", "nearest"];

    pub fn parse(arg: &str, s: &str) -> Result<Self> {
        match s {
            "linear" => Ok(Self::Linear),
            "nearest" => Ok(Self::Nearest),
            other => Err(Error::invalid(arg, format!("must be 'linear' or 'nearest', got {other:?}"))),
        }
    }

    pub fn name(self) -> &'static str {
        Self::NAMES[self as usize]
    }
}

impl Wrap {
    pub const NAMES: [&'static str; 3] = ["repeat", "clamp", "mirror"];

    pub fn parse(arg: &str, s: &str) -> Result<Self> {
        match s {
            "repeat" => Ok(Self::Repeat),
            "clamp" => Ok(Self::Clamp),
            "mirror" => Ok(Self::Mirror),
            other => {
                Err(Error::invalid(arg, format!("must be 'repeat', 'clamp' or 'mirror', got {other:?}")))
            }
        }
    }

    pub fn name(self) -> &'static str {
        Self::NAMES[self as usize]
    }

    /// The texel index that index `i` reads on an axis of `n` texels.
    pub fn index(self, i: i64, n: u32) -> u32 {
        let n = n as i64;
        (match self {
            Wrap::Repeat => i.rem_euclid(n),
            Wrap::Clamp => i.clamp(0, n - 1),
            Wrap::Mirror => {
                let m = i.rem_euclid(2 * n);
                if m < n {
                    m
                } else {
                    2 * n - 1 - m
                }
            }
        }) as u32
    }
}

/// A mesh's texture settings.
#[derive(Clone, Copy, Debug, Default, PartialEq, Serialize, Deserialize)]
pub struct Sampling {
    pub filter: Filter,
    pub wrap: Wrap,
    /// glTF's alpha mask: pixels whose alpha (colour alpha x texture alpha) is below this are
    /// not drawn. None: alpha is ignored (glTF's OPAQUE).
    pub alpha_cutoff: Option<f32>,
    /// glTF's alpha blend: the alpha (colour alpha x texture alpha) multiplies the material's
    /// opacity, and the mesh is drawn as glass (`passes::glass`).
    #[serde(default)]
    pub alpha_blend: bool,
}

impl Sampling {
    pub fn check(&self) -> Result<()> {
        match self.alpha_cutoff {
            Some(c) if !(0.0..=1.0).contains(&c) => {
                Err(Error::invalid("alpha_cutoff", format!("must be in [0, 1], got {c}")))
            }
            _ => Ok(()),
        }
    }
}

/// Texel (x, y) of `level` after wrapping, in linear light.
fn texel(level: &Texture, x: i64, y: i64, wrap: Wrap) -> [f32; 4] {
    linear(level.at(wrap.index(x, level.width), wrap.index(y, level.height)))
}

/// The nearest texel to (u, v) on `level`.
pub fn nearest(level: &Texture, uv: [f32; 2], wrap: Wrap) -> [f32; 4] {
    let x = (uv[0] as f64 * level.width as f64).floor() as i64;
    let y = (uv[1] as f64 * level.height as f64).floor() as i64;
    texel(level, x, y, wrap)
}

/// The four texels around (u, v) on `level`, weighted by their distance (texel centres at
/// half-integers).
pub fn bilinear(level: &Texture, uv: [f32; 2], wrap: Wrap) -> [f32; 4] {
    let x = uv[0] as f64 * level.width as f64 - 0.5;
    let y = uv[1] as f64 * level.height as f64 - 0.5;
    let (x0, y0) = (x.floor(), y.floor());
    let (fx, fy) = ((x - x0) as f32, (y - y0) as f32);
    let (x0, y0) = (x0 as i64, y0 as i64);
    let mut c = [0f32; 4];
    for (dx, dy, w) in
        [(0, 0, (1.0 - fx) * (1.0 - fy)), (1, 0, fx * (1.0 - fy)), (0, 1, (1.0 - fx) * fy), (1, 1, fx * fy)]
    {
        let t = texel(level, x0 + dx, y0 + dy, wrap);
        (0..4).for_each(|k| c[k] += w * t[k]);
    }
    c
}

/// The mip level (fractional) for texture coordinates that change by `dx` and `dy` across one
/// pixel in x and y: log2 of the longer change in texels of the full-size image.
pub fn level_of_detail(full: &Texture, dx: [f32; 2], dy: [f32; 2]) -> f32 {
    let texels = |d: [f32; 2]| (d[0] * full.width as f32).hypot(d[1] * full.height as f32);
    texels(dx).max(texels(dy)).max(f32::MIN_POSITIVE).log2()
}

/// The linear RGBA the GPU reads from the mip chain `levels` at (u, v), the coordinates
/// changing by `dx` and `dy` across a pixel.
pub fn sample(levels: &[Texture], uv: [f32; 2], dx: [f32; 2], dy: [f32; 2], s: &Sampling) -> [f32; 4] {
    match s.filter {
        Filter::Nearest => nearest(&levels[0], uv, s.wrap),
        Filter::Linear => {
            let lod = level_of_detail(&levels[0], dx, dy).clamp(0.0, (levels.len() - 1) as f32);
            let lo = lod.floor() as usize;
            let f = lod - lo as f32;
            let a = bilinear(&levels[lo], uv, s.wrap);
            if f == 0.0 {
                return a;
            }
            let b = bilinear(&levels[lo + 1], uv, s.wrap);
            std::array::from_fn(|k| a[k] + f * (b[k] - a[k]))
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn wrap_modes_index_as_gltf_says() {
        let at = |w: Wrap| (-3..7).map(|i| w.index(i, 3)).collect::<Vec<_>>();
        assert_eq!(at(Wrap::Repeat), vec![0, 1, 2, 0, 1, 2, 0, 1, 2, 0]);
        assert_eq!(at(Wrap::Clamp), vec![0, 0, 0, 0, 1, 2, 2, 2, 2, 2]);
        assert_eq!(at(Wrap::Mirror), vec![2, 1, 0, 0, 1, 2, 2, 1, 0, 0]);
    }

    #[test]
    fn bilinear_is_exact_at_texel_centres_and_halfway_between() {
        let t = Texture::new(2, 1, vec![[0, 0, 0, 0], [255, 255, 255, 255]]).unwrap();
        assert_eq!(bilinear(&t, [0.25, 0.5], Wrap::Clamp), [0.0; 4]);
        assert_eq!(bilinear(&t, [0.5, 0.5], Wrap::Clamp), [0.5; 4]);
        // repeat wraps the left edge onto the right texel
        assert_eq!(bilinear(&t, [0.0, 0.5], Wrap::Repeat), [0.5; 4]);
        assert_eq!(nearest(&t, [0.74, 0.5], Wrap::Repeat), [1.0; 4]);
    }

    #[test]
    fn minification_reads_the_level_whose_texels_match_the_pixels() {
        let t = Texture::new(8, 8, vec![[200, 100, 50, 255]; 64]).unwrap();
        assert_eq!(level_of_detail(&t, [1.0 / 8.0, 0.0], [0.0, 1.0 / 8.0]), 0.0);
        assert_eq!(level_of_detail(&t, [0.5, 0.0], [0.0, 0.1]), 2.0);
        let levels = t.mip_chain();
        let s = Sampling::default();
        // a uniform image reads the same at every level
        let c = sample(&levels, [0.3, 0.7], [0.3, 0.0], [0.0, 0.3], &s);
        let want = linear([200, 100, 50, 255]);
        assert!((0..4).all(|k| (c[k] - want[k]).abs() < 2e-3), "{c:?} vs {want:?}");
    }
}

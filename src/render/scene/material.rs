//! Shading models, each a named material with the defaults of the paper it comes from.
//! `reference.rs` and `shaders/common.wgsl` evaluate the same formulas; the model ids the
//! shader switches on come from `Model::id` through the WGSL prelude (`wgsl.rs`).
//!
//! For every model the colour is  C = a_l a_m + sum over lights of ( f(L.n) d_l d_m + s S_l S_m ),
//! with a = ambient, d = diffuse, S = specular, l = light, m = material, all in linear light;
//! the models differ in the diffuse factor f and the highlight factor s.

use crate::error::{Error, Result};
use crate::render::color::{scaled, to_linear, Srgb};

use super::style::{Dither, Hatching};

/// Largest lookup table (one uniform array on the GPU).
pub const MAX_LUT: usize = 256;
/// Most band thresholds.
pub const MAX_BANDS: usize = 8;

/// The base colour of materials when none is given (sRGB).
pub const DEFAULT_COLOR: Srgb = [0.95, 0.55, 0.25];
/// Borquez and Yepez's bands: L.n thresholds and the value of each band.
pub const PAPER_BAND_THRESHOLDS: [f32; 4] = [0.2, 0.5, 0.7, 0.9];
pub const PAPER_BAND_VALUES: [f32; 5] = [0.0, 0.2, 0.7, 0.9, 1.0];
/// Al-Rousan et al.'s thresholds: diffuse at L.n >= 0, a small highlight.
pub const DEFAULT_T_H: f32 = 0.0;
pub const DEFAULT_T_S: f32 = 0.95;
pub const DEFAULT_SHININESS: f32 = 32.0;
/// Highlight colours of the Phong and thresholded Phong models (sRGB).
pub const PHONG_SPECULAR: Srgb = [0.5, 0.5, 0.5];
pub const TOON_SPECULAR: Srgb = [0.6, 0.6, 0.6];
/// Shares of the base colour (in linear light) lit by ambient and diffuse light: the shadow side
/// of a Lambert or Phong surface keeps 10%; the thresholded Phong model's shadow side 35%.
const SHADED_AMBIENT: f64 = 0.1;
const SHADED_DIFFUSE: f64 = 0.9;
const TOON_AMBIENT: f64 = 0.35;
const TOON_DIFFUSE: f64 = 0.65;

#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Highlight {
    /// thresh(L.v, t_s), as Al-Rousan et al. write it.
    Paper,
    /// thresh(n.h, t_s) with h = normalize(L + v): the usual Blinn-Phong highlight.
    Blinn,
}

impl Highlight {
    pub fn parse(arg: &str, s: &str) -> Result<Self> {
        match s {
            "paper" => Ok(Self::Paper),
            "blinn" => Ok(Self::Blinn),
            other => Err(Error::invalid(arg, format!("must be 'paper' or 'blinn', got {other:?}"))),
        }
    }

    pub fn name(self) -> &'static str {
        match self {
            Self::Paper => "paper",
            Self::Blinn => "blinn",
        }
    }
}

#[derive(Clone, Debug, PartialEq)]
pub enum Model {
    /// f = max(L.n, 0), s = 0.
    Lambert,
    /// f = max(L.n, 0), s = max(R.v, 0)^shininess where L.n > 0 (R = reflect(-L, n)).
    Phong { shininess: f32 },
    /// Al-Rousan et al.: f = thresh(L.n, t_h), s = thresh(L.v or n.h, t_s); thresh(a, b) = a >= b.
    ThresholdedPhong { t_h: f32, t_s: f32, highlight: Highlight },
    /// Borquez and Yepez: f = values[number of thresholds t with L.n >= t].
    Bands { thresholds: Vec<f32>, values: Vec<f32> },
    /// Kang et al.: f = table[min(floor(clamp(L.n, 0, 1) N), N - 1)], an RGB gradient map.
    Lut { table: Vec<[f32; 3]> },
}

impl Model {
    /// Every model, in id order (the WGSL prelude names them).
    pub const NAMES: [&'static str; 5] = ["lambert", "phong", "thresholded_phong", "bands", "lut"];

    pub fn id(&self) -> u32 {
        match self {
            Model::Lambert => 0,
            Model::Phong { .. } => 1,
            Model::ThresholdedPhong { .. } => 2,
            Model::Bands { .. } => 3,
            Model::Lut { .. } => 4,
        }
    }

    pub fn name(&self) -> &'static str {
        Self::NAMES[self.id() as usize]
    }
}

#[derive(Clone, Debug, PartialEq)]
pub struct Material {
    pub model: Model,
    /// sRGB coefficients a_m, d_m, S_m (decoded to linear light for shading).
    pub ambient: Srgb,
    pub diffuse: Srgb,
    pub specular: Srgb,
    /// Shade the vertices and interpolate the colours (Gouraud, as the paper colours vertices)
    /// instead of shading every pixel.
    pub per_vertex: bool,
    /// Cross-hatching: strokes of ink on the diffuse colour (paper), denser where the band is
    /// darker. Bands only.
    pub hatching: Option<Hatching>,
    /// Dithering between neighbouring bands. Toon models only, shaded per pixel.
    pub dither: Option<Dither>,
}

/// A 256-entry table with three levels, as Kang et al. map 256 intensities to 3 tones
/// (the paper gives no numbers: these split the range in thirds).
pub fn kang_table() -> Vec<[f32; 3]> {
    (0..256).map(|i| [[0.3f32, 0.65, 1.0][i * 3 / 256]; 3]).collect()
}

impl Default for Material {
    /// Borquez and Yepez's toon bands on the default colour.
    fn default() -> Self {
        Material::bands(DEFAULT_COLOR, None, None, false).expect("the defaults are valid")
    }
}

fn check_color(arg: &str, c: Srgb) -> Result<()> {
    crate::render::color::check_unit(arg, &c)
}

impl Material {
    /// Plain Lambert; the ambient term defaults to 10% of `color` and the diffuse to 90%.
    pub fn lambert(color: Srgb, ambient: Option<Srgb>, per_vertex: bool) -> Result<Self> {
        Self::checked(Material {
            model: Model::Lambert,
            ambient: ambient.unwrap_or_else(|| scaled(color, SHADED_AMBIENT)),
            diffuse: scaled(color, SHADED_DIFFUSE),
            specular: [0.0; 3],
            per_vertex,
            hatching: None,
            dither: None,
        })
    }

    pub fn phong(
        color: Srgb,
        specular: Option<Srgb>,
        shininess: Option<f32>,
        ambient: Option<Srgb>,
        per_vertex: bool,
    ) -> Result<Self> {
        Self::checked(Material {
            model: Model::Phong { shininess: shininess.unwrap_or(DEFAULT_SHININESS) },
            ambient: ambient.unwrap_or_else(|| scaled(color, SHADED_AMBIENT)),
            diffuse: scaled(color, SHADED_DIFFUSE),
            specular: specular.unwrap_or(PHONG_SPECULAR),
            per_vertex,
            hatching: None,
            dither: None,
        })
    }

    /// Al-Rousan et al.'s model; the shadow side keeps 35% of `color` and the lit side reaches it.
    pub fn thresholded_phong(
        color: Srgb,
        t_h: Option<f32>,
        t_s: Option<f32>,
        highlight: Option<Highlight>,
        ambient: Option<Srgb>,
        specular: Option<Srgb>,
        per_vertex: bool,
    ) -> Result<Self> {
        Self::checked(Material {
            model: Model::ThresholdedPhong {
                t_h: t_h.unwrap_or(DEFAULT_T_H),
                t_s: t_s.unwrap_or(DEFAULT_T_S),
                highlight: highlight.unwrap_or(Highlight::Blinn),
            },
            ambient: ambient.unwrap_or_else(|| scaled(color, TOON_AMBIENT)),
            diffuse: scaled(color, TOON_DIFFUSE),
            specular: specular.unwrap_or(TOON_SPECULAR),
            per_vertex,
            hatching: None,
            dither: None,
        })
    }

    /// Borquez and Yepez's bands (the paper's thresholds and values by default) times `color`.
    pub fn bands(
        color: Srgb,
        thresholds: Option<Vec<f32>>,
        values: Option<Vec<f32>>,
        per_vertex: bool,
    ) -> Result<Self> {
        Self::checked(Material {
            model: Model::Bands {
                thresholds: thresholds.unwrap_or_else(|| PAPER_BAND_THRESHOLDS.to_vec()),
                values: values.unwrap_or_else(|| PAPER_BAND_VALUES.to_vec()),
            },
            ambient: [0.0; 3],
            diffuse: color,
            specular: [0.0; 3],
            per_vertex,
            hatching: None,
            dither: None,
        })
    }

    /// A lookup table of linear RGB factors applied to `color` (Kang et al.'s by default).
    pub fn lut(table: Option<Vec<[f32; 3]>>, color: Srgb, per_vertex: bool) -> Result<Self> {
        Self::checked(Material {
            model: Model::Lut { table: table.unwrap_or_else(kang_table) },
            ambient: [0.0; 3],
            diffuse: color,
            specular: [0.0; 3],
            per_vertex,
            hatching: None,
            dither: None,
        })
    }

    /// Borquez and Yepez's cross-hatching: the bands' tone picks how many stroke layers of
    /// `hatching.ink` cover the paper colour `paper`.
    pub fn hatching(
        paper: Srgb,
        thresholds: Option<Vec<f32>>,
        values: Option<Vec<f32>>,
        hatching: Hatching,
        per_vertex: bool,
    ) -> Result<Self> {
        let mut m = Self::bands(paper, thresholds, values, per_vertex)?;
        m.hatching = Some(hatching);
        m.checked()
    }

    /// This material, dithered.
    pub fn with_dither(mut self, dither: Option<Dither>) -> Result<Self> {
        self.dither = dither;
        self.checked()
    }

    fn checked(self) -> Result<Self> {
        self.validate("material")?;
        Ok(self)
    }

    pub fn ambient_linear(&self) -> [f32; 3] {
        to_linear(self.ambient)
    }

    pub fn diffuse_linear(&self) -> [f32; 3] {
        to_linear(self.diffuse)
    }

    pub fn specular_linear(&self) -> [f32; 3] {
        to_linear(self.specular)
    }

    pub fn validate(&self, arg: &str) -> Result<()> {
        check_color(&format!("{arg}.ambient"), self.ambient)?;
        check_color(&format!("{arg}.diffuse"), self.diffuse)?;
        check_color(&format!("{arg}.specular"), self.specular)?;
        if let Some(h) = &self.hatching {
            if !matches!(self.model, Model::Bands { .. }) {
                return Err(Error::invalid(format!("{arg}.hatching"), "hatches only toon bands"));
            }
            h.validate(&format!("{arg}."))?;
        }
        if let Some(d) = &self.dither {
            if !matches!(self.model, Model::Bands { .. } | Model::Lut { .. } | Model::ThresholdedPhong { .. })
            {
                return Err(Error::invalid(
                    "dither",
                    format!(
                        "dithers toon bands only (bands, lut, thresholded_phong, hatching), not {}",
                        self.model.name()
                    ),
                ));
            }
            if self.per_vertex {
                return Err(Error::invalid("dither", "needs per-pixel shading (per_vertex=False)"));
            }
            d.validate("dither.")?;
        }
        match &self.model {
            Model::Lambert => {}
            Model::Phong { shininess } => {
                if !(shininess.is_finite() && *shininess > 0.0) {
                    return Err(Error::invalid(
                        format!("{arg}.shininess"),
                        format!("must be finite and > 0, got {shininess}"),
                    ));
                }
            }
            Model::ThresholdedPhong { t_h, t_s, .. } => {
                for (name, t) in [("t_h", t_h), ("t_s", t_s)] {
                    if !(t.is_finite() && (-1.0..=1.0).contains(t)) {
                        return Err(Error::invalid(
                            format!("{arg}.{name}"),
                            format!("must be in [-1, 1], got {t}"),
                        ));
                    }
                }
            }
            Model::Bands { thresholds, values } => {
                if thresholds.is_empty() || thresholds.len() > MAX_BANDS {
                    return Err(Error::invalid(
                        format!("{arg}.thresholds"),
                        format!("needs 1 to {MAX_BANDS} thresholds, got {}", thresholds.len()),
                    ));
                }
                if values.len() != thresholds.len() + 1 {
                    return Err(Error::invalid(
                        format!("{arg}.thresholds, {arg}.values"),
                        format!(
                            "needs one value more than thresholds: {} thresholds and {} values",
                            thresholds.len(),
                            values.len()
                        ),
                    ));
                }
                if !thresholds.iter().all(|t| t.is_finite()) || thresholds.windows(2).any(|w| w[1] <= w[0]) {
                    return Err(Error::invalid(
                        format!("{arg}.thresholds"),
                        format!("must be finite and strictly increasing, got {thresholds:?}"),
                    ));
                }
                if !values.iter().all(|v| v.is_finite() && *v >= 0.0) {
                    return Err(Error::invalid(
                        format!("{arg}.values"),
                        format!("must be finite and >= 0, got {values:?}"),
                    ));
                }
            }
            Model::Lut { table } => {
                if table.is_empty() || table.len() > MAX_LUT {
                    return Err(Error::invalid(
                        format!("{arg}.table"),
                        format!("needs 1 to {MAX_LUT} entries, got {}", table.len()),
                    ));
                }
                if !table.iter().flatten().all(|v| v.is_finite() && *v >= 0.0) {
                    return Err(Error::invalid(format!("{arg}.table"), "entries must be finite and >= 0"));
                }
            }
        }
        Ok(())
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn constructors_apply_defaults_and_checks() {
        let m = Material::default();
        assert_eq!(
            m.model,
            Model::Bands { thresholds: PAPER_BAND_THRESHOLDS.to_vec(), values: PAPER_BAND_VALUES.to_vec() }
        );
        assert_eq!(m.diffuse, DEFAULT_COLOR);
        let l = Material::lambert([1.0, 1.0, 1.0], None, false).unwrap();
        assert!((crate::render::color::srgb_to_linear(l.ambient[0]) - 0.1).abs() < 1e-12);
        assert!(Material::thresholded_phong(DEFAULT_COLOR, Some(2.0), None, None, None, None, false).is_err());
        assert!(Material::bands(DEFAULT_COLOR, Some(vec![0.5, 0.2]), Some(vec![0.0; 3]), false).is_err());
        assert!(Material::bands([2.0, 0.0, 0.0], None, None, false).is_err());
        assert_eq!(Model::NAMES[Model::Lut { table: vec![] }.id() as usize], "lut");
    }
}

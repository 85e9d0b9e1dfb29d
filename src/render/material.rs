//! Shading models, each a named material with the defaults of the paper it comes from.
//! `reference.rs` and `shaders/common.wgsl` evaluate the same formulas; keep the three in step.
//!
//! For every model the colour is  C = a_l a_m + sum over lights of ( f(L.n) d_l d_m + s S_l S_m ),
//! with a = ambient, d = diffuse, S = specular, l = light, m = material, all in linear light;
//! the models differ in the diffuse factor f and the highlight factor s.

use crate::error::{Error, Result};

/// Largest lookup table (one uniform array on the GPU).
pub const MAX_LUT: usize = 256;
/// Most band thresholds.
pub const MAX_BANDS: usize = 8;

#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Highlight {
    /// thresh(L.v, t_s), as Al-Rousan et al. write it.
    Paper,
    /// thresh(n.h, t_s) with h = normalize(L + v): the usual Blinn-Phong highlight.
    Blinn,
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
    pub fn id(&self) -> u32 {
        match self {
            Model::Lambert => 0,
            Model::Phong { .. } => 1,
            Model::ThresholdedPhong { .. } => 2,
            Model::Bands { .. } => 3,
            Model::Lut { .. } => 4,
        }
    }
}

#[derive(Clone, Debug, PartialEq)]
pub struct Material {
    pub model: Model,
    /// Linear RGB coefficients a_m, d_m, S_m.
    pub ambient: [f32; 3],
    pub diffuse: [f32; 3],
    pub specular: [f32; 3],
    /// Shade the vertices and interpolate the colours (Gouraud, as the paper colours vertices)
    /// instead of shading every pixel.
    pub per_vertex: bool,
}

/// Borquez and Yepez's bands: L.n thresholds and the value of each band.
pub const PAPER_BAND_THRESHOLDS: [f32; 4] = [0.2, 0.5, 0.7, 0.9];
pub const PAPER_BAND_VALUES: [f32; 5] = [0.0, 0.2, 0.7, 0.9, 1.0];

/// A 256-entry table with three levels, as Kang et al. map 256 intensities to 3 tones
/// (the paper gives no numbers: these split the range in thirds).
pub fn kang_table() -> Vec<[f32; 3]> {
    (0..256).map(|i| [[0.3f32, 0.65, 1.0][i * 3 / 256]; 3]).collect()
}

impl Default for Material {
    /// Toon bands on an orange base.
    fn default() -> Self {
        Material {
            model: Model::Bands {
                thresholds: PAPER_BAND_THRESHOLDS.to_vec(),
                values: PAPER_BAND_VALUES.to_vec(),
            },
            ambient: [0.0; 3],
            diffuse: [0.9, 0.45, 0.15],
            specular: [0.0; 3],
            per_vertex: false,
        }
    }
}

fn check_color(arg: &str, c: [f32; 3]) -> Result<()> {
    if c.iter().all(|v| v.is_finite() && *v >= 0.0) {
        Ok(())
    } else {
        Err(Error::invalid(arg, format!("must be finite and >= 0, got {c:?}")))
    }
}

impl Material {
    pub fn validate(&self, arg: &str) -> Result<()> {
        check_color(&format!("{arg}.ambient"), self.ambient)?;
        check_color(&format!("{arg}.diffuse"), self.diffuse)?;
        check_color(&format!("{arg}.specular"), self.specular)?;
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
                        format!("{arg}.values"),
                        format!(
                            "needs one value more than thresholds ({}), got {}",
                            thresholds.len() + 1,
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

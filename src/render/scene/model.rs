//! Shading models: the diffuse factor f(L.n) and the highlight factor s of each, with the
//! defaults of the paper it comes from. `reference.rs` and `shaders/common.wgsl` evaluate the
//! same formulas; the model ids the shader switches on come from `Model::id` through the WGSL
//! prelude (`wgsl.rs`).

use serde::{Deserialize, Serialize};

use crate::error::{Error, Result};

use crate::error::field;

/// 1 where a >= b, else 0: a hard band border (`thresh` in shaders/common.wgsl).
pub fn thresh(a: f32, b: f32) -> f32 {
    if a >= b {
        1.0
    } else {
        0.0
    }
}

/// `thresh(a, b)` blended over a width `w` of a (0: the hard step), as `step_aa` in the shader.
pub fn step_aa(a: f32, b: f32, w: f32) -> f32 {
    if w > 0.0 {
        ((a - b) / w + 0.5).clamp(0.0, 1.0)
    } else {
        thresh(a, b)
    }
}

/// Largest lookup table (one uniform array on the GPU).
pub const MAX_LUT: usize = 256;
/// Most band thresholds.
pub const MAX_BANDS: usize = 8;

/// Borquez and Yepez's bands: L.n thresholds and the value of each band.
pub const PAPER_BAND_THRESHOLDS: [f32; 4] = [0.2, 0.5, 0.7, 0.9];
pub const PAPER_BAND_VALUES: [f32; 5] = [0.0, 0.2, 0.7, 0.9, 1.0];
/// The bands' values when none are given: the paper's thresholds, but the darkest tone keeps
/// 30% of the colour (Kang et al.'s darkest tone) instead of going black, so the shadow side
/// keeps the material's hue and black ink stays visible over it.
pub const DEFAULT_BAND_VALUES: [f32; 5] = [0.3, 0.45, 0.7, 0.9, 1.0];
/// Al-Rousan et al.'s thresholds: diffuse at L.n >= 0, a small highlight.
pub const DEFAULT_T_H: f32 = 0.0;
pub const DEFAULT_T_S: f32 = 0.95;
pub const DEFAULT_SHININESS: f32 = 32.0;

crate::named_enum! {
    pub enum Highlight {
        /// thresh(L.v, t_s), as Al-Rousan et al. write it.
        Paper = "paper",
        /// thresh(n.h, t_s) with h = normalize(L + v): the usual Blinn-Phong highlight.
        Blinn = "blinn",
    }
}

#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(tag = "model", rename_all = "snake_case")]
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

/// A 256-entry table with three levels, as Kang et al. map 256 intensities to 3 tones
/// (the paper gives no numbers: these split the range in thirds).
pub fn kang_table() -> Vec<[f32; 3]> {
    (0..256).map(|i| [[0.3f32, 0.65, 1.0][i * 3 / 256]; 3]).collect()
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

    /// Whether the model bands the light into tones (what dithering moves between).
    pub fn is_toon(&self) -> bool {
        matches!(self, Model::Bands { .. } | Model::Lut { .. } | Model::ThresholdedPhong { .. })
    }

    /// Checks the model's parameters; `prefix` names the material in errors.
    pub fn validate(&self, prefix: &str) -> Result<()> {
        match self {
            Model::Lambert => {}
            // shininess, t_h and t_s: their bounds are Material's description's
            Model::Phong { .. } | Model::ThresholdedPhong { .. } => {}
            Model::Bands { thresholds, values } => {
                if thresholds.is_empty() || thresholds.len() > MAX_BANDS {
                    return Err(Error::invalid(
                        field(prefix, "thresholds"),
                        format!("needs 1 to {MAX_BANDS} thresholds, got {}", thresholds.len()),
                    ));
                }
                if values.len() != thresholds.len() + 1 {
                    return Err(Error::invalid(
                        format!("{}, {}", field(prefix, "thresholds"), field(prefix, "values")),
                        format!(
                            "needs one value more than thresholds: {} thresholds and {} values",
                            thresholds.len(),
                            values.len()
                        ),
                    ));
                }
                if !thresholds.iter().all(|t| t.is_finite()) || thresholds.windows(2).any(|w| w[1] <= w[0]) {
                    return Err(Error::invalid(
                        field(prefix, "thresholds"),
                        format!("must be finite and strictly increasing, got {thresholds:?}"),
                    ));
                }
                if !values.iter().all(|v| v.is_finite() && *v >= 0.0) {
                    return Err(Error::invalid(
                        field(prefix, "values"),
                        format!("must be finite and >= 0, got {values:?}"),
                    ));
                }
            }
            Model::Lut { table } => {
                if table.is_empty() || table.len() > MAX_LUT {
                    return Err(Error::invalid(
                        field(prefix, "table"),
                        format!("needs 1 to {MAX_LUT} entries, got {}", table.len()),
                    ));
                }
                if !table.iter().flatten().all(|v| v.is_finite() && *v >= 0.0) {
                    return Err(Error::invalid(field(prefix, "table"), "entries must be finite and >= 0"));
                }
            }
        }
        Ok(())
    }
}

//! Shadow settings of a light (Kang, Kim and Yoon's shadow z-buffer): the shadow map's size,
//! the depth bias that keeps lit surfaces from shadowing themselves, and the filter.

use serde::{Deserialize, Serialize};

use crate::error::field;
use crate::error::{Error, Result};

/// The shadow map's side when none is given, in texels.
pub const DEFAULT_SHADOW_SIZE: u32 = 2048;
/// The depth bias when none is given, in shadow-map texels per unit of receiver slope.
pub const DEFAULT_SHADOW_BIAS: f64 = 1.0;
/// The share of its light a shadow takes away when none is given: all of it.
pub const DEFAULT_SHADOW_STRENGTH: f64 = 1.0;
/// Sides a shadow map may have.
pub const SHADOW_SIZES: std::ops::RangeInclusive<u32> = 64..=8192;
/// Receiver slopes (tangent of the angle to the light) beyond this get this slope's bias:
/// surfaces that graze the light would otherwise get a bias without bound.
pub const MAX_BIAS_SLOPE: f64 = 8.0;

crate::named_enum! {
    /// How the shadow map is read.
    pub enum ShadowFilter {
        /// One test against the nearest texel: hard, aliased edges.
        Nearest = "none",
        /// Percentage-closer filtering: four bilinear comparisons (a tent over 3x3 texels), soft
        /// edges a few texels wide.
        Pcf = "pcf",
    }
}

impl ShadowFilter {
    /// How far from its centre a lookup reads, in texels (the bias must cover that distance):
    /// PCF's four bilinear taps sit half a texel off centre (shadow_test.wgsl).
    pub fn reach(self) -> f64 {
        match self {
            Self::Nearest => 1.0,
            Self::Pcf => 2.0,
        }
    }
}

#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
pub struct Shadows {
    /// Side of the square shadow map in texels: a power of two in `SHADOW_SIZES`.
    pub size: u32,
    /// Depth bias in texels per unit of receiver slope (>= 0).
    pub bias: f64,
    pub filter: ShadowFilter,
    /// The share of the light a shadow takes away, in [0, 1]: 1 a full shadow, less a lighter
    /// one (the shadowed side keeps 1 - strength of the light). Surfaces facing away from the
    /// light get none of it whatever this is.
    #[serde(default = "full_strength")]
    pub strength: f64,
}

/// Settings saved before the strength existed load with full shadows.
fn full_strength() -> f64 {
    DEFAULT_SHADOW_STRENGTH
}

impl Default for Shadows {
    fn default() -> Self {
        Shadows {
            size: DEFAULT_SHADOW_SIZE,
            bias: DEFAULT_SHADOW_BIAS,
            filter: ShadowFilter::Pcf,
            strength: DEFAULT_SHADOW_STRENGTH,
        }
    }
}

impl Shadows {
    /// Checks the settings; `prefix` names them in errors ("" while they are being made).
    pub fn validate(&self, prefix: &str) -> Result<()> {
        if !(SHADOW_SIZES.contains(&self.size) && self.size.is_power_of_two()) {
            return Err(Error::invalid(
                field(prefix, "size"),
                format!(
                    "must be a power of two from {} to {}, got {}",
                    SHADOW_SIZES.start(),
                    SHADOW_SIZES.end(),
                    self.size
                ),
            ));
        }
        if !(self.bias.is_finite() && self.bias >= 0.0) {
            return Err(Error::invalid(
                field(prefix, "bias"),
                format!("must be finite and >= 0, got {}", self.bias),
            ));
        }
        if !(0.0..=1.0).contains(&self.strength) {
            return Err(Error::invalid(
                field(prefix, "strength"),
                format!("must be in [0, 1], got {}", self.strength),
            ));
        }
        Ok(())
    }

    /// The depth tolerance per unit of receiver slope, in the light's depth units (the scene's
    /// bounding diameter is 1, as is the map's side).
    pub fn tolerance(&self) -> f64 {
        self.bias * self.filter.reach() / self.size as f64
    }

    /// How far a receiver moves along its normal before the test, in the same units: half the
    /// tolerance, which keeps surfaces the light grazes from shadowing themselves.
    pub fn normal_offset(&self) -> f64 {
        0.5 * self.tolerance()
    }
}

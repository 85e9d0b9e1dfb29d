//! Shadow settings of a light (Kang, Kim and Yoon's shadow z-buffer): the shadow map's size,
//! the depth bias that keeps lit surfaces from shadowing themselves, and the filter.

use crate::error::field;
use crate::error::{Error, Result};
use crate::render::settings::{check_bounds, settings, Range};

/// Sides a shadow map may have.
pub const SHADOW_SIZES: std::ops::RangeInclusive<u32> = 64..=8192;
/// The size's rule.
const SIZE_RULE: Range =
    Range::closed(*SHADOW_SIZES.start() as f64, *SHADOW_SIZES.end() as f64).rule("a power of two");
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

settings! {
    #[derive(Clone, Copy, Debug, PartialEq)]
    pub struct Shadows {
        /// Side of the square shadow map in texels: a power of two in `SHADOW_SIZES`.
        pub size: u32 = 2048
            => int(SIZE_RULE), "the shadow map's side in texels, a power of two";
        /// Depth bias in texels per unit of receiver slope.
        pub bias: f64 = 1.0 => float(at_least(0.0).slider(0.0, 8.0)),
            "depth bias in texels per unit of receiver slope, >= 0";
        pub filter: ShadowFilter = ShadowFilter::Pcf => choice(ShadowFilter::NAMES),
            "how the map is read: 'pcf' (soft edges) or 'none'";
        /// The share of the light a shadow takes away: 1 a full shadow, less a lighter one (the
        /// shadowed side keeps 1 - strength of the light). Surfaces facing away from the light
        /// get none of it whatever this is. Settings saved before it existed load at full.
        pub strength: f64 = 1.0 => float(closed(0.0, 1.0)),
            "the share of the light a shadow takes away: 1 a full shadow, 0.5 a half-tone one";
    }
    described(positional: 3);
}

impl Shadows {
    /// Checks the settings; `prefix` names them in errors ("" while they are being made): the
    /// bounds of their description, and the size's power of two.
    pub fn validate(&self, prefix: &str) -> Result<()> {
        check_bounds(self, prefix)?;
        if !self.size.is_power_of_two() {
            return Err(Error::invalid(field(prefix, "size"), SIZE_RULE.rule_refusal(self.size as f64)));
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

//! Eye-dome lighting's settings, declared (`render::settings::declare`).

use crate::error::Result;
use crate::render::settings::{check_bounds, settings};

settings! {
    #[derive(Clone, Copy, Debug, PartialEq)]
    pub struct EyeDome {
        /// How strongly depth steps darken (Potree's and CloudCompare's strength).
        pub strength: f64 = 1.0 => float(closed(0.0, 10.0)), "how strongly a pixel behind its neighbours darkens, 0 to 10";
        /// How far the neighbours lie, in output pixels.
        pub radius: f64 = 1.4 => float(closed(0.5, 16.0)), "how far its neighbours lie, 0.5 to 16 output pixels", pixels;
    }
    described(positional: 0);
}

impl EyeDome {
    /// Checks the settings; `prefix` names them in errors ("" while they are being made). Its
    /// numbers' bounds are its declaration's.
    pub fn validate(&self, prefix: &str) -> Result<()> {
        check_bounds(self, prefix)
    }
}

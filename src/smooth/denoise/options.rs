//! Options of the feature-preserving smoothers: what the caller passes, and the defaults.
//!
//! Every length is relative to the mesh's mean edge length, and the range width follows the
//! measured noise (`noise`), so the defaults need no tuning across scales and noise levels.

use crate::error::{Error, Result};
use crate::smooth::described::{self, Value, SIGMA_R_MAX, SIGMA_R_MIN, SIGMA_R_PER_NOISE};
use crate::smooth::given::args;
use crate::smooth::options::parse_preset;
use crate::smooth::preset::Preset;

#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Filter {
    /// Zheng et al. 2011: range weights from the normals themselves.
    Bilateral,
    /// Zhang et al. 2015: range weights from guidance normals (the most consistent patch).
    Guided,
}

impl Filter {
    /// The normal filter a smoothing method names (None: a method of the Laplacian family).
    pub fn of_method(method: &str) -> Option<Filter> {
        [Filter::Bilateral, Filter::Guided].into_iter().find(|f| f.name() == method)
    }

    /// The smoothing method's name of this filter.
    pub fn name(self) -> &'static str {
        match self {
            Filter::Bilateral => "bilateral",
            Filter::Guided => "guided",
        }
    }
}

args! {
    iterations: i64,
    vertex_iterations: i64,
    sigma_s: f64,
    sigma_r: f64,
    preset: String,
    weld: bool,
}

/// Resolved options; `sigma_r` None means "from the noise estimate".
#[derive(Debug, Clone, PartialEq)]
pub struct Options {
    pub filter: Filter,
    /// Passes of normal filtering.
    pub iterations: u32,
    /// Steps of vertex fitting after the normals are filtered.
    pub vertex_iterations: u32,
    /// Spatial kernel width, in mean edge lengths.
    pub sigma_s: f64,
    pub sigma_r: Option<f64>,
    /// `Paper`: Zhang et al.'s rule as their code has it (see `denoise_mesh`); else `Clean`.
    pub preset: Preset,
    pub weld: bool,
}

/// The guided filter's range weight also compares two faces' own normals, with a width of the
/// measured range width (as `sigma_r` defaults to) over the square root of this share
/// (dimensionless): at the defaults, their squared distance adds at this share to that between
/// the guidance normals. Where every patch around a face crosses a crease (features a few
/// faces wide, as a groove's walls), the guidance blurs the two sides together and the faces'
/// own normals still tell them apart; a small share, so that outliers, which the guidance sees
/// through, still weigh little. Not in Zhang et al.; without it the held-out parts' errors rise
/// (with half the passes alone, the sharp sphere at Gaussian 0.3: 4.9 degrees against 4.4, the
/// chamfered box 3.8 against 3.5). It follows the noise, not a given `sigma_r`, so that a narrow
/// `sigma_r` narrows the guidance's weight alone.
pub const GUIDED_OWN_NORMALS: f64 = 0.3;

/// The share of the guided filter's passes that filter the normals alone; each later pass is
/// followed by `vertex_iterations` steps of vertex fitting, and the next pass filters the
/// fitted mesh's own normals. Zhang et al.'s local scheme fits after every pass: from the first
/// pass, heavy noise on thin triangles (noise larger than their short sides) folds faces that
/// the fitting does not unfold (the held-out twelve-sided prism at Gaussian 0.7: 25 degrees,
/// against 10 with this share), while fitting the later passes, which the normals-then-vertices
/// order did not, recovers the creases the fitted mesh shows (the held-out sharp sphere at 0.3:
/// 4.4 degrees, against 5.2).
pub const GUIDED_NORMALS_ALONE: f64 = 0.6;

/// The options of `filter` with the keywords `a` gives, the others at their described
/// defaults (`described`), each checked against its described range.
pub fn resolve(filter: Filter, a: &Args) -> Result<Options> {
    let name = filter.name();
    let described =
        described::method(name).ok_or_else(|| Error::Internal(format!("{name}: not described")))?;
    let keyword =
        |k: &str| described.keyword(k).ok_or_else(|| Error::Internal(format!("{name}.{k}: not described")));
    if let Some(k) = a.given().find(|k| described.keyword(k).is_none()) {
        return Err(Error::wrong_type(k, format!("not an option of {name}")));
    }
    let preset = match &a.preset {
        None => Preset::Clean,
        // The method's own choices, so that the error lists only the presets it has.
        Some(given) => parse_preset(keyword("preset")?.choose(given)?)?,
    };
    let count = |k: &str, given: Option<i64>| -> Result<u32> {
        let kw = keyword(k)?;
        Ok(kw.check_int(preset, given.map_or_else(|| kw.default_for(preset).int(k), Ok)?)? as u32)
    };
    let width = |k: &str, given: Option<f64>| -> Result<Option<f64>> {
        let kw = keyword(k)?;
        match (given, kw.default_for(preset)) {
            (Some(x), _) => kw.check_float(preset, x).map(Some),
            (None, Value::Measured(_)) => Ok(None),
            (None, d) => d.float(k).map(Some),
        }
    };
    Ok(Options {
        filter,
        iterations: count("iterations", a.iterations)?,
        vertex_iterations: count("vertex_iterations", a.vertex_iterations)?,
        sigma_s: width("sigma_s", a.sigma_s)?.ok_or_else(|| Error::Internal("sigma_s: measured".into()))?,
        sigma_r: width("sigma_r", a.sigma_r)?,
        preset,
        weld: match a.weld {
            Some(weld) => weld,
            None => keyword("weld")?.default.flag("weld")?,
        },
    })
}

/// The range width that follows the measured normal noise.
fn measured_sigma_r(noise: f64) -> f64 {
    (SIGMA_R_PER_NOISE * noise).clamp(SIGMA_R_MIN, SIGMA_R_MAX)
}

impl Options {
    /// The range width for a mesh whose measured normal noise is `noise`.
    pub fn sigma_r_for(&self, noise: f64) -> f64 {
        self.sigma_r.unwrap_or_else(|| measured_sigma_r(noise))
    }

    /// How many of the guided filter's first passes filter the normals alone
    /// (`GUIDED_NORMALS_ALONE`); at least the last pass fits the vertices.
    pub fn passes_before_fitting(&self) -> u32 {
        if self.preset == Preset::Paper {
            return 0;
        }
        ((GUIDED_NORMALS_ALONE * self.iterations as f64).floor() as u32)
            .min(self.iterations.saturating_sub(1))
    }

    /// The guided filter's range width for the faces' own normals (`GUIDED_OWN_NORMALS`), None
    /// for the bilateral filter and the paper preset.
    pub fn sigma_own_for(&self, noise: f64) -> Option<f64> {
        (self.filter == Filter::Guided && self.preset != Preset::Paper)
            .then(|| measured_sigma_r(noise) / GUIDED_OWN_NORMALS.sqrt())
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_guided_filter_fits_the_vertices_in_its_later_passes_or_every_one_under_the_paper() {
        let opts = |iterations: u32, preset: Preset| Options {
            filter: Filter::Guided,
            iterations,
            vertex_iterations: 10,
            sigma_s: 1.0,
            sigma_r: None,
            preset,
            weld: false,
        };
        let alone = |n| opts(n, Preset::Clean).passes_before_fitting();
        assert_eq!([alone(20), alone(10), alone(2), alone(1), alone(0)], [12, 6, 1, 0, 0]);
        assert_eq!(opts(20, Preset::Paper).passes_before_fitting(), 0);
        assert!(opts(20, Preset::Clean).sigma_own_for(0.5).is_some());
        assert!(opts(20, Preset::Paper).sigma_own_for(0.5).is_none());
    }
}

//! Smoothing options: the names users pass, and the presets that pick defaults and rules.
//!
//! Every argument is optional at this level; `resolve` fills what the caller left out with the
//! chosen preset's default and refuses combinations the preset does not have, naming the
//! argument, so a preset never silently computes something its library would not.

use crate::error::{Error, Result};

#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Method {
    Laplacian,
    Taubin,
    Hc,
    Implicit,
}

#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Weights {
    Uniform,
    Cotangent,
    Distance,
}

#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Boundary {
    /// Boundary vertices do not move.
    Fixed,
    /// Boundary vertices are averaged like interior ones.
    Free,
    /// Boundary vertices are averaged with their boundary neighbours only, so they slide along
    /// the boundary curve.
    Slide,
}

#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Preset {
    /// No preset: distinct neighbours, rows that sum to one, boundaries as asked.
    Clean,
    Trimesh,
    Pymeshlab,
    /// Al-Rousan et al.: every vertex moves to the plain mean of its neighbours.
    Paper,
}

/// What the caller passed (None: use the preset's default).
#[derive(Debug, Clone, Default)]
pub struct Args {
    pub iterations: Option<i64>,
    pub lamb: Option<f64>,
    pub mu: Option<f64>,
    pub alpha: Option<f64>,
    pub beta: Option<f64>,
    pub step: Option<f64>,
    pub tol: Option<f64>,
    pub max_iter: Option<i64>,
    pub weights: Option<String>,
    pub boundary: Option<String>,
    pub volume_constraint: Option<bool>,
    pub preset: Option<String>,
    pub weld: Option<bool>,
}

/// Fully resolved options.
#[derive(Debug, Clone, PartialEq)]
pub struct Plan {
    pub method: Method,
    pub preset: Preset,
    pub iterations: u32,
    pub lamb: f64,
    pub mu: f64,
    pub alpha: f64,
    pub beta: f64,
    pub step: f64,
    pub tol: f64,
    pub max_iter: u32,
    pub weights: Weights,
    pub boundary: Boundary,
    pub volume_constraint: bool,
    /// Smooth the welded mesh (vertices at equal positions merged) and give every copy its
    /// position's result. Any preset allows it: the preset's algorithm then runs on the welded
    /// mesh.
    pub weld: bool,
}

fn parse<T: Copy>(arg: &str, value: &str, table: &[(&str, T)]) -> Result<T> {
    let v = value.to_ascii_lowercase();
    table.iter().find(|(k, _)| *k == v).map(|(_, t)| *t).ok_or_else(|| {
        let names: Vec<String> = table.iter().map(|(k, _)| format!("'{k}'")).collect();
        Error::invalid(arg, format!("unknown value '{value}'; expected one of {}", names.join(", ")))
    })
}

/// The names each option takes, for parsing and for front ends to list.
pub const WEIGHTS: [(&str, Weights); 3] =
    [("uniform", Weights::Uniform), ("cotangent", Weights::Cotangent), ("distance", Weights::Distance)];
pub const BOUNDARIES: [(&str, Boundary); 3] =
    [("fixed", Boundary::Fixed), ("free", Boundary::Free), ("slide", Boundary::Slide)];
pub const PRESETS: [(&str, Preset); 3] =
    [("trimesh", Preset::Trimesh), ("pymeshlab", Preset::Pymeshlab), ("paper", Preset::Paper)];
pub const METHODS: [(&str, Method); 4] = [
    ("laplacian", Method::Laplacian),
    ("taubin", Method::Taubin),
    ("hc", Method::Hc),
    ("implicit", Method::Implicit),
];

pub fn parse_weights(s: &str) -> Result<Weights> {
    parse("weights", s, &WEIGHTS)
}

pub fn parse_boundary(s: &str) -> Result<Boundary> {
    parse("boundary", s, &BOUNDARIES)
}

pub fn parse_preset(s: &str) -> Result<Preset> {
    parse("preset", s, &PRESETS)
}

pub fn parse_method(s: &str) -> Result<Method> {
    parse("method", s, &METHODS)
}

fn name(m: Method) -> &'static str {
    METHODS.iter().find(|(_, x)| *x == m).map_or("?", |(n, _)| n)
}

fn preset_name(p: Preset) -> &'static str {
    match p {
        Preset::Clean => "None",
        Preset::Trimesh => "'trimesh'",
        Preset::Pymeshlab => "'pymeshlab'",
        Preset::Paper => "'paper'",
    }
}

fn finite(arg: &str, v: f64, lo: f64, hi: f64) -> Result<f64> {
    if v.is_finite() && v >= lo && v <= hi {
        Ok(v)
    } else {
        Err(Error::invalid(arg, format!("must be a finite number in [{lo}, {hi}], got {v}")))
    }
}

pub fn resolve(method: Method, a: &Args) -> Result<Plan> {
    let preset = match &a.preset {
        None => Preset::Clean,
        Some(s) => parse_preset(s)?,
    };
    let unsupported = |arg: &str, why: &str| {
        Error::invalid(arg, format!("{}(preset={}) {why}", name(method), preset_name(preset)))
    };
    use Method::*;
    use Preset::*;
    match (method, preset) {
        (Taubin | Hc | Implicit, Paper) => {
            return Err(unsupported("preset", "does not exist: the paper describes only the plain Laplacian"))
        }
        (Implicit, Pymeshlab) => {
            return Err(unsupported("preset", "does not exist: pymeshlab has no implicit smoothing"))
        }
        _ => {}
    }

    // Defaults per preset.
    let iterations_default = match (method, preset) {
        (Laplacian, Pymeshlab) => 3,
        (Hc, Pymeshlab) => 1,
        (Implicit, Clean) => 1,
        _ => 10,
    };
    let lamb_default = match (method, preset) {
        // VCG's update (x + S) / (C + 1) is a full step to its average.
        (Laplacian, Paper | Pymeshlab) => 1.0,
        _ => 0.5,
    };
    let mu_default = if preset == Trimesh { -0.5 } else { -0.53 };
    let weights_default =
        if (method, preset) == (Laplacian, Pymeshlab) { Weights::Cotangent } else { Weights::Uniform };
    let boundary_default = match preset {
        Pymeshlab => Boundary::Slide,
        Paper | Trimesh => Boundary::Free,
        Clean => Boundary::Fixed,
    };
    let volume_default = preset == Trimesh && matches!(method, Laplacian | Implicit);

    let iterations = a.iterations.unwrap_or(iterations_default);
    if !(0..=1_000_000).contains(&iterations) {
        return Err(Error::invalid("iterations", format!("must be in [0, 1000000], got {iterations}")));
    }
    let weights = match &a.weights {
        None => weights_default,
        Some(s) => parse_weights(s)?,
    };
    let boundary = match &a.boundary {
        None => boundary_default,
        Some(s) => parse_boundary(s)?,
    };
    let volume_constraint = a.volume_constraint.unwrap_or(volume_default);

    // What each preset does not have.
    match preset {
        Trimesh => {
            if a.boundary.is_some() {
                return Err(unsupported(
                    "boundary",
                    "has no boundary option: trimesh's half-edge rule decides",
                ));
            }
            let ok = match method {
                Laplacian | Implicit => weights != Weights::Cotangent,
                Taubin | Hc => weights == Weights::Uniform,
            };
            if !ok {
                return Err(unsupported("weights", "has no such weights in trimesh"));
            }
        }
        Pymeshlab => {
            if a.lamb.is_some() && method == Laplacian {
                return Err(unsupported("lamb", "has no step size: VCG moves x to (x + S) / (C + 1)"));
            }
            if method != Laplacian && weights != Weights::Uniform {
                return Err(unsupported("weights", "uses uniform weights only"));
            }
            if weights == Weights::Distance {
                return Err(unsupported("weights", "has no inverse-distance weights"));
            }
            if boundary == Boundary::Fixed || (method != Laplacian && boundary != Boundary::Slide) {
                return Err(unsupported(
                    "boundary",
                    "supports 'slide' (boundary=True) and, for laplacian, 'free' (boundary=False)",
                ));
            }
            if method == Hc && (a.alpha.is_some() || a.beta.is_some_and(|b| b != 0.5)) {
                return Err(unsupported("alpha", "has no alpha, and beta is fixed at 0.5"));
            }
        }
        Paper => {
            if weights != Weights::Uniform {
                return Err(unsupported("weights", "uses the plain neighbour mean (uniform)"));
            }
        }
        Clean => {
            if method == Implicit && boundary == Boundary::Slide {
                return Err(unsupported("boundary", "supports 'fixed' and 'free'"));
            }
        }
    }
    if volume_constraint && !matches!(method, Laplacian | Implicit) {
        return Err(unsupported("volume_constraint", "is only available for laplacian and implicit"));
    }
    if volume_constraint && matches!(preset, Pymeshlab | Paper) {
        return Err(unsupported("volume_constraint", "has no volume constraint"));
    }

    let lamb = match method {
        Laplacian if preset == Trimesh => finite("lamb", a.lamb.unwrap_or(lamb_default), -1e6, 1e6)?,
        _ => finite("lamb", a.lamb.unwrap_or(lamb_default), 0.0, 1.0)?,
    };
    let mu = finite("mu", a.mu.unwrap_or(mu_default), -1.0, 0.0)?;
    let alpha = finite("alpha", a.alpha.unwrap_or(0.1), 0.0, 1.0)?;
    let beta = finite("beta", a.beta.unwrap_or(0.5), 0.0, 1.0)?;
    let step_default = if preset == Trimesh { lamb } else { 1.0 };
    let step = finite("step", a.step.unwrap_or(step_default), 0.0, 1e12)?;
    let tol = a.tol.unwrap_or(1e-10);
    if !(tol.is_finite() && tol > 0.0 && tol < 1.0) {
        return Err(Error::invalid("tol", format!("must be in (0, 1), got {tol}")));
    }
    let max_iter = a.max_iter.unwrap_or(10_000);
    if !(1..=10_000_000).contains(&max_iter) {
        return Err(Error::invalid("max_iter", format!("must be in [1, 10000000], got {max_iter}")));
    }
    let (lamb, mu) = if preset == Pymeshlab && method == Taubin {
        // VCG stores both factors as float32.
        (lamb as f32 as f64, mu as f32 as f64)
    } else {
        (lamb, mu)
    };
    Ok(Plan {
        method,
        preset,
        iterations: iterations as u32,
        lamb,
        mu,
        alpha,
        beta,
        step,
        tol,
        max_iter: max_iter as u32,
        weights,
        boundary,
        volume_constraint,
        weld: a.weld.unwrap_or(false),
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn presets_pick_their_defaults() {
        let p = resolve(Method::Laplacian, &Args { preset: Some("pymeshlab".into()), ..Default::default() })
            .unwrap();
        assert_eq!((p.iterations, p.weights, p.boundary), (3, Weights::Cotangent, Boundary::Slide));
        let t = resolve(Method::Laplacian, &Args { preset: Some("trimesh".into()), ..Default::default() })
            .unwrap();
        assert!(t.volume_constraint);
        let c = resolve(Method::Laplacian, &Args::default()).unwrap();
        assert_eq!((c.boundary, c.volume_constraint, c.lamb), (Boundary::Fixed, false, 0.5));
    }

    #[test]
    fn refuses_what_a_preset_lacks() {
        let e = resolve(Method::Implicit, &Args { preset: Some("pymeshlab".into()), ..Default::default() })
            .unwrap_err();
        assert!(e.to_string().starts_with("preset:"));
        let e = resolve(Method::Laplacian, &Args { weights: Some("cot".into()), ..Default::default() })
            .unwrap_err();
        assert!(e.to_string().contains("'cotangent'"));
        assert!(resolve(Method::Laplacian, &Args { lamb: Some(f64::NAN), ..Default::default() }).is_err());
    }
}

//! Smoothing options: the names users pass, and the presets that pick defaults and rules.
//!
//! Every argument is optional at this level; `resolve` fills what the caller left out with the
//! chosen preset's default, checks each value against its range (both read from the method's
//! description, `described`) and refuses combinations the preset does not have, naming the
//! argument, so a preset never silently computes something its library would not.

use super::described::{self, Described, Keyword, Value};
use super::given::args;
pub use super::preset::{Preset, PRESETS};
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

args! {
    iterations: i64,
    lamb: f64,
    mu: f64,
    alpha: f64,
    beta: f64,
    step: f64,
    tol: f64,
    max_iter: i64,
    weights: String,
    boundary: String,
    volume_constraint: bool,
    preset: String,
    weld: bool,
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

pub fn name(m: Method) -> &'static str {
    METHODS.iter().find(|(_, x)| *x == m).map_or("?", |(n, _)| n)
}

fn preset_name(p: Preset) -> String {
    described::preset_name(p).map_or("None".into(), |n| format!("'{n}'"))
}

/// Why a method lacks a preset.
fn lacks(preset: Preset, method: Method) -> String {
    match preset {
        Preset::Paper => "the paper describes only the plain Laplacian".into(),
        _ => format!("{} has no {} smoothing", described::preset_name(preset).unwrap_or("?"), name(method)),
    }
}

/// A method's keywords under a preset: each given value checked against its described range,
/// or the described default. A number the method does not take (never given: `resolve`
/// refuses it) is read from the first method of the family that does, so that every field of
/// a `Plan` holds a described value; a flag it does not take is off.
struct Keywords {
    method: &'static Described,
    preset: Preset,
}

impl Keywords {
    fn keyword(&self, name: &str) -> Result<&'static Keyword> {
        let family = METHODS.iter().filter_map(|(n, _)| described::method(n));
        self.method
            .keyword(name)
            .or_else(|| family.into_iter().find_map(|m| m.keyword(name)))
            .ok_or_else(|| Error::Internal(format!("{name}: no smoothing method describes it")))
    }

    fn default(&self, name: &str) -> Result<Value> {
        Ok(self.keyword(name)?.default_for(self.preset))
    }

    fn int(&self, name: &str, given: Option<i64>) -> Result<i64> {
        let k = self.keyword(name)?;
        k.check_int(self.preset, given.map_or_else(|| k.default_for(self.preset).int(name), Ok)?)
    }

    fn float(&self, name: &str, given: Option<f64>) -> Result<f64> {
        let k = self.keyword(name)?;
        k.check_float(self.preset, given.map_or_else(|| k.default_for(self.preset).float(name), Ok)?)
    }

    fn choice(&self, name: &str, given: &Option<String>) -> Result<&'static str> {
        let k = self.keyword(name)?;
        match given {
            Some(s) => k.choose(s),
            None => k.default_for(self.preset).name(name),
        }
    }

    /// A flag's value: off where the method does not take it.
    fn flag(&self, name: &str, given: Option<bool>) -> Result<bool> {
        match self.method.keyword(name) {
            None => Ok(false),
            Some(k) => given.map_or_else(|| k.default_for(self.preset).flag(name), Ok),
        }
    }
}

/// The plan of `method` with the keywords `a` gives, the others at their described defaults
/// (`described`), each checked against its described range.
pub fn resolve(method: Method, a: &Args) -> Result<Plan> {
    let described = described::method(name(method))
        .ok_or_else(|| Error::Internal(format!("{}: not described", name(method))))?;
    if let Some(k) = a.given().find(|k| described.keyword(k).is_none()) {
        return Err(Error::wrong_type(k, format!("not an option of {}", name(method))));
    }
    let preset = match &a.preset {
        None => Preset::Clean,
        Some(s) => parse_preset(s)?,
    };
    let unsupported = |arg: &str, why: &str| {
        Error::invalid(arg, format!("{}(preset={}) {why}", name(method), preset_name(preset)))
    };
    if !described.has(preset) {
        return Err(unsupported("preset", &format!("does not exist: {}", lacks(preset, method))));
    }
    use Method::*;
    use Preset::*;
    let k = Keywords { method: described, preset };

    let iterations = k.int("iterations", a.iterations)?;
    let weights = parse_weights(k.choice("weights", &a.weights)?)?;
    let boundary = parse_boundary(k.choice("boundary", &a.boundary)?)?;
    let volume_constraint = k.flag("volume_constraint", a.volume_constraint)?;

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
            // VCG's HC has no alpha and a fixed beta: the default
            let fixed_beta = k.default("beta")?.float("beta")?;
            if method == Hc && (a.alpha.is_some() || a.beta.is_some_and(|b| b != fixed_beta)) {
                return Err(unsupported(
                    "alpha",
                    &format!("has no alpha, and beta is fixed at {fixed_beta}"),
                ));
            }
        }
        Paper => {
            if weights != Weights::Uniform {
                return Err(unsupported("weights", "uses the plain neighbour mean (uniform)"));
            }
        }
        Clean => {}
    }
    if volume_constraint && matches!(preset, Pymeshlab | Paper) {
        return Err(unsupported("volume_constraint", "has no volume constraint"));
    }

    let lamb = k.float("lamb", a.lamb)?;
    let mu = k.float("mu", a.mu)?;
    let alpha = k.float("alpha", a.alpha)?;
    let beta = k.float("beta", a.beta)?;
    let step = k.float("step", a.step)?;
    let tol = k.float("tol", a.tol)?;
    let max_iter = k.int("max_iter", a.max_iter)?;
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
        weld: k.flag("weld", a.weld)?,
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

//! Each smoothing method described once: the keywords it takes, in the order they are checked,
//! each with its kind, the values it allows (a range with open or closed ends, or names), its
//! default (and the presets whose default differs) and a line of help; and the presets it has.
//! `options::resolve` and `denoise::resolve` read their defaults and ranges here, and the front
//! ends (the Python signatures, docstrings and TypedDicts, the command line's flags) are made
//! from it, so that none of them is written twice.

use super::preset::{Preset, PRESETS};
use crate::error::{Error, Result};

/// sigma_r's measured default: the range width is this many times the measured normal noise (`noise`: the 90th percentile
/// of |n_i - n_j| over neighbouring faces), within [SIGMA_R_MIN, SIGMA_R_MAX].
pub const SIGMA_R_PER_NOISE: f64 = 0.35;
pub const SIGMA_R_MIN: f64 = 0.05;
pub const SIGMA_R_MAX: f64 = 0.6;

/// What a keyword holds, and so how a front end reads it.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Kind {
    Int,
    Float,
    Name,
    Bool,
}

/// The values a keyword allows.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Rule {
    /// A number from `min` to `max` (infinite: unbounded); an end marked in `exclusive` is
    /// open. NaN is never in range.
    Range { min: f64, max: f64, exclusive: [bool; 2] },
    /// One of these names, in any case.
    Choices(&'static [&'static str]),
    /// True or False.
    Flag,
}

/// A keyword's default.
#[derive(Clone, Copy, Debug)]
pub enum Value {
    Int(i64),
    Float(f64),
    Name(&'static str),
    Bool(bool),
    /// None: no preset.
    Unset,
    /// None: the method measures it from the mesh, as these words say.
    Measured(fn() -> String),
}

/// One keyword of a smoothing method.
#[derive(Clone, Copy, Debug)]
pub struct Keyword {
    pub name: &'static str,
    pub kind: Kind,
    pub rule: Rule,
    /// The default without a preset.
    pub default: Value,
    /// The presets whose default differs from `default`.
    pub presets: &'static [(Preset, Value)],
    /// The presets whose range differs from `rule`.
    pub preset_rules: &'static [(Preset, Rule)],
    /// None means the default. `weld` takes no None: it is always given (False by default).
    pub takes_none: bool,
    pub help: &'static str,
}

/// One smoothing method: its name as the API spells it, what it does, and its keywords.
#[derive(Clone, Copy, Debug)]
pub struct Described {
    pub name: &'static str,
    pub help: &'static str,
    pub keywords: &'static [Keyword],
}

const fn range(min: f64, max: f64, exclusive: [bool; 2]) -> Rule {
    Rule::Range { min, max, exclusive }
}

const CLOSED: [bool; 2] = [false, false];
const POSITIVE: Rule = range(0.0, f64::INFINITY, [true, true]);
/// The most steps or passes accepted: far beyond any useful count, low enough to refuse typos.
const STEPS: Rule = range(0.0, 1_000_000.0, CLOSED);
const UNIT: Rule = range(0.0, 1.0, CLOSED);

impl Keyword {
    const fn new(name: &'static str, kind: Kind, rule: Rule, default: Value, help: &'static str) -> Keyword {
        Keyword { name, kind, rule, default, presets: &[], preset_rules: &[], takes_none: true, help }
    }

    const fn int(name: &'static str, rule: Rule, default: i64, help: &'static str) -> Keyword {
        Keyword::new(name, Kind::Int, rule, Value::Int(default), help)
    }

    const fn float(name: &'static str, rule: Rule, default: f64, help: &'static str) -> Keyword {
        Keyword::new(name, Kind::Float, rule, Value::Float(default), help)
    }

    const fn choice(
        name: &'static str,
        choices: &'static [&'static str],
        default: Value,
        help: &'static str,
    ) -> Keyword {
        Keyword::new(name, Kind::Name, Rule::Choices(choices), default, help)
    }

    const fn flag(name: &'static str, default: bool, help: &'static str) -> Keyword {
        Keyword::new(name, Kind::Bool, Rule::Flag, Value::Bool(default), help)
    }

    const fn with_presets(self, presets: &'static [(Preset, Value)]) -> Keyword {
        Keyword { presets, ..self }
    }

    const fn with_preset_rules(self, preset_rules: &'static [(Preset, Rule)]) -> Keyword {
        Keyword { preset_rules, ..self }
    }

    const fn always_given(self) -> Keyword {
        Keyword { takes_none: false, ..self }
    }

    /// The default under `preset`.
    pub fn default_for(&self, preset: Preset) -> Value {
        self.presets.iter().find(|(p, _)| *p == preset).map_or(self.default, |(_, v)| *v)
    }

    /// The values allowed under `preset`.
    pub fn rule_for(&self, preset: Preset) -> Rule {
        self.preset_rules.iter().find(|(p, _)| *p == preset).map_or(self.rule, |(_, r)| *r)
    }

    /// `v` if `preset`'s range holds it, else the error naming this keyword.
    pub fn check_float(&self, preset: Preset, v: f64) -> Result<f64> {
        let Rule::Range { min, max, exclusive } = self.rule_for(preset) else {
            return Err(self.not_described("a range"));
        };
        let above = v > min || (!exclusive[0] && v == min);
        let below = v < max || (!exclusive[1] && v == max);
        if v.is_finite() && above && below {
            return Ok(v);
        }
        let rule = if max.is_infinite() {
            format!("{} {min}", if exclusive[0] { ">" } else { ">=" })
        } else {
            format!(
                "in {}{min}, {max}{}",
                ["[", "("][exclusive[0] as usize],
                ["]", ")"][exclusive[1] as usize]
            )
        };
        Err(Error::invalid(self.name, format!("must be a finite number {rule}, got {v}")))
    }

    /// `n` if `preset`'s range holds it, else the error naming this keyword.
    pub fn check_int(&self, preset: Preset, n: i64) -> Result<i64> {
        let Rule::Range { min, max, .. } = self.rule_for(preset) else {
            return Err(self.not_described("a range"));
        };
        if (min..=max).contains(&(n as f64)) {
            return Ok(n);
        }
        Err(Error::invalid(self.name, format!("must be in [{}, {}], got {n}", min as i64, max as i64)))
    }

    /// The choice `given` names (any case), else the error naming this keyword.
    pub fn choose(&self, given: &str) -> Result<&'static str> {
        let Rule::Choices(choices) = self.rule else { return Err(self.not_described("choices")) };
        let lower = given.to_ascii_lowercase();
        choices.iter().find(|c| **c == lower).copied().ok_or_else(|| {
            let names: Vec<String> = choices.iter().map(|c| format!("'{c}'")).collect();
            Error::invalid(
                self.name,
                format!("unknown value '{given}'; expected one of {}", names.join(", ")),
            )
        })
    }

    fn not_described(&self, what: &str) -> Error {
        Error::Internal(format!("{}: described without {what}", self.name))
    }
}

/// Each kind's value out of a described default (an internal error naming the keyword if the
/// description gave it another kind).
macro_rules! value_as {
    ($($f:ident: $variant:ident($t:ty), $what:literal;)*) => {$(
        pub fn $f(self, name: &str) -> Result<$t> {
            match self {
                Value::$variant(x) => Ok(x),
                _ => Err(Self::wrong(name, $what)),
            }
        }
    )*};
}

impl Value {
    value_as! {
        int: Int(i64), "an int";
        float: Float(f64), "a float";
        name: Name(&'static str), "a name";
        flag: Bool(bool), "a bool";
    }

    fn wrong(name: &str, what: &str) -> Error {
        Error::Internal(format!("{name}: its default is described as other than {what}"))
    }
}

impl Described {
    /// The keyword `name` of this method, if it takes one.
    pub fn keyword(&self, name: &str) -> Option<&'static Keyword> {
        self.keywords.iter().find(|k| k.name == name)
    }

    /// The presets this method has (the choices of its `preset` keyword), by name.
    pub fn presets(&self) -> &'static [&'static str] {
        match self.keyword("preset").map(|k| k.rule) {
            Some(Rule::Choices(names)) => names,
            _ => &[],
        }
    }

    /// Whether this method has `preset` (every method runs without one).
    pub fn has(&self, preset: Preset) -> bool {
        preset == Preset::Clean || PRESETS.iter().any(|(n, p)| *p == preset && self.presets().contains(n))
    }
}

/// The method named `name`, if there is one.
pub fn method(name: &str) -> Option<&'static Described> {
    METHODS.iter().find(|m| m.name == name)
}

/// `preset`'s name as the API spells it (None for no preset).
pub fn preset_name(preset: Preset) -> Option<&'static str> {
    PRESETS.iter().find(|(_, p)| *p == preset).map(|(n, _)| *n)
}

use Preset::{Paper, Pymeshlab, Trimesh};

const WEIGHTS: Keyword = Keyword::choice(
    "weights",
    &["uniform", "cotangent", "distance"],
    Value::Name("uniform"),
    "neighbour weights: the mean of the distinct neighbours, cotangent, or 1 / edge length; cotangent \
     and distance weights are recomputed from the current positions at each step (the trimesh \
     preset's inverse-distance weights once, as trimesh does)",
);
const BOUNDARY_HELP: &str = "what a vertex on a boundary edge (an edge with one face) does: stay put, \
     average like interior vertices, or average only with its boundary neighbours, sliding along \
     the boundary (pymeshlab's boundary=True)";
const BOUNDARY: Keyword =
    Keyword::choice("boundary", &["fixed", "free", "slide"], Value::Name("fixed"), BOUNDARY_HELP)
        .with_presets(&[
            (Pymeshlab, Value::Name("slide")),
            (Paper, Value::Name("free")),
            (Trimesh, Value::Name("free")),
        ]);
const VOLUME: Keyword = Keyword::flag(
    "volume_constraint",
    false,
    "after each step, rescale about the initial centre of mass to restore the enclosed volume \
     (skipped on meshes that enclose none)",
)
.with_presets(&[(Trimesh, Value::Bool(true))]);
const PRESET_HELP: &str = "reproduce another library's filter, quirks included (None: the clean rules)";
const fn preset(names: &'static [&'static str]) -> Keyword {
    Keyword::choice("preset", names, Value::Unset, PRESET_HELP)
}
const WELD: Keyword = Keyword::flag(
    "weld",
    false,
    "smooth the welded mesh: vertices at exactly the same position (UV seams, split normals, an \
     STL's per-face copies) are one vertex, so seams neither open into cracks nor count as \
     boundaries, and every copy gets its position's result",
)
.always_given();
/// Keyword `lamb` as the explicit steps take it.
const LAMB_HELP: &str =
    "step size of each explicit step; 1 moves a vertex all the way to its neighbours' mean";

const LAPLACIAN: &[Keyword] = &[
    Keyword::int("iterations", STEPS, 10, "number of steps").with_presets(&[(Pymeshlab, Value::Int(3))]),
    Keyword::float("lamb", UNIT, 0.5, LAMB_HELP)
        .with_presets(&[(Paper, Value::Float(1.0)), (Pymeshlab, Value::Float(1.0))])
        .with_preset_rules(&[(Trimesh, range(-1e6, 1e6, CLOSED))]),
    WEIGHTS.with_presets(&[(Pymeshlab, Value::Name("cotangent"))]),
    BOUNDARY,
    VOLUME,
    preset(&["trimesh", "pymeshlab", "paper"]),
    WELD,
];

const TAUBIN: &[Keyword] = &[
    Keyword::int(
        "iterations",
        STEPS,
        10,
        "shrink-and-inflate pairs (the trimesh preset counts passes: even ones shrink, odd ones inflate)",
    ),
    Keyword::float("lamb", UNIT, 0.5, "shrink factor of each iteration's first pass"),
    Keyword::float(
        "mu",
        range(-1.0, 0.0, CLOSED),
        -0.53,
        "inflate factor of each iteration's second pass (the pymeshlab preset stores both factors \
         as float32, as pymeshlab does)",
    )
    .with_presets(&[(Trimesh, Value::Float(-0.5))]),
    WEIGHTS,
    BOUNDARY,
    preset(&["trimesh", "pymeshlab"]),
    WELD,
];

const HC: &[Keyword] = &[
    Keyword::int("iterations", STEPS, 10, "number of steps (the pymeshlab preset: calls of its filter)")
        .with_presets(&[(Pymeshlab, Value::Int(1))]),
    Keyword::float("alpha", UNIT, 0.1, "pull toward the original positions (the pymeshlab preset has none)"),
    Keyword::float(
        "beta",
        UNIT,
        0.5,
        "how much of the correction is the vertex's own versus its neighbours' mean (the pymeshlab \
         preset takes only the default)",
    ),
    WEIGHTS,
    BOUNDARY,
    preset(&["trimesh", "pymeshlab"]),
    WELD,
];

const IMPLICIT: &[Keyword] = &[
    Keyword::float(
        "step",
        range(0.0, 1e12, CLOSED),
        1.0,
        "time step, in units of one explicit step with lamb=1",
    )
    .with_presets(&[(Trimesh, Value::Float(0.5))]),
    Keyword::int("iterations", STEPS, 1, "backward Euler steps, each one sparse solve")
        .with_presets(&[(Trimesh, Value::Int(10))]),
    Keyword::float("tol", range(0.0, 1.0, [true, true]), 1e-10, "relative residual at which the solve stops"),
    Keyword::int(
        "max_iter",
        range(1.0, 10_000_000.0, CLOSED),
        10_000,
        "solver iterations before toonmesh.ConvergenceError is raised",
    ),
    WEIGHTS,
    Keyword::choice(
        "boundary",
        &["fixed", "free"],
        Value::Name("fixed"),
        "what a vertex on a boundary edge (an edge with one face) does: stay put, or average like \
         interior vertices",
    )
    .with_presets(&[(Trimesh, Value::Name("free"))]),
    VOLUME,
    preset(&["trimesh"]),
    WELD,
];

fn measured_sigma_r() -> String {
    format!(
        "measured from the mesh: {SIGMA_R_PER_NOISE} times the 90th percentile, over pairs of faces \
         sharing an edge, of the distance between their normals (on a noisy part, the noise), \
         clamped to [{SIGMA_R_MIN}, {SIGMA_R_MAX}]"
    )
}

const PASSES: Keyword = Keyword::int(
    "iterations",
    STEPS,
    20,
    "passes of normal filtering: more removes stronger noise, at a cost linear in the count",
);
const SIGMA_S: Keyword = Keyword::float(
    "sigma_s",
    POSITIVE,
    1.0,
    "width of the spatial kernel, in mean edge lengths of the input mesh (so that it suits any \
     scale and resolution)",
);
const SIGMA_R: Keyword = Keyword::new(
    "sigma_r",
    Kind::Float,
    POSITIVE,
    Value::Measured(measured_sigma_r),
    "width of the range kernel, a distance between unit normals (2 sin(angle / 2): 0.35 is about \
     20 degrees); smaller keeps more detail (and noise), larger smooths more (and rounds weaker \
     creases)",
);

const BILATERAL: &[Keyword] = &[
    PASSES,
    Keyword::int(
        "vertex_iterations",
        STEPS,
        20,
        "vertex-fitting steps after the normals are filtered (0 returns the input unchanged)",
    ),
    SIGMA_S,
    SIGMA_R,
    WELD,
];

const GUIDED: &[Keyword] = &[
    PASSES,
    Keyword::int(
        "vertex_iterations",
        STEPS,
        10,
        "vertex-fitting steps after each of the later passes of normal filtering (the paper \
         preset: after every pass), whose next pass filters the fitted mesh's normals (0 returns \
         the input unchanged)",
    ),
    Keyword::float(
        "sigma_s",
        POSITIVE,
        1.0,
        "width of the spatial kernel, in mean edge lengths of the input mesh (so that it suits any \
         scale and resolution); the paper preset: in mean distances between the centroids of \
         faces sharing an edge, re-measured at every pass, over the faces whose centroids lie \
         within two such distances",
    ),
    SIGMA_R.with_presets(&[(Paper, Value::Float(0.35))]),
    Keyword::choice(
        "preset",
        &["paper"],
        Value::Unset,
        "'paper': Zhang et al.'s rule as their code has it (vertices fitted after every pass, their \
         neighbourhood and widths, no comparison of the faces' own normals); None: the rule \
         measured best on irregular parts",
    ),
    WELD,
];

/// Every smoothing method, in the order the API lists them.
pub const METHODS: [Described; 6] = [
    Described {
        name: "laplacian",
        help:
            "explicit Laplacian smoothing: each step moves every vertex toward its neighbours' weighted mean",
        keywords: LAPLACIAN,
    },
    Described {
        name: "taubin",
        help: "Taubin's shrink-and-inflate smoothing, which does not shrink the mesh",
        keywords: TAUBIN,
    },
    Described {
        name: "hc",
        help: "HC smoothing (Vollmer et al.): Laplacian steps pushed back toward the original positions",
        keywords: HC,
    },
    Described {
        name: "implicit",
        help: "implicit (backward Euler) Laplacian smoothing: stable for any step size",
        keywords: IMPLICIT,
    },
    Described {
        name: "bilateral",
        help: "feature-preserving smoothing by bilateral normal filtering (Zheng et al. 2011)",
        keywords: BILATERAL,
    },
    Described {
        name: "guided",
        help: "feature-preserving smoothing by guided normal filtering (Zhang et al. 2015)",
        keywords: GUIDED,
    },
];

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn every_default_is_of_its_kind_and_in_its_range() {
        for m in &METHODS {
            for k in m.keywords {
                let presets = [Preset::Clean, Trimesh, Pymeshlab, Paper];
                for p in presets.into_iter().filter(|p| m.has(*p)) {
                    let ok = match (k.kind, k.default_for(p)) {
                        (Kind::Int, Value::Int(n)) => k.check_int(p, n).is_ok(),
                        (Kind::Float, Value::Float(x)) => k.check_float(p, x).is_ok(),
                        (Kind::Float, Value::Measured(words)) => !words().is_empty(),
                        (Kind::Name, Value::Name(s)) => k.choose(s).is_ok(),
                        (Kind::Name, Value::Unset) => k.takes_none,
                        (Kind::Bool, Value::Bool(_)) => true,
                        _ => false,
                    };
                    assert!(ok, "{}.{} under {p:?}", m.name, k.name);
                }
            }
            for name in m.presets() {
                assert!(PRESETS.iter().any(|(n, _)| n == name), "{}: {name}", m.name);
            }
        }
    }

    #[test]
    fn ranges_say_which_ends_are_open() {
        let tol = method("implicit").unwrap().keyword("tol").unwrap();
        assert!(tol.check_float(Preset::Clean, 0.0).is_err() && tol.check_float(Preset::Clean, 1e-3).is_ok());
        let e = tol.check_float(Preset::Clean, 1.0).unwrap_err().to_string();
        assert!(e.contains("(0, 1)"), "{e}");
        let lamb = method("laplacian").unwrap().keyword("lamb").unwrap();
        assert!(lamb.check_float(Preset::Clean, -0.5).is_err() && lamb.check_float(Trimesh, -0.5).is_ok());
        let sigma = method("guided").unwrap().keyword("sigma_s").unwrap();
        let e = sigma.check_float(Preset::Clean, f64::NAN).unwrap_err().to_string();
        assert_eq!(e, "sigma_s: must be a finite number > 0, got NaN");
    }
}

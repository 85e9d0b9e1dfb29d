//! The keywords of a smoothing method as a front end hands them over: read by the kinds the
//! method's description (`described`) gives, by name, without listing them again. A keyword not
//! given is the method's described default (see `resolve` and `denoise::resolve`).

use super::denoise::{self, Filter};
pub use super::described::{Keyword, Kind};
use super::options::{self, Args, Method};
use super::{described, Run};
use crate::error::{Error, Result};

/// A keyword's value as a front end read it.
#[derive(Clone, Debug, PartialEq)]
pub enum Given {
    Int(i64),
    Float(f64),
    Name(String),
    Bool(bool),
}

/// A smoothing method by name: one of the Laplacian family or a normal filter.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Smoother {
    Laplacian(Method),
    Normals(Filter),
}

impl Smoother {
    pub fn parse(method: &str) -> Result<Smoother> {
        match Filter::of_method(method) {
            Some(f) => Ok(Smoother::Normals(f)),
            None => options::parse_method(method).map(Smoother::Laplacian),
        }
    }

    /// This method's name as the API spells it.
    pub fn name(self) -> &'static str {
        match self {
            Smoother::Laplacian(m) => options::name(m),
            Smoother::Normals(f) => f.name(),
        }
    }

    /// The keywords this method takes, in the order they are checked.
    pub fn keywords(self) -> &'static [Keyword] {
        described::method(self.name()).map_or(&[], |d| d.keywords)
    }

    /// How this method runs with the keywords `given` (those left out take their defaults),
    /// each of the kind `keywords` says.
    pub fn plan(self, given: Vec<(&str, Given)>) -> Result<Run> {
        let mut given = ByName(given);
        Ok(match self {
            Smoother::Normals(filter) => Run::Normals(denoise::resolve(
                filter,
                &denoise::Args {
                    iterations: given.get("iterations")?,
                    vertex_iterations: given.get("vertex_iterations")?,
                    sigma_s: given.get("sigma_s")?,
                    sigma_r: given.get("sigma_r")?,
                    weld: given.get("weld")?.unwrap_or(false),
                },
            )?),
            Smoother::Laplacian(method) => Run::Laplacian(options::resolve(
                method,
                &Args {
                    iterations: given.get("iterations")?,
                    lamb: given.get("lamb")?,
                    mu: given.get("mu")?,
                    alpha: given.get("alpha")?,
                    beta: given.get("beta")?,
                    step: given.get("step")?,
                    tol: given.get("tol")?,
                    max_iter: given.get("max_iter")?,
                    weights: given.get("weights")?,
                    boundary: given.get("boundary")?,
                    volume_constraint: given.get("volume_constraint")?,
                    preset: given.get("preset")?,
                    weld: given.get("weld")?,
                },
            )?),
        })
    }
}

/// Each kind's value out of a `Given` (the `Given` back when it is of another kind).
macro_rules! given_as {
    ($($kind:ident($t:ty)),*) => {$(
        impl TryFrom<Given> for $t {
            type Error = Given;
            fn try_from(g: Given) -> std::result::Result<$t, Given> {
                match g {
                    Given::$kind(x) => Ok(x),
                    other => Err(other),
                }
            }
        }
    )*};
}
given_as!(Int(i64), Float(f64), Name(String), Bool(bool));

/// The keywords given, taken out by name.
struct ByName<'a>(Vec<(&'a str, Given)>);

impl ByName<'_> {
    /// The value given for `name` (None: not given).
    fn get<T: TryFrom<Given, Error = Given>>(&mut self, name: &str) -> Result<Option<T>> {
        let Some(i) = self.0.iter().position(|(n, _)| *n == name) else { return Ok(None) };
        // a value of another kind than the keyword's is a front end's bug, not the user's
        T::try_from(self.0.swap_remove(i).1)
            .map(Some)
            .map_err(|v| Error::wrong_type(name, format!("cannot take {v:?}")))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn each_method_lists_what_it_reads() {
        let bilateral = Smoother::parse("bilateral").unwrap();
        assert!(bilateral.keywords().iter().any(|k| k.name == "sigma_r"));
        assert!(!bilateral.keywords().iter().any(|k| k.name == "lamb"));
        let run = Smoother::parse("taubin").unwrap().plan(vec![("iterations", Given::Int(3))]).unwrap();
        assert!(matches!(run, Run::Laplacian(p) if p.iterations == 3));
        assert!(Smoother::parse("nope").is_err());
        let e = Smoother::parse("laplacian").unwrap().plan(vec![("lamb", Given::Float(2.0))]).err();
        assert!(e.is_some_and(|e| e.to_string().starts_with("lamb:")));
    }
}

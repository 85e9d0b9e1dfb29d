//! The keywords of a smoothing method as a front end hands them over: read by the kinds the
//! method's description (`described`) gives, by name, without listing them again. A keyword not
//! given is the method's described default (see `resolve` and `denoise::resolve`).

use super::denoise::{self, Filter};
pub use super::described::{Keyword, Kind};
use super::given::ByName;
pub use super::given::Given;
use super::options::{self, Args, Method};
use super::{described, Run};
use crate::error::Result;

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
            Smoother::Normals(filter) => {
                Run::Normals(denoise::resolve(filter, &denoise::Args::take(&mut given)?)?)
            }
            Smoother::Laplacian(method) => {
                Run::Laplacian(options::resolve(method, &Args::take(&mut given)?)?)
            }
        })
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

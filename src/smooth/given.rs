//! A smoothing keyword's value as a front end hands it over, and the keywords given, taken out
//! by name (`keywords::Smoother::plan`), and the `Args` of a family of methods declared from
//! them (`args!`).

use crate::error::{Error, Result};

/// A keyword's value as a front end read it.
#[derive(Clone, Debug, PartialEq)]
pub enum Given {
    Int(i64),
    Float(f64),
    Name(String),
    Bool(bool),
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
pub struct ByName<'a>(pub Vec<(&'a str, Given)>);

impl ByName<'_> {
    /// The value given for `name` (None: not given).
    pub fn get<T: TryFrom<Given, Error = Given>>(&mut self, name: &str) -> Result<Option<T>> {
        let Some(i) = self.0.iter().position(|(n, _)| *n == name) else { return Ok(None) };
        // a value of another kind than the keyword's is a front end's bug, not the user's
        T::try_from(self.0.swap_remove(i).1)
            .map(Some)
            .map_err(|v| Error::wrong_type(name, format!("cannot take {v:?}")))
    }
}

/// Declares `Args`, what the caller passed (None: use the preset's default), `Args::take`, which
/// reads it from the keywords given, and `Args::given`, their names, so that each name is written
/// once.
macro_rules! args {
    ($($field:ident: $t:ty,)*) => {
        /// What the caller passed (None: the method's default, or its preset's).
        #[derive(Debug, Clone, Default)]
        pub struct Args {
            $(pub $field: Option<$t>,)*
        }

        impl Args {
            /// The keywords of these names taken out of `given` (those not there: None).
            pub fn take(given: &mut $crate::smooth::given::ByName<'_>) -> $crate::error::Result<Args> {
                Ok(Args { $($field: given.get(stringify!($field))?,)* })
            }

            /// The names of the keywords given.
            pub fn given(&self) -> impl Iterator<Item = &'static str> + '_ {
                [$((stringify!($field), self.$field.is_some())),*]
                    .into_iter()
                    .filter_map(|(name, given)| given.then_some(name))
            }
        }
    };
}
pub(crate) use args;

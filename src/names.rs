//! Enumerations whose values go by name: in Python arguments, in pickles and in error
//! messages, each name written once (`named_enum!`).

/// `'a', 'b' or 'c'`: the names an argument takes, for an error message.
pub fn one_of(names: &[&str]) -> String {
    listed(&names.iter().map(|n| format!("'{n}'")).collect::<Vec<_>>())
}

/// `a, b or c`.
pub fn listed<S: AsRef<str>>(items: &[S]) -> String {
    let items: Vec<&str> = items.iter().map(AsRef::as_ref).collect();
    match items.split_last() {
        Some((last, rest)) if !rest.is_empty() => format!("{} or {last}", rest.join(", ")),
        _ => items.concat(),
    }
}

/// An enum whose values go by name (`named_enum!`), for code that takes any of them.
pub trait Named: Copy + Sized + 'static {
    fn name(self) -> &'static str;
    fn parse(arg: &str, s: &str) -> crate::error::Result<Self>;
}

/// An enum whose variants have names: `NAMES` (in variant order), `name()`, and
/// `parse(arg, name)`, whose error names the argument and the names it takes (and `Named`).
/// Serialised by name.
#[macro_export]
macro_rules! named_enum {
    ($(#[$meta:meta])* pub enum $enum:ident { $($(#[$vmeta:meta])* $variant:ident = $name:literal,)* }) => {
        $(#[$meta])*
        #[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, serde::Serialize, serde::Deserialize)]
        pub enum $enum {
            $($(#[$vmeta])* #[serde(rename = $name)] $variant,)*
        }

        impl $enum {
            pub const NAMES: &'static [&'static str] = &[$($name),*];

            pub fn name(self) -> &'static str {
                Self::NAMES[self as usize]
            }

            pub fn parse(arg: &str, s: &str) -> $crate::error::Result<Self> {
                match s {
                    $($name => Ok($enum::$variant),)*
                    other => Err($crate::error::Error::invalid(
                        arg,
                        format!("must be {}, got {other:?}", $crate::names::one_of(Self::NAMES)),
                    )),
                }
            }
        }

        impl $crate::names::Named for $enum {
            fn name(self) -> &'static str {
                $enum::name(self)
            }

            fn parse(arg: &str, s: &str) -> $crate::error::Result<Self> {
                $enum::parse(arg, s)
            }
        }
    };
}

#[cfg(test)]
mod tests {
    #[test]
    fn names_are_listed_as_a_sentence() {
        assert_eq!(super::one_of(&["a"]), "'a'");
        assert_eq!(super::one_of(&["a", "b", "c"]), "'a', 'b' or 'c'");
    }
}

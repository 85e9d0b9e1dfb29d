//! A settings value's state: its serde form as JSON, which pickling keeps and hashing reads, and
//! the value made again from it (checked again, as a state may come from anywhere).

use std::hash::{Hash, Hasher};

use serde::Serialize;

use super::{settings_classes, Described, Setting};
use crate::error::{Error, Result};

pub fn state<T: Serialize>(x: &T) -> String {
    serde_json::to_string(x).expect("settings serialise")
}

/// A hash of the state: equal values hash alike.
pub fn hash<T: Serialize>(x: &T) -> u64 {
    let mut h = std::collections::hash_map::DefaultHasher::new();
    state(x).hash(&mut h);
    h.finish()
}

fn restored<T: Described>(state: &str) -> Result<T> {
    let value: T = serde_json::from_str(state).map_err(|e| Error::invalid("state", format!("{e}")))?;
    value.check()?;
    Ok(value)
}

/// `Setting::restore` for each class of the list.
macro_rules! restore {
    ($($class:ident($docs:literal) = $core:path { $($ctors:tt)* })*) => {
        impl Setting {
            /// A value of the settings class `class` from its `state`.
            pub fn restore(class: &str, state: &str) -> Result<Setting> {
                match class {
                    $(stringify!($class) => restored(state).map(Setting::$class),)*
                    other => Err(Error::invalid("cls", format!("no settings class {other:?}"))),
                }
            }
        }
    };
}
settings_classes!(restore);

#[cfg(test)]
mod tests {
    use super::*;
    use crate::render::effects::paper::settings::Paper;

    #[test]
    fn a_state_makes_the_value_again() {
        let paper = Paper::default();
        assert_eq!(Setting::restore("Paper", &state(&paper)).unwrap(), Setting::Paper(paper));
        assert!(Setting::restore("Nope", "{}").unwrap_err().to_string().starts_with("cls:"));
        assert!(Setting::restore("Paper", "{").unwrap_err().to_string().starts_with("state:"));
    }
}

//! A settings value's state: its serde form as JSON, which pickling keeps and hashing reads, and
//! the value made again from it (checked again, as a state may come from anywhere).

use std::hash::{Hash, Hasher};

use serde::Serialize;

use super::{settings_classes, Described, Setting};
use crate::error::{Error, Result};

pub fn state<T: Serialize>(x: &T) -> String {
    serde_json::to_string(x).expect("settings serialise")
}

/// A hash of the state: equal values hash alike (-0.0 as 0.0, which it equals).
pub fn hash<T: Serialize>(x: &T) -> u64 {
    let mut value = serde_json::to_value(x).expect("settings serialise");
    unsigned_zeros(&mut value);
    let mut h = std::collections::hash_map::DefaultHasher::new();
    value.to_string().hash(&mut h);
    h.finish()
}

fn unsigned_zeros(value: &mut serde_json::Value) {
    use serde_json::Value as J;
    match value {
        J::Number(n) if n.as_f64() == Some(0.0) => *value = J::from(0.0),
        J::Array(items) => items.iter_mut().for_each(unsigned_zeros),
        J::Object(fields) => fields.values_mut().for_each(unsigned_zeros),
        _ => {}
    }
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

    #[test]
    fn equal_values_hash_alike() {
        let (plus, minus) =
            (Paper { strength: 0.0, ..Paper::default() }, Paper { strength: -0.0, ..Paper::default() });
        assert_eq!(plus, minus);
        assert_eq!(hash(&plus), hash(&minus));
    }
}

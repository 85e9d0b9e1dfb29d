//! `settings!`: a settings struct whose every field is declared once, on one line beside it:
//!
//! ```text
//! settings! {
//!     #[derive(Clone, Copy, Debug, PartialEq)]
//!     pub struct Shadows {
//!         /// The Rust doc of the field.
//!         pub bias: f64 = 1.0
//!             => float(at_least(0.0).slider(0.0, 8.0)), "depth bias in texels, >= 0";
//!         pub scale: f64 = 1.5 => float(closed(0.25, 64.0)), "pixels a cell covers", pixels;
//!     }
//!     described(positional: 3);
//! }
//! ```
//!
//! A field's line gives its Rust type, its default, its kind (with its rule: `kinds`), its
//! one line of help and its flags (`pixels`, `optional`, `fixed`). From it come the struct,
//! its `Default`, its serde form (a field missing from a saved state takes its default, so
//! older pickles load), its description (`Declared::FIELDS`), reading and writing a field by
//! name (`Declared::field` and `set_field`, through `FieldValue`), and with `described(...)`
//! the whole `Described` impl of a type made by one constructor. The bounds are checked by
//! `check_bounds`, which the type's `validate` starts with; `validate` keeps only the rules
//! between fields and those that are not a range.

use super::{f32_value, mismatch, shortest, unknown, Field, GreyImage, Range, Value};
use crate::error::{Error, Result};
use crate::names::Named;

/// A settings type's fields, each read and written by name (`settings!`, `declared_fields!`).
pub trait Declared {
    /// The type's name, for errors.
    const NAME: &'static str;
    const FIELDS: &'static [Field];
    /// A field's value (None where no field has that name).
    fn field(&self, name: &str) -> Option<Value>;
    /// Sets a field from a value of its kind (its rule is checked by `check_bounds`).
    fn set_field(&mut self, name: &str, value: Value) -> Result<()>;
}

/// The error for a name that is none of `T`'s fields.
pub fn not_a_field<T: Declared>(name: &str) -> Error {
    let names: Vec<&str> = T::FIELDS.iter().map(|f| f.name).collect();
    unknown(name, &names, &format!("a field of {}", T::NAME))
}

/// A Rust type a field holds, read into and out of a `Value`: implemented once per type.
pub trait FieldValue: Sized {
    /// The largest number the type holds as a field reads it back (a number field's rule ends
    /// there; infinite: the rule's own bounds).
    const LARGEST: f64 = f64::INFINITY;
    fn to_value(&self) -> Value;
    fn from_value(field: &str, value: Value) -> Result<Self>;
    /// The value of a field where None is a value too.
    fn from_optional(field: &str, value: Value) -> Result<Option<Self>> {
        match value {
            Value::None => Ok(None),
            other => Self::from_value(field, other).map(Some),
        }
    }
}

impl FieldValue for f64 {
    fn to_value(&self) -> Value {
        Value::Float(*self)
    }

    fn from_value(field: &str, value: Value) -> Result<Self> {
        value.float(field)
    }
}

/// Kept as its shortest decimal, so that a repr reads 0.3 and not 0.30000001192092896.
impl FieldValue for f32 {
    // float32's largest as its shortest decimal reads back (3.4028235e38, a little above
    // f32::MAX as f64, and still stored as f32::MAX)
    const LARGEST: f64 = 3.4028235e38;

    fn to_value(&self) -> Value {
        f32_value(*self)
    }

    fn from_value(field: &str, value: Value) -> Result<Self> {
        value.float(field).map(|x| x as f32)
    }
}

impl FieldValue for u32 {
    fn to_value(&self) -> Value {
        Value::Int(*self as i64)
    }

    fn from_value(field: &str, value: Value) -> Result<Self> {
        let n = value.int(field)?;
        u32::try_from(n).map_err(|_| Error::invalid(field, Range::count(0.0).refusal(n as f64)))
    }
}

/// `FieldValue` for a type that one variant of `Value` holds as it is.
macro_rules! value_field {
    ($($ty:ty => $variant:ident,)*) => {$(
        impl $crate::render::settings::FieldValue for $ty {
            fn to_value(&self) -> $crate::render::settings::Value {
                $crate::render::settings::Value::$variant(self.clone())
            }

            fn from_value(field: &str, value: $crate::render::settings::Value) -> $crate::error::Result<Self> {
                match value {
                    $crate::render::settings::Value::$variant(x) => Ok(x),
                    other => Err($crate::render::settings::mismatch(field, &other)),
                }
            }
        }
    )*};
}
pub(crate) use value_field;

value_field! {
    bool => Bool,
    // a colour or a point
    [f64; 3] => Triple,
    GreyImage => Image,
    [[f64; 4]; 4] => Matrix,
}

/// A field whose accessors take any form of its value (a flag or a name for a setting).
impl FieldValue for Value {
    fn to_value(&self) -> Value {
        self.clone()
    }

    fn from_value(_: &str, value: Value) -> Result<Self> {
        Ok(value)
    }
}

/// A choice among names.
impl<T: Named> FieldValue for T {
    fn to_value(&self) -> Value {
        Value::Text(self.name().to_string())
    }

    fn from_value(field: &str, value: Value) -> Result<Self> {
        T::parse(field, &value.text(field)?)
    }
}

/// None is a value.
impl<T: FieldValue> FieldValue for Option<T> {
    const LARGEST: f64 = T::LARGEST;

    fn to_value(&self) -> Value {
        self.as_ref().map_or(Value::None, T::to_value)
    }

    fn from_value(field: &str, value: Value) -> Result<Self> {
        T::from_optional(field, value)
    }
}

/// A colour with alpha, kept as f32 (read back as its shortest decimal).
impl FieldValue for [f32; 4] {
    fn to_value(&self) -> Value {
        Value::Rgba(self.map(shortest))
    }

    fn from_value(field: &str, value: Value) -> Result<Self> {
        match value {
            Value::Rgba(c) => Ok(c.map(|x| x as f32)),
            other => Err(mismatch(field, &other)),
        }
    }
}

/// A name.
impl FieldValue for String {
    fn to_value(&self) -> Value {
        Value::Text(self.clone())
    }

    fn from_value(field: &str, value: Value) -> Result<Self> {
        value.text(field)
    }
}

/// A name written by the constructor (a light's kind): read only.
impl FieldValue for &'static str {
    fn to_value(&self) -> Value {
        Value::Text(self.to_string())
    }

    fn from_value(field: &str, _: Value) -> Result<Self> {
        Err(Error::invalid(field, "is set by the constructor that makes the value"))
    }
}

/// What a declaration's kind is written with: `float(closed(0.0, 1.0))`,
/// `int(closed(64.0, 8192.0).rule("a power of two"))`, `choice(Names::NAMES)`, `color()`.
pub mod kinds {
    use super::super::{Kind, Range};

    pub const fn float(range: Range) -> Kind {
        Kind::Float(range)
    }

    pub const fn int(range: Range) -> Kind {
        Kind::Int(range)
    }

    pub const fn boolean() -> Kind {
        Kind::Bool
    }

    pub const fn color() -> Kind {
        Kind::Color
    }

    pub const fn vec3() -> Kind {
        Kind::Vec3
    }

    pub const fn image() -> Kind {
        Kind::Image
    }

    pub const fn choice(names: &'static [&'static str]) -> Kind {
        Kind::Choice(names)
    }

    pub const fn setting(class: &'static str) -> Kind {
        Kind::Setting(class)
    }

    pub const fn closed(min: f64, max: f64) -> Range {
        Range::closed(min, max)
    }

    pub const fn open(min: f64, max: f64) -> Range {
        Range::open(min, max)
    }

    pub const fn above_up_to(min: f64, max: f64) -> Range {
        Range::above_up_to(min, max)
    }

    pub const fn at_least(min: f64) -> Range {
        Range::at_least(min)
    }

    pub const fn above(min: f64) -> Range {
        Range::above(min)
    }

    pub const fn finite() -> Range {
        Range::finite()
    }

    pub const fn count(min: f64) -> Range {
        Range::count(min)
    }
}

/// A field's description from its declaration: its kind written with `kinds`, its flags as
/// `Field`'s builders.
macro_rules! declared_field {
    ($name:ident: $ty:ty, $kind:expr, $help:expr $(, $flag:ident)*) => {{
        #[allow(unused_imports)]
        use $crate::render::settings::declare::kinds::*;
        let kind = $kind.within(<$ty as $crate::render::settings::declare::FieldValue>::LARGEST);
        $crate::render::settings::Field::new(stringify!($name), kind, $help) $(.$flag())*
    }};
}
pub(crate) use declared_field;

/// A settings struct declared field by field (the module's docs): the struct, its `Default`,
/// its serde form, `Declared` (through `declared_fields!`) and with `described(...)` its
/// `Described`.
macro_rules! settings {
    (
        $(#[$meta:meta])*
        pub struct $name:ident {
            $(
                $(#[$fmeta:meta])*
                pub $field:ident: $ty:ty = $default:expr => $kind:expr, $help:expr $(, $flag:ident)*;
            )*
        }
        $(described(positional: $positional:expr);)?
    ) => {
        $(#[$meta])*
        #[derive(serde::Serialize, serde::Deserialize)]
        #[serde(default)]
        pub struct $name {
            $($(#[$fmeta])* pub $field: $ty,)*
        }

        impl Default for $name {
            fn default() -> Self {
                $name { $($field: $default,)* }
            }
        }

        $crate::render::settings::declare::declared_fields! {
            $name {
                $($field: $ty [.$field] => $kind, $help $(, $flag)*;)*
            }
        }

        $($crate::render::settings::declare::described!($name, $positional);)?
    };
}
pub(crate) use settings;

/// `Described` for a declared type made by one constructor, `Class(...)`, that takes every
/// field in order (the first `positional` by position) and is checked by its `validate`.
macro_rules! described {
    ($name:ident, $positional:expr) => {
        impl $crate::render::settings::Described for $name {
            $crate::render::settings::one_constructor!(
                <$name as $crate::render::settings::declare::Declared>::FIELDS,
                positional: $positional
            );
        }
    };
}
pub(crate) use described;

/// `Declared` for a type whose fields are not all stored as they are described (a light's
/// direction lives in its kind): each field's line gives its type, how it is reached, its kind,
/// help and flags, as `settings!`'s lines do:
///
/// ```text
/// declared_fields! {
///     Light {
///         kind: &'static str [get kind_name] => choice(&["directional", "point"]), "...", fixed;
///         direction: Option<[f64; 3]> [get placed, set set_placed] => vec3(), "...", optional;
///         color: Srgb [.color] => color(), "the light's sRGB colour";
///     }
/// }
/// ```
///
/// `[.name]` is a stored field (`[.a.b]` one of a part);
/// a last line `..part: Type;` adds the fields of a part that is `Declared` itself; `[get g, set s]` calls `self.g(field)` and
/// `self.s(field, value)?` (a value of the line's type); `[get g]` alone is read only.
macro_rules! declared_fields {
    (
        $type:ident {
            $($field:ident: $ty:ty [$($access:tt)*] => $kind:expr, $help:expr $(, $flag:ident)*;)*
            $(..$part:ident: $part_type:ty;)?
        }
    ) => {
        impl $crate::render::settings::declare::Declared for $type {
            const NAME: &'static str = stringify!($type);
            const FIELDS: &'static [$crate::render::settings::Field] = {
                const OWN: &[$crate::render::settings::Field] = &[
                    $($crate::render::settings::declare::declared_field!($field: $ty, $kind, $help $(, $flag)*),)*
                ];
                const PART: &[$crate::render::settings::Field] =
                    $crate::render::settings::declare::part_fields!($($part_type)?);
                &$crate::render::settings::concat::<_, { OWN.len() + PART.len() }>(OWN, PART)
            };

            fn field(&self, name: &str) -> Option<$crate::render::settings::Value> {
                use $crate::render::settings::declare::FieldValue;
                let this = self;
                match name {
                    $(stringify!($field) => {
                        let v: $ty = $crate::render::settings::declare::field_get!(this, name, $($access)*);
                        Some(v.to_value())
                    })*
                    $(other => $crate::render::settings::declare::Declared::field(&this.$part, other),)?
                    #[allow(unreachable_patterns)]
                    _ => None,
                }
            }

            fn set_field(&mut self, name: &str, value: $crate::render::settings::Value) -> $crate::error::Result<()> {
                use $crate::render::settings::declare::FieldValue;
                let this = self;
                match name {
                    $(stringify!($field) => {
                        let v = <$ty as FieldValue>::from_value(name, value)?;
                        $crate::render::settings::declare::field_set!(this, name, v, $($access)*);
                    })*
                    $(other => return $crate::render::settings::declare::Declared::set_field(&mut this.$part, other, value),)?
                    #[allow(unreachable_patterns)]
                    other => return Err($crate::render::settings::declare::not_a_field::<Self>(other)),
                }
                Ok(())
            }
        }
    };
}

/// The fields of a type's part (`..part: Type;`), none without one.
macro_rules! part_fields {
    () => {
        &[]
    };
    ($part_type:ty) => {
        <$part_type as $crate::render::settings::declare::Declared>::FIELDS
    };
}
pub(crate) use part_fields;

pub(crate) use declared_fields;

/// A field's value, reached as its line says (`declared_fields!`).
macro_rules! field_get {
    ($this:ident, $name:ident, $(. $f:ident)+) => {
        $this$(.$f)+.clone()
    };
    ($this:ident, $name:ident, get $get:ident $(, set $set:ident)?) => {
        $this.$get($name)
    };
}
pub(crate) use field_get;

/// A field written, as its line says (`declared_fields!`).
macro_rules! field_set {
    ($this:ident, $name:ident, $v:ident, $(. $f:ident)+) => {
        $this$(.$f)+ = $v
    };
    ($this:ident, $name:ident, $v:ident, get $get:ident, set $set:ident) => {
        $this.$set($name, $v)?
    };
    ($this:ident, $name:ident, $v:ident, get $get:ident) => {{
        let _ = $v;
        return Err($crate::error::Error::invalid($name, "is set by the constructor that makes the value"));
    }};
}
pub(crate) use field_set;

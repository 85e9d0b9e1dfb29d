//! The machinery of the scene's settings, each described once: a settings type declares each
//! field on one line beside the field (`declare`: its kind and rule, default, help and flags),
//! and lists its constructors (which parameters each takes, in order). Everything a front end
//! needs is derived from this description: the Python classes (keyword constructors, getters,
//! `replace`, a `repr` that evaluates back to an equal value), the type stub, the viewer's
//! controls and the command line's flags. A field's default is what its constructor makes when
//! the field is not given.

mod classes;
pub mod declare;
mod grey_image;
mod range;
pub mod state;
mod value;

pub(crate) use classes::settings_classes;
pub use classes::{Class, Setting, CLASSES};
pub(crate) use declare::settings;
pub use declare::{Declared, FieldValue};
pub use grey_image::{GreyImage, MAX_IMAGE_SIDE};
pub use range::Range;
pub use value::Value;

use serde::de::DeserializeOwned;
use serde::Serialize;

use crate::error::{closest, Error, Result};

/// What a field holds, and so how a front end reads it from the user.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Kind {
    Bool,
    /// An integer within its rule (`check_bounds` checks it).
    Int(Range),
    /// A real number within its rule (`check_bounds` checks it).
    Float(Range),
    /// One of these names.
    Choice(&'static [&'static str]),
    /// An sRGB colour: '#rrggbb' or three numbers in [0, 1].
    Color,
    /// An sRGB colour with alpha.
    Rgba,
    /// Three finite numbers (a point or a direction).
    Vec3,
    /// A sequence of numbers.
    Floats,
    /// (N,) or (N, 3) numbers: a lookup table.
    Table,
    /// A 4x4 matrix.
    Matrix,
    /// One name or several, from these.
    Names(&'static [&'static str]),
    /// An ink kind's style: True (the common style), False (not drawn), a LineStyle or a colour.
    Style,
    /// Another settings class (by its name); some also take a name or a flag, as the field's
    /// help says.
    Setting(&'static str),
    /// A Light or a list of Lights.
    Lights,
    /// A grey image (`GreyImage`): an (H, W) or (H, W, C) array of 8-bit integers or of numbers
    /// in [0, 1].
    Image,
}

impl Kind {
    /// A real number's rule within plus or minus `largest`, what the field's type holds.
    pub const fn within(self, largest: f64) -> Kind {
        match self {
            Kind::Float(range) => Kind::Float(range.within(largest)),
            other => other,
        }
    }

    /// The kind's name, for front ends.
    pub fn name(self) -> &'static str {
        match self {
            Kind::Bool => "bool",
            Kind::Int(_) => "int",
            Kind::Float(_) => "float",
            Kind::Choice(_) => "choice",
            Kind::Names(_) => "names",
            Kind::Setting(_) => "setting",
            Kind::Color => "color",
            Kind::Rgba => "rgba",
            Kind::Vec3 => "vec3",
            Kind::Floats => "floats",
            Kind::Table => "table",
            Kind::Matrix => "matrix",
            Kind::Style => "style",
            Kind::Lights => "lights",
            Kind::Image => "image",
        }
    }
}

/// One field of a settings type.
#[derive(Clone, Copy, Debug)]
pub struct Field {
    pub name: &'static str,
    pub kind: Kind,
    /// None is a value of the field (not only "the default").
    pub optional: bool,
    /// Set by the constructor that makes the value, not by `replace`.
    pub fixed: bool,
    /// A length in output pixels (a width, a spacing, a cell's size): multiplied by the frame's
    /// pixel ratio (`at_pixel_ratio`).
    pub pixels: bool,
    pub help: &'static str,
}

impl Field {
    pub const fn new(name: &'static str, kind: Kind, help: &'static str) -> Field {
        Field { name, kind, optional: false, fixed: false, pixels: false, help }
    }

    /// A real number within `range`.
    pub const fn float(name: &'static str, range: Range, help: &'static str) -> Field {
        Field::new(name, Kind::Float(range), help)
    }

    /// One of the names `choices`.
    pub const fn choice(name: &'static str, choices: &'static [&'static str], help: &'static str) -> Field {
        Field::new(name, Kind::Choice(choices), help)
    }

    pub const fn optional(self) -> Field {
        Field { optional: true, ..self }
    }

    pub const fn fixed(self) -> Field {
        Field { fixed: true, ..self }
    }

    /// A length in output pixels, which the frame's pixel ratio scales.
    pub const fn pixels(self) -> Field {
        Field { pixels: true, ..self }
    }
}

/// A way to make a value: `Class(...)` (name "") or `Class.name(...)`.
#[derive(Clone, Copy, Debug)]
pub struct Constructor {
    pub name: &'static str,
    /// Its parameters, in order: fields, or the constructor-only parameters of
    /// `Described::extras` (a base colour from which a model derives its coefficients).
    pub params: &'static [&'static str],
    /// How many of the first parameters may be given by position, and how many must be given.
    pub positional: usize,
    pub required: usize,
    pub help: &'static str,
}

/// A named constructor of a class, `named!("Class", "name", [params...], positional, required)`,
/// its docstring the file `src/render/settings/docs/Class.name.md`.
macro_rules! named {
    ($class:literal, $name:literal, [$($param:literal),* $(,)?], $positional:expr, $required:expr) => {
        $crate::render::settings::Constructor {
            name: $name,
            params: &[$($param),*],
            positional: $positional,
            required: $required,
            help: include_str!(concat!(
                env!("CARGO_MANIFEST_DIR"), "/src/render/settings/docs/", $class, ".", $name, ".md"
            )),
        }
    };
}
pub(crate) use named;

/// The parts of `impl Described` that a settings type made by one constructor, `Class(...)`,
/// shares with the others: the constructor takes every field, in order, the first
/// `positional` of them by position; a value starts from the type's default; and its check is
/// the type's `validate`, which names the fields as the constructor's arguments.
macro_rules! one_constructor {
    ($fields:expr, positional: $positional:expr) => {
        const CONSTRUCTORS: &'static [$crate::render::settings::Constructor] =
            &[$crate::render::settings::Constructor::only(
                &$crate::render::settings::field_names::<{ $fields.len() }>($fields),
                $positional,
            )];

        fn start(_: &str) -> Self {
            Self::default()
        }

        fn check(&self) -> $crate::error::Result<()> {
            self.validate("")
        }
    };
}
pub(crate) use one_constructor;

/// The names of `fields`, in order (`N` of them): the parameters of a constructor that takes
/// every field.
pub const fn field_names<const N: usize>(fields: &[Field]) -> [&'static str; N] {
    let mut out = [""; N];
    let mut i = 0;
    while i < N {
        out[i] = fields[i].name;
        i += 1;
    }
    out
}

/// `a` then `b` as one constant array (`N` the two lengths together, `a` not empty): a
/// description that gathers lists kept elsewhere.
pub const fn concat<T: Copy, const N: usize>(a: &[T], b: &[T]) -> [T; N] {
    let mut out = [a[0]; N];
    let mut i = 0;
    while i < N {
        out[i] = if i < a.len() { a[i] } else { b[i - a.len()] };
        i += 1;
    }
    out
}

impl Constructor {
    /// The class's only constructor, `Class(...)`, whose first `positional` parameters may be
    /// given by position.
    pub const fn only(params: &'static [&'static str], positional: usize) -> Constructor {
        Constructor { name: "", params, positional, required: 0, help: "" }
    }
}

/// A settings type described for front ends (its class's name and docstring are its `Class`,
/// from `settings_classes!`).
pub trait Described: Class + Declared + Clone + PartialEq + Serialize + DeserializeOwned {
    /// What an unknown keyword is not, where "a parameter of Class.constructor" is not the
    /// best word ("a render option").
    const PARAMETER: Option<&'static str> = None;
    /// Constructor-only parameters.
    const EXTRAS: &'static [Field] = &[];
    const CONSTRUCTORS: &'static [Constructor];
    /// What `constructor` makes from no arguments (its required parameters at a placeholder).
    fn start(constructor: &str) -> Self;
    /// The constructor that makes this value (by default the class's only one).
    fn made_by(&self) -> &'static str {
        ""
    }
    /// A field's value (None where this value has no such field: a Phong exponent of bands).
    fn get(&self, field: &str) -> Value {
        self.field(field).unwrap_or(Value::None)
    }
    /// Sets a field from a value of its kind; range checks are `check`'s.
    fn set(&mut self, field: &str, value: Value) -> Result<()> {
        self.set_field(field, value)
    }
    /// A parameter of `constructor` applied while making a value; fields by default.
    fn apply(&mut self, _constructor: &str, param: &str, value: Value) -> Result<()> {
        self.set(param, value)
    }
    /// A parameter read back from a value it made, for the repr; None where it cannot be
    /// (a colour that a model scaled: the coefficients it set are printed instead).
    fn read(&self, _constructor: &str, param: &str) -> Option<Value> {
        Self::FIELDS.iter().any(|f| f.name == param).then(|| self.get(param))
    }
    /// The core's checks, naming fields as constructor arguments.
    fn check(&self) -> Result<()>;
    /// A field's value of this type given in a shorter form (a name for a Dither); by default
    /// none is taken.
    fn shorthand(field: &str, value: Value) -> Result<Self> {
        Err(mismatch(field, &value))
    }
    /// `constructor` applied to the arguments (`build`, unless a type's parameters depend on
    /// each other in more than their order).
    fn construct(constructor: &str, args: Vec<(&'static str, Value)>) -> Result<Self> {
        build(constructor, args)
    }
}

pub fn constructor<T: Described>(name: &str) -> &'static Constructor {
    T::CONSTRUCTORS.iter().find(|c| c.name == name).expect("a described constructor")
}

/// The field or constructor-only parameter called `name`.
pub fn parameter<T: Described>(name: &str) -> Option<&'static Field> {
    T::FIELDS.iter().chain(T::EXTRAS).find(|f| f.name == name)
}

fn title<T: Described>(c: &Constructor) -> String {
    if c.name.is_empty() {
        T::CLASS.to_string()
    } else {
        format!("{}.{}", T::CLASS, c.name)
    }
}

pub(crate) fn unknown(name: &str, known: &[&str], what: &str) -> Error {
    let hint = closest(name, known).map_or(String::new(), |k| format!("; did you mean '{k}'?"));
    Error::wrong_type(name, format!("not {what}{hint} (they are: {})", known.join(", ")))
}

/// The parameter `name` of `ctor`; an error that lists them for any other name.
fn parameter_of<T: Described>(ctor: &Constructor, name: &str) -> Result<&'static Field> {
    match parameter::<T>(name).filter(|_| ctor.params.contains(&name)) {
        Some(field) => Ok(field),
        None => {
            let what =
                T::PARAMETER.map_or_else(|| format!("a parameter of {}", title::<T>(ctor)), String::from);
            Err(unknown(name, ctor.params, &what))
        }
    }
}

/// The parameters a call of `ctor` names: its first `positional` by position, then the
/// `keywords`; refused when it is given more by position than it takes, a parameter twice, or
/// a name that is none of its parameters.
pub fn bind<T: Described>(
    ctor: &Constructor,
    positional: usize,
    keywords: Vec<String>,
) -> Result<Vec<&'static Field>> {
    if positional > ctor.positional {
        let most = ctor.positional;
        let why =
            format!("{} takes at most {most} positional arguments ({positional} given)", title::<T>(ctor));
        return Err(Error::wrong_type("args", why));
    }
    let mut names: Vec<String> = ctor.params.iter().take(positional).map(|p| p.to_string()).collect();
    for k in keywords {
        if names.contains(&k) {
            return Err(Error::wrong_type(k, format!("{} got it twice", title::<T>(ctor))));
        }
        names.push(k);
    }
    names.iter().map(|n| parameter_of::<T>(ctor, n)).collect()
}

/// Checks that the arguments (name, value; None values dropped by the caller) belong to
/// `constructor` and that its required ones are there.
pub fn check_arguments<T: Described>(ctor: &Constructor, given: &[&str]) -> Result<()> {
    for name in given {
        parameter_of::<T>(ctor, name)?;
    }
    if let Some(missing) = ctor.params[..ctor.required].iter().find(|p| !given.contains(p)) {
        return Err(Error::wrong_type(*missing, format!("{} needs it", title::<T>(ctor))));
    }
    Ok(())
}

/// `constructor` applied to the arguments: in the order of its parameters (so a base colour
/// comes before the coefficients it sets), then checked.
pub fn build<T: Described>(constructor: &str, mut args: Vec<(&'static str, Value)>) -> Result<T> {
    let ctor = self::constructor::<T>(constructor);
    let names: Vec<&str> = args.iter().map(|(n, _)| *n).collect();
    check_arguments::<T>(ctor, &names)?;
    args.sort_by_key(|(n, _)| ctor.params.iter().position(|p| p == n));
    let mut value = T::start(constructor);
    for (name, v) in args {
        value.apply(constructor, name, v)?;
    }
    value.check()?;
    Ok(value)
}

/// `value` with every length in output pixels (its fields marked `pixels`, and those of the
/// settings its fields hold) multiplied by `ratio`: what a frame at `ratio` times the size
/// needs to show the same picture, sharper (a screen's device pixel ratio). Not checked again:
/// a width at its bound stays drawable at any ratio.
pub fn at_pixel_ratio<T: Described>(value: &T, ratio: f64) -> T {
    let mut out = value.clone();
    if ratio == 1.0 {
        return out;
    }
    for f in T::FIELDS {
        let scaled = match value.get(f.name) {
            Value::Float(x) if f.pixels => Value::Float(x * ratio),
            Value::Setting(s) => Value::setting(s.at_pixel_ratio(ratio)),
            _ => continue,
        };
        out.set(f.name, scaled).expect("a field takes back a value of its own kind");
    }
    out
}

/// Checks that every number of `value` (its int and float fields) keeps its field's rule
/// (`prefix` names the fields in errors). A settings type's `validate` starts with it, and
/// keeps for itself only the rules between fields and those that are not a range.
pub fn check_bounds<T: Described>(value: &T, prefix: &str) -> Result<()> {
    for f in T::FIELDS {
        let (Kind::Int(range) | Kind::Float(range)) = f.kind else { continue };
        let x = match value.get(f.name) {
            Value::Float(x) => x,
            Value::Int(i) => i as f64,
            _ => continue,
        };
        if !range.contains(x) {
            let name = crate::error::field(prefix, f.name);
            return Err(Error::invalid(name, range.refusal(x)));
        }
    }
    Ok(())
}

/// A copy of `value` with the fields named changed (None: the field's default), checked.
pub fn replace<T: Described>(value: &T, changes: Vec<(String, Option<Value>)>) -> Result<T> {
    let mut out = value.clone();
    let base = T::start(value.made_by());
    let names: Vec<&str> = T::FIELDS.iter().filter(|f| !f.fixed).map(|f| f.name).collect();
    for (name, v) in changes {
        if !names.contains(&name.as_str()) {
            return Err(unknown(&name, &names, &format!("a field of {} to replace", T::CLASS)));
        }
        out.set(&name, v.unwrap_or_else(|| base.get(&name)))?;
    }
    out.check()?;
    Ok(out)
}

/// The arguments that make `value` again with its constructor: the required ones, and each
/// other that differs from what the constructor makes without it.
pub fn arguments<T: Described>(value: &T) -> (&'static Constructor, Vec<(&'static str, Value)>) {
    let ctor = constructor::<T>(value.made_by());
    let base = T::start(ctor.name);
    let args = ctor
        .params
        .iter()
        .enumerate()
        .filter_map(|(i, &p)| {
            // None always means "the default" to a constructor: it adds nothing to a repr
            let v = value.read(ctor.name, p).filter(|v| *v != Value::None)?;
            (i < ctor.required || base.read(ctor.name, p).as_ref() != Some(&v)).then_some((p, v))
        })
        .collect();
    (ctor, args)
}

/// The fields that the constructor's `args` do not make as `value` has them (a field the
/// constructor does not take, such as a band material's ambient coefficient), with their
/// values: what `replace` must change after the call.
pub fn replaced<T: Described>(
    value: &T,
    ctor: &Constructor,
    args: &[(&'static str, Value)],
) -> Vec<(&'static str, Value)> {
    // a value that its own arguments do not make again prints as its constructor's start
    let made = T::construct(ctor.name, args.to_vec()).unwrap_or_else(|_| T::start(ctor.name));
    T::FIELDS
        .iter()
        .filter(|f| !f.fixed)
        .filter_map(|f| {
            let v = value.get(f.name);
            (v != made.get(f.name)).then_some((f.name, v))
        })
        .collect()
}

/// The call that makes `value` again, `Class.constructor(required, ..., name=value, ...)`,
/// followed by `.replace(name=value, ...)` for the fields that the constructor does not make
/// as `value` has them; each value as `write` spells it (in a front end's own syntax).
pub fn call<T: Described, E>(
    value: &T,
    mut write: impl FnMut(&Value) -> std::result::Result<String, E>,
) -> std::result::Result<String, E> {
    let (ctor, args) = arguments(value);
    let mut parts = Vec::with_capacity(args.len());
    for (i, (name, v)) in args.iter().enumerate() {
        let text = write(v)?;
        let by_position = ctor.params.get(i) == Some(name) && i < ctor.required;
        parts.push(if by_position { text } else { format!("{name}={text}") });
    }
    let dot = if ctor.name.is_empty() { "" } else { "." };
    let mut out = format!("{}{dot}{}({})", T::CLASS, ctor.name, parts.join(", "));
    let changes = replaced(value, ctor, &args);
    if !changes.is_empty() {
        let mut parts = Vec::with_capacity(changes.len());
        for (name, v) in &changes {
            parts.push(format!("{name}={}", write(v)?));
        }
        out += &format!(".replace({})", parts.join(", "));
    }
    Ok(out)
}

/// `T` described for front ends: its class, help, fields (each with its name, kind, bounds,
/// choices or class, whether None is a value, whether only a constructor sets it, and help) and
/// constructors (their name, help, how many parameters go by position and how many must be
/// given, and their parameters, described as fields with the default of each).
pub fn describe<T: Described>() -> Value {
    let text = |s: &str| Value::Text(s.to_string());
    let field = |f: &Field, default: Option<Value>| {
        let mut d = vec![("name", text(f.name)), ("kind", text(f.kind.name()))];
        match f.kind {
            Kind::Int(r) => d.extend(r.describe(true)),
            Kind::Float(r) => d.extend(r.describe(false)),
            Kind::Choice(c) | Kind::Names(c) => {
                d.push(("choices", Value::Names(c.iter().map(|n| n.to_string()).collect())))
            }
            Kind::Setting(class) => d.push(("class", text(class))),
            _ => {}
        }
        d.extend([
            ("optional", Value::Bool(f.optional)),
            ("fixed", Value::Bool(f.fixed)),
            ("pixels", Value::Bool(f.pixels)),
            ("help", text(f.help)),
        ]);
        Value::Map(d.into_iter().chain(default.map(|v| ("default", v))).collect())
    };
    let constructor = |c: &Constructor| {
        let start = T::start(c.name);
        let param = |p: &&str| {
            let f = parameter::<T>(p).expect("a described parameter");
            field(f, Some(start.read(c.name, p).unwrap_or(Value::None)))
        };
        Value::Map(vec![
            ("name", text(c.name)),
            ("help", text(c.help)),
            ("positional", Value::Int(c.positional as i64)),
            ("required", Value::Int(c.required as i64)),
            ("params", Value::List(c.params.iter().map(param).collect())),
        ])
    };
    Value::Map(vec![
        ("class", text(T::CLASS)),
        ("help", text(T::HELP)),
        ("fields", Value::List(T::FIELDS.iter().map(|f| field(f, None)).collect())),
        ("constructors", Value::List(T::CONSTRUCTORS.iter().map(constructor).collect())),
    ])
}

/// Each field with its default: the value `constructor` makes.
pub fn defaults<T: Described>(constructor: &str) -> Vec<(&'static Field, Value)> {
    let start = T::start(constructor);
    T::FIELDS.iter().map(|f| (f, start.get(f.name))).collect()
}

/// An f32 as the f64 of its shortest decimal, so that a repr reads 0.3 and not
/// 0.30000001192092896.
pub fn shortest(x: f32) -> f64 {
    format!("{x}").parse().unwrap_or(x as f64)
}

/// Converts between a field's value and the core's numbers (f32 fields keep their shortest
/// decimal).
pub fn f32_value(x: f32) -> Value {
    Value::Float(shortest(x))
}

pub fn f32s_value(xs: &[f32]) -> Value {
    Value::Floats(xs.iter().map(|&x| shortest(x)).collect())
}

/// The value of a field that this variant of the type lacks, as an error.
pub fn not_here(field: &str, what: &str) -> Error {
    Error::invalid(field, format!("only {what} has it"))
}

/// The value of a field that every value having it holds (a variant's field, read as an
/// Option by its accessors): None is not one.
pub fn required<T>(field: &str, value: Option<T>) -> Result<T> {
    value.ok_or_else(|| mismatch(field, &Value::None))
}

/// A value of the wrong variant for the field: a bug of a front end, not of the user.
pub fn mismatch(field: &str, value: &Value) -> Error {
    Error::wrong_type(field, format!("cannot take {value:?}"))
}

#[cfg(test)]
mod tests;

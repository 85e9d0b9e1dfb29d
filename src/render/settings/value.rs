//! A field's value, as front ends hand it to the core and read it back.

use crate::error::Result;
use crate::render::scene::light::Light;

use super::{mismatch, GreyImage, Setting};

#[derive(Clone, Debug, PartialEq)]
pub enum Value {
    None,
    Bool(bool),
    Int(i64),
    Float(f64),
    /// A name (of a choice).
    Text(String),
    /// A colour or a point.
    Triple([f64; 3]),
    Rgba([f64; 4]),
    Floats(Vec<f64>),
    Rows(Vec<[f64; 3]>),
    Matrix([[f64; 4]; 4]),
    Names(Vec<String>),
    Setting(Box<Setting>),
    Lights(Vec<Light>),
    Image(GreyImage),
    /// Named values, in order: a description for front ends (`describe`).
    Map(Vec<(&'static str, Value)>),
    List(Vec<Value>),
}

impl Value {
    pub fn setting(s: Setting) -> Value {
        Value::Setting(Box::new(s))
    }

    pub fn bool(self, field: &str) -> Result<bool> {
        match self {
            Value::Bool(b) => Ok(b),
            other => Err(mismatch(field, &other)),
        }
    }

    pub fn int(self, field: &str) -> Result<i64> {
        match self {
            Value::Int(i) => Ok(i),
            other => Err(mismatch(field, &other)),
        }
    }

    pub fn float(self, field: &str) -> Result<f64> {
        match self {
            Value::Float(x) => Ok(x),
            Value::Int(i) => Ok(i as f64),
            other => Err(mismatch(field, &other)),
        }
    }

    pub fn opt_float(self, field: &str) -> Result<Option<f64>> {
        match self {
            Value::None => Ok(None),
            other => other.float(field).map(Some),
        }
    }

    pub fn opt_triple(self, field: &str) -> Result<Option<[f64; 3]>> {
        match self {
            Value::None => Ok(None),
            other => other.triple(field).map(Some),
        }
    }

    pub fn text(self, field: &str) -> Result<String> {
        match self {
            Value::Text(s) => Ok(s),
            other => Err(mismatch(field, &other)),
        }
    }

    pub fn triple(self, field: &str) -> Result<[f64; 3]> {
        match self {
            Value::Triple(t) => Ok(t),
            other => Err(mismatch(field, &other)),
        }
    }

    pub fn floats(self, field: &str) -> Result<Vec<f64>> {
        match self {
            Value::Floats(v) => Ok(v),
            other => Err(mismatch(field, &other)),
        }
    }

    pub fn f32s(self, field: &str) -> Result<Vec<f32>> {
        Ok(self.floats(field)?.into_iter().map(|x| x as f32).collect())
    }

    pub fn into_setting(self, field: &str) -> Result<Setting> {
        match self {
            Value::Setting(s) => Ok(*s),
            other => Err(mismatch(field, &other)),
        }
    }
}

impl From<bool> for Value {
    fn from(b: bool) -> Value {
        Value::Bool(b)
    }
}

impl From<f64> for Value {
    fn from(x: f64) -> Value {
        Value::Float(x)
    }
}

impl From<[f64; 3]> for Value {
    fn from(t: [f64; 3]) -> Value {
        Value::Triple(t)
    }
}

impl From<&str> for Value {
    fn from(s: &str) -> Value {
        Value::Text(s.to_string())
    }
}

impl From<Option<f64>> for Value {
    fn from(x: Option<f64>) -> Value {
        x.map_or(Value::None, Value::Float)
    }
}

impl From<Option<[f64; 3]>> for Value {
    fn from(t: Option<[f64; 3]>) -> Value {
        t.map_or(Value::None, Value::Triple)
    }
}

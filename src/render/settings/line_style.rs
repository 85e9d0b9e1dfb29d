//! `LineStyle` described.

use super::{f32_value, one_constructor, Described, Field, Kind, Value};
use crate::error::Result;
use crate::render::effects::outlines::settings::{LineStyle, MAX_WIDTH};

const FIELDS: &[Field] = &[
    Field::new("color", Kind::Color, "the ink's sRGB colour"),
    Field::float(
        "width",
        0.25,
        MAX_WIDTH as f64,
        "width in output pixels, the same at every resolution and supersampling factor",
    )
    .pixels(),
];

impl Described for LineStyle {
    one_constructor!(FIELDS, positional: 2);

    fn get(&self, field: &str) -> Value {
        match field {
            "color" => self.color.into(),
            "width" => f32_value(self.width),
            _ => Value::None,
        }
    }

    fn set(&mut self, field: &str, v: Value) -> Result<()> {
        match field {
            "color" => self.color = v.triple(field)?,
            _ => self.width = v.float(field)? as f32,
        }
        Ok(())
    }
}

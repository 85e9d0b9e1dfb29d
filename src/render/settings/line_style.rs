//! `LineStyle` described.

use super::{f32_value, Constructor, Described, Field, Kind, Value};
use crate::error::Result;
use crate::render::effects::outlines::settings::{LineStyle, MAX_WIDTH};

const FIELDS: &[Field] = &[
    Field::new("color", Kind::Color, "the ink's sRGB colour"),
    Field::new(
        "width",
        Kind::Float { min: 0.25, max: MAX_WIDTH as f64 },
        "width in output pixels, the same at every resolution and supersampling factor",
    ),
];

impl Described for LineStyle {
    const CLASS: &'static str = "LineStyle";
    const HELP: &'static str = include_str!("docs/LineStyle.md");

    const FIELDS: &'static [Field] = FIELDS;

    const CONSTRUCTORS: &'static [Constructor] = &[Constructor::only(&["color", "width"], 2)];

    fn start(_: &str) -> Self {
        LineStyle::default()
    }

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

    fn check(&self) -> Result<()> {
        self.validate("")
    }
}

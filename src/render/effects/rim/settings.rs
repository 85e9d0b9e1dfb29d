//! `Rim` described (`render::settings`).

use super::{Rim, RimBlend, RimSide};
use crate::error::Result;
use crate::render::settings::{one_constructor, Described, Field, Kind, Value};

const FIELDS: &[Field] = &[
    Field::new("color", Kind::Color, "the rim's sRGB colour"),
    Field::float("width", 0.0, 1.0, "the rim covers the surface where n.v < width, 0 to 1"),
    Field::float("softness", 0.0, 1.0, "how far in n.v its border fades, 0 (a hard border) to 1"),
    Field::float("strength", 0.0, 1.0, "the share of its colour at full coverage, 0 to 1"),
    Field::choice(
        "side",
        RimSide::NAMES,
        "where it shows: 'both' sides, the 'lit' side or the 'shadowed' side",
    ),
    Field::choice("blend", RimBlend::NAMES, "'add' (as light) or 'mix' (painted over, as a colour)"),
];

impl Described for Rim {
    one_constructor!(FIELDS, positional: 1);

    fn get(&self, field: &str) -> Value {
        match field {
            "color" => self.color.into(),
            "width" => self.width.into(),
            "softness" => self.softness.into(),
            "strength" => self.strength.into(),
            "side" => self.side.name().into(),
            "blend" => self.blend.name().into(),
            _ => Value::None,
        }
    }

    fn set(&mut self, field: &str, v: Value) -> Result<()> {
        match field {
            "color" => self.color = v.triple(field)?,
            "width" => self.width = v.float(field)?,
            "softness" => self.softness = v.float(field)?,
            "strength" => self.strength = v.float(field)?,
            "side" => self.side = RimSide::parse(field, &v.text(field)?)?,
            _ => self.blend = RimBlend::parse(field, &v.text(field)?)?,
        }
        Ok(())
    }
}

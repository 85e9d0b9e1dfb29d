//! `Dither` described.

use super::{one_constructor, Described, Field, Value};
use crate::error::Result;
use crate::render::effects::dither::{Dither, DitherPattern, DitherSpace};

const FIELDS: &[Field] = &[
    Field::choice("pattern", DitherPattern::NAMES, "the threshold pattern"),
    Field::choice(
        "space",
        DitherSpace::NAMES,
        "what the pattern is fixed to: the screen's pixels or the surface",
    ),
    Field::float("amount", 0.0, 2.0, "how far in L.n a pixel may move toward the neighbouring band, 0 to 2"),
    Field::float("scale", 1.0, 64.0, "pixels a pattern cell covers, 1 to 64").pixels(),
];

impl Described for Dither {
    one_constructor!(FIELDS, positional: 1);

    fn get(&self, field: &str) -> Value {
        match field {
            "pattern" => self.pattern.name().into(),
            "space" => self.space.name().into(),
            "amount" => self.amount.into(),
            "scale" => self.scale.into(),
            _ => Value::None,
        }
    }

    fn set(&mut self, field: &str, v: Value) -> Result<()> {
        match field {
            "pattern" => self.pattern = DitherPattern::parse(field, &v.text(field)?)?,
            "space" => self.space = DitherSpace::parse(field, &v.text(field)?)?,
            "amount" => self.amount = v.float(field)?,
            _ => self.scale = v.float(field)?,
        }
        Ok(())
    }
}

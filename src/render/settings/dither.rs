//! `Dither` described.

use super::{Constructor, Described, Field, Kind, Value};
use crate::error::Result;
use crate::render::effects::dither::{Dither, DitherPattern, DitherSpace};

const FIELDS: &[Field] = &[
    Field::new("pattern", Kind::Choice(DitherPattern::NAMES), "the threshold pattern"),
    Field::new(
        "space",
        Kind::Choice(DitherSpace::NAMES),
        "what the pattern is fixed to: the screen's pixels or the surface",
    ),
    Field::new(
        "amount",
        Kind::Float { min: 0.0, max: 2.0 },
        "how far in L.n a pixel may move toward the neighbouring band, 0 to 2",
    ),
    Field::new("scale", Kind::Float { min: 1.0, max: 64.0 }, "pixels a pattern cell covers, 1 to 64"),
];

impl Described for Dither {
    const CLASS: &'static str = "Dither";
    const HELP: &'static str = include_str!("docs/Dither.md");

    const FIELDS: &'static [Field] = FIELDS;

    const CONSTRUCTORS: &'static [Constructor] =
        &[Constructor::only(&["pattern", "space", "amount", "scale"], 1)];

    fn start(_: &str) -> Self {
        Dither::default()
    }

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

    fn check(&self) -> Result<()> {
        self.validate("")
    }
}

//! `Shadows` described.

use super::{one_constructor, Described, Field, Kind, Value};
use crate::error::{Error, Result};
use crate::render::effects::shadows::settings::{ShadowFilter, Shadows, SHADOW_SIZES};

const FIELDS: &[Field] = &[
    Field::new(
        "size",
        Kind::Int { min: *SHADOW_SIZES.start() as i64, max: *SHADOW_SIZES.end() as i64 },
        "the shadow map's side in texels, a power of two",
    ),
    Field::float("bias", 0.0, 8.0, "depth bias in texels per unit of receiver slope, >= 0"),
    Field::choice("filter", ShadowFilter::NAMES, "how the map is read: 'pcf' (soft edges) or 'none'"),
    Field::float(
        "strength",
        0.0,
        1.0,
        "the share of the light a shadow takes away: 1 a full shadow, 0.5 a half-tone one",
    ),
];

impl Described for Shadows {
    one_constructor!(FIELDS, positional: 3);

    fn get(&self, field: &str) -> Value {
        match field {
            "size" => Value::Int(self.size as i64),
            "bias" => self.bias.into(),
            "filter" => self.filter.name().into(),
            "strength" => self.strength.into(),
            _ => Value::None,
        }
    }

    fn set(&mut self, field: &str, v: Value) -> Result<()> {
        match field {
            "size" => {
                let n = v.int(field)?;
                self.size = u32::try_from(n).map_err(|_| {
                    Error::invalid(
                        field,
                        format!(
                            "must be a power of two from {} to {}, got {n}",
                            SHADOW_SIZES.start(),
                            SHADOW_SIZES.end()
                        ),
                    )
                })?
            }
            "bias" => self.bias = v.float(field)?,
            "strength" => self.strength = v.float(field)?,
            _ => self.filter = ShadowFilter::parse(field, &v.text(field)?)?,
        }
        Ok(())
    }
}

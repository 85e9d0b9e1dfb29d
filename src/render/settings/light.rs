//! `Light` described.

use super::{named, not_here, Constructor, Described, Field, Kind, Setting, Value};
use crate::error::Result;
use crate::render::effects::shadows::settings::Shadows;
use crate::render::scene::light::{Light, LightKind, Space};

const FIELDS: &[Field] = &[
    Field::choice("kind", &["directional", "point"], "directional (sun-like) or point").fixed(),
    Field::new("direction", Kind::Vec3, "a directional light's direction, from the light toward the scene")
        .optional(),
    Field::new("position", Kind::Vec3, "a point light's position").optional(),
    Field::new("color", Kind::Color, "sRGB colour"),
    Field::float("intensity", 0.0, 4.0, "factor on the colour, >= 0"),
    Field::choice(
        "space",
        Space::NAMES,
        "'world', or 'camera': fixed to the view (x right, y up, -z forward)",
    ),
    Field::new(
        "shadows",
        Kind::Setting("Shadows"),
        "a directional light's shadows: True (the default Shadows), False or None (none), or a Shadows",
    )
    .optional(),
];

const CONSTRUCTORS: &[Constructor] = &[
    named!("Light", "directional", ["direction", "color", "intensity", "space", "shadows"], 1, 1),
    named!("Light", "point", ["position", "color", "intensity", "space"], 1, 1),
    named!("Light", "key", [], 0, 0),
];

impl Described for Light {
    const FIELDS: &'static [Field] = FIELDS;

    const CONSTRUCTORS: &'static [Constructor] = CONSTRUCTORS;

    fn start(constructor: &str) -> Self {
        let kind = match constructor {
            "key" => return Light::default(),
            "point" => LightKind::Point { position: [0.0; 3] },
            _ => LightKind::Directional { direction: [0.0, 0.0, -1.0] },
        };
        Light { kind, space: Space::World, color: [1.0; 3], intensity: 1.0, shadows: None }
    }

    fn made_by(&self) -> &'static str {
        match self.kind {
            _ if *self == Light::default() => "key",
            LightKind::Directional { .. } => "directional",
            LightKind::Point { .. } => "point",
        }
    }

    fn get(&self, field: &str) -> Value {
        match (field, self.kind) {
            ("kind", LightKind::Directional { .. }) => "directional".into(),
            ("kind", LightKind::Point { .. }) => "point".into(),
            ("direction", LightKind::Directional { direction }) => direction.into(),
            ("position", LightKind::Point { position }) => position.into(),
            ("color", _) => self.color.into(),
            ("intensity", _) => self.intensity.into(),
            ("space", _) => self.space.name().into(),
            ("shadows", _) => self.shadows.map_or(Value::None, |s| Value::setting(Setting::Shadows(s))),
            _ => Value::None,
        }
    }

    fn set(&mut self, field: &str, v: Value) -> Result<()> {
        match (field, &mut self.kind) {
            ("direction", LightKind::Directional { direction }) => *direction = v.triple(field)?,
            ("position", LightKind::Point { position }) => *position = v.triple(field)?,
            ("direction", _) => return Err(not_here(field, "a directional light")),
            ("position", _) => return Err(not_here(field, "a point light")),
            ("color", _) => self.color = v.triple(field)?,
            ("intensity", _) => self.intensity = v.float(field)?,
            ("space", _) => self.space = Space::parse(field, &v.text(field)?)?,
            _ => {
                self.shadows = match v {
                    Value::None | Value::Bool(false) => None,
                    Value::Bool(true) => Some(Shadows::default()),
                    other => match other.into_setting(field)? {
                        Setting::Shadows(s) => Some(s),
                        other => return Err(super::mismatch(field, &Value::setting(other))),
                    },
                }
            }
        }
        Ok(())
    }

    fn check(&self) -> Result<()> {
        self.validate("")
    }
}

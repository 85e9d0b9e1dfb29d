//! The paper's settings, and their description (`render::settings`).

use serde::{Deserialize, Serialize};

use crate::error::Result;
use crate::render::settings::{check_bounds, one_constructor, Described, Field, GreyImage, Kind, Value};

crate::named_enum! {
    /// What the grain is fixed to.
    pub enum PaperSpace {
        /// The image's pixels: the grain stays still while the scene moves under it.
        Screen = "screen",
        /// The scene's surfaces (world coordinates, mapped on the three axis planes): it turns
        /// with the view, as a painted object's paper would.
        Surface = "surface",
    }
}

#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct Paper {
    /// The grain heights (None: the built-in procedural grain, `grain::procedural`), tiled.
    pub grain: Option<GreyImage>,
    pub space: PaperSpace,
    /// Output pixels a grain texel covers (on the surface: at the scene's centre).
    pub scale: f64,
    /// How much of the pigment the grain's valleys refuse: 0 none, 1 all.
    pub strength: f64,
    /// How much the blank paper's valleys darken it: 0 not at all.
    pub tone: f64,
}

impl Default for Paper {
    fn default() -> Self {
        Paper { grain: None, space: PaperSpace::Screen, scale: 1.5, strength: 0.3, tone: 0.1 }
    }
}

impl Paper {
    /// Checks the settings; `prefix` names them in errors ("" while they are being made). Its
    /// numbers' bounds are its description's (`FIELDS`); the grain was checked when it was read.
    pub fn validate(&self, prefix: &str) -> Result<()> {
        check_bounds(self, prefix)
    }

    /// The linear colour `c` of a pixel whose grain height is `g`: the CPU reference of
    /// `paper_blend` in paper.wgsl with the pass's blending.
    pub fn color(&self, c: [f32; 3], g: f32) -> [f32; 3] {
        let m = 1.0 - self.strength as f32 * (1.0 - g);
        let paper = 1.0 - self.tone as f32 * (1.0 - g);
        c.map(|x| paper * (1.0 - m) + x * m)
    }
}

const FIELDS: &[Field] = &[
    Field::new(
        "grain",
        Kind::Image,
        "the grain's heights: None (a built-in grain) or an image, (H, W) or (H, W, C), tiled",
    )
    .optional(),
    Field::choice(
        "space",
        PaperSpace::NAMES,
        "what the grain is fixed to: the 'screen' or the scene's 'surface'",
    ),
    Field::float("scale", 0.25, 64.0, "output pixels a grain texel covers, 0.25 to 64").pixels(),
    Field::float("strength", 0.0, 1.0, "how much pigment the grain's valleys refuse, 0 to 1"),
    Field::float("tone", 0.0, 1.0, "how much the blank paper's valleys darken it, 0 to 1"),
];

impl Described for Paper {
    one_constructor!(FIELDS, positional: 1);

    fn get(&self, field: &str) -> Value {
        match field {
            "grain" => self.grain.clone().map_or(Value::None, Value::Image),
            "space" => self.space.name().into(),
            "scale" => self.scale.into(),
            "strength" => self.strength.into(),
            "tone" => self.tone.into(),
            _ => Value::None,
        }
    }

    fn set(&mut self, field: &str, v: Value) -> Result<()> {
        match (field, v) {
            ("grain", Value::None) => self.grain = None,
            ("grain", Value::Image(g)) => self.grain = Some(g),
            ("grain", other) => return Err(crate::render::settings::mismatch(field, &other)),
            ("space", v) => self.space = PaperSpace::parse(field, &v.text(field)?)?,
            ("scale", v) => self.scale = v.float(field)?,
            ("strength", v) => self.strength = v.float(field)?,
            (_, v) => self.tone = v.float(field)?,
        }
        Ok(())
    }
}

//! Materials: a shading model (`model.rs`) with its colour coefficients, and the per-pixel
//! effects it carries (`effects::surface`: hatching, dithering).
//!
//! For every model the colour is  C = a_l a_m + sum over lights of ( f(L.n) d_l d_m + s S_l S_m ),
//! with a = ambient, d = diffuse, S = specular, l = light, m = material, all in linear light;
//! the models differ in the diffuse factor f and the highlight factor s.

use serde::{Deserialize, Serialize};

use crate::error::{Error, Result};
use crate::render::color::{check_unit, scaled, to_linear, Srgb};
use crate::render::effects::dither::{Dither, DitherPattern};
use crate::render::effects::hatching::{HatchMode, Hatching};
use crate::render::effects::surface::SurfaceSettings;
use crate::render::effects::surface_effect::Surface;
use crate::render::settings::declare::not_a_field;
use crate::render::settings::{
    f32_value, f32s_value, named, not_here, shortest, Constructor, Declared, Described, Field, FieldValue,
    Kind, Range, Value,
};

use super::model::{
    Highlight, Model, DEFAULT_BAND_VALUES, DEFAULT_SHININESS, DEFAULT_T_H, DEFAULT_T_S,
    PAPER_BAND_THRESHOLDS, PAPER_BAND_VALUES,
};
use crate::error::field;

pub use super::model::kang_table;

/// The base colour of materials when none is given (sRGB).
pub const DEFAULT_COLOR: Srgb = [0.95, 0.55, 0.25];
/// Highlight colours of the Phong and thresholded Phong models (sRGB).
pub const PHONG_SPECULAR: Srgb = [0.5, 0.5, 0.5];
pub const TOON_SPECULAR: Srgb = [0.6, 0.6, 0.6];
/// Shares of the base colour (in linear light) lit by ambient and diffuse light: the shadow side
/// of a Lambert or Phong surface keeps 10%; the thresholded Phong model's shadow side 35%.
const SHADED_AMBIENT: f64 = 0.1;
const SHADED_DIFFUSE: f64 = 0.9;
const TOON_AMBIENT: f64 = 0.35;
const TOON_DIFFUSE: f64 = 0.65;

#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct Material {
    #[serde(flatten)]
    pub model: Model,
    /// sRGB coefficients a_m, d_m, S_m (decoded to linear light for shading).
    pub ambient: Srgb,
    pub diffuse: Srgb,
    pub specular: Srgb,
    /// Shade the vertices and interpolate the colours (Gouraud, as the paper colours vertices)
    /// instead of shading every pixel.
    pub per_vertex: bool,
    /// The per-pixel effects on top of the shading (hatching, dithering).
    pub effects: SurfaceSettings,
    /// How much of what lies behind the surface it hides, in [0, 1]: below 1 the mesh is glass,
    /// composited over what lies behind it (`passes::glass`).
    #[serde(default = "opaque")]
    pub opacity: f32,
}

fn opaque() -> f32 {
    1.0
}

impl Default for Material {
    /// Borquez and Yepez's toon bands on the default colour.
    fn default() -> Self {
        Material::bands(DEFAULT_COLOR, None, None, false).expect("the defaults are valid")
    }
}

impl Material {
    fn with_model(
        model: Model,
        ambient: Srgb,
        diffuse: Srgb,
        specular: Srgb,
        per_vertex: bool,
    ) -> Result<Self> {
        let effects = SurfaceSettings::default();
        let m = Material { model, ambient, diffuse, specular, per_vertex, effects, opacity: opaque() };
        m.validate("")?;
        Ok(m)
    }

    /// Plain Lambert; the ambient term defaults to 10% of `color` and the diffuse to 90%.
    pub fn lambert(color: Srgb, ambient: Option<Srgb>, per_vertex: bool) -> Result<Self> {
        let ambient = ambient.unwrap_or_else(|| scaled(color, SHADED_AMBIENT));
        Self::with_model(Model::Lambert, ambient, scaled(color, SHADED_DIFFUSE), [0.0; 3], per_vertex)
    }

    pub fn phong(
        color: Srgb,
        specular: Option<Srgb>,
        shininess: Option<f32>,
        ambient: Option<Srgb>,
        per_vertex: bool,
    ) -> Result<Self> {
        Self::with_model(
            Model::Phong { shininess: shininess.unwrap_or(DEFAULT_SHININESS) },
            ambient.unwrap_or_else(|| scaled(color, SHADED_AMBIENT)),
            scaled(color, SHADED_DIFFUSE),
            specular.unwrap_or(PHONG_SPECULAR),
            per_vertex,
        )
    }

    /// Al-Rousan et al.'s model; the shadow side keeps 35% of `color` and the lit side reaches it.
    pub fn thresholded_phong(
        color: Srgb,
        t_h: Option<f32>,
        t_s: Option<f32>,
        highlight: Option<Highlight>,
        ambient: Option<Srgb>,
        specular: Option<Srgb>,
        per_vertex: bool,
    ) -> Result<Self> {
        Self::with_model(
            Model::ThresholdedPhong {
                t_h: t_h.unwrap_or(DEFAULT_T_H),
                t_s: t_s.unwrap_or(DEFAULT_T_S),
                highlight: highlight.unwrap_or(Highlight::Blinn),
            },
            ambient.unwrap_or_else(|| scaled(color, TOON_AMBIENT)),
            scaled(color, TOON_DIFFUSE),
            specular.unwrap_or(TOON_SPECULAR),
            per_vertex,
        )
    }

    /// Borquez and Yepez's bands times `color`: the paper's thresholds, and by default values
    /// whose darkest tone keeps the colour (`DEFAULT_BAND_VALUES`; the paper's own values are
    /// `PAPER_BAND_VALUES`).
    pub fn bands(
        color: Srgb,
        thresholds: Option<Vec<f32>>,
        values: Option<Vec<f32>>,
        per_vertex: bool,
    ) -> Result<Self> {
        Self::with_model(
            Model::Bands {
                thresholds: thresholds.unwrap_or_else(|| PAPER_BAND_THRESHOLDS.to_vec()),
                values: values.unwrap_or_else(|| DEFAULT_BAND_VALUES.to_vec()),
            },
            [0.0; 3],
            color,
            [0.0; 3],
            per_vertex,
        )
    }

    /// A lookup table of linear RGB factors applied to `color` (Kang et al.'s by default).
    pub fn lut(table: Option<Vec<[f32; 3]>>, color: Srgb, per_vertex: bool) -> Result<Self> {
        Self::with_model(
            Model::Lut { table: table.unwrap_or_else(kang_table) },
            [0.0; 3],
            color,
            [0.0; 3],
            per_vertex,
        )
    }

    /// Sets the coefficients that a base colour gives under this material's model, as its
    /// constructor does: Lambert and Phong keep 10% of it as ambient and 90% as diffuse, the
    /// thresholded Phong model 35% and 65%; bands and tables take it as it is.
    pub fn set_color(&mut self, color: Srgb) {
        let (ambient, diffuse) = match self.model {
            Model::Lambert | Model::Phong { .. } => (SHADED_AMBIENT, SHADED_DIFFUSE),
            Model::ThresholdedPhong { .. } => (TOON_AMBIENT, TOON_DIFFUSE),
            Model::Bands { .. } | Model::Lut { .. } => {
                self.diffuse = color;
                return;
            }
        };
        self.ambient = scaled(color, ambient);
        self.diffuse = scaled(color, diffuse);
    }

    /// This material with other per-pixel effects, checked against it.
    pub fn with_effects(mut self, effects: SurfaceSettings) -> Result<Self> {
        self.effects = effects;
        self.validate("")?;
        Ok(self)
    }

    pub fn ambient_linear(&self) -> [f32; 3] {
        to_linear(self.ambient)
    }

    pub fn diffuse_linear(&self) -> [f32; 3] {
        to_linear(self.diffuse)
    }

    pub fn specular_linear(&self) -> [f32; 3] {
        to_linear(self.specular)
    }

    /// Checks the material; `prefix` names it in errors ("" while it is being made).
    pub fn validate(&self, prefix: &str) -> Result<()> {
        crate::render::settings::check_bounds(self, prefix)?;
        check_unit(&field(prefix, "ambient"), &self.ambient)?;
        check_unit(&field(prefix, "diffuse"), &self.diffuse)?;
        check_unit(&field(prefix, "specular"), &self.specular)?;
        self.model.validate(prefix)?;
        self.effects.validate(&Surface { model: &self.model, per_vertex: self.per_vertex }, prefix)
    }
}

// Material described for front ends: one field per coefficient of any model; a model's
// constructor takes those it uses, and a base colour from which it derives the colour
// coefficients.

const FIELDS: &[Field] = &[
    Field::choice("model", &Model::NAMES, "the shading model (hatching is 'bands' with hatch strokes)").fixed(),
    Field::new("diffuse", Kind::Color, "the diffuse coefficient d_m, sRGB"),
    Field::new("ambient", Kind::Color, "the ambient coefficient a_m, sRGB"),
    Field::new("specular", Kind::Color, "the highlight coefficient S_m, sRGB"),
    Field::new("per_vertex", Kind::Bool, "shade the vertices and interpolate (Gouraud) instead of every pixel"),
    Field::float(
        "opacity",
        Range::closed(0.0, 1.0),
        "how much of what lies behind it the surface hides: below 1 it is glass, composited in depth order over what lies behind it",
    ),
    Field::float("shininess", Range::above(0.0).within(<f32 as FieldValue>::LARGEST).slider(1.0, 256.0), "Phong's exponent, > 0").optional(),
    Field::float("t_h", Range::closed(-1.0, 1.0), "the thresholded Phong model's diffuse threshold on L.n").optional(),
    Field::float("t_s", Range::closed(-1.0, 1.0), "the thresholded Phong model's highlight threshold").optional(),
    Field::choice(
        "highlight",
        Highlight::NAMES,
        "the highlight term: 'blinn' (n . h) or 'paper' (L . v, as the paper writes it)",
    )
    .optional(),
    Field::new("thresholds", Kind::Floats, "the bands' thresholds on L.n: 1 to 8, strictly increasing").optional(),
    Field::new("values", Kind::Floats, "the bands' tones: one more than the thresholds, each >= 0").optional(),
    Field::new("table", Kind::Table, "a lookup table: (N,) grey or (N, 3) RGB factors, 1 <= N <= 256").optional(),
    Field::new("ink", Kind::Color, "hatch strokes' sRGB colour").optional(),
    Field::float("spacing", Range::closed(2.0, 256.0), "pixels between hatch strokes, 2 to 256").optional().pixels(),
    Field::float(
        "width",
        Range::above_up_to(0.0, 256.0).slider(0.25, 16.0).rule("at most the spacing"),
        "hatch strokes' width in pixels, up to the spacing",
    )
    .optional()
    .pixels(),
    Field::choice(
        "mode",
        HatchMode::NAMES,
        "how hatch strokes are laid: along the principal directions ('field') or straight on the axis planes ('triplanar')",
    )
    .optional(),
    Field::new(
        "dither",
        Kind::Setting("Dither"),
        "dithering between bands: None, a pattern name or a Dither (needs per-pixel shading)",
    )
    .optional(),
    Field::new("rim", Kind::Setting("Rim"), "a rim light along the silhouette: None or a Rim").optional(),
];

const EXTRAS: &[Field] = &[
    Field::new("color", Kind::Color, "the base colour, from which the model derives its coefficients"),
    Field::choice("preset", &["paper"], "'paper': the paper's band values (a black darkest band)"),
];

/// A shading model's constructor, `Material.<model>(color, ...)`: its base colour may be
/// given by position, and no parameter must be given.
macro_rules! model {
    ($name:literal, [$($param:literal),* $(,)?]) => {
        named!("Material", $name, [$($param),*], 1, 0)
    };
}

const CONSTRUCTORS: &[Constructor] = &[
    model!("lambert", ["color", "ambient", "diffuse", "per_vertex", "opacity", "rim"]),
    model!("phong", ["color", "specular", "shininess", "ambient", "diffuse", "per_vertex", "opacity", "rim"]),
    model!(
        "thresholded_phong",
        [
            "color",
            "t_h",
            "t_s",
            "highlight",
            "ambient",
            "specular",
            "diffuse",
            "per_vertex",
            "opacity",
            "dither",
            "rim"
        ]
    ),
    model!("bands", ["color", "thresholds", "preset", "values", "per_vertex", "opacity", "dither", "rim"]),
    model!(
        "hatching",
        [
            "color",
            "ink",
            "thresholds",
            "values",
            "spacing",
            "width",
            "mode",
            "per_vertex",
            "opacity",
            "dither",
            "rim"
        ]
    ),
    // the table comes first, and may be given by position too
    named!("Material", "lut", ["table", "color", "per_vertex", "opacity", "dither", "rim"], 2, 0),
];

fn hatching(m: &Material) -> Option<&Hatching> {
    m.effects.hatching.as_ref()
}

/// Material's fields, by hand: which a value has depends on its model.
impl Declared for Material {
    const NAME: &'static str = "Material";

    const FIELDS: &'static [Field] = FIELDS;

    /// None where no field has the name; `Value::None` where this model has no such field.
    fn field(&self, field: &str) -> Option<Value> {
        let h = hatching(self);
        Some(match (field, &self.model) {
            ("model", m) => m.name().into(),
            ("diffuse", _) => self.diffuse.into(),
            ("ambient", _) => self.ambient.into(),
            ("specular", _) => self.specular.into(),
            ("per_vertex", _) => self.per_vertex.into(),
            ("opacity", _) => f32_value(self.opacity),
            ("shininess", Model::Phong { shininess }) => f32_value(*shininess),
            ("t_h", Model::ThresholdedPhong { t_h, .. }) => f32_value(*t_h),
            ("t_s", Model::ThresholdedPhong { t_s, .. }) => f32_value(*t_s),
            ("highlight", Model::ThresholdedPhong { highlight, .. }) => highlight.name().into(),
            ("thresholds", Model::Bands { thresholds, .. }) => f32s_value(thresholds),
            ("values", Model::Bands { values, .. }) => f32s_value(values),
            ("table", Model::Lut { table }) => Value::Rows(table.iter().map(|r| r.map(shortest)).collect()),
            ("ink", _) if h.is_some() => h.map(|h| h.ink).into(),
            ("spacing", _) => h.map(|h| h.spacing).into(),
            ("width", _) => h.map(|h| h.width).into(),
            ("mode", _) => h.map_or(Value::None, |h| h.mode.name().into()),
            ("dither", _) => self.effects.dither.to_value(),
            ("rim", _) => self.effects.rim.to_value(),
            _ if FIELDS.iter().any(|f| f.name == field) => Value::None,
            _ => return None,
        })
    }

    fn set_field(&mut self, field: &str, v: Value) -> Result<()> {
        let hatch = self.effects.hatching.as_mut();
        match (field, &mut self.model, hatch) {
            ("diffuse", ..) => self.diffuse = v.triple(field)?,
            ("ambient", ..) => self.ambient = v.triple(field)?,
            ("specular", ..) => self.specular = v.triple(field)?,
            ("per_vertex", ..) => self.per_vertex = v.bool(field)?,
            ("opacity", ..) => self.opacity = v.float(field)? as f32,
            ("shininess", Model::Phong { shininess }, _) => *shininess = v.float(field)? as f32,
            ("t_h", Model::ThresholdedPhong { t_h, .. }, _) => *t_h = v.float(field)? as f32,
            ("t_s", Model::ThresholdedPhong { t_s, .. }, _) => *t_s = v.float(field)? as f32,
            ("highlight", Model::ThresholdedPhong { highlight, .. }, _) => {
                *highlight = Highlight::parse(field, &v.text(field)?)?
            }
            ("thresholds", Model::Bands { thresholds, .. }, _) => *thresholds = v.f32s(field)?,
            ("values", Model::Bands { values, .. }, _) => *values = v.f32s(field)?,
            ("table", Model::Lut { table }, _) => match v {
                Value::Rows(rows) => *table = rows.iter().map(|r| r.map(|x| x as f32)).collect(),
                other => return Err(crate::render::settings::mismatch(field, &other)),
            },
            ("ink", _, Some(h)) => h.ink = v.triple(field)?,
            ("spacing", _, Some(h)) => h.spacing = v.float(field)?,
            ("width", _, Some(h)) => h.width = v.float(field)?,
            ("mode", _, Some(h)) => h.mode = HatchMode::parse(field, &v.text(field)?)?,
            ("dither", ..) => {
                self.effects.dither = match v {
                    Value::Text(name) => Some(Dither::new(DitherPattern::parse(field, &name)?)),
                    other => FieldValue::from_value(field, other)?,
                }
            }
            ("rim", ..) => self.effects.rim = FieldValue::from_value(field, v)?,
            ("shininess", ..) => return Err(not_here(field, "a phong material")),
            ("t_h" | "t_s" | "highlight", ..) => return Err(not_here(field, "a thresholded_phong material")),
            ("thresholds" | "values", ..) => return Err(not_here(field, "a bands or hatching material")),
            ("table", ..) => return Err(not_here(field, "a lut material")),
            ("ink" | "spacing" | "width" | "mode", ..) => return Err(not_here(field, "a hatching material")),
            (other, ..) => return Err(not_a_field::<Self>(other)),
        }
        Ok(())
    }
}

impl Described for Material {
    const EXTRAS: &'static [Field] = EXTRAS;

    const CONSTRUCTORS: &'static [Constructor] = CONSTRUCTORS;

    fn start(constructor: &str) -> Self {
        let c = DEFAULT_COLOR;
        match constructor {
            "lambert" => Material::lambert(c, None, false),
            "phong" => Material::phong(c, None, None, None, false),
            "thresholded_phong" => Material::thresholded_phong(c, None, None, None, None, None, false),
            "lut" => Material::lut(None, c, false),
            // the tone picks the number of stroke layers: the paper's values reach all of them
            "hatching" => {
                Material::bands([1.0; 3], None, Some(PAPER_BAND_VALUES.to_vec()), false).and_then(|m| {
                    m.with_effects(SurfaceSettings {
                        hatching: Some(Hatching::default()),
                        ..Default::default()
                    })
                })
            }
            _ => Material::bands(c, None, None, false),
        }
        .expect("the defaults are valid")
    }

    fn made_by(&self) -> &'static str {
        match self.model {
            _ if hatching(self).is_some() => "hatching",
            ref m => m.name(),
        }
    }

    fn apply(&mut self, _: &str, param: &str, value: Value) -> Result<()> {
        match param {
            "color" => self.set_color(value.triple(param)?),
            "preset" => match value.text(param)?.as_str() {
                "paper" => self.set("values", f32s_value(&PAPER_BAND_VALUES))?,
                other => {
                    return Err(Error::invalid(param, format!("must be None or 'paper', got {other:?}")))
                }
            },
            _ => self.set(param, value)?,
        }
        Ok(())
    }

    fn read(&self, constructor: &str, param: &str) -> Option<Value> {
        match (param, constructor) {
            // bands, hatching and tables take the colour as their diffuse coefficient
            ("color", "bands" | "hatching" | "lut") => Some(self.diffuse.into()),
            ("color" | "preset", _) => None,
            _ => Some(self.get(param)),
        }
    }

    fn check(&self) -> Result<()> {
        self.validate("")
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn constructors_apply_defaults_and_checks() {
        let m = Material::default();
        assert_eq!(
            m.model,
            Model::Bands { thresholds: PAPER_BAND_THRESHOLDS.to_vec(), values: DEFAULT_BAND_VALUES.to_vec() }
        );
        assert_eq!(m.diffuse, DEFAULT_COLOR);
        let l = Material::lambert([1.0, 1.0, 1.0], None, false).unwrap();
        assert!((crate::render::color::srgb_to_linear(l.ambient[0]) - 0.1).abs() < 1e-12);
        assert!(Material::thresholded_phong(DEFAULT_COLOR, Some(2.0), None, None, None, None, false).is_err());
        assert!(Material::bands(DEFAULT_COLOR, Some(vec![0.5, 0.2]), Some(vec![0.0; 3]), false).is_err());
        assert!(Material::bands([2.0, 0.0, 0.0], None, None, false).is_err());
        assert_eq!(Model::NAMES[Model::Lut { table: vec![] }.id() as usize], "lut");
    }

    #[test]
    fn a_material_survives_its_text_form() {
        let m = Material::thresholded_phong(
            DEFAULT_COLOR,
            Some(0.1),
            None,
            Some(Highlight::Paper),
            None,
            None,
            true,
        )
        .unwrap();
        let back: Material = serde_json::from_str(&serde_json::to_string(&m).unwrap()).unwrap();
        assert_eq!(back, m);
    }
}

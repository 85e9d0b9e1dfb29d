//! `Material` described: one field per coefficient of any model; a model's constructor takes
//! those it uses, and a base colour from which it derives the colour coefficients.

use super::{f32_value, f32s_value, named, not_here, Constructor, Described, Field, Kind, Setting, Value};
use crate::error::{Error, Result};
use crate::render::effects::dither::{Dither, DitherPattern};
use crate::render::effects::hatching::{HatchMode, Hatching};
use crate::render::effects::surface::SurfaceSettings;
use crate::render::scene::material::{Material, DEFAULT_COLOR};
use crate::render::scene::model::{Highlight, Model, PAPER_BAND_VALUES};

const FIELDS: &[Field] = &[
    Field::choice("model", &Model::NAMES, "the shading model (hatching is 'bands' with hatch strokes)").fixed(),
    Field::new("diffuse", Kind::Color, "the diffuse coefficient d_m, sRGB"),
    Field::new("ambient", Kind::Color, "the ambient coefficient a_m, sRGB"),
    Field::new("specular", Kind::Color, "the highlight coefficient S_m, sRGB"),
    Field::new("per_vertex", Kind::Bool, "shade the vertices and interpolate (Gouraud) instead of every pixel"),
    Field::float("shininess", 1.0, 256.0, "Phong's exponent, > 0").optional(),
    Field::float("t_h", -1.0, 1.0, "the thresholded Phong model's diffuse threshold on L.n").optional(),
    Field::float("t_s", -1.0, 1.0, "the thresholded Phong model's highlight threshold").optional(),
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
    Field::float("spacing", 2.0, 256.0, "pixels between hatch strokes, 2 to 256").optional().pixels(),
    Field::float("width", 0.25, 16.0, "hatch strokes' width in pixels, up to the spacing").optional().pixels(),
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
    model!("lambert", ["color", "ambient", "diffuse", "per_vertex", "rim"]),
    model!("phong", ["color", "specular", "shininess", "ambient", "diffuse", "per_vertex", "rim"]),
    model!(
        "thresholded_phong",
        ["color", "t_h", "t_s", "highlight", "ambient", "specular", "diffuse", "per_vertex", "dither", "rim"]
    ),
    model!("bands", ["color", "thresholds", "preset", "values", "per_vertex", "dither", "rim"]),
    model!(
        "hatching",
        ["color", "ink", "thresholds", "values", "spacing", "width", "mode", "per_vertex", "dither", "rim"]
    ),
    // the table comes first, and may be given by position too
    named!("Material", "lut", ["table", "color", "per_vertex", "dither", "rim"], 2, 0),
];

fn hatching(m: &Material) -> Option<&Hatching> {
    m.effects.hatching.as_ref()
}

impl Described for Material {
    const FIELDS: &'static [Field] = FIELDS;

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

    fn get(&self, field: &str) -> Value {
        let h = hatching(self);
        match (field, &self.model) {
            ("model", m) => m.name().into(),
            ("diffuse", _) => self.diffuse.into(),
            ("ambient", _) => self.ambient.into(),
            ("specular", _) => self.specular.into(),
            ("per_vertex", _) => self.per_vertex.into(),
            ("shininess", Model::Phong { shininess }) => f32_value(*shininess),
            ("t_h", Model::ThresholdedPhong { t_h, .. }) => f32_value(*t_h),
            ("t_s", Model::ThresholdedPhong { t_s, .. }) => f32_value(*t_s),
            ("highlight", Model::ThresholdedPhong { highlight, .. }) => highlight.name().into(),
            ("thresholds", Model::Bands { thresholds, .. }) => f32s_value(thresholds),
            ("values", Model::Bands { values, .. }) => f32s_value(values),
            ("table", Model::Lut { table }) => Value::Rows(
                table.iter().map(|r| r.map(|x| format!("{x}").parse().unwrap_or(x as f64))).collect(),
            ),
            ("ink", _) if h.is_some() => h.map(|h| h.ink).into(),
            ("spacing", _) => h.map(|h| h.spacing).into(),
            ("width", _) => h.map(|h| h.width).into(),
            ("mode", _) => h.map_or(Value::None, |h| h.mode.name().into()),
            ("dither", _) => self.effects.dither.map_or(Value::None, |d| Value::setting(Setting::Dither(d))),
            ("rim", _) => self.effects.rim.map_or(Value::None, |r| Value::setting(Setting::Rim(r))),
            _ => Value::None,
        }
    }

    fn set(&mut self, field: &str, v: Value) -> Result<()> {
        let hatch = self.effects.hatching.as_mut();
        match (field, &mut self.model, hatch) {
            ("diffuse", ..) => self.diffuse = v.triple(field)?,
            ("ambient", ..) => self.ambient = v.triple(field)?,
            ("specular", ..) => self.specular = v.triple(field)?,
            ("per_vertex", ..) => self.per_vertex = v.bool(field)?,
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
                other => return Err(super::mismatch(field, &other)),
            },
            ("ink", _, Some(h)) => h.ink = v.triple(field)?,
            ("spacing", _, Some(h)) => h.spacing = v.float(field)?,
            ("width", _, Some(h)) => h.width = v.float(field)?,
            ("mode", _, Some(h)) => h.mode = HatchMode::parse(field, &v.text(field)?)?,
            ("dither", ..) => {
                self.effects.dither = match v {
                    Value::None => None,
                    Value::Text(name) => Some(Dither::new(DitherPattern::parse(field, &name)?)),
                    other => match other.into_setting(field)? {
                        Setting::Dither(d) => Some(d),
                        other => return Err(super::mismatch(field, &Value::setting(other))),
                    },
                }
            }
            ("rim", ..) => {
                self.effects.rim = match v {
                    Value::None => None,
                    other => match other.into_setting(field)? {
                        Setting::Rim(r) => Some(r),
                        other => return Err(super::mismatch(field, &Value::setting(other))),
                    },
                }
            }
            ("shininess", ..) => return Err(not_here(field, "a phong material")),
            ("t_h" | "t_s" | "highlight", ..) => return Err(not_here(field, "a thresholded_phong material")),
            ("thresholds" | "values", ..) => return Err(not_here(field, "a bands or hatching material")),
            ("table", ..) => return Err(not_here(field, "a lut material")),
            _ => return Err(not_here(field, "a hatching material")),
        }
        Ok(())
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

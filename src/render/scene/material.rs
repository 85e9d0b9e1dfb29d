//! Materials: a shading model (`model.rs`) with its colour coefficients, and the per-pixel
//! effects it carries (`effects::surface`: hatching, dithering).
//!
//! For every model the colour is  C = a_l a_m + sum over lights of ( f(L.n) d_l d_m + s S_l S_m ),
//! with a = ambient, d = diffuse, S = specular, l = light, m = material, all in linear light;
//! the models differ in the diffuse factor f and the highlight factor s.

use serde::{Deserialize, Serialize};

use crate::error::Result;
use crate::render::color::{check_unit, scaled, to_linear, Srgb};
use crate::render::effects::surface::SurfaceSettings;
use crate::render::effects::surface_effect::Surface;

use super::model::{
    Highlight, Model, DEFAULT_BAND_VALUES, DEFAULT_SHININESS, DEFAULT_T_H, DEFAULT_T_S, PAPER_BAND_THRESHOLDS,
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
        let m =
            Material { model, ambient, diffuse, specular, per_vertex, effects: SurfaceSettings::default() };
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
        check_unit(&field(prefix, "ambient"), &self.ambient)?;
        check_unit(&field(prefix, "diffuse"), &self.diffuse)?;
        check_unit(&field(prefix, "specular"), &self.specular)?;
        self.model.validate(prefix)?;
        self.effects.validate(&Surface { model: &self.model, per_vertex: self.per_vertex }, prefix)
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

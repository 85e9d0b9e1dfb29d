//! Lights: directional (sun-like) or point lights, fixed in the world or to the camera.

use glam::{DMat4, DVec3};
use serde::{Deserialize, Serialize};

use crate::error::{Error, Result};
use crate::render::color::{check_unit, to_linear, Srgb};
use crate::render::effects::shadows::settings::Shadows;

use crate::error::field;
use crate::render::settings::declare::{declared_fields, value_field};
use crate::render::settings::{named, not_here, required, Constructor, Described};

/// Most lights one scene may have (the shader's fixed-size array).
pub const MAX_LIGHTS: usize = 8;

#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
#[serde(tag = "kind", rename_all = "snake_case")]
pub enum LightKind {
    /// Parallel light travelling along `direction` (from the light toward the scene).
    Directional { direction: [f64; 3] },
    /// Light radiating from `position`, without falloff.
    Point { position: [f64; 3] },
}

crate::named_enum! {
    /// What a light's direction or position is given in.
    pub enum Space {
        World = "world",
        /// Fixed to the camera: x right, y up, -z forward (a light that moves with the view).
        Camera = "camera",
    }
}

#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
pub struct Light {
    pub kind: LightKind,
    pub space: Space,
    /// sRGB colour; d_l = S_l of the papers is its linear light times `intensity`.
    pub color: Srgb,
    pub intensity: f64,
    /// Whether (and how) the light casts shadows: directional lights only.
    pub shadows: Option<Shadows>,
}

impl Default for Light {
    /// A key light from the upper left, behind the viewer, that moves with the camera.
    fn default() -> Self {
        Light {
            kind: LightKind::Directional { direction: [0.4, -0.55, -0.75] },
            space: Space::Camera,
            color: [1.0, 1.0, 1.0],
            intensity: 1.0,
            shadows: None,
        }
    }
}

/// A light as the shader sees it, in view space.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum ViewLight {
    /// Unit vector from the surface toward the light (the papers' L).
    Toward(DVec3),
    At(DVec3),
}

declared_fields! {
    Light {
        kind: &'static str [get kind_name] => choice(&["directional", "point"]), "directional (sun-like) or point", fixed;
        direction: Option<[f64; 3]> [get placed, set set_placed] => vec3(),
            "a directional light's direction, from the light toward the scene", optional;
        position: Option<[f64; 3]> [get placed, set set_placed] => vec3(), "a point light's position", optional;
        color: Srgb [.color] => color(), "sRGB colour";
        intensity: f64 [.intensity] => float(at_least(0.0).slider(0.0, 4.0)), "factor on the colour, >= 0";
        space: Space [.space] => choice(Space::NAMES),
            "'world', or 'camera': fixed to the view (x right, y up, -z forward)";
        shadows: Option<Shadows> [.shadows] => setting("Shadows"),
            "a directional light's shadows: True (the default Shadows), False or None (none), or a Shadows", optional;
    }
}

// a field of lights (`RenderOptions.lights`)
value_field! {
    Vec<Light> => Lights,
}

/// The fields that live in the kind.
impl Light {
    fn kind_name(&self, _: &str) -> &'static str {
        match self.kind {
            LightKind::Directional { .. } => "directional",
            LightKind::Point { .. } => "point",
        }
    }

    /// A directional light's `direction` or a point light's `position`: None on the other.
    fn placed(&self, field: &str) -> Option<[f64; 3]> {
        match (field, self.kind) {
            ("direction", LightKind::Directional { direction }) => Some(direction),
            ("position", LightKind::Point { position }) => Some(position),
            _ => None,
        }
    }

    fn set_placed(&mut self, field: &str, value: Option<[f64; 3]>) -> Result<()> {
        let place = match (field, &mut self.kind) {
            ("direction", LightKind::Directional { direction }) => direction,
            ("position", LightKind::Point { position }) => position,
            ("direction", _) => return Err(not_here(field, "a directional light")),
            _ => return Err(not_here(field, "a point light")),
        };
        *place = required(field, value)?;
        Ok(())
    }
}

const CONSTRUCTORS: &[Constructor] = &[
    named!("Light", "directional", ["direction", "color", "intensity", "space", "shadows"], 1, 1),
    named!("Light", "point", ["position", "color", "intensity", "space"], 1, 1),
    named!("Light", "key", [], 0, 0),
];

impl Described for Light {
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

    fn check(&self) -> Result<()> {
        self.validate("")
    }
}

impl Light {
    /// Checks the light; `prefix` names it in errors ("" while it is being made).
    pub fn validate(&self, prefix: &str) -> Result<()> {
        let arg = |name| field(prefix, name);
        match self.kind {
            LightKind::Directional { direction } => {
                let d = DVec3::from_array(direction);
                if !d.is_finite() {
                    return Err(Error::invalid(
                        arg("direction"),
                        format!("must be finite, got {direction:?}"),
                    ));
                }
                if !(d.length() > 1e-300) {
                    return Err(Error::invalid(arg("direction"), "must not be the zero vector"));
                }
            }
            LightKind::Point { position } => {
                if !DVec3::from_array(position).is_finite() {
                    return Err(Error::invalid(arg("position"), format!("must be finite, got {position:?}")));
                }
            }
        }
        check_unit(&arg("color"), &self.color)?;
        crate::render::settings::check_bounds(self, prefix)?;
        if let Some(s) = &self.shadows {
            if !matches!(self.kind, LightKind::Directional { .. }) {
                return Err(Error::invalid(arg("shadows"), "only directional lights cast shadows"));
            }
            s.validate(&arg("shadows"))?;
        }
        Ok(())
    }

    /// d_l = S_l: linear light of the colour times the intensity.
    pub fn radiance(&self) -> [f32; 3] {
        to_linear(self.color).map(|c| c * self.intensity as f32)
    }

    pub fn space_name(&self) -> &'static str {
        self.space.name()
    }

    pub fn to_view(&self, view: &DMat4) -> ViewLight {
        let m = match self.space {
            Space::World => *view,
            Space::Camera => DMat4::IDENTITY,
        };
        match self.kind {
            LightKind::Directional { direction } => {
                ViewLight::Toward(-m.transform_vector3(DVec3::from_array(direction)).normalize())
            }
            LightKind::Point { position } => ViewLight::At(m.transform_point3(DVec3::from_array(position))),
        }
    }
}

/// Checks a scene's lights together: how many, and that at most one casts shadows.
pub fn validate_lights(lights: &[Light]) -> Result<()> {
    if lights.len() > MAX_LIGHTS {
        return Err(Error::invalid("lights", format!("at most {MAX_LIGHTS} lights, got {}", lights.len())));
    }
    let casting: Vec<usize> =
        lights.iter().enumerate().filter(|(_, l)| l.shadows.is_some()).map(|(i, _)| i).collect();
    if casting.len() > 1 {
        return Err(Error::invalid(
            "lights",
            format!("one light may cast shadows, but lights {casting:?} do"),
        ));
    }
    Ok(())
}

/// The light that casts shadows, if any, and its index.
pub fn shadow_caster(lights: &[Light]) -> Option<(usize, &Light, Shadows)> {
    lights.iter().enumerate().find_map(|(i, l)| l.shadows.map(|s| (i, l, s)))
}

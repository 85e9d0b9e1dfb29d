//! A scene and frame checked together, once per render, with what every later step would
//! otherwise look up again resolved: the shadow-casting light, the lights in the order the
//! shaders see them, and which of them are point lights.

use crate::error::Result;

use super::camera::Camera;
use super::light::{shadow_caster, validate_lights, Light, LightKind};
use super::sequence::SequenceFrame;
use super::{check_transform, FrameSpec, Scene};
use crate::render::effects::shadows::settings::Shadows;

/// The light that casts shadows.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Caster {
    /// Its index in the scene's lights.
    pub index: usize,
    pub light: Light,
    pub settings: Shadows,
}

/// What a device allows a frame.
#[derive(Clone, Debug, PartialEq)]
pub struct DeviceLimits {
    pub max_texture_size: u32,
    pub msaa_samples: Vec<u32>,
}

#[derive(Clone, Debug)]
pub struct CheckedScene {
    pub scene: Scene,
    pub frame: FrameSpec,
    pub caster: Option<Caster>,
    /// The lights in the order the shaders see them: the shadow-casting light first.
    pub shader_lights: Vec<Light>,
    /// Bit k set when `shader_lights[k]` is a point light.
    pub point_lights: u32,
    /// Whether each item is glass (`is_glass`): from its material, and once its mesh is known,
    /// from the mesh's colour (`mark_blended`).
    pub glass: Vec<bool>,
    /// The frame's place in a sequence of views whose suggestive contours hold still
    /// (`Renderer::render_views`); None for a frame alone.
    pub sequence: Option<SequenceFrame>,
}

/// Whether a mesh lets light through: its material's opacity is below 1, or its colour's alpha
/// counts (`alpha_blend`).
pub fn is_glass(opacity: f32, alpha_blend: bool) -> bool {
    opacity < 1.0 || alpha_blend
}

impl CheckedScene {
    /// Checks every setting of `scene` and `frame` (each error names its place in the scene)
    /// and resolves what the frame's steps share: the lengths the settings give in pixels are
    /// scaled to the frame's pixel ratio once checked. Meshes are checked by their renderer.
    pub fn check(scene: Scene, frame: FrameSpec, limits: &DeviceLimits) -> Result<Self> {
        frame.validate(limits.max_texture_size, &limits.msaa_samples)?;
        for (i, item) in scene.items.iter().enumerate() {
            check_transform(&format!("meshes[{i}].transform"), &item.transform)?;
            item.material.validate(&format!("meshes[{i}].material"))?;
        }
        scene.camera.validate("camera")?;
        validate_lights(&scene.lights)?;
        for (i, l) in scene.lights.iter().enumerate() {
            l.validate(&format!("lights[{i}]"))?;
        }
        crate::render::color::check_unit("ambient", &scene.ambient)?;
        if let Some(o) = &scene.outlines {
            o.validate("outlines")?;
        }
        scene.effects.validate()?;
        let mut scene = scene;
        for (i, set) in scene.lines.iter_mut().enumerate() {
            set.validate(&format!("lines[{i}]"))?;
            // the outlines' ink where the set has none, scaled to the pixel ratio with its own
            let ink = set.ink(scene.outlines.as_ref());
            (set.color, set.width) = (Some(ink.color), Some(ink.width));
        }
        let scene = scene.at_pixel_ratio(frame.pixel_ratio);
        let caster = shadow_caster(&scene.lights).map(|(index, light, settings)| Caster {
            index,
            light: *light,
            settings,
        });
        let shader_lights: Vec<Light> = caster
            .map(|c| c.light)
            .into_iter()
            .chain(
                scene
                    .lights
                    .iter()
                    .enumerate()
                    .filter(|(i, _)| Some(*i) != caster.map(|c| c.index))
                    .map(|(_, l)| *l),
            )
            .collect();
        let point_lights = shader_lights
            .iter()
            .enumerate()
            .filter(|(_, l)| matches!(l.kind, LightKind::Point { .. }))
            .fold(0, |bits, (k, _)| bits | 1 << k);
        let glass = scene.items.iter().map(|i| is_glass(i.material.opacity, false)).collect();
        Ok(CheckedScene { scene, frame, caster, shader_lights, point_lights, glass, sequence: None })
    }

    /// Marks as glass the items whose mesh's colour alpha counts (`blended(i)` for item i), as
    /// well as those whose material lets light through.
    pub fn mark_blended(&mut self, blended: impl Fn(usize) -> bool) {
        for (i, (g, item)) in self.glass.iter_mut().zip(&self.scene.items).enumerate() {
            *g = is_glass(item.material.opacity, blended(i));
        }
    }

    /// Whether the frame composites glass: some item is glass, and colour is asked for.
    pub fn has_glass(&self) -> bool {
        self.frame.outputs.has(super::Output::Color) && self.glass.iter().any(|&g| g)
    }

    /// The same scene and frame seen through another camera (checked when it was made).
    pub fn with_camera(&self, camera: Camera) -> Self {
        let mut c = self.clone();
        c.scene.camera = camera;
        c
    }

    /// The same, as a frame of a sequence of views.
    pub fn in_sequence(mut self, sequence: Option<SequenceFrame>) -> Self {
        self.sequence = sequence;
        self
    }

    /// Each line set's ink (its colour and width resolved when the scene was checked).
    pub fn line_inks(&self) -> Vec<crate::render::effects::outlines::settings::LineStyle> {
        self.scene.lines.iter().map(|set| set.ink(None)).collect()
    }

    /// The shadow caster, when the scene has something to cast shadows onto.
    pub fn casting(&self) -> Option<&Caster> {
        self.caster.as_ref().filter(|_| !self.scene.items.is_empty())
    }
}

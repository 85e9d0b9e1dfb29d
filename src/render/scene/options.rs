//! Everything a render takes besides its meshes, with every default in one place: the one
//! object that `render`, `Renderer.render`, `Renderer.render_many`, the command line and batch
//! rendering hand to the core.

use serde::{Deserialize, Serialize};

use crate::render::color::Srgb;

use super::camera::Camera;
use super::light::Light;
use super::material::Material;
use super::up::{scene_up, Axis};
use super::{FrameSpec, MeshId, Scene, SceneItem, IDENTITY};
use crate::error::Result;
use crate::render::effects::outlines::settings::Outlines;
use crate::render::effects::scene_settings::SceneEffects;

#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(default)]
pub struct RenderOptions {
    /// The material of meshes that name none.
    pub material: Material,
    /// The row-major model -> world transform of meshes that give none.
    pub transform: [[f64; 4]; 4],
    pub camera: Camera,
    pub lights: Vec<Light>,
    /// Ambient light (sRGB).
    pub ambient: Srgb,
    /// Ink lines, if any.
    pub outlines: Option<Outlines>,
    /// The frame effects' settings (paper grain).
    #[serde(flatten)]
    pub effects: SceneEffects,
    /// Size, outputs, accuracy knobs and background.
    #[serde(flatten)]
    pub frame: FrameSpec,
    /// The scene's up axis; None: the one its meshes name (a file's convention), else +y
    /// (`up::scene_up`).
    pub up: Option<Axis>,
}

impl Default for RenderOptions {
    fn default() -> Self {
        let scene = Scene::default();
        RenderOptions {
            material: Material::default(),
            transform: IDENTITY,
            camera: scene.camera,
            lights: scene.lights,
            ambient: scene.ambient,
            outlines: scene.outlines,
            effects: scene.effects,
            frame: FrameSpec::default(),
            up: None,
        }
    }
}

/// A mesh of a render, with its own material, transform and up axis where it has them.
pub type MeshSpec = (MeshId, Option<Material>, Option<[[f64; 4]; 4]>, Option<Axis>);

impl RenderOptions {
    /// The scene of `meshes` with these options; refused when the meshes name different up
    /// axes and the options none.
    pub fn scene(&self, meshes: &[MeshSpec]) -> Result<Scene> {
        let up = scene_up(self.up, meshes.iter().map(|m| m.3))?;
        Ok(Scene {
            items: meshes
                .iter()
                .map(|(mesh, material, transform, _)| SceneItem {
                    mesh: *mesh,
                    material: material.clone().unwrap_or_else(|| self.material.clone()),
                    transform: transform.unwrap_or(self.transform),
                })
                .collect(),
            camera: self.camera,
            lights: self.lights.clone(),
            ambient: self.ambient,
            outlines: self.outlines.clone(),
            effects: self.effects.clone(),
            up,
        })
    }
}

//! Everything a render takes besides its meshes, with every default in one place: the one
//! object that `render`, `Renderer.render`, `Renderer.render_many`, the command line and batch
//! rendering hand to the core.

use serde::{Deserialize, Serialize};

use crate::render::color::Srgb;

use super::camera::Camera;
use super::light::Light;
use super::lines::LineSet;
use super::material::Material;
use super::up::{scene_up, Axis};
use super::{FrameSpec, MeshId, Output, Outputs, Scene, SceneItem, IDENTITY, MAX_SUPERSAMPLE, PIXEL_RATIOS};
use crate::error::Result;
use crate::render::effects::outlines::settings::Outlines;
use crate::render::effects::scene_settings::SceneEffects;
use crate::render::settings::declare::declared_fields;
use crate::render::settings::{check_bounds, field_names, Constructor, Declared, Described, Kind, Range};

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

declared_fields! {
    RenderOptions {
        material: Material [.material] => setting("Material"), "the material of meshes that name none";
        transform: [[f64; 4]; 4] [.transform] => Kind::Matrix,
            "a 4x4 affine model -> world matrix (row-major, applied to column vectors) for meshes that give none";
        camera: Camera [.camera] => setting("Camera"),
            "the camera (Camera.fit(): the scene framed from a three-quarter view about its up axis)";
        up: Option<Axis> [.up] => choice(Axis::NAMES),
            "the scene's up axis, which a fitted camera keeps up in the image and turns about (None: its meshes' own, as toonmesh.load reads a file's convention, else y)", optional;
        lights: Vec<Light> [.lights] => Kind::Lights, "a Light or a list of up to 8";
        ambient: Srgb [.ambient] => color(), "the ambient light's sRGB colour";
        background: [f32; 4] [.frame.background] => Kind::Rgba, "sRGB or sRGBA where no mesh is";
        width: u32 [.frame.width] => int(SIDE), "the image's width in pixels, 1 to the device's limit";
        height: u32 [.frame.height] => int(SIDE), "the image's height in pixels, 1 to the device's limit";
        outputs: Outputs [.frame.outputs] => Kind::Names(&Output::NAMES),
            "the outputs computed and read back, and only those ('outline' and 'lines' need outlines, 'shadow' a light with shadows)";
        msaa: u32 [.frame.msaa] => int(closed(1.0, 4.0).rule("1 or 4")), "samples per pixel: 1 or 4";
        supersample: u32 [.frame.supersample] => int(closed(1.0, MAX_SUPERSAMPLE as f64)),
            "render this many times larger in each direction and average down";
        pixel_ratio: f64 [.frame.pixel_ratio] => float(closed(PIXEL_RATIOS.0, PIXEL_RATIOS.1)),
            "output pixels per pixel of the widths, spacings and scales given in pixels: 2 with twice the width and height draws the same picture, sharper (a 2x screen)";
        band_antialias: bool [.frame.band_antialias] => boolean(),
            "blend across each band border over about one pixel, from the screen-space change of the shading term: smooth tone borders at no extra samples (False: the papers' hard borders)";
        glass_layers: u32 [.frame.glass_layers] => int(closed(1.0, 16.0)),
            "the most glass surfaces (meshes with opacity below 1) one pixel composites, nearest first: each layer costs one more draw of the glass meshes and one full-screen pass; opaque scenes pay nothing";
        outlines: Option<Outlines> [.outlines] => setting("Outlines"),
            "ink outlines: None, 'mesh', 'image', 'both' or an Outlines", optional;
        // then the frame effects' (`effects::scene_settings`)
        ..effects: SceneEffects;
    }
}

/// An image's side in pixels: the device's limit is checked when it renders; a control spans
/// the common limit.
const SIDE: Range = Range::count(1.0).slider(1.0, 16384.0);

/// `RenderOptions(...)`: every field by keyword.
impl Described for RenderOptions {
    const PARAMETER: Option<&'static str> = Some("a render option");

    const CONSTRUCTORS: &'static [Constructor] = &[Constructor::only(
        &field_names::<{ <RenderOptions as Declared>::FIELDS.len() }>(<RenderOptions as Declared>::FIELDS),
        0,
    )];

    fn start(_: &str) -> Self {
        RenderOptions::default()
    }

    /// The numbers' bounds; sizes, samples and outputs are checked against the device when it
    /// renders.
    fn check(&self) -> Result<()> {
        check_bounds(self, "")
    }
}

/// A line set of a render, with its own transform and up axis where it has them (the set's
/// `transform` is replaced).
pub type LineSpec = (LineSet, Option<[[f64; 4]; 4]>, Option<Axis>);

/// A mesh of a render, with its own material, transform and up axis where it has them.
pub type MeshSpec = (MeshId, Option<Material>, Option<[[f64; 4]; 4]>, Option<Axis>);

impl RenderOptions {
    /// The scene of `meshes` with these options; refused when the meshes name different up
    /// axes and the options none.
    pub fn scene(&self, meshes: &[MeshSpec]) -> Result<Scene> {
        self.scene_with_lines(meshes, Vec::new())
    }

    /// The scene of `meshes` and the line sets `lines` (each with its up axis where it has
    /// one; a set without its own transform takes the options'), with these options.
    pub fn scene_with_lines(&self, meshes: &[MeshSpec], lines: Vec<LineSpec>) -> Result<Scene> {
        let ups = meshes.iter().map(|m| m.3).chain(lines.iter().map(|l| l.2));
        let up = scene_up(self.up, ups)?;
        let lines = lines
            .into_iter()
            .map(|(set, transform, _)| LineSet { transform: transform.unwrap_or(self.transform), ..set })
            .collect();
        Ok(Scene {
            items: meshes
                .iter()
                .map(|(mesh, material, transform, _)| SceneItem {
                    mesh: *mesh,
                    material: material.clone().unwrap_or_else(|| self.material.clone()),
                    transform: transform.unwrap_or(self.transform),
                    splats: false,
                })
                .collect(),
            camera: self.camera,
            lights: self.lights.clone(),
            ambient: self.ambient,
            outlines: self.outlines.clone(),
            effects: self.effects.clone(),
            up,
            lines,
        })
    }
}

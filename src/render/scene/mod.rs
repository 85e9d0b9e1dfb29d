//! What to render (meshes placed in the world, camera, lights, materials, outlines) and how
//! (size, outputs, accuracy). All of it is plain data: a scene can be built, checked and sent
//! to another process without a device; meshes are named by the id their renderer gave them.
//!
//! Errors name what is wrong as a path: a setting's own field while it is being made
//! (`"shininess"`), its place in the scene when a scene is checked (`"meshes[0].transform"`);
//! `error::field` joins the two.

pub mod camera;
pub mod checked;
pub mod light;
pub mod lines;
pub mod material;
pub mod model;
pub mod options;
pub mod outputs;
pub mod sequence;
pub mod up;

use glam::{DMat3, DMat4, DVec3};
use serde::{Deserialize, Serialize};

use crate::error::{Error, Result};
use crate::render::settings::at_pixel_ratio;

use camera::{Camera, SceneBounds, Sphere};
use light::Light;
use material::Material;

pub use outputs::{Output, Outputs};

use crate::render::effects::outlines::settings::Outlines;
use crate::render::effects::scene_settings::SceneEffects;

/// Image size, outputs and accuracy knobs.
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
pub struct FrameSpec {
    pub width: u32,
    pub height: u32,
    pub outputs: Outputs,
    /// Samples per pixel of the shading pass: 1 or 4.
    pub msaa: u32,
    /// The shading pass runs at this many times the size in each direction, then is averaged down.
    pub supersample: u32,
    /// Blend across each band border (and threshold) over about one pixel, from the screen-space
    /// derivative of the shading term: antialiased tones at no extra samples (on by default;
    /// off gives the hard borders of the papers' figures).
    #[serde(default)]
    pub band_antialias: bool,
    /// sRGB colour and alpha of pixels no mesh covers.
    pub background: [f32; 4],
    /// Output pixels per pixel of the lengths the settings give in pixels (line widths, hatch
    /// spacing, dither cells, paper grain): 2 draws a frame twice the size that looks the same,
    /// sharper (for a screen with two device pixels per layout pixel).
    #[serde(default = "unit_ratio")]
    pub pixel_ratio: f64,
    /// The most glass surfaces one pixel composites (`passes::glass`): each costs a draw of the
    /// glass meshes and a full-screen pass.
    #[serde(default = "default_glass_layers")]
    pub glass_layers: u32,
}

fn unit_ratio() -> f64 {
    1.0
}

/// `FrameSpec::glass_layers` by default.
pub const GLASS_LAYERS: u32 = 4;

fn default_glass_layers() -> u32 {
    GLASS_LAYERS
}

/// The range of `FrameSpec::pixel_ratio`.
pub const PIXEL_RATIOS: (f64, f64) = (0.25, 8.0);

impl Default for FrameSpec {
    fn default() -> Self {
        FrameSpec {
            width: 512,
            height: 512,
            outputs: Outputs::of(&[Output::Color]),
            msaa: 1,
            supersample: 1,
            band_antialias: true,
            background: [1.0, 1.0, 1.0, 1.0],
            pixel_ratio: 1.0,
            glass_layers: GLASS_LAYERS,
        }
    }
}

/// Largest supersampling factor.
pub const MAX_SUPERSAMPLE: u32 = 4;

impl FrameSpec {
    /// Checks the spec against a device with textures up to `max_size` and the given MSAA
    /// sample counts.
    pub fn validate(&self, max_size: u32, msaa_supported: &[u32]) -> Result<()> {
        for (arg, v) in [("width", self.width), ("height", self.height)] {
            if v == 0 {
                return Err(Error::invalid(arg, "must be at least 1 pixel"));
            }
            if v > max_size {
                return Err(Error::invalid(
                    arg,
                    format!("{v} pixels exceeds this GPU's limit of {max_size}"),
                ));
            }
        }
        self.outputs.validate()?;
        if !(self.msaa == 1 || self.msaa == 4) {
            return Err(Error::invalid("msaa", format!("must be 1 or 4, got {}", self.msaa)));
        }
        if !msaa_supported.contains(&self.msaa) {
            return Err(Error::invalid(
                "msaa",
                format!("{}x is not supported by this GPU (it offers {msaa_supported:?})", self.msaa),
            ));
        }
        if !(1..=MAX_SUPERSAMPLE).contains(&self.supersample) {
            return Err(Error::invalid(
                "supersample",
                format!("must be 1 to {MAX_SUPERSAMPLE}, got {}", self.supersample),
            ));
        }
        let big = self.width.max(self.height) as u64 * self.supersample as u64;
        if self.outputs.has(Output::Color) && big > max_size as u64 {
            return Err(Error::invalid(
                "supersample",
                format!(
                    "{}x supersampling needs {big} pixels across, beyond this GPU's limit of {max_size}",
                    self.supersample
                ),
            ));
        }
        let (least, most) = PIXEL_RATIOS;
        if !(least..=most).contains(&self.pixel_ratio) {
            return Err(Error::invalid(
                "pixel_ratio",
                format!("must be in [{least}, {most}], got {}", self.pixel_ratio),
            ));
        }
        crate::render::color::check_unit("background", &self.background.map(|c| c as f64))
    }
}

/// A renderer's name for a mesh it holds.
pub type MeshId = u64;

/// A mesh placed in the world with a material.
#[derive(Clone, Debug, PartialEq)]
pub struct SceneItem {
    pub mesh: MeshId,
    /// Row-major 4x4 affine model -> world transform (applied to column vectors).
    pub transform: [[f64; 4]; 4],
    pub material: Material,
    /// A point cloud's splats (set from its mesh when the scene is checked): no mesh-space
    /// lines; image-space edges ink it.
    pub splats: bool,
}

pub const IDENTITY: [[f64; 4]; 4] =
    [[1.0, 0.0, 0.0, 0.0], [0.0, 1.0, 0.0, 0.0], [0.0, 0.0, 1.0, 0.0], [0.0, 0.0, 0.0, 1.0]];

/// Checks a row-major 4x4 model -> world transform: finite, affine and not flattening.
impl Scene {
    /// The scene with the lengths its settings give in pixels (line widths, hatch spacing,
    /// dither cells, paper grain) multiplied by `ratio` (`FrameSpec::pixel_ratio`).
    pub fn at_pixel_ratio(mut self, ratio: f64) -> Scene {
        if ratio == 1.0 {
            return self;
        }
        for item in &mut self.items {
            item.material = at_pixel_ratio(&item.material, ratio);
        }
        self.outlines = self.outlines.map(|o| at_pixel_ratio(&o, ratio));
        for set in &mut self.lines {
            set.width = set.width.map(|w| (w as f64 * ratio) as f32);
        }
        self.effects = self.effects.at_pixel_ratio(ratio);
        self
    }
}

pub fn check_transform(arg: &str, t: &[[f64; 4]; 4]) -> Result<()> {
    if !t.iter().flatten().all(|v| v.is_finite()) {
        return Err(Error::invalid(arg, "must be finite"));
    }
    if t[3] != [0.0, 0.0, 0.0, 1.0] {
        return Err(Error::invalid(arg, format!("must be affine (last row 0, 0, 0, 1), got {:?}", t[3])));
    }
    let det = DMat3::from_mat4(DMat4::from_cols_array_2d(t).transpose()).determinant();
    if !(det.abs() > 1e-300) || !det.is_finite() {
        return Err(Error::invalid(arg, "is singular (it flattens the mesh)"));
    }
    Ok(())
}

impl SceneItem {
    pub fn model_matrix(&self) -> DMat4 {
        DMat4::from_cols_array_2d(&self.transform).transpose()
    }

    /// Whether the transform mirrors the mesh (turning its winding around).
    pub fn mirrors(&self) -> bool {
        DMat3::from_mat4(self.model_matrix()).determinant() < 0.0
    }
}

#[derive(Clone, Debug, PartialEq)]
pub struct Scene {
    pub items: Vec<SceneItem>,
    pub camera: Camera,
    pub lights: Vec<Light>,
    /// Ambient light a_l (sRGB).
    pub ambient: crate::render::color::Srgb,
    /// Ink lines, if any.
    pub outlines: Option<Outlines>,
    /// The frame effects' settings (paper grain).
    pub effects: SceneEffects,
    /// The up axis fitted cameras keep up and turn about (`up::scene_up` decides it).
    pub up: up::Axis,
    /// Line segments drawn as ink (`toonmesh.Lines`), after the meshes.
    pub lines: Vec<lines::LineSet>,
}

impl Default for Scene {
    /// No meshes; the default camera, key light and white ambient light; no outlines; +y up.
    fn default() -> Self {
        Scene {
            items: Vec::new(),
            camera: Camera::default(),
            lights: vec![Light::default()],
            ambient: [1.0; 3],
            outlines: None,
            effects: SceneEffects::default(),
            up: up::DEFAULT_UP,
            lines: Vec::new(),
        }
    }
}

impl Scene {
    /// A sphere around every mesh and line set as placed (a unit sphere at the origin for an empty scene),
    /// given each mesh's own bounding sphere.
    pub fn bounding_sphere(&self, mesh_sphere: impl Fn(MeshId) -> Result<Sphere>) -> Result<Sphere> {
        let mut all: Option<Sphere> = None;
        for item in &self.items {
            let m = item.model_matrix();
            let own = mesh_sphere(item.mesh)?;
            let s = Sphere {
                center: m.transform_point3(own.center),
                radius: own.radius * largest_stretch(DMat3::from_mat4(m)),
            };
            all = Some(match all {
                None => s,
                Some(a) => merge(a, s),
            });
        }
        for [lo, hi] in self.lines.iter().filter_map(lines::LineSet::world_box) {
            let s = Sphere { center: (lo + hi) * 0.5, radius: camera::length_of(hi - lo) * 0.5 };
            all = Some(match all {
                None => s,
                Some(a) => merge(a, s),
            });
        }
        Ok(match all {
            // a scene collapsed to a point (within the precision of its position) still gets a
            // frame; any larger scene keeps its own size, however small
            Some(s) if s.center.is_finite() && s.radius.is_finite() => Sphere {
                center: s.center,
                radius: s.radius.max(4.0 * f64::EPSILON * camera::length_of(s.center)).max(f64::MIN_POSITIVE),
            },
            _ => Sphere { center: DVec3::ZERO, radius: 1.0 },
        })
    }
}

impl Scene {
    /// What a fitted camera frames: the bounding sphere, the world box around every mesh's own
    /// box as placed and every line set's points (`mesh_box`: its min and max corners), and the up axis. An empty scene's box
    /// is its sphere's cube.
    pub fn bounds(
        &self,
        mesh_sphere: impl Fn(MeshId) -> Result<Sphere>,
        mesh_box: impl Fn(MeshId) -> Result<[DVec3; 2]>,
    ) -> Result<SceneBounds> {
        let sphere = self.bounding_sphere(mesh_sphere)?;
        let (mut lo, mut hi) = (DVec3::INFINITY, DVec3::NEG_INFINITY);
        for item in &self.items {
            let m = item.model_matrix();
            let [a, b] = mesh_box(item.mesh)?;
            for k in 0..8 {
                let corner = DVec3::new(
                    if k & 1 == 0 { a.x } else { b.x },
                    if k & 2 == 0 { a.y } else { b.y },
                    if k & 4 == 0 { a.z } else { b.z },
                );
                let p = m.transform_point3(corner);
                (lo, hi) = (lo.min(p), hi.max(p));
            }
        }
        for [a, b] in self.lines.iter().filter_map(lines::LineSet::world_box) {
            (lo, hi) = (lo.min(a), hi.max(b));
        }
        if !(lo.is_finite() && hi.is_finite()) {
            return Ok(SceneBounds::of_sphere(sphere, self.up));
        }
        let corners = std::array::from_fn(|k| {
            DVec3::new(
                if k & 1 == 0 { lo.x } else { hi.x },
                if k & 2 == 0 { lo.y } else { hi.y },
                if k & 4 == 0 { lo.z } else { hi.z },
            )
        });
        Ok(SceneBounds { sphere, corners, up: self.up })
    }
}

/// The largest factor by which `m` stretches a vector (its spectral norm), by power iteration.
fn largest_stretch(m: DMat3) -> f64 {
    let mtm = m.transpose() * m;
    let mut v = DVec3::new(0.577, 0.577, 0.578);
    for _ in 0..64 {
        let w = mtm * v;
        let l = w.length();
        if !(l > 0.0) {
            break;
        }
        v = w / l;
    }
    // never below the largest column: power iteration can only approach the norm from below
    let cols = [m.x_axis.length(), m.y_axis.length(), m.z_axis.length()];
    (m * v).length().max(cols[0]).max(cols[1]).max(cols[2]) * (1.0 + 1e-9)
}

/// The smallest sphere containing two spheres.
fn merge(a: Sphere, b: Sphere) -> Sphere {
    let d = camera::length_of(b.center - a.center);
    if d + b.radius <= a.radius {
        return a;
    }
    if d + a.radius <= b.radius {
        return b;
    }
    let radius = (d + a.radius + b.radius) / 2.0;
    let center = a.center + (b.center - a.center) * ((radius - a.radius) / d);
    Sphere { center, radius }
}

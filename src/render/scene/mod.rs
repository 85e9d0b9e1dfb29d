//! What to render (meshes placed in the world, camera, lights, materials, outlines) and how
//! (size, outputs, accuracy). All of it is plain data: a scene can be built, checked and sent
//! to another process without a device; meshes are named by the id their renderer gave them.

pub mod camera;
pub mod light;
pub mod material;
pub mod outlines;
pub mod shadows;
pub mod style;

use glam::{DMat3, DMat4, DVec3};

use crate::error::{Error, Result};

use camera::{Camera, Sphere};
use light::{validate_lights, Light};
use material::Material;
use outlines::Outlines;

/// What a render can return.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub struct Outputs {
    /// (H, W, 4) sRGB colour.
    pub color: bool,
    /// (H, W, 3) view-space unit normals.
    pub normal: bool,
    /// (H, W) linear view depth.
    pub depth: bool,
    /// (H, W) ink coverage of the outlines in [0, 1].
    pub outline: bool,
    /// The visible mesh-space lines as polylines in pixel coordinates.
    pub lines: bool,
    /// (H, W) visibility of the shadow-casting light in [0, 1]: 1 lit, 0 shadowed (or facing
    /// away from the light), 1 where no mesh is.
    pub shadow: bool,
}

impl Outputs {
    /// The names `outputs=` accepts, in the order they are read back.
    pub const NAMES: [&'static str; 6] = ["color", "normal", "depth", "outline", "lines", "shadow"];

    pub fn any(&self) -> bool {
        self.color || self.normal || self.depth || self.outline || self.lines || self.shadow
    }

    /// Sets the output called `name`.
    pub fn add(&mut self, arg: &str, name: &str) -> Result<()> {
        let flag = match name {
            "color" => &mut self.color,
            "normal" => &mut self.normal,
            "depth" => &mut self.depth,
            "outline" => &mut self.outline,
            "lines" => &mut self.lines,
            "shadow" => &mut self.shadow,
            other => {
                return Err(Error::invalid(
                    arg,
                    format!(
                        "unknown output {other:?}; use {}",
                        Self::NAMES.map(|n| format!("'{n}'")).join(", ")
                    ),
                ))
            }
        };
        *flag = true;
        Ok(())
    }
}

/// Image size, outputs and accuracy knobs.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct FrameSpec {
    pub width: u32,
    pub height: u32,
    pub outputs: Outputs,
    /// Samples per pixel of the shading pass: 1 or 4.
    pub msaa: u32,
    /// The shading pass runs at this many times the size in each direction, then is averaged down.
    pub supersample: u32,
    /// sRGB colour and alpha of pixels no mesh covers.
    pub background: [f32; 4],
}

impl Default for FrameSpec {
    fn default() -> Self {
        FrameSpec {
            width: 512,
            height: 512,
            outputs: Outputs { color: true, ..Default::default() },
            msaa: 1,
            supersample: 1,
            background: [1.0, 1.0, 1.0, 1.0],
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
        if !self.outputs.any() {
            return Err(Error::invalid(
                "outputs",
                "ask for at least one output ('color', 'normal', 'depth', ...)",
            ));
        }
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
        if self.outputs.color && big > max_size as u64 {
            return Err(Error::invalid(
                "supersample",
                format!(
                    "{}x supersampling needs {big} pixels across, beyond this GPU's limit of {max_size}",
                    self.supersample
                ),
            ));
        }
        if !self.background.iter().all(|c| c.is_finite() && (0.0..=1.0).contains(c)) {
            return Err(Error::invalid(
                "background",
                format!("channels must be in [0, 1], got {:?}", self.background),
            ));
        }
        Ok(())
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
}

pub const IDENTITY: [[f64; 4]; 4] =
    [[1.0, 0.0, 0.0, 0.0], [0.0, 1.0, 0.0, 0.0], [0.0, 0.0, 1.0, 0.0], [0.0, 0.0, 0.0, 1.0]];

impl SceneItem {
    pub fn model_matrix(&self) -> DMat4 {
        DMat4::from_cols_array_2d(&self.transform).transpose()
    }

    /// Whether the transform mirrors the mesh (turning its winding around).
    pub fn mirrors(&self) -> bool {
        DMat3::from_mat4(self.model_matrix()).determinant() < 0.0
    }

    pub fn validate(&self, arg: &str) -> Result<()> {
        let t = &self.transform;
        if !t.iter().flatten().all(|v| v.is_finite()) {
            return Err(Error::invalid(format!("{arg}.transform"), "must be finite"));
        }
        if t[3] != [0.0, 0.0, 0.0, 1.0] {
            return Err(Error::invalid(
                format!("{arg}.transform"),
                format!("must be affine (last row 0, 0, 0, 1), got {:?}", t[3]),
            ));
        }
        let det = DMat3::from_mat4(self.model_matrix()).determinant();
        if !(det.abs() > 1e-300) || !det.is_finite() {
            return Err(Error::invalid(format!("{arg}.transform"), "is singular (it flattens the mesh)"));
        }
        self.material.validate(&format!("{arg}.material"))
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
}

impl Default for Scene {
    /// No meshes; the default camera, key light and white ambient light; no outlines.
    fn default() -> Self {
        Scene {
            items: Vec::new(),
            camera: Camera::default(),
            lights: vec![Light::default()],
            ambient: [1.0; 3],
            outlines: None,
        }
    }
}

impl Scene {
    pub fn validate(&self) -> Result<()> {
        for (i, item) in self.items.iter().enumerate() {
            item.validate(&format!("meshes[{i}]"))?;
        }
        self.camera.validate()?;
        validate_lights(&self.lights)?;
        crate::render::color::check_unit("ambient", &self.ambient)?;
        if let Some(o) = &self.outlines {
            o.validate("outlines")?;
        }
        Ok(())
    }

    /// Mesh-space lines are drawn.
    pub fn mesh_lines(&self) -> bool {
        self.outlines.as_ref().is_some_and(|o| o.draws_mesh_lines())
    }

    /// Image-space edges are drawn.
    pub fn image_edges(&self) -> bool {
        self.outlines.as_ref().is_some_and(|o| o.draws_image_edges())
    }

    /// A sphere around every mesh as placed (a unit sphere at the origin for an empty scene),
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

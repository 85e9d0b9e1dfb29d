//! Cameras: a perspective or orthographic look-at camera, or one framed to fit the scene.
//!
//! Conventions: right-handed world; the camera looks down its -z axis with +y up (view space).
//! wgpu's clip space has depth in [0, 1] and y up (the Direct3D convention); the matrices below
//! are written out in f64 for that convention.

use glam::{DMat4, DVec3};
use serde::{Deserialize, Serialize};

use crate::error::{Error, Result};

use super::up::{Axis, Frame, FLAT_MOST_OFF_NORMAL};
use crate::error::field;
use crate::render::settings::declare::declared_fields;
use crate::render::settings::{named, not_here, required, Constructor, Described, Field, Kind, Range, Value};

#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
#[serde(tag = "kind", rename_all = "snake_case")]
pub enum Projection {
    /// Vertical field of view in degrees, in (0, 180).
    Perspective { fov_y_deg: f64 },
    /// Height of the view volume in world units (> 0).
    Orthographic { height: f64 },
}

#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
#[serde(tag = "kind", rename_all = "snake_case")]
pub enum Placement {
    /// An explicit eye, target and up vector.
    LookAt { eye: [f64; 3], target: [f64; 3], up: [f64; 3] },
    /// Frame the scene from `direction` (pointing from the scene toward the eye; None: the
    /// three-quarter view about the up axis that looks across the scene's longest horizontal
    /// extent, `up::Frame`), turned `turn` degrees about the up axis, as near as the scene's
    /// bounds allow with `margin` (1 = touching the image's edge). `up`: the image's up
    /// direction; None: the scene's up axis (`up::scene_up`).
    Fit {
        direction: Option<[f64; 3]>,
        up: Option<[f64; 3]>,
        margin: f64,
        #[serde(default)]
        turn: f64,
    },
}

#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
pub struct Camera {
    pub placement: Placement,
    pub projection: Projection,
    /// Clip distances; chosen from the scene's bounding sphere when `None`.
    pub near: Option<f64>,
    pub far: Option<f64>,
}

/// Defaults of the camera constructors: +y up for a look-at camera (a fitted one takes the
/// scene's up axis), a 35 degree vertical field of view, and 5% room around the scene.
pub const DEFAULT_UP: [f64; 3] = [0.0, 1.0, 0.0];
pub const DEFAULT_FOV_Y: f64 = 35.0;
pub const DEFAULT_MARGIN: f64 = 1.05;
/// Height of an orthographic view in world units.
pub const DEFAULT_HEIGHT: f64 = 2.0;

impl Default for Camera {
    /// Framed to fit from the default direction.
    fn default() -> Self {
        Camera {
            placement: Placement::Fit { direction: None, up: None, margin: DEFAULT_MARGIN, turn: 0.0 },
            projection: Projection::Perspective { fov_y_deg: DEFAULT_FOV_Y },
            near: None,
            far: None,
        }
    }
}

declared_fields! {
    Camera {
        kind: &'static str [get kind_name] => choice(&["fit", "look_at"]),
            "framed to fit the scene, or looking at a point", fixed;
        projection: &'static str [get projection_name] => choice(&["perspective", "orthographic"]),
            "the projection", fixed;
        eye: Option<[f64; 3]> [get look_at, set set_look_at] => vec3(), "a look-at camera's position", optional;
        target: Option<[f64; 3]> [get look_at, set set_look_at] => vec3(),
            "the point a look-at camera looks at", optional;
        up: Option<[f64; 3]> [get up, set set_up] => vec3(),
            "the direction that is up in the image (a fitted camera's None: the scene's up axis)", optional;
        direction: Option<[f64; 3]> [get fit_direction, set set_fit_direction] => vec3(),
            "a fitted camera's direction from the scene toward the eye (None: a three-quarter view about the up axis, across the scene's longest horizontal extent)", optional;
        margin: Option<f64> [get fit_number, set set_fit_number] => float(above(0.0).slider(0.5, 4.0)),
            "a fitted camera's room around the scene (1: touching)", optional;
        turn: Option<f64> [get fit_number, set set_fit_number] => float(finite().slider(-360.0, 360.0)),
            "degrees a fitted camera's view turns about the up axis, counter-clockwise seen from above (a turntable's views)", optional;
        fov_y: Option<f64> [get lens, set set_lens] => float(open(0.0, 180.0).slider(1.0, 179.0)),
            "vertical field of view in degrees, in (0, 180)", optional;
        height: Option<f64> [get lens, set set_lens] => float(above(0.0).slider(0.01, 100.0)),
            "height of an orthographic view in world units, > 0", optional;
        near: Option<f64> [.near] => float(CLIP.slider(0.0, 100.0)),
            "near clip distance (None: from the scene's bounds)", optional;
        far: Option<f64> [.far] => float(CLIP.slider(0.0, 1000.0)),
            "far clip distance (None: from the scene's bounds)", optional;
    }
}

/// A clip distance's rule: `Camera::validate` checks the sign, which depends on the projection.
const CLIP: Range = Range::finite().rule("> 0 for a perspective camera");

/// The fields that live in the placement and the projection: None where this camera has none.
impl Camera {
    fn kind_name(&self, _: &str) -> &'static str {
        match self.placement {
            Placement::Fit { .. } => "fit",
            Placement::LookAt { .. } => "look_at",
        }
    }

    fn projection_name(&self, _: &str) -> &'static str {
        match self.projection {
            Projection::Perspective { .. } => "perspective",
            Projection::Orthographic { .. } => "orthographic",
        }
    }

    fn look_at(&self, field: &str) -> Option<[f64; 3]> {
        match self.placement {
            Placement::LookAt { eye, target, .. } => Some(if field == "eye" { eye } else { target }),
            Placement::Fit { .. } => None,
        }
    }

    fn set_look_at(&mut self, field: &str, value: Option<[f64; 3]>) -> Result<()> {
        let Placement::LookAt { eye, target, .. } = &mut self.placement else {
            return Err(not_here(field, "a look-at camera"));
        };
        *(if field == "eye" { eye } else { target }) = required(field, value)?;
        Ok(())
    }

    fn up(&self, _: &str) -> Option<[f64; 3]> {
        match self.placement {
            Placement::LookAt { up, .. } => Some(up),
            Placement::Fit { up, .. } => up,
        }
    }

    fn set_up(&mut self, field: &str, value: Option<[f64; 3]>) -> Result<()> {
        match &mut self.placement {
            Placement::LookAt { up, .. } => *up = required(field, value)?,
            Placement::Fit { up, .. } => *up = value,
        }
        Ok(())
    }

    fn fit_direction(&self, _: &str) -> Option<[f64; 3]> {
        match self.placement {
            Placement::Fit { direction, .. } => direction,
            Placement::LookAt { .. } => None,
        }
    }

    fn set_fit_direction(&mut self, field: &str, value: Option<[f64; 3]>) -> Result<()> {
        let Placement::Fit { direction, .. } = &mut self.placement else {
            return Err(not_here(field, "a fitted camera"));
        };
        *direction = value;
        Ok(())
    }

    /// `margin` or `turn`.
    fn fit_number(&self, field: &str) -> Option<f64> {
        match self.placement {
            Placement::Fit { margin, turn, .. } => Some(if field == "margin" { margin } else { turn }),
            Placement::LookAt { .. } => None,
        }
    }

    fn set_fit_number(&mut self, field: &str, value: Option<f64>) -> Result<()> {
        let Placement::Fit { margin, turn, .. } = &mut self.placement else {
            return Err(not_here(field, "a fitted camera"));
        };
        *(if field == "margin" { margin } else { turn }) = required(field, value)?;
        Ok(())
    }

    /// `fov_y` or `height`, whichever the projection has.
    fn lens(&self, field: &str) -> Option<f64> {
        match (field, self.projection) {
            ("fov_y", Projection::Perspective { fov_y_deg }) => Some(fov_y_deg),
            ("height", Projection::Orthographic { height }) => Some(height),
            _ => None,
        }
    }

    fn set_lens(&mut self, field: &str, value: Option<f64>) -> Result<()> {
        let lens = match (field, &mut self.projection) {
            ("fov_y", Projection::Perspective { fov_y_deg }) => fov_y_deg,
            ("height", Projection::Orthographic { height }) => height,
            ("fov_y", _) => return Err(not_here(field, "a perspective camera")),
            _ => return Err(not_here(field, "an orthographic camera")),
        };
        *lens = required(field, value)?;
        Ok(())
    }
}

const EXTRAS: &[Field] =
    &[Field::new("orthographic", Kind::Bool, "a fitted camera with an orthographic projection")];

const CONSTRUCTORS: &[Constructor] = &[
    named!("Camera", "fit", ["direction", "up", "fov_y", "margin", "turn", "orthographic"], 1, 0),
    named!("Camera", "look_at", ["eye", "target", "up", "fov_y", "near", "far"], 2, 1),
    named!("Camera", "orthographic", ["eye", "target", "up", "height", "near", "far"], 2, 1),
];

impl Described for Camera {
    const EXTRAS: &'static [Field] = EXTRAS;

    const CONSTRUCTORS: &'static [Constructor] = CONSTRUCTORS;

    fn start(constructor: &str) -> Self {
        let placement = Placement::LookAt { eye: [0.0, 0.0, 1.0], target: [0.0; 3], up: DEFAULT_UP };
        let projection = match constructor {
            "fit" => return Camera::default(),
            "orthographic" => Projection::Orthographic { height: DEFAULT_HEIGHT },
            _ => Projection::Perspective { fov_y_deg: DEFAULT_FOV_Y },
        };
        Camera { placement, projection, near: None, far: None }
    }

    fn made_by(&self) -> &'static str {
        match (self.placement, self.projection) {
            (Placement::Fit { .. }, _) => "fit",
            (_, Projection::Perspective { .. }) => "look_at",
            _ => "orthographic",
        }
    }

    fn apply(&mut self, constructor: &str, param: &str, value: Value) -> Result<()> {
        if param == "orthographic" {
            if value.bool(param)? {
                self.projection = Projection::Orthographic { height: DEFAULT_HEIGHT };
            }
            return Ok(());
        }
        let _ = constructor;
        self.set(param, value)
    }

    fn read(&self, _: &str, param: &str) -> Option<Value> {
        match param {
            "orthographic" => Some(matches!(self.projection, Projection::Orthographic { .. }).into()),
            _ => Some(self.get(param)),
        }
    }

    fn check(&self) -> Result<()> {
        self.validate("")
    }
}

/// A camera resolved for one image: matrices and clip distances.
#[derive(Clone, Copy, Debug)]
pub struct ResolvedCamera {
    pub view: DMat4,
    pub proj: DMat4,
    pub near: f64,
    pub far: f64,
    pub orthographic: bool,
    /// The eye and the unit direction it looks in, in world coordinates.
    pub eye: DVec3,
    pub forward: DVec3,
    /// The projection's own parameters: vertical field of view (radians) or view height, and
    /// the aspect ratio (width / height).
    pub fov_or_height: f64,
    pub aspect: f64,
    /// A power of two near the scene's size. The GPU works in view space divided by it, so that
    /// float32 keeps its precision however small, large or far away the scene is.
    pub scale: f64,
}

impl ResolvedCamera {
    /// World -> normalised view space (view space / `scale`).
    pub fn normalized_view(&self) -> DMat4 {
        DMat4::from_scale(DVec3::splat(1.0 / self.scale)) * self.view
    }

    /// Normalised view space -> clip space: the same image as `proj` of view space. For a
    /// perspective camera the clip coordinates are also divided by `scale` (which changes no
    /// image: they are homogeneous), keeping every entry near 1.
    pub fn normalized_proj(&self) -> DMat4 {
        let (n, f) = (self.near / self.scale, self.far / self.scale);
        if self.orthographic {
            let h = self.fov_or_height / 2.0 / self.scale;
            orthographic(h * self.aspect, h, n, f)
        } else {
            perspective(self.fov_or_height, self.aspect, n, f)
        }
    }
}

/// `v` scaled to unit length without squaring its components, so that vectors anywhere in
/// float64's range (1e-300 or 1e300 long) keep their direction. NaN for a zero vector.
pub fn direction_of(v: DVec3) -> DVec3 {
    let m = v.abs().max_element();
    if !(m > 0.0 && m.is_finite()) {
        return DVec3::NAN;
    }
    let w = v / m;
    w / w.length()
}

/// The length of `v` without overflow or underflow.
pub fn length_of(v: DVec3) -> f64 {
    let m = v.abs().max_element();
    if m > 0.0 && m.is_finite() {
        m * (v / m).length()
    } else {
        m
    }
}

/// The power of two at or above `x` (1 for zero or non-finite `x`).
pub fn power_of_two_above(x: f64) -> f64 {
    if !(x.is_finite() && x > 0.0) {
        return 1.0;
    }
    let p = 2f64.powi(x.log2().ceil() as i32);
    if p.is_finite() && p > 0.0 {
        p
    } else {
        1.0
    }
}

/// A sphere enclosing what is to be seen.
#[derive(Clone, Copy, Debug)]
pub struct Sphere {
    pub center: DVec3,
    pub radius: f64,
}

fn vec3(arg: &str, v: [f64; 3]) -> Result<DVec3> {
    crate::real::finite3(arg, &v).map(DVec3::from_array)
}

fn unit(arg: &str, v: [f64; 3]) -> Result<DVec3> {
    let v = vec3(arg, v)?;
    if v == DVec3::ZERO {
        return Err(Error::invalid(arg, "must not be the zero vector"));
    }
    Ok(direction_of(v))
}

impl Camera {
    /// A checked camera.
    pub fn new(
        placement: Placement,
        projection: Projection,
        near: Option<f64>,
        far: Option<f64>,
    ) -> Result<Self> {
        let c = Camera { placement, projection, near, far };
        c.validate("")?;
        Ok(c)
    }

    /// Checks the camera; `prefix` names it in errors ("" when it is being made).
    pub fn validate(&self, prefix: &str) -> Result<()> {
        let f = |name| field(prefix, name);
        // fov_y, height, margin, turn and the clip distances' finiteness: the description's bounds
        crate::render::settings::check_bounds(self, prefix)?;
        match self.placement {
            Placement::LookAt { eye, target, up } => {
                let (e, t) = (vec3(&f("eye"), eye)?, vec3(&f("target"), target)?);
                let forward = t - e;
                if forward == DVec3::ZERO {
                    return Err(Error::invalid(f("target"), format!("must differ from {}", f("eye"))));
                }
                if !forward.is_finite() {
                    return Err(Error::invalid(f("target"), "is too far from camera.eye for float64"));
                }
                let u = unit(&f("up"), up)?;
                if direction_of(forward).cross(u).length() < 1e-9 {
                    return Err(Error::invalid(f("up"), "must not be parallel to the viewing direction"));
                }
            }
            Placement::Fit { direction, up, .. } => {
                let d = direction.map(|d| unit(&f("direction"), d)).transpose()?;
                let u = up.map(|u| unit(&f("up"), u)).transpose()?;
                if let (Some(d), Some(u)) = (d, u) {
                    if d.cross(u).length() < 1e-9 {
                        return Err(Error::invalid(
                            f("up"),
                            format!("must not be parallel to {}", f("direction")),
                        ));
                    }
                }
            }
        }
        for (arg, v) in [(f("near"), self.near), (f("far"), self.far)] {
            if let Some(x) = v {
                if !(x > 0.0 || matches!(self.projection, Projection::Orthographic { .. })) {
                    return Err(Error::invalid(
                        arg,
                        format!("must be finite (and > 0 for a perspective camera), got {x}"),
                    ));
                }
            }
        }
        if let (Some(near), Some(far)) = (self.near, self.far) {
            if !(far > near) {
                return Err(Error::invalid(
                    f("far"),
                    format!("must be greater than {} ({near}), got {far}", f("near")),
                ));
            }
        }
        Ok(())
    }

    /// Whether it is a fitted camera given no direction (whose view a flat scene changes).
    pub fn fits_by_default(&self) -> bool {
        matches!(self.placement, Placement::Fit { direction: None, .. })
    }

    /// Matrices for an image of the given aspect ratio (width / height) showing `scene`, framed
    /// by its box and sphere.
    pub fn resolve(&self, scene: &SceneBounds, aspect: f64) -> Result<ResolvedCamera> {
        self.resolve_with(scene, &|n| n.map(|n| scene.support(n)), None, aspect)
    }

    /// `resolve`, framed by `support`: how far the scene reaches from its sphere's centre along
    /// each of four directions (at most what its box and sphere reach, at least what it holds);
    /// `flat`: the normal of a flat scene (`framing::flat_normal`), which a fitted camera given
    /// no direction sees from its front.
    pub fn resolve_with(
        &self,
        scene: &SceneBounds,
        support: &dyn Fn([DVec3; 4]) -> [f64; 4],
        flat: Option<DVec3>,
        aspect: f64,
    ) -> Result<ResolvedCamera> {
        let (eye, target, up, projection) = match self.placement {
            Placement::LookAt { eye, target, up } => {
                (DVec3::from_array(eye), DVec3::from_array(target), DVec3::from_array(up), self.projection)
            }
            Placement::Fit { direction, up, margin, turn } => {
                let (dir, up) = fit_view(scene, direction, up, turn, flat);
                let (eye, projection) = fit(scene, support, dir, up, margin, aspect, self.projection);
                let forward = -dir;
                let depth = (scene.sphere.center - eye).dot(forward);
                let target =
                    eye + forward * if depth > 0.0 { depth } else { scene.sphere.radius.max(1e-300) };
                (eye, target, up, projection)
            }
        };
        let view = look_at(eye, target, up);
        // clip distances that enclose the scene's sphere
        let forward = direction_of(target - eye);
        let d = (scene.sphere.center - eye).dot(forward);
        let r = scene.sphere.radius.max(1e-300);
        let orthographic = matches!(projection, Projection::Orthographic { .. });
        let (auto_near, auto_far) = if orthographic {
            ((d - r * 1.01).max(0.0), (d + r * 1.01).max(r * 1e-3))
        } else {
            let far = (d + r * 1.01).max(r * 1e-3);
            // inside the sphere (or it is behind): keep a small positive near plane
            (((d - r * 1.01).max(far * 1e-4)).min(far * 0.5), far)
        };
        let near = self.near.unwrap_or(auto_near);
        let far = self.far.unwrap_or(auto_far).max(near * (1.0 + 1e-6) + 1e-12);
        let fov_or_height = match projection {
            Projection::Perspective { fov_y_deg } => fov_y_deg.to_radians(),
            Projection::Orthographic { height } => height,
        };
        let proj = if orthographic {
            let h = fov_or_height / 2.0;
            self::orthographic(h * aspect, h, near, far)
        } else {
            perspective(fov_or_height, aspect, near, far)
        };
        if !view.is_finite() || !proj.is_finite() {
            return Err(Error::invalid("camera", "gives a non-finite view or projection matrix"));
        }
        let scale = power_of_two_above(scene.sphere.radius);
        Ok(ResolvedCamera { view, proj, near, far, orthographic, eye, forward, fov_or_height, aspect, scale })
    }
}

/// What a fitted camera frames: a sphere and a box around every mesh as placed (the box's
/// corners, in world coordinates), and the scene's up axis.
#[derive(Clone, Copy, Debug)]
pub struct SceneBounds {
    pub sphere: Sphere,
    pub corners: [DVec3; 8],
    pub up: Axis,
}

impl SceneBounds {
    /// The bounds of a sphere alone (its box the cube around it).
    pub fn of_sphere(sphere: Sphere, up: Axis) -> SceneBounds {
        let corners = std::array::from_fn(|k| {
            let sign = |bit: usize| if k >> bit & 1 == 1 { 1.0 } else { -1.0 };
            sphere.center + DVec3::new(sign(0), sign(1), sign(2)) * sphere.radius
        });
        SceneBounds { sphere, corners, up }
    }

    /// The largest of `n . (p - c)` over the scene (`c` the sphere's centre): the smaller of the
    /// box's and the sphere's, both enclosing it.
    pub fn support(&self, n: DVec3) -> f64 {
        let c = self.sphere.center;
        let boxed = self.corners.iter().map(|&p| (p - c).dot(n)).fold(f64::NEG_INFINITY, f64::max);
        boxed.min(self.sphere.radius * length_of(n))
    }
}

/// A fitted camera's direction (scene -> eye, unit) and image up: `direction` or the
/// three-quarter view across the scene's longest horizontal extent (a flat scene, of normal
/// `flat`, seen from its front: `facing`), turned `turn` degrees about up; `up` or the scene's up
/// axis (and where that is parallel to the direction, as a view from straight above, the
/// canonical frame's back: its front at the image's bottom).
fn fit_view(
    scene: &SceneBounds,
    direction: Option<[f64; 3]>,
    up: Option<[f64; 3]>,
    turn: f64,
    flat: Option<DVec3>,
) -> (DVec3, DVec3) {
    let axis = scene.up.vector();
    let up_given = up.map(|u| direction_of(DVec3::from_array(u)));
    let u = up_given.unwrap_or(axis);
    let frame = match direction {
        Some(_) => Frame::canonical(u),
        None => Frame::across(u, &scene.corners),
    };
    let dir = direction.map_or_else(
        || flat.map_or(frame.three_quarter(), |n| facing(frame.three_quarter(), n, frame)),
        |d| direction_of(DVec3::from_array(d)),
    );
    let dir = glam::DQuat::from_axis_angle(u, turn.to_radians()) * dir;
    let up = if up_given.is_none() && dir.cross(u).length() < 1e-9 { -Frame::canonical(u).front } else { u };
    (dir, up)
}

/// `dir` (unit, scene -> eye), or where it sees a flat scene of unit normal `normal` more than
/// `FLAT_MOST_OFF_NORMAL` off its normal (within 30 degrees of edge-on), `dir` turned toward the
/// normal on the side it looks from until it sees the scene as the three-quarter view sees the
/// front (38 degrees off: a plate facing the front keeps the usual view). Edge-on exactly, the
/// side is the one facing up, else the front of `frame`.
fn facing(dir: DVec3, normal: DVec3, frame: Frame) -> DVec3 {
    let side = [dir.dot(normal), frame.up.dot(normal), frame.front.dot(normal)]
        .into_iter()
        .find(|x| x.abs() > 1e-9)
        .unwrap_or(1.0);
    let n = normal * side.signum();
    let cos = dir.dot(n);
    if cos >= FLAT_MOST_OFF_NORMAL.to_radians().cos() {
        return dir;
    }
    // at least 60 degrees off the normal here: `dir` has a part along the plate
    let along = direction_of(dir - n * cos);
    let angle = Frame::three_quarter_off_front();
    direction_of(n * angle.cos() + along * angle.sin())
}

/// The eye that frames `scene` seen along -`dir` with `up` up, with `margin` room, and the
/// projection (an orthographic one gets the height that fits). A perspective eye is the nearest
/// from which every point of the scene lies inside the view's four side planes shrunk by
/// `margin`: each plane's offset is the scene's `support` along its normal, the eye's depth the
/// larger that the two axes need, and it sits midway across the other.
fn fit(
    scene: &SceneBounds,
    support: &dyn Fn([DVec3; 4]) -> [f64; 4],
    dir: DVec3,
    up: DVec3,
    margin: f64,
    aspect: f64,
    projection: Projection,
) -> (DVec3, Projection) {
    let f = -dir;
    let s = direction_of(f.cross(up));
    let v = s.cross(f);
    let c = scene.sphere.center;
    // an empty scene reaches nowhere: its box and sphere (the unit sphere) frame it
    let support = |normals: [DVec3; 4]| {
        let h = support(normals);
        if h.iter().all(|x| x.is_finite()) {
            h
        } else {
            normals.map(|n| scene.support(n))
        }
    };
    match projection {
        Projection::Perspective { fov_y_deg } => {
            let ty = (fov_y_deg.to_radians() / 2.0).tan() / margin;
            let tx = ty * aspect;
            let place = |[r, l, t, b]: [f64; 4]| {
                let depth = (-(r + l) / (2.0 * tx)).min(-(t + b) / (2.0 * ty));
                (s * ((r - l) / 2.0) + v * ((t - b) / 2.0) + f * depth, depth)
            };
            let normals = [s - f * tx, -s - f * tx, v - f * ty, -v - f * ty];
            let (offset, depth) = place(support(normals));
            // a scene without extent (a point, a flat box edge-on) is framed by its sphere
            let offset = if depth < 0.0 {
                offset
            } else {
                place(normals.map(|n| scene.sphere.radius * length_of(n))).0
            };
            (c + offset, projection)
        }
        Projection::Orthographic { .. } => {
            let [r, l, t, b] = support([s, -s, v, -v]);
            let height = ((t + b).max((r + l) / aspect) * margin).max(scene.sphere.radius * 1e-6);
            let reach = (scene.sphere.radius * margin).max(1e-300);
            let eye = c + s * ((r - l) / 2.0) + v * ((t - b) / 2.0) + dir * (2.0 * reach);
            (eye, Projection::Orthographic { height })
        }
    }
}

fn from_rows(r: [[f64; 4]; 4]) -> DMat4 {
    DMat4::from_cols_array_2d(&r).transpose()
}

/// World -> view: the eye at the origin looking down -z, `up` projected to +y.
pub fn look_at(eye: DVec3, target: DVec3, up: DVec3) -> DMat4 {
    let f = direction_of(target - eye);
    let s = direction_of(f.cross(direction_of(up)));
    let u = s.cross(f);
    from_rows([
        [s.x, s.y, s.z, -s.dot(eye)],
        [u.x, u.y, u.z, -u.dot(eye)],
        [-f.x, -f.y, -f.z, f.dot(eye)],
        [0.0, 0.0, 0.0, 1.0],
    ])
}

/// View -> clip for a perspective camera: view depth `near` maps to 0 and `far` to 1.
pub fn perspective(fov_y: f64, aspect: f64, near: f64, far: f64) -> DMat4 {
    let f = 1.0 / (fov_y / 2.0).tan();
    from_rows([
        [f / aspect, 0.0, 0.0, 0.0],
        [0.0, f, 0.0, 0.0],
        // near * (far / (near - far)), not (near * far) / ...: no underflow for tiny scenes
        [0.0, 0.0, far / (near - far), near * (far / (near - far))],
        [0.0, 0.0, -1.0, 0.0],
    ])
}

/// View -> clip for an orthographic camera with half extents `half_w`, `half_h`.
pub fn orthographic(half_w: f64, half_h: f64, near: f64, far: f64) -> DMat4 {
    from_rows([
        [1.0 / half_w, 0.0, 0.0, 0.0],
        [0.0, 1.0 / half_h, 0.0, 0.0],
        [0.0, 0.0, 1.0 / (near - far), near / (near - far)],
        [0.0, 0.0, 0.0, 1.0],
    ])
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn projections_map_near_to_0_and_far_to_1() {
        for p in [perspective(1.0, 1.5, 0.5, 20.0), orthographic(2.0, 1.0, 0.5, 20.0)] {
            for (z, want) in [(-0.5, 0.0), (-20.0, 1.0)] {
                let c = p * glam::DVec4::new(0.3, 0.2, z, 1.0);
                assert!((c.z / c.w - want).abs() < 1e-12);
            }
        }
        let v = look_at(DVec3::new(0.0, 0.0, 5.0), DVec3::ZERO, DVec3::Y);
        assert!((v.transform_point3(DVec3::ZERO) - DVec3::new(0.0, 0.0, -5.0)).length() < 1e-12);
    }

    #[test]
    fn fit_frames_a_tall_box_to_the_image_s_height() {
        // a bottle 10 tall and 1 wide, z up: upright in the image, filling its height
        let lo = DVec3::new(-0.5, -0.5, 0.0);
        let hi = DVec3::new(0.5, 0.5, 10.0);
        let corners = std::array::from_fn(|k| {
            DVec3::new([lo.x, hi.x][k & 1], [lo.y, hi.y][k >> 1 & 1], [lo.z, hi.z][k >> 2 & 1])
        });
        let center = (lo + hi) / 2.0;
        let sphere = Sphere { center, radius: (hi - lo).length() / 2.0 };
        let scene = SceneBounds { sphere, corners, up: Axis::Z };
        let r = Camera::default().resolve(&scene, 4.0 / 3.0).unwrap();
        let vp = r.proj * r.view;
        let ndc: Vec<DVec3> = corners.iter().map(|&p| vp.project_point3(p)).collect();
        let (top, bottom) = ndc.iter().fold((-9.0f64, 9.0f64), |(t, b), p| (t.max(p.y), b.min(p.y)));
        let right = ndc.iter().fold(0.0f64, |m, p| m.max(p.x.abs()));
        assert!(
            (top - 1.0 / DEFAULT_MARGIN).abs() < 1e-9 && (bottom + 1.0 / DEFAULT_MARGIN).abs() < 1e-9,
            "{top} {bottom}"
        );
        assert!(right < 0.5, "narrow: {right}");
        // upright: the bottle's top above its foot
        let foot = vp.project_point3(DVec3::new(0.0, 0.0, 0.0));
        let head = vp.project_point3(DVec3::new(0.0, 0.0, 10.0));
        assert!(head.y > foot.y + 1.0 && (head.x - foot.x).abs() < 0.1);
    }

    #[test]
    fn fit_frames_the_sphere_and_encloses_it() {
        let cam = Camera {
            placement: Placement::Fit { direction: Some([0.35, 0.3, 1.0]), up: None, margin: 1.0, turn: 0.0 },
            ..Camera::default()
        };
        let s = Sphere { center: DVec3::new(1.0, 2.0, 3.0), radius: 2.0 };
        let r = cam.resolve(&SceneBounds::of_sphere(s, Axis::Y), 2.0).unwrap();
        let c = r.view.transform_point3(s.center);
        assert!(-c.z - s.radius > r.near && -c.z + s.radius < r.far);
        assert!(c.x.abs() < 1e-9 && c.y.abs() < 1e-9);
        // the sphere's box is larger than the sphere: the sphere frames it, touching top and bottom
        let half = (35f64.to_radians() / 2.0).tan();
        assert!(((s.radius / (-c.z)).asin().tan() / half - 1.0).abs() < 1e-9);
    }
}

//! `Camera` described.

use super::{named, not_here, Constructor, Described, Field, Kind, Value};
use crate::error::Result;
use crate::render::scene::camera::{
    Camera, Placement, Projection, DEFAULT_FOV_Y, DEFAULT_HEIGHT, DEFAULT_UP,
};

const FIELDS: &[Field] = &[
    Field::choice("kind", &["fit", "look_at"], "framed to fit the scene, or looking at a point").fixed(),
    Field::choice("projection", &["perspective", "orthographic"], "the projection").fixed(),
    Field::new("eye", Kind::Vec3, "a look-at camera's position").optional(),
    Field::new("target", Kind::Vec3, "the point a look-at camera looks at").optional(),
    Field::new(
        "up",
        Kind::Vec3,
        "the direction that is up in the image (a fitted camera's None: the scene's up axis)",
    )
    .optional(),
    Field::new(
        "direction",
        Kind::Vec3,
        "a fitted camera's direction from the scene toward the eye (None: a three-quarter view about the up axis, across the scene's longest horizontal extent)",
    )
    .optional(),
    Field::float("margin", 0.5, 4.0, "a fitted camera's room around the scene (1: touching)").optional(),
    Field::float(
        "turn",
        -360.0,
        360.0,
        "degrees a fitted camera's view turns about the up axis, counter-clockwise seen from above (a turntable's views)",
    )
    .optional(),
    Field::float("fov_y", 1.0, 179.0, "vertical field of view in degrees, in (0, 180)").optional(),
    Field::float("height", 0.0, 100.0, "height of an orthographic view in world units, > 0").optional(),
    Field::float("near", 0.0, 100.0, "near clip distance (None: from the scene's bounds)").optional(),
    Field::float("far", 0.0, 1000.0, "far clip distance (None: from the scene's bounds)").optional(),
];

const EXTRAS: &[Field] =
    &[Field::new("orthographic", Kind::Bool, "a fitted camera with an orthographic projection")];

const CONSTRUCTORS: &[Constructor] = &[
    named!("Camera", "fit", ["direction", "up", "fov_y", "margin", "turn", "orthographic"], 1, 0),
    named!("Camera", "look_at", ["eye", "target", "up", "fov_y", "near", "far"], 2, 1),
    named!("Camera", "orthographic", ["eye", "target", "up", "height", "near", "far"], 2, 1),
];

impl Described for Camera {
    const FIELDS: &'static [Field] = FIELDS;

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

    fn get(&self, field: &str) -> Value {
        use Placement::*;
        match (field, self.placement, self.projection) {
            ("kind", Fit { .. }, _) => "fit".into(),
            ("kind", LookAt { .. }, _) => "look_at".into(),
            ("projection", _, Projection::Perspective { .. }) => "perspective".into(),
            ("projection", _, Projection::Orthographic { .. }) => "orthographic".into(),
            ("eye", LookAt { eye, .. }, _) => eye.into(),
            ("target", LookAt { target, .. }, _) => target.into(),
            ("up", LookAt { up, .. }, _) => up.into(),
            ("up", Fit { up, .. }, _) => up.into(),
            ("direction", Fit { direction, .. }, _) => direction.into(),
            ("margin", Fit { margin, .. }, _) => margin.into(),
            ("turn", Fit { turn, .. }, _) => turn.into(),
            ("fov_y", _, Projection::Perspective { fov_y_deg }) => fov_y_deg.into(),
            ("height", _, Projection::Orthographic { height }) => height.into(),
            ("near", ..) => self.near.into(),
            ("far", ..) => self.far.into(),
            _ => Value::None,
        }
    }

    fn set(&mut self, field: &str, v: Value) -> Result<()> {
        use Placement::*;
        match (field, &mut self.placement, &mut self.projection) {
            ("eye", LookAt { eye, .. }, _) => *eye = v.triple(field)?,
            ("target", LookAt { target, .. }, _) => *target = v.triple(field)?,
            ("up", LookAt { up, .. }, _) => *up = v.triple(field)?,
            ("up", Fit { up, .. }, _) => *up = v.opt_triple(field)?,
            ("direction", Fit { direction, .. }, _) => *direction = v.opt_triple(field)?,
            ("margin", Fit { margin, .. }, _) => *margin = v.float(field)?,
            ("turn", Fit { turn, .. }, _) => *turn = v.float(field)?,
            ("fov_y", _, Projection::Perspective { fov_y_deg }) => *fov_y_deg = v.float(field)?,
            ("height", _, Projection::Orthographic { height }) => *height = v.float(field)?,
            ("near", ..) => self.near = v.opt_float(field)?,
            ("far", ..) => self.far = v.opt_float(field)?,
            ("eye" | "target", ..) => return Err(not_here(field, "a look-at camera")),
            ("direction" | "margin" | "turn", ..) => return Err(not_here(field, "a fitted camera")),
            ("fov_y", ..) => return Err(not_here(field, "a perspective camera")),
            _ => return Err(not_here(field, "an orthographic camera")),
        }
        Ok(())
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

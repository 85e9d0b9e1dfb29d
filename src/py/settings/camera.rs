//! `Camera`: framed to fit, looking at a point, or orthographic.

use pyo3::prelude::*;

use super::{getters, settings_class, tup};
use crate::error::Result;
use crate::py::args::{flag_or, opt_number, triple, Obj};
use crate::py::errors::to_py;
use crate::render::scene::camera::{self, Camera, Placement, Projection};

/// A camera; build one with :meth:`fit` (the default), :meth:`look_at` or :meth:`orthographic`.
///
/// View space is right-handed: x right, y up, the camera looks down -z. ``near``/``far`` (clip
/// distances, > 0 for perspective) are chosen to enclose the scene when None.
#[pyclass(name = "Camera", module = "toonmesh._core", frozen, eq)]
#[derive(Clone, PartialEq)]
pub struct PyCamera {
    pub inner: Camera,
}

settings_class!(PyCamera, Camera, "Camera", |c| c.validate(""));

fn opt_triple(name: &str, obj: Obj<'_, '_>, default: [f64; 3]) -> Result<[f64; 3]> {
    obj.map_or(Ok(default), |o| triple(name, o))
}

/// A camera from its arguments, checked.
fn camera(
    make: impl FnOnce() -> Result<(Placement, Projection)>,
    near: Obj<'_, '_>,
    far: Obj<'_, '_>,
) -> PyResult<PyCamera> {
    (|| {
        let (placement, projection) = make()?;
        Camera::new(placement, projection, opt_number("near", near)?, opt_number("far", far)?)
    })()
    .map(|inner| PyCamera { inner })
    .map_err(to_py)
}

/// A camera at `eye` looking at `target` (default the origin) with `up` (default y).
fn look_at(eye: &Bound<'_, PyAny>, target: Obj<'_, '_>, up: Obj<'_, '_>) -> Result<Placement> {
    Ok(Placement::LookAt {
        eye: triple("eye", eye)?,
        target: opt_triple("target", target, [0.0; 3])?,
        up: opt_triple("up", up, camera::DEFAULT_UP)?,
    })
}

#[pymethods]
impl PyCamera {
    /// Frame the meshes' bounding sphere, seen from ``direction`` (scene -> eye; default
    /// (0.35, 0.3, 1.0): from the front, a little from the right and above), with ``up`` the
    /// image's up direction (default (0, 1, 0): +y up; pass (0, 0, 1) for a z-up scan).
    /// fov_y: vertical field of view in degrees (default 35); margin >= 1 leaves room around the
    /// sphere (default 1.05); orthographic: bool (default False).
    #[staticmethod]
    #[pyo3(signature = (direction = None, *, up = None, fov_y = None, margin = None, orthographic = None))]
    fn fit(
        direction: Obj<'_, '_>,
        up: Obj<'_, '_>,
        fov_y: Obj<'_, '_>,
        margin: Obj<'_, '_>,
        orthographic: Obj<'_, '_>,
    ) -> PyResult<Self> {
        let make = || {
            let placement = Placement::Fit {
                direction: opt_triple("direction", direction, camera::DEFAULT_DIRECTION)?,
                up: opt_triple("up", up, camera::DEFAULT_UP)?,
                margin: opt_number("margin", margin)?.unwrap_or(camera::DEFAULT_MARGIN),
            };
            let projection = if flag_or("orthographic", orthographic, false)? {
                Projection::Orthographic { height: camera::DEFAULT_HEIGHT }
            } else {
                Projection::Perspective {
                    fov_y_deg: opt_number("fov_y", fov_y)?.unwrap_or(camera::DEFAULT_FOV_Y),
                }
            };
            Ok((placement, projection))
        };
        camera(make, None, None)
    }

    /// A perspective camera at ``eye`` looking at ``target`` (default the origin), with ``up``
    /// (default (0, 1, 0)) and a vertical field of view ``fov_y`` in degrees (default 35).
    #[staticmethod]
    #[pyo3(signature = (eye, target = None, *, up = None, fov_y = None, near = None, far = None))]
    fn look_at(
        eye: &Bound<'_, PyAny>,
        target: Obj<'_, '_>,
        up: Obj<'_, '_>,
        fov_y: Obj<'_, '_>,
        near: Obj<'_, '_>,
        far: Obj<'_, '_>,
    ) -> PyResult<Self> {
        let make = || {
            let fov_y_deg = opt_number("fov_y", fov_y)?.unwrap_or(camera::DEFAULT_FOV_Y);
            Ok((look_at(eye, target, up)?, Projection::Perspective { fov_y_deg }))
        };
        camera(make, near, far)
    }

    /// An orthographic camera at ``eye`` looking at ``target``; ``height`` is the height of the
    /// view in world units (default 2).
    #[staticmethod]
    #[pyo3(signature = (eye, target = None, *, up = None, height = None, near = None, far = None))]
    fn orthographic(
        eye: &Bound<'_, PyAny>,
        target: Obj<'_, '_>,
        up: Obj<'_, '_>,
        height: Obj<'_, '_>,
        near: Obj<'_, '_>,
        far: Obj<'_, '_>,
    ) -> PyResult<Self> {
        let make = || {
            let height = opt_number("height", height)?.unwrap_or(camera::DEFAULT_HEIGHT);
            Ok((look_at(eye, target, up)?, Projection::Orthographic { height }))
        };
        camera(make, near, far)
    }

    fn __repr__(&self) -> String {
        let c = &self.inner;
        format!("Camera({:?}, {:?}, near={:?}, far={:?})", c.placement, c.projection, c.near, c.far)
    }
}

getters!(PyCamera {
    /// "fit" or "look_at".
    kind -> &'static str = |c| match c.placement {
        Placement::Fit { .. } => "fit",
        Placement::LookAt { .. } => "look_at",
    };
    /// "perspective" or "orthographic".
    projection -> &'static str = |c| match c.projection {
        Projection::Perspective { .. } => "perspective",
        Projection::Orthographic { .. } => "orthographic",
    };
    eye -> Option<(f64, f64, f64)> = |c| match c.placement {
        Placement::LookAt { eye, .. } => Some(tup(eye)),
        _ => None,
    };
    target -> Option<(f64, f64, f64)> = |c| match c.placement {
        Placement::LookAt { target, .. } => Some(tup(target)),
        _ => None,
    };
    up -> (f64, f64, f64) = |c| match c.placement {
        Placement::LookAt { up, .. } | Placement::Fit { up, .. } => tup(up),
    };
    direction -> Option<(f64, f64, f64)> = |c| match c.placement {
        Placement::Fit { direction, .. } => Some(tup(direction)),
        _ => None,
    };
    margin -> Option<f64> = |c| match c.placement {
        Placement::Fit { margin, .. } => Some(margin),
        _ => None,
    };
    fov_y -> Option<f64> = |c| match c.projection {
        Projection::Perspective { fov_y_deg } => Some(fov_y_deg),
        _ => None,
    };
    height -> Option<f64> = |c| match (c.projection, c.placement) {
        (Projection::Orthographic { height }, Placement::LookAt { .. }) => Some(height),
        _ => None,
    };
    near -> Option<f64> = |c| c.near;
    far -> Option<f64> = |c| c.far;
});

//! `Light` and its `Shadows`.

use pyo3::prelude::*;

use super::{getters, settings_class, tup};
use crate::error::{Error, Result};
use crate::py::args::{flag, opt_number, opt_rgb, optional, text, triple, type_name, unsigned, Obj};
use crate::py::errors::to_py;
use crate::render::effects::shadows::settings::{ShadowFilter, Shadows};
use crate::render::scene::light::{Light, LightKind, Space};

/// A directional or point light; build one with the static methods. ``color`` is sRGB (default
/// white) and ``intensity`` (>= 0, default 1) scales its light. ``space``: "world" (default) or
/// "camera" (fixed to the camera: x right, y up, -z forward, so it moves with the view).
#[pyclass(name = "Light", module = "toonmesh._core", frozen, eq)]
#[derive(Clone, PartialEq)]
pub struct PyLight {
    pub inner: Light,
}

settings_class!(PyLight, Light, "Light", |l| l.validate(""));

/// Shadow settings of a directional light: the shadow map's side in texels (a power of two
/// from 64 to 8192, default 2048), the depth bias in texels per unit of receiver slope (>= 0,
/// default 1.0; more removes shadow acne on lit surfaces, less keeps contact shadows tight) and
/// the filter: "pcf" (default; percentage-closer filtering, soft edges a few texels wide) or
/// "none" (one nearest test). The map is fitted to the scene's bounding sphere.
#[pyclass(name = "Shadows", module = "toonmesh._core", frozen, eq)]
#[derive(Clone, PartialEq)]
pub struct PyShadows {
    pub inner: Shadows,
}

settings_class!(PyShadows, Shadows, "Shadows", |s| s.validate(""));

#[pymethods]
impl PyShadows {
    #[new]
    #[pyo3(signature = (size = None, bias = None, filter = None))]
    fn new(size: Obj<'_, '_>, bias: Obj<'_, '_>, filter: Obj<'_, '_>) -> PyResult<Self> {
        (|| {
            let d = Shadows::default();
            let size = match optional("size", size, unsigned)? {
                None => d.size,
                Some(v) => u32::try_from(v).map_err(|_| {
                    Error::invalid("size", format!("must be a power of two from 64 to 8192, got {v}"))
                })?,
            };
            let s = Shadows {
                size,
                bias: opt_number("bias", bias)?.unwrap_or(d.bias),
                filter: match optional("filter", filter, text)? {
                    None => d.filter,
                    Some(f) => ShadowFilter::parse("filter", &f)?,
                },
            };
            s.validate("")?;
            Ok(PyShadows { inner: s })
        })()
        .map_err(to_py)
    }

    fn __repr__(&self) -> String {
        shadows_repr(&self.inner)
    }
}

getters!(PyShadows {
    size -> u32 = |s| s.size;
    bias -> f64 = |s| s.bias;
    filter -> &'static str = |s| s.filter.name();
});

getters!(PyLight {
    /// "directional" or "point".
    kind -> &'static str = |l| match l.kind {
        LightKind::Directional { .. } => "directional",
        LightKind::Point { .. } => "point",
    };
    direction -> Option<(f64, f64, f64)> = |l| match l.kind {
        LightKind::Directional { direction } => Some(tup(direction)),
        _ => None,
    };
    position -> Option<(f64, f64, f64)> = |l| match l.kind {
        LightKind::Point { position } => Some(tup(position)),
        _ => None,
    };
    color -> (f64, f64, f64) = |l| tup(l.color);
    intensity -> f64 = |l| l.intensity;
    space -> &'static str = |l| l.space_name();
    /// The shadow settings, or None when the light casts no shadows.
    shadows -> Option<PyShadows> = |l| l.shadows.map(|inner| PyShadows { inner });
});

fn shadows_repr(s: &Shadows) -> String {
    format!("Shadows(size={}, bias={}, filter={:?})", s.size, s.bias, s.filter.name())
}

/// The `shadows=` argument: None or False (none), True (the default settings) or a Shadows.
fn shadows_arg(obj: Obj<'_, '_>) -> Result<Option<Shadows>> {
    let Some(o) = obj else { return Ok(None) };
    if let Ok(s) = o.cast::<PyShadows>() {
        return Ok(Some(s.get().inner));
    }
    match flag("shadows", o) {
        Ok(on) => Ok(on.then(Shadows::default)),
        Err(_) => Err(Error::wrong_type(
            "shadows",
            format!("expected True, False or a toonmesh.Shadows, got {}", type_name(o)),
        )),
    }
}

fn light(
    kind: LightKind,
    color: Obj<'_, '_>,
    intensity: Obj<'_, '_>,
    space: Obj<'_, '_>,
    shadows: Obj<'_, '_>,
) -> PyResult<PyLight> {
    (|| {
        let space = match space {
            None => Space::World,
            Some(s) => Space::parse("space", &text("space", s)?)?,
        };
        let l = Light {
            kind,
            space,
            color: opt_rgb("color", color)?.unwrap_or([1.0; 3]),
            intensity: opt_number("intensity", intensity)?.unwrap_or(1.0),
            shadows: shadows_arg(shadows)?,
        };
        l.validate("")?;
        Ok(PyLight { inner: l })
    })()
    .map_err(to_py)
}

#[pymethods]
impl PyLight {
    /// Parallel light travelling along ``direction`` (3 numbers, from the light toward the
    /// scene; any length > 0). ``shadows``: True (default settings), a :class:`Shadows`, or
    /// False/None (default): the light casts shadows from a shadow map (one light a scene).
    #[staticmethod]
    #[pyo3(signature = (direction, *, color = None, intensity = None, space = None, shadows = None))]
    fn directional(
        direction: &Bound<'_, PyAny>,
        color: Obj<'_, '_>,
        intensity: Obj<'_, '_>,
        space: Obj<'_, '_>,
        shadows: Obj<'_, '_>,
    ) -> PyResult<Self> {
        let direction = triple("direction", direction).map_err(to_py)?;
        light(LightKind::Directional { direction }, color, intensity, space, shadows)
    }

    /// Light radiating from ``position`` (3 numbers; no falloff with distance).
    #[staticmethod]
    #[pyo3(signature = (position, *, color = None, intensity = None, space = None))]
    fn point(
        position: &Bound<'_, PyAny>,
        color: Obj<'_, '_>,
        intensity: Obj<'_, '_>,
        space: Obj<'_, '_>,
    ) -> PyResult<Self> {
        let position = triple("position", position).map_err(to_py)?;
        light(LightKind::Point { position }, color, intensity, space, None)
    }

    /// The default light: from the upper left, behind the viewer, fixed to the camera.
    #[staticmethod]
    fn key() -> Self {
        PyLight { inner: Light::default() }
    }

    fn __repr__(&self) -> String {
        let l = &self.inner;
        let (kind, v) = match l.kind {
            LightKind::Directional { direction } => ("directional", direction),
            LightKind::Point { position } => ("point", position),
        };
        let shadows = l.shadows.map_or(String::new(), |s| format!(", shadows={}", shadows_repr(&s)));
        format!(
            "Light.{kind}({v:?}, color={:?}, intensity={}, space={:?}{shadows})",
            l.color,
            l.intensity,
            l.space_name()
        )
    }
}

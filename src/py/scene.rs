//! The scene's settings as frozen Python classes around the core's typed objects: `Material`,
//! `Light`, `Camera`, `Outlines` and `LineStyle`. Defaults and checks live in the core
//! (`crate::render::scene`); these classes convert arguments (naming them in errors), expose the
//! fields read-only, compare by value, and pickle (for sending to worker processes).

use std::hash::{Hash, Hasher};

use pyo3::prelude::*;
use pyo3::types::{PyDict, PyString};

use super::args::{
    flag, flag_or, number, numbers, opt_number, opt_rgb, optional, rgb, text, triple, type_name, unsigned,
};
use super::errors::to_py;
use crate::edges::outlines::LineKind;
use crate::error::{Error, Result};
use crate::render::color::Srgb;
use crate::render::scene::camera::{self, Camera, Placement, Projection};
use crate::render::scene::light::{Light, LightKind, Space};
use crate::render::scene::material::{self, Highlight, Material, Model, MAX_LUT};
use crate::render::scene::outlines::{kind_names, LineStyle, Outlines, IMAGE_KIND, INK_KINDS};
use crate::render::scene::shadows::{ShadowFilter, Shadows};
use crate::render::scene::style::{Dither, DitherPattern, DitherSpace, Hatching};

type Obj<'a, 'py> = Option<&'a Bound<'py, PyAny>>;

fn hash_of(x: &impl std::fmt::Debug) -> u64 {
    let mut h = std::collections::hash_map::DefaultHasher::new();
    format!("{x:?}").hash(&mut h);
    h.finish()
}

/// A triple as a Python tuple.
fn tup(v: [f64; 3]) -> (f64, f64, f64) {
    (v[0], v[1], v[2])
}

fn f32s(v: Vec<f64>) -> Vec<f32> {
    v.into_iter().map(|x| x as f32).collect()
}

fn color_or(name: &str, obj: Obj<'_, '_>) -> Result<Srgb> {
    Ok(opt_rgb(name, obj)?.unwrap_or(material::DEFAULT_COLOR))
}

/// A lookup table: (N,) grey factors or (N, 3) RGB factors, 1 <= N <= 256.
fn table(name: &str, obj: &Bound<'_, PyAny>) -> Result<Vec<[f32; 3]>> {
    super::args::refuse_text(name, obj, "(N,) or (N, 3) numbers")?;
    let rows: Vec<Bound<'_, PyAny>> = obj
        .try_iter()
        .map_err(|_| {
            Error::wrong_type(name, format!("expected (N,) or (N, 3) numbers, got {}", type_name(obj)))
        })?
        .collect::<PyResult<_>>()
        .map_err(|e| Error::invalid(name, e.to_string()))?;
    if rows.is_empty() || rows.len() > MAX_LUT {
        return Err(Error::invalid(name, format!("needs 1 to {MAX_LUT} entries, got {}", rows.len())));
    }
    rows.iter()
        .enumerate()
        .map(|(i, r)| {
            let arg = format!("{name}[{i}]");
            if r.try_iter().is_ok() && !r.is_instance_of::<PyString>() {
                Ok(triple(&arg, r)?.map(|x| x as f32))
            } else {
                Ok([number(&arg, r)? as f32; 3])
            }
        })
        .collect()
}

/// Dithering between neighbouring bands (Borquez and Yepez): L.n + (t - 1/2) amount is banded,
/// t the pattern's threshold at the pixel. pattern: "bayer2", "bayer4" (default), "bayer8"
/// (ordered dithering) or "blue" (the R2 sequence, a blue-noise-like pattern). space: "screen"
/// (default, as in the paper: the pattern stays put while the object moves) or "object"
/// (anchored to the surface, so a turntable does not shimmer). amount: in L.n, 0 to 2 (default
/// 0.15). scale: pixels a pattern cell covers, 1 to 64 (default 1).
#[pyclass(name = "Dither", module = "toonmesh._core", frozen, eq)]
#[derive(Clone, PartialEq)]
pub struct PyDither {
    pub inner: Dither,
}

#[pymethods]
impl PyDither {
    #[new]
    #[pyo3(signature = (pattern = None, *, space = None, amount = None, scale = None))]
    fn new(
        pattern: Obj<'_, '_>,
        space: Obj<'_, '_>,
        amount: Obj<'_, '_>,
        scale: Obj<'_, '_>,
    ) -> PyResult<Self> {
        (|| {
            let mut d = Dither::new(match optional("pattern", pattern, text)? {
                None => DitherPattern::Bayer4,
                Some(p) => DitherPattern::parse("pattern", &p)?,
            });
            if let Some(s) = optional("space", space, text)? {
                d.space = DitherSpace::parse("space", &s)?;
            }
            d.amount = opt_number("amount", amount)?.unwrap_or(d.amount);
            d.scale = opt_number("scale", scale)?.unwrap_or(d.scale);
            d.validate("")?;
            Ok(PyDither { inner: d })
        })()
        .map_err(to_py)
    }

    #[getter]
    fn pattern(&self) -> &'static str {
        self.inner.pattern.name()
    }

    #[getter]
    fn space(&self) -> &'static str {
        self.inner.space.name()
    }

    #[getter]
    fn amount(&self) -> f64 {
        self.inner.amount
    }

    #[getter]
    fn scale(&self) -> f64 {
        self.inner.scale
    }

    fn __hash__(&self) -> u64 {
        hash_of(&self.inner)
    }

    fn __repr__(&self) -> String {
        dither_repr(&self.inner)
    }

    #[allow(clippy::type_complexity)]
    fn __reduce__<'py>(
        &self,
        py: Python<'py>,
    ) -> PyResult<(Bound<'py, PyAny>, (&'static str, &'static str, f64, f64), Bound<'py, PyAny>)> {
        // keyword-only arguments: rebuilt by `_restore_dither`
        let d = &self.inner;
        Ok((
            py.import("toonmesh._core")?.getattr("_restore_dither")?,
            (d.pattern.name(), d.space.name(), d.amount, d.scale),
            py.None().into_bound(py),
        ))
    }
}

fn dither_repr(d: &Dither) -> String {
    format!(
        "Dither({:?}, space={:?}, amount={}, scale={})",
        d.pattern.name(),
        d.space.name(),
        d.amount,
        d.scale
    )
}

#[pyfunction]
fn _restore_dither(pattern: &str, space: &str, amount: f64, scale: f64) -> PyResult<PyDither> {
    (|| {
        let d = Dither {
            pattern: DitherPattern::parse("pattern", pattern)?,
            space: DitherSpace::parse("space", space)?,
            amount,
            scale,
        };
        d.validate("")?;
        Ok(PyDither { inner: d })
    })()
    .map_err(to_py)
}

/// The `dither=` argument: None (none), a pattern name (its defaults) or a Dither.
fn dither_arg(obj: Obj<'_, '_>) -> Result<Option<Dither>> {
    let Some(o) = obj else { return Ok(None) };
    if let Ok(d) = o.cast::<PyDither>() {
        return Ok(Some(d.get().inner));
    }
    if o.is_instance_of::<PyString>() {
        return Ok(Some(Dither::new(DitherPattern::parse("dither", &text("dither", o)?)?)));
    }
    Err(Error::wrong_type(
        "dither",
        format!("expected a pattern name or a toonmesh.Dither, got {}", type_name(o)),
    ))
}

/// A shading model with its coefficients; build one with the static methods. Colours are sRGB:
/// ``'#rrggbb'`` or three numbers in [0, 1].
///
/// Every model computes, in linear light, ``C = a_l * ambient + sum over lights of
/// (f(L.n) * d_l * diffuse + s * S_l * specular)``, where ``a_l`` is the scene's ambient light,
/// ``d_l = S_l`` a light's colour times its intensity, ``L`` the unit vector toward the light and
/// ``n`` the unit normal; the models differ in ``f`` and ``s``. With ``per_vertex=True`` the
/// vertices are shaded and the colours interpolated (Gouraud, as Al-Rousan et al. colour
/// vertices); otherwise every pixel is shaded.
#[pyclass(name = "Material", module = "toonmesh._core", frozen, eq)]
#[derive(Clone, PartialEq)]
pub struct PyMaterial {
    pub inner: Material,
}

impl PyMaterial {
    fn made(m: Result<Material>) -> PyResult<Self> {
        m.map(|inner| PyMaterial { inner }).map_err(to_py)
    }
}

#[pymethods]
impl PyMaterial {
    /// Plain Lambert: f = max(L.n, 0), no highlight.
    ///
    /// color: base colour (default (0.95, 0.55, 0.25)); the diffuse coefficient is 90% of it and
    /// ambient (default) 10%, in linear light. per_vertex: bool, default False.
    #[staticmethod]
    #[pyo3(signature = (color = None, *, ambient = None, per_vertex = None))]
    fn lambert(color: Obj<'_, '_>, ambient: Obj<'_, '_>, per_vertex: Obj<'_, '_>) -> PyResult<Self> {
        Self::made((|| {
            Material::lambert(
                color_or("color", color)?,
                opt_rgb("ambient", ambient)?,
                flag_or("per_vertex", per_vertex, false)?,
            )
        })())
    }

    /// Plain Phong: f = max(L.n, 0), s = max(R.v, 0)^shininess on lit points (R: L reflected).
    ///
    /// color as in :meth:`lambert`; specular: highlight colour (default (0.5, 0.5, 0.5));
    /// shininess: exponent > 0 (default 32).
    #[staticmethod]
    #[pyo3(signature = (color = None, *, specular = None, shininess = None, ambient = None, per_vertex = None))]
    fn phong(
        color: Obj<'_, '_>,
        specular: Obj<'_, '_>,
        shininess: Obj<'_, '_>,
        ambient: Obj<'_, '_>,
        per_vertex: Obj<'_, '_>,
    ) -> PyResult<Self> {
        Self::made((|| {
            Material::phong(
                color_or("color", color)?,
                opt_rgb("specular", specular)?,
                opt_number("shininess", shininess)?.map(|x| x as f32),
                opt_rgb("ambient", ambient)?,
                flag_or("per_vertex", per_vertex, false)?,
            )
        })())
    }

    /// Al-Rousan et al.'s toon model: C = a_l a_m + thresh(L.n, t_h) d_l d_m + thresh(h, t_s) S_l S_m.
    ///
    /// thresh(a, b) is 1 where a >= b, else 0; t_h (default 0.0) and t_s (default 0.95) lie in
    /// [-1, 1]. highlight: "blinn" (default, h = n . normalize(L + v)) or "paper" (h = L.v, as the
    /// paper writes it). By default the shadow side keeps 35% of ``color`` (ambient) and the lit
    /// side reaches it; specular defaults to (0.6, 0.6, 0.6). The paper shades vertices: pass
    /// ``per_vertex=True`` for that.
    #[staticmethod]
    #[pyo3(signature = (color = None, *, t_h = None, t_s = None, highlight = None, ambient = None,
                        specular = None, per_vertex = None, dither = None))]
    #[allow(clippy::too_many_arguments)]
    fn thresholded_phong(
        color: Obj<'_, '_>,
        t_h: Obj<'_, '_>,
        t_s: Obj<'_, '_>,
        highlight: Obj<'_, '_>,
        ambient: Obj<'_, '_>,
        specular: Obj<'_, '_>,
        per_vertex: Obj<'_, '_>,
        dither: Obj<'_, '_>,
    ) -> PyResult<Self> {
        Self::made((|| {
            let highlight =
                highlight.map(|h| Highlight::parse("highlight", &text("highlight", h)?)).transpose()?;
            Material::thresholded_phong(
                color_or("color", color)?,
                opt_number("t_h", t_h)?.map(|x| x as f32),
                opt_number("t_s", t_s)?.map(|x| x as f32),
                highlight,
                opt_rgb("ambient", ambient)?,
                opt_rgb("specular", specular)?,
                flag_or("per_vertex", per_vertex, false)?,
            )?
            .with_dither(dither_arg(dither)?)
        })())
    }

    /// Borquez and Yepez's toon bands: f = values[k], k = number of thresholds t with L.n >= t.
    ///
    /// Defaults are the paper's: thresholds (0.2, 0.5, 0.7, 0.9) and values (0, 0.2, 0.7, 0.9,
    /// 1), so L.n >= 0.9 -> 1.0, 0.7-0.9 -> 0.9, 0.5-0.7 -> 0.7, 0.2-0.5 -> 0.2, below -> 0,
    /// times ``color``. 1 to 8 strictly increasing thresholds, and one value more (each >= 0).
    /// dither (here and on the other toon models): None (default), a pattern name or a
    /// :class:`Dither`; needs per-pixel shading.
    #[staticmethod]
    #[pyo3(signature = (color = None, *, thresholds = None, values = None, per_vertex = None, dither = None))]
    fn bands(
        color: Obj<'_, '_>,
        thresholds: Obj<'_, '_>,
        values: Obj<'_, '_>,
        per_vertex: Obj<'_, '_>,
        dither: Obj<'_, '_>,
    ) -> PyResult<Self> {
        Self::made((|| {
            Material::bands(
                color_or("color", color)?,
                thresholds.map(|t| numbers("thresholds", t).map(f32s)).transpose()?,
                values.map(|v| numbers("values", v).map(f32s)).transpose()?,
                flag_or("per_vertex", per_vertex, false)?,
            )?
            .with_dither(dither_arg(dither)?)
        })())
    }

    /// Borquez and Yepez's cross-hatching: the bands' tone (their value times the light, as
    /// :meth:`bands` computes it) picks how many layers of ink strokes cover the paper: none
    /// where the tone is above 0.8, then strokes at 45 degrees, then -45 (cross-hatching), 0
    /// and 90 degrees below 0.6, 0.4 and 0.2. The strokes are mapped on the object without UVs
    /// (triplanar, in the mesh's own coordinates), keep about ``spacing`` pixels between them
    /// (default 6, 2 to 256) and ``width`` pixels of width (default 1.25, up to ``spacing``) at
    /// any distance, and give the same bits for the same scene.
    ///
    /// color: the paper (default white); ink: the strokes (default (0.1, 0.1, 0.1));
    /// thresholds, values, dither and per_vertex as in :meth:`bands`.
    #[staticmethod]
    #[pyo3(signature = (color = None, *, ink = None, thresholds = None, values = None, spacing = None,
                        width = None, per_vertex = None, dither = None))]
    #[allow(clippy::too_many_arguments)]
    fn hatching(
        color: Obj<'_, '_>,
        ink: Obj<'_, '_>,
        thresholds: Obj<'_, '_>,
        values: Obj<'_, '_>,
        spacing: Obj<'_, '_>,
        width: Obj<'_, '_>,
        per_vertex: Obj<'_, '_>,
        dither: Obj<'_, '_>,
    ) -> PyResult<Self> {
        Self::made((|| {
            let d = Hatching::default();
            let h = Hatching {
                ink: opt_rgb("ink", ink)?.unwrap_or(d.ink),
                spacing: opt_number("spacing", spacing)?.unwrap_or(d.spacing),
                width: opt_number("width", width)?.unwrap_or(d.width),
            };
            h.validate("")?;
            Material::hatching(
                opt_rgb("color", color)?.unwrap_or([1.0; 3]),
                thresholds.map(|t| numbers("thresholds", t).map(f32s)).transpose()?,
                values.map(|v| numbers("values", v).map(f32s)).transpose()?,
                h,
                flag_or("per_vertex", per_vertex, false)?,
            )?
            .with_dither(dither_arg(dither)?)
        })())
    }

    /// A lookup table (gradient map): f = table[min(floor(clamp(L.n, 0, 1) N), N - 1)].
    ///
    /// table: (N,) grey factors or (N, 3) RGB factors (linear, >= 0, 1 <= N <= 256) applied to
    /// ``color``; the default is :func:`kang_table`, Kang et al.'s 256-to-3-level mapping.
    #[staticmethod]
    #[pyo3(signature = (table = None, color = None, *, per_vertex = None, dither = None))]
    fn lut(
        table: Obj<'_, '_>,
        color: Obj<'_, '_>,
        per_vertex: Obj<'_, '_>,
        dither: Obj<'_, '_>,
    ) -> PyResult<Self> {
        Self::made((|| {
            Material::lut(
                table.map(|t| self::table("table", t)).transpose()?,
                color_or("color", color)?,
                flag_or("per_vertex", per_vertex, false)?,
            )?
            .with_dither(dither_arg(dither)?)
        })())
    }

    /// The shading model: "lambert", "phong", "thresholded_phong", "bands" or "lut" (a
    /// hatching material is "bands" with :attr:`hatch_style` set).
    #[getter]
    fn model(&self) -> &'static str {
        self.inner.model.name()
    }

    /// A hatching material's ink (sRGB), spacing and width in pixels as a dict; None for others.
    #[getter]
    fn hatch_style<'py>(&self, py: Python<'py>) -> PyResult<Option<Bound<'py, PyDict>>> {
        let Some(h) = &self.inner.hatching else { return Ok(None) };
        let d = PyDict::new(py);
        d.set_item("ink", tup(h.ink))?;
        d.set_item("spacing", h.spacing)?;
        d.set_item("width", h.width)?;
        Ok(Some(d))
    }

    /// The dithering, or None.
    #[getter]
    fn dither(&self) -> Option<PyDither> {
        self.inner.dither.map(|inner| PyDither { inner })
    }

    /// sRGB coefficients (tuples of 3 floats).
    #[getter]
    fn diffuse(&self) -> (f64, f64, f64) {
        tup(self.inner.diffuse)
    }

    #[getter]
    fn ambient(&self) -> (f64, f64, f64) {
        tup(self.inner.ambient)
    }

    #[getter]
    fn specular(&self) -> (f64, f64, f64) {
        tup(self.inner.specular)
    }

    #[getter]
    fn per_vertex(&self) -> bool {
        self.inner.per_vertex
    }

    /// Phong's exponent (None for other models).
    #[getter]
    fn shininess(&self) -> Option<f32> {
        match self.inner.model {
            Model::Phong { shininess } => Some(shininess),
            _ => None,
        }
    }

    /// The thresholded Phong model's t_h, t_s and highlight (None for other models).
    #[getter]
    fn t_h(&self) -> Option<f32> {
        match self.inner.model {
            Model::ThresholdedPhong { t_h, .. } => Some(t_h),
            _ => None,
        }
    }

    #[getter]
    fn t_s(&self) -> Option<f32> {
        match self.inner.model {
            Model::ThresholdedPhong { t_s, .. } => Some(t_s),
            _ => None,
        }
    }

    #[getter]
    fn highlight(&self) -> Option<&'static str> {
        match self.inner.model {
            Model::ThresholdedPhong { highlight, .. } => Some(highlight.name()),
            _ => None,
        }
    }

    /// The bands' thresholds and values (None for other models).
    #[getter]
    fn thresholds(&self) -> Option<Vec<f64>> {
        match &self.inner.model {
            Model::Bands { thresholds, .. } => Some(thresholds.iter().map(|&x| x as f64).collect()),
            _ => None,
        }
    }

    #[getter]
    fn values(&self) -> Option<Vec<f64>> {
        match &self.inner.model {
            Model::Bands { values, .. } => Some(values.iter().map(|&x| x as f64).collect()),
            _ => None,
        }
    }

    /// The lookup table's (N, 3) rows (None for other models).
    #[getter]
    fn table(&self) -> Option<Vec<(f64, f64, f64)>> {
        match &self.inner.model {
            Model::Lut { table } => Some(table.iter().map(|c| tup(c.map(|x| x as f64))).collect()),
            _ => None,
        }
    }

    fn __hash__(&self) -> u64 {
        hash_of(&self.inner)
    }

    fn __repr__(&self) -> String {
        let m = &self.inner;
        let params = match &m.model {
            Model::Lambert => String::new(),
            Model::Phong { shininess } => format!(", shininess={shininess}"),
            Model::ThresholdedPhong { t_h, t_s, highlight } => {
                format!(", t_h={t_h}, t_s={t_s}, highlight={:?}", highlight.name())
            }
            Model::Bands { thresholds, values } => format!(", thresholds={thresholds:?}, values={values:?}"),
            Model::Lut { table } => format!(", table=<{} entries>", table.len()),
        };
        let mut params = params;
        if let Some(h) = &m.hatching {
            params += &format!(", hatching=(ink={:?}, spacing={}, width={})", h.ink, h.spacing, h.width);
        }
        if let Some(d) = &m.dither {
            params += &format!(", dither={}", dither_repr(d));
        }
        format!(
            "Material.{}(diffuse={:?}, ambient={:?}, specular={:?}{params}, per_vertex={})",
            m.model.name(),
            m.diffuse,
            m.ambient,
            m.specular,
            if m.per_vertex { "True" } else { "False" }
        )
    }

    fn __reduce__<'py>(&self, py: Python<'py>) -> PyResult<(Bound<'py, PyAny>, (String,))> {
        restorer(py, "_restore_material", saved(&self.inner))
    }
}

/// A directional or point light; build one with the static methods. ``color`` is sRGB (default
/// white) and ``intensity`` (>= 0, default 1) scales its light. ``space``: "world" (default) or
/// "camera" (fixed to the camera: x right, y up, -z forward, so it moves with the view).
#[pyclass(name = "Light", module = "toonmesh._core", frozen, eq)]
#[derive(Clone, PartialEq)]
pub struct PyLight {
    pub inner: Light,
}

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

    #[getter]
    fn size(&self) -> u32 {
        self.inner.size
    }

    #[getter]
    fn bias(&self) -> f64 {
        self.inner.bias
    }

    #[getter]
    fn filter(&self) -> &'static str {
        self.inner.filter.name()
    }

    fn __hash__(&self) -> u64 {
        hash_of(&self.inner)
    }

    fn __repr__(&self) -> String {
        format!(
            "Shadows(size={}, bias={}, filter={:?})",
            self.inner.size,
            self.inner.bias,
            self.inner.filter.name()
        )
    }

    fn __reduce__<'py>(&self, py: Python<'py>) -> PyResult<(Bound<'py, PyAny>, (u32, f64, &'static str))> {
        Ok((
            py.get_type::<PyShadows>().into_any(),
            (self.inner.size, self.inner.bias, self.inner.filter.name()),
        ))
    }
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
    shadows: Option<Shadows>,
) -> PyResult<PyLight> {
    (|| {
        let space = match space {
            None => Space::World,
            Some(s) => Space::parse("space", &text("space", s)?)?,
        };
        let color = opt_rgb("color", color)?.unwrap_or([1.0; 3]);
        let intensity = opt_number("intensity", intensity)?.unwrap_or(1.0);
        let l = Light { kind, space, color, intensity, shadows };
        l.validate("light").map_err(|e| match e {
            Error::InvalidValue { arg, reason } => Error::invalid(arg.trim_start_matches("light."), reason),
            other => other,
        })?;
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
        let shadows = shadows_arg(shadows).map_err(to_py)?;
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

    /// "directional" or "point".
    #[getter]
    fn kind(&self) -> &'static str {
        match self.inner.kind {
            LightKind::Directional { .. } => "directional",
            LightKind::Point { .. } => "point",
        }
    }

    #[getter]
    fn direction(&self) -> Option<(f64, f64, f64)> {
        match self.inner.kind {
            LightKind::Directional { direction } => Some(tup(direction)),
            _ => None,
        }
    }

    #[getter]
    fn position(&self) -> Option<(f64, f64, f64)> {
        match self.inner.kind {
            LightKind::Point { position } => Some(tup(position)),
            _ => None,
        }
    }

    #[getter]
    fn color(&self) -> (f64, f64, f64) {
        tup(self.inner.color)
    }

    #[getter]
    fn intensity(&self) -> f64 {
        self.inner.intensity
    }

    #[getter]
    fn space(&self) -> &'static str {
        self.inner.space_name()
    }

    /// The shadow settings, or None when the light casts no shadows.
    #[getter]
    fn shadows(&self) -> Option<PyShadows> {
        self.inner.shadows.map(|inner| PyShadows { inner })
    }

    fn __hash__(&self) -> u64 {
        hash_of(&self.inner)
    }

    fn __repr__(&self) -> String {
        let where_ = match self.inner.kind {
            LightKind::Directional { direction } => format!("directional({direction:?}"),
            LightKind::Point { position } => format!("point({position:?}"),
        };
        let shadows = match self.inner.shadows {
            Some(s) => {
                format!(", shadows=Shadows(size={}, bias={}, filter={:?})", s.size, s.bias, s.filter.name())
            }
            None => String::new(),
        };
        format!(
            "Light.{where_}, color={:?}, intensity={}, space={:?}{shadows})",
            self.inner.color,
            self.inner.intensity,
            self.inner.space_name()
        )
    }

    fn __reduce__<'py>(&self, py: Python<'py>) -> PyResult<(Bound<'py, PyAny>, (String,))> {
        restorer(py, "_restore_light", saved(&self.inner))
    }
}

/// A camera; build one with :meth:`fit` (the default), :meth:`look_at` or :meth:`orthographic`.
///
/// View space is right-handed: x right, y up, the camera looks down -z. ``near``/``far`` (clip
/// distances, > 0 for perspective) are chosen to enclose the scene when None.
#[pyclass(name = "Camera", module = "toonmesh._core", frozen, eq)]
#[derive(Clone, PartialEq)]
pub struct PyCamera {
    pub inner: Camera,
}

fn camera(
    placement: Placement,
    projection: Projection,
    near: Obj<'_, '_>,
    far: Obj<'_, '_>,
) -> PyResult<PyCamera> {
    (|| {
        let c =
            Camera { placement, projection, near: opt_number("near", near)?, far: opt_number("far", far)? };
        c.validate().map_err(|e| match e {
            Error::InvalidValue { arg, reason } => Error::invalid(arg.trim_start_matches("camera."), reason),
            other => other,
        })?;
        Ok(PyCamera { inner: c })
    })()
    .map_err(to_py)
}

/// A camera at `eye` looking at `target` (default the origin) with `up` (default y).
fn look_at_placement(eye: &Bound<'_, PyAny>, target: Obj<'_, '_>, up: Obj<'_, '_>) -> Result<Placement> {
    Ok(Placement::LookAt {
        eye: triple("eye", eye)?,
        target: opt_triple("target", target, [0.0; 3])?,
        up: opt_triple("up", up, camera::DEFAULT_UP)?,
    })
}

fn opt_triple(name: &str, obj: Obj<'_, '_>, default: [f64; 3]) -> Result<[f64; 3]> {
    obj.map_or(Ok(default), |o| triple(name, o))
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
        let (placement, projection) = (|| {
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
        })()
        .map_err(to_py)?;
        camera(placement, projection, None, None)
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
        let (placement, projection) = (|| {
            let placement = look_at_placement(eye, target, up)?;
            Ok((
                placement,
                Projection::Perspective {
                    fov_y_deg: opt_number("fov_y", fov_y)?.unwrap_or(camera::DEFAULT_FOV_Y),
                },
            ))
        })()
        .map_err(to_py)?;
        camera(placement, projection, near, far)
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
        let (placement, projection) = (|| {
            let placement = look_at_placement(eye, target, up)?;
            Ok((
                placement,
                Projection::Orthographic {
                    height: opt_number("height", height)?.unwrap_or(camera::DEFAULT_HEIGHT),
                },
            ))
        })()
        .map_err(to_py)?;
        camera(placement, projection, near, far)
    }

    /// "fit" or "look_at".
    #[getter]
    fn kind(&self) -> &'static str {
        match self.inner.placement {
            Placement::Fit { .. } => "fit",
            Placement::LookAt { .. } => "look_at",
        }
    }

    /// "perspective" or "orthographic".
    #[getter]
    fn projection(&self) -> &'static str {
        match self.inner.projection {
            Projection::Perspective { .. } => "perspective",
            Projection::Orthographic { .. } => "orthographic",
        }
    }

    #[getter]
    fn eye(&self) -> Option<(f64, f64, f64)> {
        match self.inner.placement {
            Placement::LookAt { eye, .. } => Some(tup(eye)),
            _ => None,
        }
    }

    #[getter]
    fn target(&self) -> Option<(f64, f64, f64)> {
        match self.inner.placement {
            Placement::LookAt { target, .. } => Some(tup(target)),
            _ => None,
        }
    }

    #[getter]
    fn up(&self) -> (f64, f64, f64) {
        match self.inner.placement {
            Placement::LookAt { up, .. } | Placement::Fit { up, .. } => tup(up),
        }
    }

    #[getter]
    fn direction(&self) -> Option<(f64, f64, f64)> {
        match self.inner.placement {
            Placement::Fit { direction, .. } => Some(tup(direction)),
            _ => None,
        }
    }

    #[getter]
    fn margin(&self) -> Option<f64> {
        match self.inner.placement {
            Placement::Fit { margin, .. } => Some(margin),
            _ => None,
        }
    }

    #[getter]
    fn fov_y(&self) -> Option<f64> {
        match self.inner.projection {
            Projection::Perspective { fov_y_deg } => Some(fov_y_deg),
            _ => None,
        }
    }

    #[getter]
    fn height(&self) -> Option<f64> {
        match (self.inner.projection, self.inner.placement) {
            (Projection::Orthographic { height }, Placement::LookAt { .. }) => Some(height),
            _ => None,
        }
    }

    #[getter]
    fn near(&self) -> Option<f64> {
        self.inner.near
    }

    #[getter]
    fn far(&self) -> Option<f64> {
        self.inner.far
    }

    fn __hash__(&self) -> u64 {
        hash_of(&self.inner)
    }

    fn __repr__(&self) -> String {
        format!(
            "Camera({:?}, {:?}, near={:?}, far={:?})",
            self.inner.placement, self.inner.projection, self.inner.near, self.inner.far
        )
    }

    fn __reduce__<'py>(&self, py: Python<'py>) -> PyResult<(Bound<'py, PyAny>, (String,))> {
        restorer(py, "_restore_camera", saved(&self.inner))
    }
}

/// How one kind of ink line is drawn: ``color`` (sRGB, default black) and ``width`` in output
/// pixels (default 1.5; the same at every resolution and supersampling factor).
#[pyclass(name = "LineStyle", module = "toonmesh._core", frozen, eq)]
#[derive(Clone, PartialEq)]
pub struct PyLineStyle {
    pub inner: LineStyle,
}

#[pymethods]
impl PyLineStyle {
    #[new]
    #[pyo3(signature = (color = None, width = None))]
    fn new(color: Obj<'_, '_>, width: Obj<'_, '_>) -> PyResult<Self> {
        (|| {
            let d = LineStyle::default();
            let s = LineStyle {
                color: opt_rgb("color", color)?.unwrap_or(d.color),
                width: opt_number("width", width)?.map_or(d.width, |w| w as f32),
            };
            s.validate("style").map_err(|e| match e {
                Error::InvalidValue { arg, reason } => {
                    Error::invalid(arg.trim_start_matches("style."), reason)
                }
                other => other,
            })?;
            Ok(PyLineStyle { inner: s })
        })()
        .map_err(to_py)
    }

    #[getter]
    fn color(&self) -> (f64, f64, f64) {
        tup(self.inner.color)
    }

    #[getter]
    fn width(&self) -> f32 {
        self.inner.width
    }

    fn __hash__(&self) -> u64 {
        hash_of(&self.inner)
    }

    fn __repr__(&self) -> String {
        format!("LineStyle(color={:?}, width={})", self.inner.color, self.inner.width)
    }

    fn __reduce__<'py>(&self, py: Python<'py>) -> PyResult<(Bound<'py, PyAny>, (Option<Srgb>, Option<f32>))> {
        Ok((py.get_type::<PyLineStyle>().into_any(), (Some(self.inner.color), Some(self.inner.width))))
    }
}

/// The style of one ink kind from its keyword: None or True (the common style), False (not
/// drawn), a :class:`LineStyle`, or a colour (the common width).
fn style(name: &str, obj: Obj<'_, '_>, common: LineStyle) -> Result<Option<LineStyle>> {
    let Some(o) = obj else { return Ok(Some(common)) };
    if let Ok(s) = o.cast::<PyLineStyle>() {
        return Ok(Some(s.get().inner));
    }
    if flag(name, o).is_ok() {
        return Ok(flag(name, o)?.then_some(common));
    }
    rgb(name, o).map(|color| Some(LineStyle { color, ..common })).map_err(|e| match e {
        Error::WrongType { .. } => Error::wrong_type(
            name,
            format!("expected True, False, a LineStyle or a colour, got {}", type_name(o)),
        ),
        other => other,
    })
}

/// Ink outlines for a render.
///
/// kind: "mesh" (lines found on the mesh: Kang, Kim and Yoon), "image" (Sobel edges of the
/// normal and depth buffers: Borquez and Yepez) or "both" (default). color and width: the common
/// style of every kind (default black, 1.5 output pixels). Each kind can be styled on its own
/// with a keyword: silhouette, boundary, crease (both ridge and valley), ridge, valley,
/// nonmanifold, image; each takes None or True (the common style), False (not drawn), a
/// :class:`LineStyle`, or a colour. Image edges are one pixel wide whatever the width.
///
/// crease_angle: dihedral angle in degrees above which an edge is a crease (default 30, as in
/// :func:`toonmesh.edges.feature_edges`). weld: merge vertices at equal positions first, so
/// UV or normal seams are not drawn as boundaries (default True). normal_threshold (default
/// 1.0) and depth_threshold (default 0.1, in world depth units times 4): the rule of
/// :func:`toonmesh.edges.detect_edges`. depth_offset: hidden-line removal keeps a point of a
/// line when its depth is at most the largest surface depth in the 3x3 pixels around it plus
/// this many pixel footprints (the world size of one pixel at that depth; default 1.0); a
/// silhouette or boundary with background among those pixels is on the rim and always shows.
#[pyclass(name = "Outlines", module = "toonmesh._core", frozen, eq)]
#[derive(Clone, PartialEq)]
pub struct PyOutlines {
    pub inner: Outlines,
}

#[pymethods]
impl PyOutlines {
    #[new]
    #[pyo3(signature = (kind = None, *, color = None, width = None, silhouette = None, boundary = None,
                        crease = None, ridge = None, valley = None, nonmanifold = None, image = None,
                        crease_angle = None, weld = None, normal_threshold = None, depth_threshold = None,
                        depth_offset = None))]
    #[allow(clippy::too_many_arguments)]
    fn new(
        kind: Obj<'_, '_>,
        color: Obj<'_, '_>,
        width: Obj<'_, '_>,
        silhouette: Obj<'_, '_>,
        boundary: Obj<'_, '_>,
        crease: Obj<'_, '_>,
        ridge: Obj<'_, '_>,
        valley: Obj<'_, '_>,
        nonmanifold: Obj<'_, '_>,
        image: Obj<'_, '_>,
        crease_angle: Obj<'_, '_>,
        weld: Obj<'_, '_>,
        normal_threshold: Obj<'_, '_>,
        depth_threshold: Obj<'_, '_>,
        depth_offset: Obj<'_, '_>,
    ) -> PyResult<Self> {
        (|| {
            let (mesh, img) = match kind {
                None => (true, true),
                Some(k) => Outlines::parse_kind("kind", &text("kind", k)?)?,
            };
            let mut o = Outlines::new(mesh, img);
            let d = LineStyle::default();
            let common = LineStyle {
                color: opt_rgb("color", color)?.unwrap_or(d.color),
                width: opt_number("width", width)?.map_or(d.width, |w| w as f32),
            };
            let crease_style = style("crease", crease, common)?;
            let mut set =
                |k: usize, name: &str, obj: Obj<'_, '_>, fallback: Option<LineStyle>| -> Result<()> {
                    o.styles[k] = if obj.is_some() { style(name, obj, common)? } else { fallback };
                    Ok(())
                };
            set(LineKind::Silhouette as usize, "silhouette", silhouette, Some(common))?;
            set(LineKind::Boundary as usize, "boundary", boundary, Some(common))?;
            set(LineKind::NonManifold as usize, "nonmanifold", nonmanifold, Some(common))?;
            set(LineKind::Ridge as usize, "ridge", ridge, crease_style)?;
            set(LineKind::Valley as usize, "valley", valley, crease_style)?;
            set(IMAGE_KIND, "image", image, Some(common))?;
            if let Some(a) = opt_number("crease_angle", crease_angle)? {
                o.crease_angle = a;
            }
            o.weld = flag_or("weld", weld, o.weld)?;
            if let Some(t) = opt_number("normal_threshold", normal_threshold)? {
                o.normal_threshold = t as f32;
            }
            if let Some(t) = opt_number("depth_threshold", depth_threshold)? {
                o.depth_threshold = t as f32;
            }
            if let Some(t) = opt_number("depth_offset", depth_offset)? {
                o.depth_offset = t as f32;
            }
            o.validate("outlines").map_err(|e| match e {
                Error::InvalidValue { arg, reason } => {
                    Error::invalid(arg.trim_start_matches("outlines."), reason)
                }
                other => other,
            })?;
            Ok(PyOutlines { inner: o })
        })()
        .map_err(to_py)
    }

    /// "mesh", "image" or "both".
    #[getter]
    fn kind(&self) -> &'static str {
        self.inner.kind_name()
    }

    /// Each ink kind's :class:`LineStyle`, or None where it is not drawn.
    #[getter]
    fn styles<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyDict>> {
        let d = PyDict::new(py);
        for (name, s) in kind_names().iter().zip(&self.inner.styles) {
            d.set_item(name, s.map(|inner| PyLineStyle { inner }))?;
        }
        Ok(d)
    }

    #[getter]
    fn crease_angle(&self) -> f64 {
        self.inner.crease_angle
    }

    #[getter]
    fn weld(&self) -> bool {
        self.inner.weld
    }

    #[getter]
    fn normal_threshold(&self) -> f32 {
        self.inner.normal_threshold
    }

    #[getter]
    fn depth_threshold(&self) -> f32 {
        self.inner.depth_threshold
    }

    #[getter]
    fn depth_offset(&self) -> f32 {
        self.inner.depth_offset
    }

    fn __hash__(&self) -> u64 {
        hash_of(&self.inner)
    }

    fn __repr__(&self) -> String {
        format!("Outlines({:?}, crease_angle={}, ...)", self.inner.kind_name(), self.inner.crease_angle)
    }

    fn __reduce__<'py>(&self, py: Python<'py>) -> PyResult<(Bound<'py, PyAny>, (String,))> {
        restorer(py, "_restore_outlines", saved(&self.inner))
    }
}

// --- pickling: a class is saved as its value in the text form of `state` and rebuilt (and
// checked again) by a `_restore_*` function of this module.

fn restorer<'py>(py: Python<'py>, name: &str, state: String) -> PyResult<(Bound<'py, PyAny>, (String,))> {
    let module = py.import("toonmesh._core")?;
    Ok((module.getattr(name)?, (state,)))
}

fn saved<T: state::State>(x: &T) -> String {
    x.save()
}

pub mod state {
    //! A compact text form of the scene settings for pickling: numbers in full precision
    //! (Rust's shortest round-trip formatting), fields separated by ';'.
    use super::*;

    pub trait State: Sized {
        fn save(&self) -> String;
        fn load(s: &str) -> Result<Self>;
    }

    struct Reader<'a>(std::str::Split<'a, char>);

    impl<'a> Reader<'a> {
        fn next(&mut self) -> Result<&'a str> {
            self.0.next().ok_or_else(|| Error::invalid("state", "truncated"))
        }
        fn f64(&mut self) -> Result<f64> {
            self.next()?.parse().map_err(|_| Error::invalid("state", "bad number"))
        }
        fn f32(&mut self) -> Result<f32> {
            Ok(self.f64()? as f32)
        }
        fn v3(&mut self) -> Result<[f64; 3]> {
            Ok([self.f64()?, self.f64()?, self.f64()?])
        }
        fn skip(&mut self, n: usize) -> Result<()> {
            for _ in 0..n {
                self.next()?;
            }
            Ok(())
        }
        fn opt(&mut self) -> Result<Option<f64>> {
            match self.next()? {
                "-" => Ok(None),
                s => s.parse().map(Some).map_err(|_| Error::invalid("state", "bad number")),
            }
        }
        fn list(&mut self) -> Result<Vec<f32>> {
            let n: usize = self.next()?.parse().map_err(|_| Error::invalid("state", "bad count"))?;
            (0..n).map(|_| self.f32()).collect()
        }
    }

    fn reader(s: &str) -> Reader<'_> {
        Reader(s.split(';'))
    }

    fn v3(v: [f64; 3]) -> String {
        format!("{};{};{}", v[0], v[1], v[2])
    }

    fn opt(v: Option<f64>) -> String {
        v.map_or("-".into(), |x| x.to_string())
    }

    fn list(v: &[f32]) -> String {
        std::iter::once(v.len().to_string())
            .chain(v.iter().map(|x| x.to_string()))
            .collect::<Vec<_>>()
            .join(";")
    }

    impl State for Material {
        fn save(&self) -> String {
            let params = match &self.model {
                Model::Lambert => String::new(),
                Model::Phong { shininess } => shininess.to_string(),
                Model::ThresholdedPhong { t_h, t_s, highlight } => {
                    format!("{t_h};{t_s};{}", highlight.name())
                }
                Model::Bands { thresholds, values } => format!("{};{}", list(thresholds), list(values)),
                Model::Lut { table } => list(&table.iter().flatten().copied().collect::<Vec<_>>()),
            };
            let hatching = match &self.hatching {
                Some(h) => format!("{};{};{}", v3(h.ink), h.spacing, h.width),
                None => "-;-;-;-;-".into(),
            };
            let dither = match &self.dither {
                Some(d) => format!("{};{};{};{}", d.pattern.name(), d.space.name(), d.amount, d.scale),
                None => "-;-;-;-".into(),
            };
            format!(
                "{};{};{};{};{};{hatching};{dither};{params}",
                self.model.name(),
                v3(self.diffuse),
                v3(self.ambient),
                v3(self.specular),
                self.per_vertex
            )
        }

        fn load(s: &str) -> Result<Self> {
            let mut r = reader(s);
            let name = r.next()?;
            let (diffuse, ambient, specular) = (r.v3()?, r.v3()?, r.v3()?);
            let per_vertex = r.next()? == "true";
            let hatching = match r.opt()? {
                None => {
                    r.skip(4)?;
                    None
                }
                Some(x) => {
                    Some(Hatching { ink: [x, r.f64()?, r.f64()?], spacing: r.f64()?, width: r.f64()? })
                }
            };
            let dither = match r.next()? {
                "-" => {
                    r.skip(3)?;
                    None
                }
                pattern => Some(Dither {
                    pattern: DitherPattern::parse("state", pattern)?,
                    space: DitherSpace::parse("state", r.next()?)?,
                    amount: r.f64()?,
                    scale: r.f64()?,
                }),
            };
            let model = match name {
                "lambert" => Model::Lambert,
                "phong" => Model::Phong { shininess: r.f32()? },
                "thresholded_phong" => Model::ThresholdedPhong {
                    t_h: r.f32()?,
                    t_s: r.f32()?,
                    highlight: Highlight::parse("state", r.next()?)?,
                },
                "bands" => Model::Bands { thresholds: r.list()?, values: r.list()? },
                "lut" => {
                    Model::Lut { table: r.list()?.chunks_exact(3).map(|c| [c[0], c[1], c[2]]).collect() }
                }
                other => return Err(Error::invalid("state", format!("unknown model {other:?}"))),
            };
            let m = Material { model, ambient, diffuse, specular, per_vertex, hatching, dither };
            m.validate("state")?;
            Ok(m)
        }
    }

    impl State for Light {
        fn save(&self) -> String {
            let (kind, v) = match self.kind {
                LightKind::Directional { direction } => ("directional", direction),
                LightKind::Point { position } => ("point", position),
            };
            let shadows = match self.shadows {
                Some(s) => format!("{};{};{}", s.size, s.bias, s.filter.name()),
                None => "-;-;-".into(),
            };
            format!("{kind};{};{};{};{};{shadows}", v3(v), self.space_name(), v3(self.color), self.intensity)
        }

        fn load(s: &str) -> Result<Self> {
            let mut r = reader(s);
            let kind = r.next()?;
            let v = r.v3()?;
            let kind = match kind {
                "directional" => LightKind::Directional { direction: v },
                _ => LightKind::Point { position: v },
            };
            let space = Space::parse("state", r.next()?)?;
            let (color, intensity) = (r.v3()?, r.f64()?);
            let shadows = match r.opt()? {
                None => None,
                Some(size) => Some(Shadows {
                    size: size as u32,
                    bias: r.f64()?,
                    filter: ShadowFilter::parse("state", r.next()?)?,
                }),
            };
            let l = Light { kind, space, color, intensity, shadows };
            l.validate("state")?;
            Ok(l)
        }
    }

    impl State for Camera {
        fn save(&self) -> String {
            let placement = match self.placement {
                Placement::Fit { direction, up, margin } => {
                    format!("fit;{};{};{margin}", v3(direction), v3(up))
                }
                Placement::LookAt { eye, target, up } => {
                    format!("look_at;{};{};{}", v3(eye), v3(target), v3(up))
                }
            };
            let projection = match self.projection {
                Projection::Perspective { fov_y_deg } => format!("perspective;{fov_y_deg}"),
                Projection::Orthographic { height } => format!("orthographic;{height}"),
            };
            format!("{placement};{projection};{};{}", opt(self.near), opt(self.far))
        }

        fn load(s: &str) -> Result<Self> {
            let mut r = reader(s);
            let placement = match r.next()? {
                "fit" => Placement::Fit { direction: r.v3()?, up: r.v3()?, margin: r.f64()? },
                _ => Placement::LookAt { eye: r.v3()?, target: r.v3()?, up: r.v3()? },
            };
            let projection = match r.next()? {
                "perspective" => Projection::Perspective { fov_y_deg: r.f64()? },
                _ => Projection::Orthographic { height: r.f64()? },
            };
            Camera::new(placement, projection, r.opt()?, r.opt()?)
        }
    }

    impl State for Outlines {
        fn save(&self) -> String {
            let styles: Vec<String> = self
                .styles
                .iter()
                .map(|s| s.map_or("-;0;0;0".into(), |s| format!("{};{}", s.width, v3(s.color))))
                .collect();
            format!(
                "{};{};{};{};{};{};{};{}",
                self.mesh,
                self.image,
                styles.join(";"),
                self.crease_angle,
                self.weld,
                self.normal_threshold,
                self.depth_threshold,
                self.depth_offset
            )
        }

        fn load(s: &str) -> Result<Self> {
            let mut r = reader(s);
            let mut o = Outlines::new(r.next()? == "true", r.next()? == "true");
            for k in 0..INK_KINDS {
                let w = r.opt()?;
                let color = r.v3()?;
                o.styles[k] = w.map(|width| LineStyle { color, width: width as f32 });
            }
            o.crease_angle = r.f64()?;
            o.weld = r.next()? == "true";
            o.normal_threshold = r.f32()?;
            o.depth_threshold = r.f32()?;
            o.depth_offset = r.f32()?;
            o.validate("state")?;
            Ok(o)
        }
    }
}

#[pyfunction]
fn _restore_material(state: &str) -> PyResult<PyMaterial> {
    state::State::load(state).map(|inner| PyMaterial { inner }).map_err(to_py)
}

#[pyfunction]
fn _restore_light(state: &str) -> PyResult<PyLight> {
    state::State::load(state).map(|inner| PyLight { inner }).map_err(to_py)
}

#[pyfunction]
fn _restore_camera(state: &str) -> PyResult<PyCamera> {
    state::State::load(state).map(|inner| PyCamera { inner }).map_err(to_py)
}

#[pyfunction]
fn _restore_outlines(state: &str) -> PyResult<PyOutlines> {
    state::State::load(state).map(|inner| PyOutlines { inner }).map_err(to_py)
}

/// kang_table() -> ndarray
///
/// Kang et al.'s 256-to-3-level lookup table as (256,) float64: 0.3, 0.65 and 1.0 in thirds.
/// The paper maps 256 Phong intensities to three tones without giving numbers; these split the
/// range in thirds.
#[pyfunction]
fn kang_table(py: Python<'_>) -> Bound<'_, numpy::PyArray1<f64>> {
    use numpy::IntoPyArray;
    material::kang_table().into_iter().map(|c| c[0] as f64).collect::<Vec<_>>().into_pyarray(py)
}

pub fn register(m: &Bound<'_, PyModule>) -> PyResult<()> {
    m.add_class::<PyMaterial>()?;
    m.add_class::<PyLight>()?;
    m.add_class::<PyShadows>()?;
    m.add_class::<PyDither>()?;
    m.add_function(wrap_pyfunction!(_restore_dither, m)?)?;
    m.add_class::<PyCamera>()?;
    m.add_class::<PyLineStyle>()?;
    m.add_class::<PyOutlines>()?;
    m.add_function(wrap_pyfunction!(_restore_material, m)?)?;
    m.add_function(wrap_pyfunction!(_restore_light, m)?)?;
    m.add_function(wrap_pyfunction!(_restore_camera, m)?)?;
    m.add_function(wrap_pyfunction!(_restore_outlines, m)?)?;
    m.add_function(wrap_pyfunction!(kang_table, m)?)?;
    Ok(())
}

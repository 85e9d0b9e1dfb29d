//! `Material`: a shading model with its colour coefficients and per-pixel effects.

use pyo3::prelude::*;
use pyo3::types::{PyDict, PyString};

use super::dither::{dither_arg, repr as dither_repr, PyDither};
use super::{getters, settings_class, tup};
use crate::error::{Error, Result};
use crate::py::args::{
    flag_or, number, numbers, opt_number, opt_rgb, optional, text, triple, type_name, Obj,
};
use crate::py::errors::to_py;
use crate::render::color::Srgb;
use crate::render::effects::hatching::{HatchMode, Hatching};
use crate::render::effects::surface::SurfaceSettings;
use crate::render::scene::material::{Material, DEFAULT_COLOR};
use crate::render::scene::model::{self, Highlight, Model, MAX_LUT};

fn f32s(v: Vec<f64>) -> Vec<f32> {
    v.into_iter().map(|x| x as f32).collect()
}

fn color_or(name: &str, obj: Obj<'_, '_>) -> Result<Srgb> {
    Ok(opt_rgb(name, obj)?.unwrap_or(DEFAULT_COLOR))
}

/// A lookup table: (N,) grey factors or (N, 3) RGB factors, 1 <= N <= 256.
fn table(name: &str, obj: &Bound<'_, PyAny>) -> Result<Vec<[f32; 3]>> {
    crate::py::args::refuse_text(name, obj, "(N,) or (N, 3) numbers")?;
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

/// Band thresholds and values, as given.
fn bands_args(thresholds: Obj<'_, '_>, values: Obj<'_, '_>) -> Result<(Option<Vec<f32>>, Option<Vec<f32>>)> {
    Ok((
        thresholds.map(|t| numbers("thresholds", t).map(f32s)).transpose()?,
        values.map(|v| numbers("values", v).map(f32s)).transpose()?,
    ))
}

/// A toon material with the dithering `dither=` asks for.
fn dithered(m: Result<Material>, dither: Obj<'_, '_>) -> PyResult<PyMaterial> {
    (|| {
        let m = m?;
        let effects = SurfaceSettings { dither: dither_arg(dither)?, ..m.effects.clone() };
        m.with_effects(effects)
    })()
    .map(|inner| PyMaterial { inner })
    .map_err(to_py)
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

settings_class!(PyMaterial, Material, "Material", |m| m.validate(""));

#[pymethods]
impl PyMaterial {
    /// Plain Lambert: f = max(L.n, 0), no highlight.
    ///
    /// color: base colour (default (0.95, 0.55, 0.25)); the diffuse coefficient is 90% of it and
    /// ambient (default) 10%, in linear light. per_vertex: bool, default False.
    #[staticmethod]
    #[pyo3(signature = (color = None, *, ambient = None, per_vertex = None))]
    fn lambert(color: Obj<'_, '_>, ambient: Obj<'_, '_>, per_vertex: Obj<'_, '_>) -> PyResult<Self> {
        dithered(
            (|| {
                Material::lambert(
                    color_or("color", color)?,
                    opt_rgb("ambient", ambient)?,
                    flag_or("per_vertex", per_vertex, false)?,
                )
            })(),
            None,
        )
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
        dithered(
            (|| {
                Material::phong(
                    color_or("color", color)?,
                    opt_rgb("specular", specular)?,
                    opt_number("shininess", shininess)?.map(|x| x as f32),
                    opt_rgb("ambient", ambient)?,
                    flag_or("per_vertex", per_vertex, false)?,
                )
            })(),
            None,
        )
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
        dithered(
            (|| {
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
                )
            })(),
            dither,
        )
    }

    /// Borquez and Yepez's toon bands: f = values[k], k = number of thresholds t with L.n >= t.
    ///
    /// Thresholds default to the paper's (0.2, 0.5, 0.7, 0.9). Values default to (0.3, 0.45,
    /// 0.7, 0.9, 1): L.n >= 0.9 -> 1.0, 0.7-0.9 -> 0.9, 0.5-0.7 -> 0.7, 0.2-0.5 -> 0.45, below
    /// (and in shadow) -> 0.3, times ``color`` in linear light, so the darkest tone keeps the
    /// material's hue and black ink shows over it. ``preset="paper"`` takes the paper's values
    /// (0, 0.2, 0.7, 0.9, 1) instead: a black darkest band, as in its figures. 1 to 8 strictly
    /// increasing thresholds, and one value more (each >= 0).
    /// dither (here and on the other toon models): None (default), a pattern name or a
    /// :class:`Dither`; needs per-pixel shading.
    #[staticmethod]
    #[pyo3(signature = (color = None, *, thresholds = None, values = None, preset = None, per_vertex = None,
                        dither = None))]
    fn bands(
        color: Obj<'_, '_>,
        thresholds: Obj<'_, '_>,
        values: Obj<'_, '_>,
        preset: Obj<'_, '_>,
        per_vertex: Obj<'_, '_>,
        dither: Obj<'_, '_>,
    ) -> PyResult<Self> {
        dithered(
            (|| {
                let (t, v) = bands_args(thresholds, values)?;
                let v = match preset.map(|p| text("preset", p)).transpose()?.as_deref() {
                    None => v,
                    Some("paper") => v.or_else(|| Some(model::PAPER_BAND_VALUES.to_vec())),
                    Some(other) => {
                        return Err(Error::invalid(
                            "preset",
                            format!("must be None or 'paper', got {other:?}"),
                        ))
                    }
                };
                Material::bands(color_or("color", color)?, t, v, flag_or("per_vertex", per_vertex, false)?)
            })(),
            dither,
        )
    }

    /// Cross-hatching (Borquez and Yepez): the bands' tone (their value times the light, as
    /// :meth:`bands` computes it) picks how many layers of ink strokes cover the paper: none
    /// where the tone is above 0.8, then one layer below 0.8, two below 0.6 (cross-hatching),
    /// three below 0.4 and four below 0.2. The strokes keep about ``spacing`` pixels between
    /// them (default 6, 2 to 256) and ``width`` pixels of width (default 1.25, up to
    /// ``spacing``) at any distance, are anchored to the surface (they move with it, not with
    /// the camera) and give the same bits for the same scene.
    ///
    /// mode: how the strokes are laid. ``"field"`` (default) follows the form (Hertzmann and
    /// Zorin; Praun et al.): the first layer runs along the direction of largest curvature
    /// (around a cylinder), the second along the other principal direction (along its axis),
    /// the third and fourth add strokes between those of the first two. The directions are
    /// smoothed over the surface and settle on a fixed axis where curvature has no direction
    /// (flats, spheres); the strokes come from a stripe pattern per vertex (Knöppel et al.),
    /// computed once per mesh on first use (about a second for 40,000 vertices on 2 cores)
    /// and kept with it; the mesh is cut at creases sharper than 30 degrees (or the mesh's
    /// ``normals="auto"`` angle), each side hatched on its own. ``"triplanar"``: the paper's straight strokes at 45, -45, 0 and 90 degrees in
    /// the mesh's own coordinates, blended over the three axis planes (no per-mesh work).
    ///
    /// color: the paper (default white); ink: the strokes (default (0.1, 0.1, 0.1));
    /// thresholds, values (default: the paper's, (0, 0.2, 0.7, 0.9, 1), so that the darkest
    /// tone gets every layer), dither and per_vertex as in :meth:`bands`.
    #[staticmethod]
    #[pyo3(signature = (color = None, *, ink = None, thresholds = None, values = None, spacing = None,
                        width = None, mode = None, per_vertex = None, dither = None))]
    #[allow(clippy::too_many_arguments)]
    fn hatching(
        color: Obj<'_, '_>,
        ink: Obj<'_, '_>,
        thresholds: Obj<'_, '_>,
        values: Obj<'_, '_>,
        spacing: Obj<'_, '_>,
        width: Obj<'_, '_>,
        mode: Obj<'_, '_>,
        per_vertex: Obj<'_, '_>,
        dither: Obj<'_, '_>,
    ) -> PyResult<Self> {
        dithered(
            (|| {
                let d = Hatching::default();
                let h = Hatching {
                    ink: opt_rgb("ink", ink)?.unwrap_or(d.ink),
                    spacing: opt_number("spacing", spacing)?.unwrap_or(d.spacing),
                    width: opt_number("width", width)?.unwrap_or(d.width),
                    mode: match optional("mode", mode, text)? {
                        Some(m) => HatchMode::parse("mode", &m)?,
                        None => d.mode,
                    },
                };
                h.validate("")?;
                let (t, v) = bands_args(thresholds, values)?;
                // the tone picks the number of stroke layers: the paper's values reach all of them
                let v = v.or_else(|| Some(model::PAPER_BAND_VALUES.to_vec()));
                let m = Material::bands(
                    opt_rgb("color", color)?.unwrap_or([1.0; 3]),
                    t,
                    v,
                    flag_or("per_vertex", per_vertex, false)?,
                )?;
                m.with_effects(SurfaceSettings { hatching: Some(h), ..Default::default() })
            })(),
            dither,
        )
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
        dithered(
            (|| {
                Material::lut(
                    table.map(|t| self::table("table", t)).transpose()?,
                    color_or("color", color)?,
                    flag_or("per_vertex", per_vertex, false)?,
                )
            })(),
            dither,
        )
    }

    /// A hatching material's ink (sRGB), spacing and width in pixels and mode ("field" or
    /// "triplanar") as a dict; None for others.
    #[getter]
    fn hatch_style<'py>(&self, py: Python<'py>) -> PyResult<Option<Bound<'py, PyDict>>> {
        let Some(h) = &self.inner.effects.hatching else { return Ok(None) };
        let d = PyDict::new(py);
        d.set_item("ink", tup(h.ink))?;
        d.set_item("spacing", h.spacing)?;
        d.set_item("width", h.width)?;
        d.set_item("mode", h.mode.name())?;
        Ok(Some(d))
    }

    fn __repr__(&self) -> String {
        let m = &self.inner;
        let mut params = match &m.model {
            Model::Lambert => String::new(),
            Model::Phong { shininess } => format!(", shininess={shininess}"),
            Model::ThresholdedPhong { t_h, t_s, highlight } => {
                format!(", t_h={t_h}, t_s={t_s}, highlight={:?}", highlight.name())
            }
            Model::Bands { thresholds, values } => format!(", thresholds={thresholds:?}, values={values:?}"),
            Model::Lut { table } => format!(", table=<{} entries>", table.len()),
        };
        if let Some(h) = &m.effects.hatching {
            params += &format!(
                ", hatching=(ink={:?}, spacing={}, width={}, mode={:?})",
                h.ink,
                h.spacing,
                h.width,
                h.mode.name()
            );
        }
        if let Some(d) = &m.effects.dither {
            params += &format!(", dither={}", dither_repr(d));
        }
        let per_vertex = if m.per_vertex { "True" } else { "False" };
        format!(
            "Material.{}(diffuse={:?}, ambient={:?}, specular={:?}{params}, per_vertex={per_vertex})",
            m.model.name(),
            m.diffuse,
            m.ambient,
            m.specular
        )
    }
}

getters!(PyMaterial {
    /// The shading model: "lambert", "phong", "thresholded_phong", "bands" or "lut" (a
    /// hatching material is "bands" with :attr:`hatch_style` set).
    model -> &'static str = |m| m.model.name();
    /// The dithering, or None.
    dither -> Option<PyDither> = |m| m.effects.dither.map(|inner| PyDither { inner });
    /// sRGB coefficients (tuples of 3 floats).
    diffuse -> (f64, f64, f64) = |m| tup(m.diffuse);
    ambient -> (f64, f64, f64) = |m| tup(m.ambient);
    specular -> (f64, f64, f64) = |m| tup(m.specular);
    per_vertex -> bool = |m| m.per_vertex;
    /// Phong's exponent (None for other models).
    shininess -> Option<f32> = |m| match m.model {
        Model::Phong { shininess } => Some(shininess),
        _ => None,
    };
    /// The thresholded Phong model's t_h, t_s and highlight (None for other models).
    t_h -> Option<f32> = |m| match m.model {
        Model::ThresholdedPhong { t_h, .. } => Some(t_h),
        _ => None,
    };
    t_s -> Option<f32> = |m| match m.model {
        Model::ThresholdedPhong { t_s, .. } => Some(t_s),
        _ => None,
    };
    highlight -> Option<&'static str> = |m| match m.model {
        Model::ThresholdedPhong { highlight, .. } => Some(highlight.name()),
        _ => None,
    };
    /// The bands' thresholds and values (None for other models).
    thresholds -> Option<Vec<f64>> = |m| match &m.model {
        Model::Bands { thresholds, .. } => Some(thresholds.iter().map(|&x| x as f64).collect()),
        _ => None,
    };
    values -> Option<Vec<f64>> = |m| match &m.model {
        Model::Bands { values, .. } => Some(values.iter().map(|&x| x as f64).collect()),
        _ => None,
    };
    /// The lookup table's (N, 3) rows (None for other models).
    table -> Option<Vec<(f64, f64, f64)>> = |m| match &m.model {
        Model::Lut { table } => Some(table.iter().map(|c| tup(c.map(|x| x as f64))).collect()),
        _ => None,
    };
});

/// kang_table() -> ndarray
///
/// Kang et al.'s 256-to-3-level lookup table as (256,) float64: 0.3, 0.65 and 1.0 in thirds.
/// The paper maps 256 Phong intensities to three tones without giving numbers; these split the
/// range in thirds.
#[pyfunction]
pub fn kang_table(py: Python<'_>) -> Bound<'_, numpy::PyArray1<f64>> {
    use numpy::IntoPyArray;
    model::kang_table().into_iter().map(|c| c[0] as f64).collect::<Vec<_>>().into_pyarray(py)
}

/// The `material=` argument (`name` in errors): a Material.
pub fn material_arg(name: &str, obj: &Bound<'_, PyAny>) -> Result<Material> {
    obj.cast::<PyMaterial>()
        .map(|m| m.get().inner.clone())
        .map_err(|_| Error::wrong_type(name, format!("expected a toonmesh.Material, got {}", type_name(obj))))
}

//! `Outlines` and the `LineStyle` of each kind of ink.

use pyo3::prelude::*;
use pyo3::types::{PyDict, PyString};

use super::{getters, settings_class, tup};
use crate::edges::outlines::LineKind;
use crate::error::{Error, Result};
use crate::py::args::{flag, flag_or, opt_number, opt_rgb, rgb, text, type_name, Obj};
use crate::py::errors::to_py;
use crate::render::effects::outlines::settings::{
    kind_names, ContourRule, ImageRule, LineStyle, Outlines, IMAGE_KIND,
};

/// How one kind of ink line is drawn: ``color`` (sRGB, default black) and ``width`` in output
/// pixels (default 1.5; the same at every resolution and supersampling factor).
#[pyclass(name = "LineStyle", module = "toonmesh._core", frozen, eq)]
#[derive(Clone, PartialEq)]
pub struct PyLineStyle {
    pub inner: LineStyle,
}

settings_class!(PyLineStyle, LineStyle, "LineStyle", |s| s.validate(""));

/// The style of every kind from `color` and `width`.
fn common(color: Obj<'_, '_>, width: Obj<'_, '_>) -> Result<LineStyle> {
    let d = LineStyle::default();
    Ok(LineStyle {
        color: opt_rgb("color", color)?.unwrap_or(d.color),
        width: opt_number("width", width)?.map_or(d.width, |w| w as f32),
    })
}

#[pymethods]
impl PyLineStyle {
    #[new]
    #[pyo3(signature = (color = None, width = None))]
    fn new(color: Obj<'_, '_>, width: Obj<'_, '_>) -> PyResult<Self> {
        (|| {
            let s = common(color, width)?;
            s.validate("")?;
            Ok(PyLineStyle { inner: s })
        })()
        .map_err(to_py)
    }

    fn __repr__(&self) -> String {
        format!("LineStyle(color={:?}, width={})", self.inner.color, self.inner.width)
    }
}

/// The style of one ink kind from its keyword: None or True (the common style), False (not
/// drawn), a :class:`LineStyle`, or a colour (the common width).
fn style(name: &str, obj: &Bound<'_, PyAny>, common: LineStyle) -> Result<Option<LineStyle>> {
    if let Ok(s) = obj.cast::<PyLineStyle>() {
        return Ok(Some(s.get().inner));
    }
    if let Ok(on) = flag(name, obj) {
        return Ok(on.then_some(common));
    }
    rgb(name, obj).map(|color| Some(LineStyle { color, ..common })).map_err(|e| match e {
        Error::WrongType { .. } => Error::wrong_type(
            name,
            format!("expected True, False, a LineStyle or a colour, got {}", type_name(obj)),
        ),
        other => other,
    })
}

/// Ink outlines for a render.
///
/// kind: "mesh" (lines found on the mesh: Kang, Kim and Yoon), "image" (edges found in the
/// frame's normal and depth buffers, by ``image_rule`` below) or "both" (default). color and width: the common
/// style of every kind (default black, 1.5 output pixels). Each kind can be styled on its own
/// with a keyword: silhouette, boundary, crease (both ridge and valley), ridge, valley,
/// nonmanifold, suggestive, material, image; each takes None or True (the common style), False (not
/// drawn), a :class:`LineStyle`, or a colour (image edges take the width under the
/// discontinuity rule; under the paper rule they are whole pixels). Suggestive contours (DeCarlo et al., see
/// :func:`toonmesh.edges.suggestive_contours`) are drawn only when asked for (suggestive=True,
/// a style or a colour; default None: not drawn). Material borders are drawn where a boundary
/// edge of one scene item lies on a boundary edge of another (the parts of a file with
/// different materials, meshes that meet edge to edge), in place of those boundaries.
///
/// contours: how silhouettes are found: "faces" (face edges between front- and back-facing
/// faces, Kang et al.'s rule, exact for flat shading), "smooth" (the smooth contour n . v = 0
/// traced through the faces, see :func:`toonmesh.edges.contours`: long clean lines on scans;
/// the normals are split at the creases drawn, and on those crease edges the face-edge rule
/// draws the silhouette) or "auto" (default: "smooth" for meshes drawn with smooth or auto
/// normals, "faces" for flat-shaded ones).
///
/// taper: mesh-space lines thin toward the ends of each chain over this many pixels of its
/// length on screen, down to a fifth of their width (default 0: no taper; closed loops have no
/// ends). width_by_depth: scale their width by the depth of the scene's centre over the line's
/// depth, between 0.25x and 4x (default False). Both shape the ink (the colour and "outline"
/// outputs), and ``RenderResult.line_widths`` gives the ink's width at each point of
/// ``RenderResult.lines`` (pixels); the SVG then draws each stroke as a filled outline of that
/// ink (``svg(widths="kind")``: centre lines at the kind's width, for a pen plotter).
/// join_kinds: visible strokes that meet end to end within a line's width are joined into one
/// stroke even when their kinds differ (a silhouette running on into a crease), taking the kind
/// of their longest part, in ``RenderResult.lines`` and the SVG (default False: strokes of one
/// kind only). suggestive_threshold: the derivative test of suggestive contours, relative
/// to the mesh's feature size (default 0.01); a suggestive contour fades in by the strength
/// with which it passes: its width goes from a fifth of its style's at the threshold toward the
/// full width (half way where it passes by 0.03 / feature size^2, as the authors fade them). curvature_smoothing: the width, in mean edge
/// lengths, over which the curvature of suggestive contours is averaged (as
/// :func:`toonmesh.edges.curvature` with ``smoothing``), so a scan's noise does not draw
/// (default None: 2, at most 1% of the bounding-box diagonal so a coarse mesh keeps its
/// features; 0 is the one-ring estimate). min_crease_length: crease pieces (creases joined
/// at their vertices, ridges and valleys together) shorter than this fraction of the mesh's
/// bounding-box diagonal are not drawn, so that a scan's noise does not scatter crease dashes
/// while a CAD part's creases stay (default 0.02; 0 draws every crease). max_crease_turn: crease
/// pieces that turn by more than this many degrees on average at their vertices where two
/// creases meet are not drawn: a scan's creases that follow the triangulation in a saw-tooth
/// go, a CAD part's straight and gently curving creases stay (default 30; 180 draws every
/// piece; with min_crease_length=0 it is the plain dihedral rule of
/// :func:`toonmesh.edges.feature_edges`).
///
/// crease_angle: dihedral angle in degrees above which an edge is a crease (default 30, as in
/// :func:`toonmesh.edges.feature_edges`). weld: merge vertices at equal positions first, so
/// UV or normal seams are not drawn as boundaries, and a sheet stored double-sided (each face
/// twice, back to back) is drawn as one surface with its border (default True).
///
/// image_rule: how image-space edges are found. "discontinuity" (default): between neighbouring
/// pixels whose normals turn by more than normal_angle degrees (default 25), whose depths jump
/// by more than depth_jump pixel footprints beyond what the surface's slope predicts (default
/// 3; a footprint is a pixel's size at that depth, so the rule is the same at any model scale),
/// or where the surface meets the background; drawn as lines width pixels wide centred on those
/// boundaries, antialiased. "paper": Borquez and Yepez's thresholded Sobel, whole edge pixels,
/// with normal_threshold (default 1.0) and depth_threshold (default 0.1, in world depth units
/// times 4): the rule of :func:`toonmesh.edges.detect_edges`. depth_offset: hidden-line removal keeps a point of a
/// line when its depth is at most the largest surface depth in the 3x3 pixels around it plus
/// this many pixel footprints (the world size of one pixel at that depth; default 1.0); a
/// silhouette or boundary with background among those pixels is on the rim and always shows.
#[pyclass(name = "Outlines", module = "toonmesh._core", frozen, eq)]
#[derive(Clone, PartialEq)]
pub struct PyOutlines {
    pub inner: Outlines,
}

settings_class!(PyOutlines, Outlines, "Outlines", |o| o.validate(""));

#[pymethods]
impl PyOutlines {
    #[new]
    #[pyo3(signature = (kind = None, *, color = None, width = None, silhouette = None, boundary = None,
                        crease = None, ridge = None, valley = None, nonmanifold = None, suggestive = None,
                        material = None,
                        image = None, crease_angle = None, weld = None, normal_threshold = None,
                        depth_threshold = None, depth_offset = None, contours = None,
                        suggestive_threshold = None, curvature_smoothing = None, min_crease_length = None,
                        max_crease_turn = None, image_rule = None,
                        normal_angle = None, depth_jump = None, taper = None, width_by_depth = None,
                        join_kinds = None))]
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
        suggestive: Obj<'_, '_>,
        material: Obj<'_, '_>,
        image: Obj<'_, '_>,
        crease_angle: Obj<'_, '_>,
        weld: Obj<'_, '_>,
        normal_threshold: Obj<'_, '_>,
        depth_threshold: Obj<'_, '_>,
        depth_offset: Obj<'_, '_>,
        contours: Obj<'_, '_>,
        suggestive_threshold: Obj<'_, '_>,
        curvature_smoothing: Obj<'_, '_>,
        min_crease_length: Obj<'_, '_>,
        max_crease_turn: Obj<'_, '_>,
        image_rule: Obj<'_, '_>,
        normal_angle: Obj<'_, '_>,
        depth_jump: Obj<'_, '_>,
        taper: Obj<'_, '_>,
        width_by_depth: Obj<'_, '_>,
        join_kinds: Obj<'_, '_>,
    ) -> PyResult<Self> {
        (|| {
            let (mesh, img) = match kind {
                None => (true, true),
                Some(k) => Outlines::parse_kind("kind", &text("kind", k)?)?,
            };
            let mut o = Outlines::new(mesh, img);
            let common = common(color, width)?;
            let crease = crease.map_or(Ok(Some(common)), |c| style("crease", c, common))?;
            let kinds = [
                (LineKind::Silhouette as usize, "silhouette", silhouette, Some(common)),
                (LineKind::Boundary as usize, "boundary", boundary, Some(common)),
                (LineKind::NonManifold as usize, "nonmanifold", nonmanifold, Some(common)),
                (LineKind::Ridge as usize, "ridge", ridge, crease),
                (LineKind::Valley as usize, "valley", valley, crease),
                (LineKind::Suggestive as usize, "suggestive", suggestive, None),
                (LineKind::Material as usize, "material", material, Some(common)),
                (IMAGE_KIND, "image", image, Some(common)),
            ];
            for (k, name, obj, fallback) in kinds {
                o.styles[k] = obj.map_or(Ok(fallback), |s| style(name, s, common))?;
            }
            o.crease_angle = opt_number("crease_angle", crease_angle)?.unwrap_or(o.crease_angle);
            o.weld = flag_or("weld", weld, o.weld)?;
            o.normal_threshold =
                opt_number("normal_threshold", normal_threshold)?.map_or(o.normal_threshold, |t| t as f32);
            o.depth_threshold =
                opt_number("depth_threshold", depth_threshold)?.map_or(o.depth_threshold, |t| t as f32);
            o.depth_offset = opt_number("depth_offset", depth_offset)?.map_or(o.depth_offset, |t| t as f32);
            if let Some(c) = contours {
                o.contours = ContourRule::parse("contours", &text("contours", c)?)?;
            }
            o.suggestive_threshold =
                opt_number("suggestive_threshold", suggestive_threshold)?.unwrap_or(o.suggestive_threshold);
            o.curvature_smoothing = opt_number("curvature_smoothing", curvature_smoothing)?;
            o.min_crease_length =
                opt_number("min_crease_length", min_crease_length)?.unwrap_or(o.min_crease_length);
            o.max_crease_turn = opt_number("max_crease_turn", max_crease_turn)?.unwrap_or(o.max_crease_turn);
            if let Some(r) = image_rule {
                o.image_rule = ImageRule::parse("image_rule", &text("image_rule", r)?)?;
            }
            o.normal_angle = opt_number("normal_angle", normal_angle)?.map_or(o.normal_angle, |t| t as f32);
            o.depth_jump = opt_number("depth_jump", depth_jump)?.map_or(o.depth_jump, |t| t as f32);
            o.stroke_width.taper = opt_number("taper", taper)?.unwrap_or(o.stroke_width.taper);
            o.stroke_width.by_depth = flag_or("width_by_depth", width_by_depth, o.stroke_width.by_depth)?;
            o.join_kinds = flag_or("join_kinds", join_kinds, o.join_kinds)?;
            o.validate("")?;
            Ok(PyOutlines { inner: o })
        })()
        .map_err(to_py)
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

    fn __repr__(&self) -> String {
        format!("Outlines({:?}, crease_angle={}, ...)", self.inner.kind_name(), self.inner.crease_angle)
    }
}

getters!(PyLineStyle {
    color -> (f64, f64, f64) = |s| tup(s.color);
    width -> f32 = |s| s.width;
});

getters!(PyOutlines {
    /// "mesh", "image" or "both".
    kind -> &'static str = |o| o.kind_name();
    crease_angle -> f64 = |o| o.crease_angle;
    weld -> bool = |o| o.weld;
    normal_threshold -> f32 = |o| o.normal_threshold;
    depth_threshold -> f32 = |o| o.depth_threshold;
    depth_offset -> f32 = |o| o.depth_offset;
    /// "auto", "faces" or "smooth".
    contours -> &'static str = |o| o.contours.name();
    suggestive_threshold -> f64 = |o| o.suggestive_threshold;
    /// None: 2 mean edge lengths, at most 1% of the bounding-box diagonal.
    curvature_smoothing -> Option<f64> = |o| o.curvature_smoothing;
    min_crease_length -> f64 = |o| o.min_crease_length;
    max_crease_turn -> f64 = |o| o.max_crease_turn;
    /// "discontinuity" or "paper".
    image_rule -> &'static str = |o| o.image_rule.name();
    normal_angle -> f32 = |o| o.normal_angle;
    depth_jump -> f32 = |o| o.depth_jump;
    taper -> f64 = |o| o.stroke_width.taper;
    width_by_depth -> bool = |o| o.stroke_width.by_depth;
    join_kinds -> bool = |o| o.join_kinds;
});

/// The `outlines=` argument: None, "mesh", "image", "both" or an Outlines.
pub fn outlines_arg(obj: &Bound<'_, PyAny>) -> Result<Outlines> {
    if let Ok(o) = obj.cast::<PyOutlines>() {
        return Ok(o.get().inner.clone());
    }
    if obj.is_instance_of::<PyString>() {
        let (mesh, image) = Outlines::parse_kind("outlines", &text("outlines", obj)?)?;
        return Ok(Outlines::new(mesh, image));
    }
    Err(Error::wrong_type(
        "outlines",
        format!("expected None, 'mesh', 'image', 'both' or a toonmesh.Outlines, got {}", type_name(obj)),
    ))
}

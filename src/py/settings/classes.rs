//! The settings classes: each a described core type with its docstrings and constructors
//! (`settings_class!`), and the few read-only views that are not fields.

use pyo3::prelude::*;
use pyo3::types::PyDict;

use super::settings_class;
use crate::render::effects::dither::Dither;
use crate::render::effects::outlines::settings::{kind_names, LineStyle, Outlines};
use crate::render::effects::shadows::settings::Shadows;
use crate::render::scene::camera::Camera;
use crate::render::scene::light::Light;
use crate::render::scene::material::Material;
use crate::render::scene::model;
use crate::render::scene::options::RenderOptions;

settings_class! {
/// A shading model with its coefficients; build one with the static methods. Colours are sRGB:
/// ``'#rrggbb'`` or three numbers in [0, 1].
///
/// Every model computes, in linear light, ``C = a_l * ambient + sum over lights of
/// (f(L.n) * d_l * diffuse + s * S_l * specular)``, where ``a_l`` is the scene's ambient light,
/// ``d_l = S_l`` a light's colour times its intensity, ``L`` the unit vector toward the light and
/// ``n`` the unit normal; the models differ in ``f`` and ``s``. With ``per_vertex=True`` the
/// vertices are shaded and the colours interpolated (Gouraud, as Al-Rousan et al. colour
/// vertices); otherwise every pixel is shaded.
    PyMaterial(Material, "Material") {
        /// Plain Lambert: f = max(L.n, 0), no highlight.
        ///
        /// color: base colour (default (0.95, 0.55, 0.25)); the diffuse coefficient is 90% of it and
        /// ambient (default) 10%, in linear light. per_vertex: bool, default False.
        fn lambert;
        /// Plain Phong: f = max(L.n, 0), s = max(R.v, 0)^shininess on lit points (R: L reflected).
        ///
        /// color as in :meth:`lambert`; specular: highlight colour (default (0.5, 0.5, 0.5));
        /// shininess: exponent > 0 (default 32).
        fn phong;
        /// Al-Rousan et al.'s toon model: C = a_l a_m + thresh(L.n, t_h) d_l d_m + thresh(h, t_s) S_l S_m.
        ///
        /// thresh(a, b) is 1 where a >= b, else 0; t_h (default 0.0) and t_s (default 0.95) lie in
        /// [-1, 1]. highlight: "blinn" (default, h = n . normalize(L + v)) or "paper" (h = L.v, as the
        /// paper writes it). By default the shadow side keeps 35% of ``color`` (ambient) and the lit
        /// side reaches it; specular defaults to (0.6, 0.6, 0.6). The paper shades vertices: pass
        /// ``per_vertex=True`` for that.
        fn thresholded_phong;
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
        fn bands;
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
        fn hatching;
        /// A lookup table (gradient map): f = table[min(floor(clamp(L.n, 0, 1) N), N - 1)].
        ///
        /// table: (N,) grey factors or (N, 3) RGB factors (linear, >= 0, 1 <= N <= 256) applied to
        /// ``color``; the default is :func:`kang_table`, Kang et al.'s 256-to-3-level mapping.
        fn lut;
    }
}

settings_class! {
/// Dithering between neighbouring bands (Borquez and Yepez): L.n + (t - 1/2) amount is banded,
/// t the pattern's threshold at the pixel. pattern: "bayer2", "bayer4" (default), "bayer8"
/// (ordered dithering) or "blue" (the R2 sequence, a blue-noise-like pattern). space: "screen"
/// (default, as in the paper: the pattern stays put while the object moves) or "object"
/// (anchored to the surface, so a turntable does not shimmer). amount: in L.n, 0 to 2 (default
/// 0.15). scale: pixels a pattern cell covers, 1 to 64 (default 1).
    PyDither(Dither, "Dither") {
        new;
    }
}

settings_class! {
/// A directional or point light; build one with the static methods. ``color`` is sRGB (default
/// white) and ``intensity`` (>= 0, default 1) scales its light. ``space``: "world" (default) or
/// "camera" (fixed to the camera: x right, y up, -z forward, so it moves with the view).
    PyLight(Light, "Light") {
        /// Parallel light travelling along ``direction`` (3 numbers, from the light toward the
        /// scene; any length > 0). ``shadows``: True (default settings), a :class:`Shadows`, or
        /// False/None (default): the light casts shadows from a shadow map (one light a scene).
        fn directional;
        /// Light radiating from ``position`` (3 numbers; no falloff with distance).
        fn point;
        /// The default light: from the upper left, behind the viewer, fixed to the camera.
        fn key;
    }
}

settings_class! {
/// Shadow settings of a directional light: the shadow map's side in texels (a power of two
/// from 64 to 8192, default 2048), the depth bias in texels per unit of receiver slope (>= 0,
/// default 1.0; more removes shadow acne on lit surfaces, less keeps contact shadows tight) and
/// the filter: "pcf" (default; percentage-closer filtering, soft edges a few texels wide) or
/// "none" (one nearest test). The map is fitted to the scene's bounding sphere.
    PyShadows(Shadows, "Shadows") {
        new;
    }
}

settings_class! {
/// A camera; build one with :meth:`fit` (the default), :meth:`look_at` or :meth:`orthographic`.
///
/// View space is right-handed: x right, y up, the camera looks down -z. ``near``/``far`` (clip
/// distances, > 0 for perspective) are chosen to enclose the scene when None.
    PyCamera(Camera, "Camera") {
        /// Frame the meshes' bounding sphere, seen from ``direction`` (scene -> eye; default
        /// (0.35, 0.3, 1.0): from the front, a little from the right and above), with ``up`` the
        /// image's up direction (default (0, 1, 0): +y up; pass (0, 0, 1) for a z-up scan).
        /// fov_y: vertical field of view in degrees (default 35); margin >= 1 leaves room around the
        /// sphere (default 1.05); orthographic: bool (default False).
        fn fit;
        /// A perspective camera at ``eye`` looking at ``target`` (default the origin), with ``up``
        /// (default (0, 1, 0)) and a vertical field of view ``fov_y`` in degrees (default 35).
        fn look_at;
        /// An orthographic camera at ``eye`` looking at ``target``; ``height`` is the height of the
        /// view in world units (default 2).
        fn orthographic;
    }
}

settings_class! {
/// How one kind of ink line is drawn: ``color`` (sRGB, default black) and ``width`` in output
/// pixels (default 1.5; the same at every resolution and supersampling factor).
    PyLineStyle(LineStyle, "LineStyle") {
        new;
    }
}

settings_class! {
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
    PyOutlines(Outlines, "Outlines") {
        new;
    }
}

settings_class! {
/// Every render setting besides the meshes, checked, with the core's defaults: made from the
/// keywords of :class:`RenderKeywords` (``RenderOptions(width=640, outlines="mesh")``), which
/// lists them; ``replace(**keywords)`` makes a changed copy. Compared by value, hashable and
/// picklable, so a batch sends one to its workers.
    PyRenderOptions(RenderOptions, "RenderOptions") {
        new;
    }
}

#[pymethods]
impl PyOutlines {
    /// Each ink kind's :class:`LineStyle`, or None where it is not drawn.
    #[getter]
    fn styles<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyDict>> {
        let d = PyDict::new(py);
        for (name, s) in kind_names().iter().zip(&self.inner.styles) {
            d.set_item(name, s.map(|inner| PyLineStyle { inner }))?;
        }
        Ok(d)
    }
}

#[pymethods]
impl PyMaterial {
    /// A hatching material's ink (sRGB), spacing and width in pixels and mode ("field" or
    /// "triplanar") as a dict; None for others.
    #[getter]
    fn hatch_style<'py>(&self, py: Python<'py>) -> PyResult<Option<Bound<'py, PyDict>>> {
        let Some(h) = &self.inner.effects.hatching else { return Ok(None) };
        let d = PyDict::new(py);
        d.set_item("ink", (h.ink[0], h.ink[1], h.ink[2]))?;
        d.set_item("spacing", h.spacing)?;
        d.set_item("width", h.width)?;
        d.set_item("mode", h.mode.name())?;
        Ok(Some(d))
    }
}

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

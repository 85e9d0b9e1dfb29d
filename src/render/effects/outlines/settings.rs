//! Ink outlines a scene asks for: mesh-space lines (Kang, Kim and Yoon: silhouettes per view,
//! boundaries, creases and non-manifold edges once per mesh) drawn as screen-space strips with
//! hidden lines removed, and image-space edges (Borquez and Yepez: Sobel on the normal and depth
//! buffers, with the rule and defaults of `edges::detect`).

use serde::{Deserialize, Serialize};

use crate::edges::contours::DEFAULT_SUGGESTIVE_THRESHOLD;
use crate::edges::crooked_creases::DEFAULT_MAX_CREASE_TURN;
use crate::edges::detect::{DEFAULT_DEPTH_THRESHOLD, DEFAULT_NORMAL_THRESHOLD};
use crate::edges::outlines::LineKind;
use crate::edges::short_creases::DEFAULT_MIN_CREASE_LENGTH;
use crate::edges::DEFAULT_CREASE_ANGLE;
use crate::error::field;
use crate::error::{Error, Result};
use crate::render::color::{check_unit, Srgb};
use crate::render::settings::declare::declared_fields;
use crate::render::settings::{
    build, check_bounds, settings, Constructor, Described, Field, FieldValue, Kind, Range, Setting, Value,
};

use super::stroke_width::{StrokeWidth, MAX_TAPER};

/// Width of lines in output pixels when none is given.
pub const DEFAULT_WIDTH: f32 = 1.5;
/// Widest line, in output pixels.
pub const MAX_WIDTH: f32 = 64.0;
/// Hidden-line offset in pixel footprints (see `Outlines::depth_offset`).
pub const DEFAULT_DEPTH_OFFSET: f32 = 1.0;

crate::named_enum! {
    /// Where the silhouette of a mesh is drawn.
    pub enum ContourRule {
        /// Face edges between front- and back-facing faces (Kang, Kim and Yoon): exact for
        /// flat-shaded meshes; on scans they follow the triangulation in staircases.
        Faces = "faces",
        /// The smooth contour (Hertzmann and Zorin): where n . v = 0 for the interpolated vertex
        /// normals, traced through the faces, with the normals split at creases (edges sharper
        /// than `crease_angle`, as `normals="auto"` splits them); on a crease edge itself, the
        /// face-edge rule. A curved scan gets long smooth strokes and a cube its edges.
        Smooth = "smooth",
        /// `Smooth` for meshes drawn with smooth or auto normals, `Faces` for flat-shaded ones:
        /// the silhouette the shading shows.
        Auto = "auto",
    }
}

impl ContourRule {
    /// The rule for a mesh drawn with `flat` normals or not.
    pub fn resolve(self, flat: bool) -> ContourRule {
        match self {
            ContourRule::Auto if flat => ContourRule::Faces,
            ContourRule::Auto => ContourRule::Smooth,
            rule => rule,
        }
    }
}

crate::named_enum! {
    /// How mesh-space lines behind surfaces are removed.
    pub enum VisibilityRule {
        /// Against the scene's surfaces themselves (`edges::occlusion`): a ray from each point
        /// of a line toward the camera counts the surfaces it crosses, and lines are cut where
        /// that count changes. A line under a surface never shows through it, however thin the
        /// gap; hidden lines (`hidden`) can be drawn.
        Exact = "exact",
        /// Against the frame's depth image, with `depth_offset` pixel footprints of tolerance:
        /// the earlier rule, decided per pixel on the GPU; a line within the tolerance of a
        /// surface in front of it shows.
        Depth = "depth",
    }
}

crate::named_enum! {
    /// How image-space edges are found and drawn.
    pub enum ImageRule {
        /// Between neighbouring pixels whose normals turn by more than `normal_angle`, or whose
        /// depths jump by more than `depth_jump` pixel footprints beyond what the surface's
        /// slope predicts, or where the surface meets the background: thin lines centred on
        /// those boundaries, `width` pixels wide and antialiased, the same at any model scale.
        Discontinuity = "discontinuity",
        /// Borquez and Yepez's thresholded Sobel of the normal and depth buffers
        /// (`edges::detect`, `normal_threshold` and `depth_threshold`): whole edge pixels.
        Paper = "paper",
    }
}

/// The smallest turn of the normal between neighbouring pixels drawn as an image-space edge,
/// in degrees, when none is given.
pub const DEFAULT_NORMAL_ANGLE: f32 = 25.0;
/// The smallest depth jump between neighbouring pixels drawn as an image-space edge, in pixel
/// footprints beyond the surface's slope, when none is given.
pub const DEFAULT_DEPTH_JUMP: f32 = 3.0;

/// The kinds of ink: the mesh-space kinds of `edges::outlines::LineKind`, then image-space
/// edges, then the mesh-space lines behind surfaces (`Outlines(hidden=...)`).
pub const IMAGE_KIND: usize = LineKind::COUNT;
pub const HIDDEN_KIND: usize = LineKind::COUNT + 1;
pub const INK_KINDS: usize = LineKind::COUNT + 2;
/// The ink of `Lines` items (`scene::lines`): each set's own colour and width, no style of the
/// outlines, so past the table of kinds; named "lines" (`ink_name`).
pub const LINES_KIND: usize = INK_KINDS;

/// The name of ink kind `k`: `kind_names`, or "lines" for `LINES_KIND`.
pub fn ink_name(k: usize) -> &'static str {
    kind_names().get(k).copied().unwrap_or("lines")
}

/// Hidden lines' default ink: grey, ...
pub const HIDDEN_GREY: f64 = 0.5;
/// ... two thirds of the common width, ...
pub const HIDDEN_WIDTH: f32 = 2.0 / 3.0;
/// ... in dashes (and gaps) of this many times the common width.
pub const HIDDEN_DASH: f32 = 3.0;

settings! {
    /// How one kind of line is drawn.
    #[derive(Clone, Copy, Debug, PartialEq)]
    pub struct LineStyle {
        /// Black when none is given.
        pub color: Srgb = [0.0; 3] => color(), "the ink's sRGB colour";
        /// Full width in output pixels (the same at every resolution and supersampling factor).
        /// Image-space edges are one pixel wide whatever this says.
        pub width: f32 = DEFAULT_WIDTH => float(WIDTH_RULE),
            "width in output pixels, the same at every resolution and supersampling factor", pixels;
        /// Dashes this many output pixels long with gaps as long; 0: a solid line.
        pub dash: f32 = 0.0 => float(NON_NEGATIVE.slider(0.0, 32.0)),
            "dash length in output pixels, gaps as long (0: solid)", pixels;
    }
    described(positional: 2);
}

/// A line's width in output pixels: more than 0, at most `MAX_WIDTH`.
pub const WIDTH_RULE: Range = Range::above_up_to(0.0, MAX_WIDTH as f64).slider(0.25, MAX_WIDTH as f64);

impl LineStyle {
    /// The style of hidden lines asked for with True, from the common style: grey, thinner,
    /// dashed.
    pub fn hidden(common: LineStyle) -> LineStyle {
        let width = (common.width * HIDDEN_WIDTH).max(WIDTH_RULE.slider_bounds()[0] as f32);
        LineStyle { color: [HIDDEN_GREY; 3], width, dash: common.width * HIDDEN_DASH }
    }

    /// Checks the style; `prefix` names it in errors ("" while it is being made).
    pub fn validate(&self, prefix: &str) -> Result<()> {
        check_unit(&field(prefix, "color"), &self.color)?;
        check_bounds(self, prefix)
    }
}

/// Names of the ink kinds, in index order (the Python keywords and `RenderResult.lines` keys).
pub fn kind_names() -> [&'static str; INK_KINDS] {
    let mut names = ["image"; INK_KINDS];
    for k in LineKind::ALL {
        names[k as usize] = k.name();
    }
    names[HIDDEN_KIND] = "hidden";
    names
}

#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct Outlines {
    /// Draw mesh-space lines.
    pub mesh: bool,
    /// Draw image-space edges.
    pub image: bool,
    /// The style of each ink kind (indexed by `LineKind as usize`, then `IMAGE_KIND`); None
    /// leaves that kind out.
    pub styles: [Option<LineStyle>; INK_KINDS],
    /// Dihedral angle in degrees above which an edge is a crease.
    pub crease_angle: f64,
    /// Crease pieces (creases joined at their vertices) shorter than this fraction of the
    /// mesh's bounding-box diagonal are not drawn (`edges::short_creases`).
    pub min_crease_length: f64,
    /// Crease pieces that turn by more than this many degrees on average where two of their
    /// creases meet (a saw-tooth along the triangulation) are not drawn
    /// (`edges::crooked_creases`); 180 keeps every piece.
    #[serde(default = "default_max_crease_turn")]
    pub max_crease_turn: f64,
    /// Merge vertices at equal positions before finding mesh-space lines, so that UV or normal
    /// seams are not taken for boundaries.
    pub weld: bool,
    /// The image-space rule, and its thresholds.
    pub image_rule: ImageRule,
    pub normal_angle: f32,
    pub depth_jump: f32,
    /// The paper rule's thresholds, as in `edges::detect`.
    pub normal_threshold: f32,
    pub depth_threshold: f32,
    /// The rule silhouettes are found by.
    pub contours: ContourRule,
    /// The derivative threshold of suggestive contours, relative to the mesh's feature size
    /// squared (`edges::contours`).
    pub suggestive_threshold: f64,
    /// The width suggestive contours' curvature is measured at, in mean edge lengths; None:
    /// `edges::contours::auto_smoothing`.
    #[serde(default)]
    pub curvature_smoothing: Option<f64>,
    /// Suggestive contours hold still across the related views of a sequence
    /// (`edges::coherence`): faded by how fast they slide, with hysteresis between frames.
    #[serde(default = "default_suggestive_coherence")]
    pub suggestive_coherence: bool,
    /// Hidden-line removal: a line point is visible when its depth is at most the largest
    /// surface depth in the 3x3 output pixels around it plus this many pixel footprints (the
    /// world size of one pixel at that depth); a silhouette or boundary with background among
    /// those pixels is on the rim and visible (see `passes::lines::visibility`).
    pub depth_offset: f32,
    /// Taper and width by depth of mesh-space lines.
    #[serde(default)]
    pub stroke_width: StrokeWidth,
    /// Join visible strokes of different kinds that meet end to end (a silhouette running on
    /// into a crease) into one stroke, of the kind of its longest part (`strokes::join_runs`).
    #[serde(default)]
    pub join_kinds: bool,
    /// How lines behind surfaces are found.
    #[serde(default)]
    pub visibility: VisibilityRule,
    /// Hidden lines are drawn (in `styles[HIDDEN_KIND]`) behind at most this many surfaces;
    /// None: behind any number.
    #[serde(default)]
    pub max_occlusion: Option<u32>,
}

impl Default for VisibilityRule {
    fn default() -> Self {
        VisibilityRule::Exact
    }
}

/// Settings saved before coherence existed load with it on, its default.
fn default_suggestive_coherence() -> bool {
    DEFAULT_SUGGESTIVE_COHERENCE
}

/// Suggestive contours hold still across a sequence of views unless asked not to.
pub const DEFAULT_SUGGESTIVE_COHERENCE: bool = true;

/// Settings saved before the turn rule existed load with it at its default.
fn default_max_crease_turn() -> f64 {
    DEFAULT_MAX_CREASE_TURN
}

impl Default for Outlines {
    fn default() -> Self {
        Outlines::new(true, true)
    }
}

impl Outlines {
    /// Every kind in the default style, except suggestive contours (drawn when asked for).
    pub fn new(mesh: bool, image: bool) -> Self {
        let mut styles = [Some(LineStyle::default()); INK_KINDS];
        styles[LineKind::Suggestive as usize] = None;
        styles[HIDDEN_KIND] = None;
        Outlines {
            mesh,
            image,
            styles,
            contours: ContourRule::Auto,
            suggestive_threshold: DEFAULT_SUGGESTIVE_THRESHOLD,
            curvature_smoothing: None,
            suggestive_coherence: DEFAULT_SUGGESTIVE_COHERENCE,
            crease_angle: DEFAULT_CREASE_ANGLE,
            min_crease_length: DEFAULT_MIN_CREASE_LENGTH,
            max_crease_turn: DEFAULT_MAX_CREASE_TURN,
            weld: true,
            image_rule: ImageRule::Discontinuity,
            normal_angle: DEFAULT_NORMAL_ANGLE,
            depth_jump: DEFAULT_DEPTH_JUMP,
            normal_threshold: DEFAULT_NORMAL_THRESHOLD as f32,
            depth_threshold: DEFAULT_DEPTH_THRESHOLD as f32,
            depth_offset: DEFAULT_DEPTH_OFFSET,
            stroke_width: StrokeWidth::default(),
            join_kinds: false,
            visibility: VisibilityRule::Exact,
            max_occlusion: None,
        }
    }

    /// Whether lines behind surfaces are drawn (the exact rule finds them).
    pub fn draws_hidden(&self) -> bool {
        self.styles[HIDDEN_KIND].is_some()
    }

    /// The names `Outlines(kind)` takes.
    pub const KINDS: [&'static str; 3] = ["mesh", "image", "both"];

    /// `"mesh"`, `"image"` or `"both"`.
    pub fn parse_kind(arg: &str, s: &str) -> Result<(bool, bool)> {
        match s {
            "mesh" => Ok((true, false)),
            "image" => Ok((false, true)),
            "both" => Ok((true, true)),
            other => Err(Error::invalid(arg, format!("must be 'mesh', 'image' or 'both', got {other:?}"))),
        }
    }

    pub fn kind_name(&self) -> &'static str {
        match (self.mesh, self.image) {
            (true, false) => "mesh",
            (false, true) => "image",
            _ => "both",
        }
    }

    /// Whether mesh-space lines of some kind are drawn.
    pub fn draws_mesh_lines(&self) -> bool {
        self.mesh && self.styles[..LineKind::COUNT].iter().any(Option::is_some)
    }

    /// Whether the views of a sequence hold their suggestive contours still
    /// (`edges::coherence`): they are drawn, with coherence.
    pub fn holds_suggestive_still(&self) -> bool {
        self.suggestive_coherence
            && self.draws_mesh_lines()
            && self.styles[LineKind::Suggestive as usize].is_some()
    }

    pub fn draws_image_edges(&self) -> bool {
        self.image && self.styles[IMAGE_KIND].is_some()
    }

    /// Checks the settings; `prefix` names them in errors ("" while they are being made).
    pub fn validate(&self, prefix: &str) -> Result<()> {
        if !self.mesh && !self.image {
            return Err(Error::invalid(field(prefix, "kind"), "must draw mesh lines, image edges or both"));
        }
        // the other mesh kinds are on by default; suggestive contours are asked for
        if self.draws_hidden() && self.visibility != VisibilityRule::Exact {
            return Err(Error::invalid(
                field(prefix, "hidden"),
                "hidden lines are found by the exact rule: not with visibility='depth'",
            ));
        }
        if !self.mesh && self.styles[LineKind::Suggestive as usize].is_some() {
            return Err(Error::invalid(
                field(prefix, "suggestive"),
                "suggestive contours are lines found on the mesh: ask for kind \"mesh\" or \"both\", not \"image\"",
            ));
        }
        for (style, name) in self.styles.iter().zip(kind_names()) {
            if let Some(s) = style {
                s.validate(&field(prefix, name))?;
            }
        }
        // every number's bounds (the angles, thresholds, lengths and the taper): the description's
        check_bounds(self, prefix)
    }
}

/// An angle in degrees between 0 and 180.
const DEGREES: Range = Range::closed(0.0, 180.0);
/// A tolerance or threshold: finite and >= 0.
const NON_NEGATIVE: Range = Range::at_least(0.0);

const STYLE_HELP: &str = "True (the common style), False (not drawn), a LineStyle or a colour";

// each ink kind's style is a field (`style`): True, False, a LineStyle or a colour
declared_fields! {
    Outlines {
        kind: String [get kind_text, set set_kind] => choice(&Outlines::KINDS),
            "lines found on the mesh, edges found in the image, or both";
        silhouette: Value [get style, set set_style] => Kind::Style, STYLE_HELP, optional;
        boundary: Value [get style, set set_style] => Kind::Style, STYLE_HELP, optional;
        nonmanifold: Value [get style, set set_style] => Kind::Style, STYLE_HELP, optional;
        ridge: Value [get style, set set_style] => Kind::Style, STYLE_HELP, optional;
        valley: Value [get style, set set_style] => Kind::Style, STYLE_HELP, optional;
        suggestive: Value [get style, set set_style] => Kind::Style,
            "suggestive contours (DeCarlo et al.): drawn only when asked for", optional;
        material: Value [get style, set set_style] => Kind::Style,
            "borders between scene items that meet edge to edge", optional;
        intersection: Value [get style, set set_style] => Kind::Style,
            "where the surfaces of two scene items cross", optional;
        image: Value [get style, set set_style] => Kind::Style, "image-space edges", optional;
        hidden: Value [get style, set set_style] => Kind::Style,
            "lines behind surfaces (True: grey, thinner, dashed; off unless asked for)", optional;
        crease_angle: f64 [.crease_angle] => float(DEGREES),
            "dihedral angle in degrees above which an edge is a crease";
        weld: bool [.weld] => boolean(),
            "merge vertices at equal positions first, so seams are not drawn as boundaries";
        contours: ContourRule [.contours] => choice(ContourRule::NAMES),
            "how silhouettes are found: 'faces', 'smooth' or 'auto'";
        suggestive_threshold: f64 [.suggestive_threshold] => float(NON_NEGATIVE.slider(0.0, 0.2)),
            "the suggestive contours' derivative test, relative to the mesh's feature size";
        curvature_smoothing: Option<f64> [.curvature_smoothing] => float(NON_NEGATIVE.slider(0.0, 8.0)),
            "width in mean edge lengths over which suggestive contours' curvature is averaged (None: 2, at most 1% of the diagonal)", optional;
        suggestive_coherence: bool [.suggestive_coherence] => boolean(),
            "suggestive contours hold still across render_many's views: faded by how fast they slide, with hysteresis between frames";
        min_crease_length: f64 [.min_crease_length] => float(NON_NEGATIVE.slider(0.0, 0.2)),
            "crease pieces shorter than this fraction of the bounding-box diagonal are not drawn";
        max_crease_turn: f64 [.max_crease_turn] => float(DEGREES),
            "crease pieces turning by more than this many degrees on average are not drawn (180: all)";
        image_rule: ImageRule [.image_rule] => choice(ImageRule::NAMES), "how image-space edges are found";
        normal_angle: f32 [.normal_angle] => float(DEGREES), "degrees of normal turn between pixels drawn as an edge";
        depth_jump: f32 [.depth_jump] => float(NON_NEGATIVE.slider(0.0, 20.0)),
            "depth jump between pixels drawn as an edge, in pixel footprints";
        normal_threshold: f32 [.normal_threshold] => float(NON_NEGATIVE.slider(0.0, 4.0)),
            "the paper rule's Sobel threshold on normals";
        depth_threshold: f32 [.depth_threshold] => float(NON_NEGATIVE.slider(0.0, 4.0)),
            "the paper rule's Sobel threshold on depth";
        depth_offset: f32 [.depth_offset] => float(NON_NEGATIVE.slider(0.0, 8.0)),
            "the depth rule's tolerance in pixel footprints";
        visibility: VisibilityRule [.visibility] => choice(VisibilityRule::NAMES),
            "how lines behind surfaces are found: 'exact' (against the surfaces) or 'depth' (the depth image)";
        max_occlusion: Option<u32> [.max_occlusion] => int(Range::count(1.0).slider(1.0, 8.0)),
            "hidden lines are drawn behind at most this many surfaces (None: any number)", optional;
        taper: f64 [.stroke_width.taper] => float(closed(0.0, MAX_TAPER).slider(0.0, 64.0)),
            "pixels over which lines thin toward their ends (0: none)", pixels;
        width_by_depth: bool [.stroke_width.by_depth] => boolean(),
            "scale line widths by the scene centre's depth over the line's";
        join_kinds: bool [.join_kinds] => boolean(), "join strokes of different kinds that meet end to end";
    }
}

/// The fields that are not stored as they are described.
impl Outlines {
    fn kind_text(&self, _: &str) -> String {
        self.kind_name().to_string()
    }

    fn set_kind(&mut self, field: &str, kind: String) -> Result<()> {
        (self.mesh, self.image) = Outlines::parse_kind(field, &kind)?;
        Ok(())
    }

    /// An ink kind's style: a LineStyle, or False where the kind is not drawn.
    fn style(&self, field: &str) -> Value {
        let style = slot(field).and_then(|k| self.styles[k]);
        style.map_or(Value::Bool(false), |s| Value::setting(Setting::LineStyle(s)))
    }

    fn set_style(&mut self, field: &str, value: Value) -> Result<()> {
        let k = slot(field).expect("a style field is an ink kind");
        self.styles[k] =
            FieldValue::from_value(field, in_style(value, default_style(k, LineStyle::default())))?;
        Ok(())
    }
}

const EXTRAS: &[Field] = &[
    Field::new("color", Kind::Color, "the common style's sRGB colour"),
    Field::float("width", WIDTH_RULE, "the common style's width in output pixels").pixels(),
    Field::new("crease", Kind::Style, "ridges and valleys together").optional(),
];

const PARAMS: &[&str] = &[
    "kind",
    "color",
    "width",
    "silhouette",
    "boundary",
    "crease",
    "ridge",
    "valley",
    "nonmanifold",
    "suggestive",
    "material",
    "intersection",
    "image",
    "hidden",
    "max_occlusion",
    "visibility",
    "crease_angle",
    "weld",
    "normal_threshold",
    "depth_threshold",
    "depth_offset",
    "contours",
    "suggestive_threshold",
    "curvature_smoothing",
    "suggestive_coherence",
    "min_crease_length",
    "max_crease_turn",
    "image_rule",
    "normal_angle",
    "depth_jump",
    "taper",
    "width_by_depth",
    "join_kinds",
];

/// The style True gives ink kind `k`: the common style, or for hidden lines theirs
/// (`LineStyle::hidden`).
fn default_style(k: usize, common: LineStyle) -> LineStyle {
    if k == HIDDEN_KIND {
        LineStyle::hidden(common)
    } else {
        common
    }
}

fn slot(name: &str) -> Option<usize> {
    kind_names().iter().position(|k| *k == name)
}

/// A kind's style given as True or as a colour, in the common style.
fn in_style(v: Value, common: LineStyle) -> Value {
    match v {
        Value::Bool(true) => Value::setting(Setting::LineStyle(common)),
        Value::Triple(color) => Value::setting(Setting::LineStyle(LineStyle { color, ..common })),
        other => other,
    }
}

/// `Outlines(...)`: the common style and each kind's, then the rules.
impl Described for Outlines {
    const EXTRAS: &'static [Field] = EXTRAS;

    const CONSTRUCTORS: &'static [Constructor] = &[Constructor::only(PARAMS, 1)];

    fn start(_: &str) -> Self {
        Outlines::default()
    }

    /// `'mesh'`, `'image'` or `'both'`: those lines in the default styles.
    fn shorthand(field: &str, value: Value) -> Result<Self> {
        let (mesh, image) = Outlines::parse_kind(field, &value.text(field)?)?;
        Ok(Outlines::new(mesh, image))
    }

    /// The common style first (every kind drawn by default takes it), then each kind in it.
    fn construct(constructor: &str, args: Vec<(&'static str, Value)>) -> Result<Self> {
        let mut common = LineStyle::default();
        let mut rest = Vec::with_capacity(args.len());
        let mut crease = None;
        for (name, v) in args {
            match name {
                "color" => common.color = v.triple(name)?,
                "width" => common.width = v.float(name)? as f32,
                "crease" => crease = Some(v),
                _ => rest.push((name, v)),
            }
        }
        let mut with_common = Vec::with_capacity(rest.len() + 8);
        for (k, name) in kind_names().iter().enumerate() {
            if k != LineKind::Suggestive as usize && k != HIDDEN_KIND {
                with_common.push((*name, Value::setting(Setting::LineStyle(common))));
            }
        }
        if let Some(c) = crease {
            for name in ["ridge", "valley"] {
                with_common.push((name, in_style(c.clone(), common)));
            }
        }
        with_common.extend(rest.into_iter().map(|(n, v)| match slot(n) {
            Some(k) => (n, in_style(v, default_style(k, common))),
            None => (n, v),
        }));
        // later entries of the same kind win: `build` sorts stably by parameter
        let mut seen = std::collections::HashMap::new();
        for (i, (n, _)) in with_common.iter().enumerate() {
            seen.insert(*n, i);
        }
        let args =
            with_common.into_iter().enumerate().filter(|(i, (n, _))| seen[n] == *i).map(|(_, a)| a).collect();
        build(constructor, args)
    }

    fn read(&self, _: &str, param: &str) -> Option<Value> {
        match param {
            "color" | "width" | "crease" => None,
            _ => Some(self.get(param)),
        }
    }

    fn check(&self) -> Result<()> {
        self.validate("")
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn defaults_are_those_of_the_edge_functions_and_checks_name_the_field() {
        let o = Outlines::default();
        assert!(o.validate("outlines").is_ok());
        assert_eq!(o.crease_angle, DEFAULT_CREASE_ANGLE);
        assert_eq!(o.normal_threshold as f64, DEFAULT_NORMAL_THRESHOLD);
        let mut bad = o.clone();
        bad.styles[LineKind::Silhouette as usize] =
            Some(LineStyle { color: [0.0; 3], width: f32::NAN, dash: 0.0 });
        assert!(bad.validate("outlines").unwrap_err().to_string().starts_with("outlines.silhouette.width"));
        let mut bad = o.clone();
        bad.depth_threshold = -1.0;
        assert!(bad.validate("outlines").is_err());
        let mut bad = o.clone();
        bad.stroke_width.taper = -1.0;
        assert!(bad.validate("outlines").unwrap_err().to_string().starts_with("outlines.taper"));
        assert_eq!(kind_names()[IMAGE_KIND], "image");
    }
}

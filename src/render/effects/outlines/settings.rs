//! Ink outlines a scene asks for: mesh-space lines (Kang, Kim and Yoon: silhouettes per view,
//! boundaries, creases and non-manifold edges once per mesh) drawn as screen-space strips with
//! hidden lines removed, and image-space edges (Borquez and Yepez: Sobel on the normal and depth
//! buffers, with the rule and defaults of `edges::detect`).

use serde::{Deserialize, Serialize};

use crate::edges::contours::{check_smoothing, check_threshold, DEFAULT_SUGGESTIVE_THRESHOLD};
use crate::edges::crooked_creases::{check_max_crease_turn, DEFAULT_MAX_CREASE_TURN};
use crate::edges::detect::{DEFAULT_DEPTH_THRESHOLD, DEFAULT_NORMAL_THRESHOLD};
use crate::edges::outlines::LineKind;
use crate::edges::short_creases::DEFAULT_MIN_CREASE_LENGTH;
use crate::edges::DEFAULT_CREASE_ANGLE;
use crate::error::field;
use crate::error::{Error, Result};
use crate::render::color::{check_unit, Srgb};

use super::stroke_width::StrokeWidth;

/// Width of lines in output pixels when none is given.
pub const DEFAULT_WIDTH: f32 = 1.5;
/// Ink colour when none is given (sRGB).
pub const DEFAULT_INK: Srgb = [0.0, 0.0, 0.0];
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

/// The kinds of ink: the mesh-space kinds of `edges::outlines::LineKind`, then image-space edges.
pub const IMAGE_KIND: usize = LineKind::COUNT;
pub const INK_KINDS: usize = LineKind::COUNT + 1;

/// How one kind of line is drawn.
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
pub struct LineStyle {
    pub color: Srgb,
    /// Full width in output pixels (the same at every resolution and supersampling factor).
    /// Image-space edges are one pixel wide whatever this says.
    pub width: f32,
}

impl Default for LineStyle {
    fn default() -> Self {
        LineStyle { color: DEFAULT_INK, width: DEFAULT_WIDTH }
    }
}

impl LineStyle {
    /// Checks the style; `prefix` names it in errors ("" while it is being made).
    pub fn validate(&self, prefix: &str) -> Result<()> {
        check_unit(&field(prefix, "color"), &self.color)?;
        if !(self.width > 0.0 && self.width <= MAX_WIDTH) {
            return Err(Error::invalid(
                field(prefix, "width"),
                format!("must be in (0, {MAX_WIDTH}] pixels, got {}", self.width),
            ));
        }
        Ok(())
    }
}

/// Names of the ink kinds, in index order (the Python keywords and `RenderResult.lines` keys).
pub fn kind_names() -> [&'static str; INK_KINDS] {
    let mut names = ["image"; INK_KINDS];
    for k in LineKind::ALL {
        names[k as usize] = k.name();
    }
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
}

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
        Outlines {
            mesh,
            image,
            styles,
            contours: ContourRule::Auto,
            suggestive_threshold: DEFAULT_SUGGESTIVE_THRESHOLD,
            curvature_smoothing: None,
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
        }
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

    pub fn draws_image_edges(&self) -> bool {
        self.image && self.styles[IMAGE_KIND].is_some()
    }

    /// Checks the settings; `prefix` names them in errors ("" while they are being made).
    pub fn validate(&self, prefix: &str) -> Result<()> {
        if !self.mesh && !self.image {
            return Err(Error::invalid(field(prefix, "kind"), "must draw mesh lines, image edges or both"));
        }
        // the other mesh kinds are on by default; suggestive contours are asked for
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
        // angles between normals, by the crease angle's rule
        let in_degrees = |name: &str, a: f64| {
            crate::edges::feature::check_crease_angle(a).map_err(|_| {
                Error::invalid(field(prefix, name), format!("must be in [0, 180] degrees, got {a}"))
            })
        };
        in_degrees("crease_angle", self.crease_angle)?;
        in_degrees("normal_angle", self.normal_angle as f64)?;
        check_max_crease_turn(&field(prefix, "max_crease_turn"), self.max_crease_turn)?;
        // finite and >= 0, in the unit each is measured in
        for (name, t, unit) in [
            ("normal_threshold", self.normal_threshold as f64, ""),
            ("depth_threshold", self.depth_threshold as f64, ""),
            ("depth_jump", self.depth_jump as f64, " pixel footprints"),
            ("min_crease_length", self.min_crease_length, " (a fraction of the diagonal)"),
            ("depth_offset", self.depth_offset as f64, " pixels"),
        ] {
            if !(t.is_finite() && t >= 0.0) {
                return Err(Error::invalid(
                    field(prefix, name),
                    format!("must be finite and >= 0{unit}, got {t}"),
                ));
            }
        }
        check_threshold(&field(prefix, "suggestive_threshold"), self.suggestive_threshold)?;
        if let Some(s) = self.curvature_smoothing {
            check_smoothing(&field(prefix, "curvature_smoothing"), s)?;
        }
        self.stroke_width.validate(prefix)
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
        bad.styles[LineKind::Silhouette as usize] = Some(LineStyle { color: [0.0; 3], width: f32::NAN });
        assert!(bad.validate("outlines").unwrap_err().to_string().starts_with("outlines.silhouette.width"));
        let mut bad = o.clone();
        bad.depth_threshold = -1.0;
        assert!(bad.validate("outlines").is_err());
        assert_eq!(kind_names()[IMAGE_KIND], "image");
    }
}

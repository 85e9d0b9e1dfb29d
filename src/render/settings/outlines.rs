//! `Outlines` described: each ink kind's style is a field; `color` and `width` set the common
//! style of the kinds given as True (or as a colour), `crease` both ridges and valleys.

use super::{build, f32_value, mismatch, Constructor, Described, Field, Kind, Setting, Value};
use crate::edges::outlines::LineKind;
use crate::error::Result;
use crate::render::effects::outlines::settings::{
    kind_names, ContourRule, ImageRule, LineStyle, Outlines, MAX_WIDTH,
};

const STYLE_HELP: &str = "True (the common style), False (not drawn), a LineStyle or a colour";

const fn style(name: &'static str) -> Field {
    Field::new(name, Kind::Style, STYLE_HELP).optional()
}

const FIELDS: &[Field] = &[
    Field::choice("kind", &Outlines::KINDS, "lines found on the mesh, edges found in the image, or both"),
    style("silhouette"),
    style("boundary"),
    style("nonmanifold"),
    style("ridge"),
    style("valley"),
    Field::new("suggestive", Kind::Style, "suggestive contours (DeCarlo et al.): drawn only when asked for").optional(),
    Field::new("material", Kind::Style, "borders between scene items that meet edge to edge").optional(),
    Field::new("image", Kind::Style, "image-space edges").optional(),
    Field::float("crease_angle", 0.0, 180.0, "dihedral angle in degrees above which an edge is a crease"),
    Field::new("weld", Kind::Bool, "merge vertices at equal positions first, so seams are not drawn as boundaries"),
    Field::choice("contours", ContourRule::NAMES, "how silhouettes are found: 'faces', 'smooth' or 'auto'"),
    Field::float("suggestive_threshold", 0.0, 0.2, "the suggestive contours' derivative test, relative to the mesh's feature size"),
    Field::float(
        "curvature_smoothing",
        0.0,
        8.0,
        "width in mean edge lengths over which suggestive contours' curvature is averaged (None: 2, at most 1% of the diagonal)",
    )
    .optional(),
    Field::float("min_crease_length", 0.0, 0.2, "crease pieces shorter than this fraction of the bounding-box diagonal are not drawn"),
    Field::float("max_crease_turn", 0.0, 180.0, "crease pieces turning by more than this many degrees on average are not drawn (180: all)"),
    Field::choice("image_rule", ImageRule::NAMES, "how image-space edges are found"),
    Field::float("normal_angle", 0.0, 180.0, "degrees of normal turn between pixels drawn as an edge"),
    Field::float("depth_jump", 0.0, 20.0, "depth jump between pixels drawn as an edge, in pixel footprints"),
    Field::float("normal_threshold", 0.0, 4.0, "the paper rule's Sobel threshold on normals"),
    Field::float("depth_threshold", 0.0, 4.0, "the paper rule's Sobel threshold on depth"),
    Field::float("depth_offset", 0.0, 8.0, "hidden-line removal's tolerance in pixel footprints"),
    Field::float("taper", 0.0, 64.0, "pixels over which lines thin toward their ends (0: none)").pixels(),
    Field::new("width_by_depth", Kind::Bool, "scale line widths by the scene centre's depth over the line's"),
    Field::new("join_kinds", Kind::Bool, "join strokes of different kinds that meet end to end"),
];

const EXTRAS: &[Field] = &[
    Field::new("color", Kind::Color, "the common style's sRGB colour"),
    Field::float("width", 0.25, MAX_WIDTH as f64, "the common style's width in output pixels").pixels(),
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
    "image",
    "crease_angle",
    "weld",
    "normal_threshold",
    "depth_threshold",
    "depth_offset",
    "contours",
    "suggestive_threshold",
    "curvature_smoothing",
    "min_crease_length",
    "max_crease_turn",
    "image_rule",
    "normal_angle",
    "depth_jump",
    "taper",
    "width_by_depth",
    "join_kinds",
];

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

impl Described for Outlines {
    const FIELDS: &'static [Field] = FIELDS;

    const EXTRAS: &'static [Field] = EXTRAS;

    const CONSTRUCTORS: &'static [Constructor] = &[Constructor::only(PARAMS, 1)];

    fn start(_: &str) -> Self {
        Outlines::default()
    }

    fn get(&self, field: &str) -> Value {
        if let Some(k) = slot(field) {
            return self.styles[k].map_or(Value::Bool(false), |s| Value::setting(Setting::LineStyle(s)));
        }
        match field {
            "kind" => self.kind_name().into(),
            "crease_angle" => self.crease_angle.into(),
            "weld" => self.weld.into(),
            "contours" => self.contours.name().into(),
            "suggestive_threshold" => self.suggestive_threshold.into(),
            "curvature_smoothing" => self.curvature_smoothing.into(),
            "min_crease_length" => self.min_crease_length.into(),
            "max_crease_turn" => self.max_crease_turn.into(),
            "image_rule" => self.image_rule.name().into(),
            "normal_angle" => f32_value(self.normal_angle),
            "depth_jump" => f32_value(self.depth_jump),
            "normal_threshold" => f32_value(self.normal_threshold),
            "depth_threshold" => f32_value(self.depth_threshold),
            "depth_offset" => f32_value(self.depth_offset),
            "taper" => self.stroke_width.taper.into(),
            "width_by_depth" => self.stroke_width.by_depth.into(),
            "join_kinds" => self.join_kinds.into(),
            _ => Value::None,
        }
    }

    fn set(&mut self, field: &str, v: Value) -> Result<()> {
        if let Some(k) = slot(field) {
            self.styles[k] = match in_style(v, LineStyle::default()) {
                Value::None | Value::Bool(false) => None,
                other => match other.into_setting(field)? {
                    Setting::LineStyle(s) => Some(s),
                    other => return Err(mismatch(field, &Value::setting(other))),
                },
            };
            return Ok(());
        }
        let f32_of = |v: Value| v.float(field).map(|x| x as f32);
        match field {
            "kind" => (self.mesh, self.image) = Outlines::parse_kind(field, &v.text(field)?)?,
            "crease_angle" => self.crease_angle = v.float(field)?,
            "weld" => self.weld = v.bool(field)?,
            "contours" => self.contours = ContourRule::parse(field, &v.text(field)?)?,
            "suggestive_threshold" => self.suggestive_threshold = v.float(field)?,
            "curvature_smoothing" => self.curvature_smoothing = v.opt_float(field)?,
            "min_crease_length" => self.min_crease_length = v.float(field)?,
            "max_crease_turn" => self.max_crease_turn = v.float(field)?,
            "image_rule" => self.image_rule = ImageRule::parse(field, &v.text(field)?)?,
            "normal_angle" => self.normal_angle = f32_of(v)?,
            "depth_jump" => self.depth_jump = f32_of(v)?,
            "normal_threshold" => self.normal_threshold = f32_of(v)?,
            "depth_threshold" => self.depth_threshold = f32_of(v)?,
            "depth_offset" => self.depth_offset = f32_of(v)?,
            "taper" => self.stroke_width.taper = v.float(field)?,
            "width_by_depth" => self.stroke_width.by_depth = v.bool(field)?,
            _ => self.join_kinds = v.bool(field)?,
        }
        Ok(())
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
            if k != LineKind::Suggestive as usize {
                with_common.push((*name, Value::setting(Setting::LineStyle(common))));
            }
        }
        if let Some(c) = crease {
            for name in ["ridge", "valley"] {
                with_common.push((name, in_style(c.clone(), common)));
            }
        }
        with_common.extend(
            rest.into_iter().map(|(n, v)| (n, if slot(n).is_some() { in_style(v, common) } else { v })),
        );
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

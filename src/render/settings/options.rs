//! `RenderOptions` described: every render setting besides the meshes.

use super::{concat, mismatch, Constructor, Described, Field, Kind, Setting, Value};
use crate::error::{Error, Result};
use crate::render::effects::outlines::settings::Outlines;
use crate::render::effects::scene_settings as effects;
use crate::render::scene::options::RenderOptions;
use crate::render::scene::up::Axis;
use crate::render::scene::{Output, Outputs, MAX_SUPERSAMPLE, PIXEL_RATIOS};

const OWN_FIELDS: &[Field] = &[
    Field::new("material", Kind::Setting("Material"), "the material of meshes that name none"),
    Field::new(
        "transform",
        Kind::Matrix,
        "a 4x4 affine model -> world matrix (row-major, applied to column vectors) for meshes that give none",
    ),
    Field::new(
        "camera",
        Kind::Setting("Camera"),
        "the camera (Camera.fit(): the scene framed from a three-quarter view about its up axis)",
    ),
    Field::new(
        "up",
        Kind::Choice(Axis::NAMES),
        "the scene's up axis, which a fitted camera keeps up in the image and turns about (None: its meshes' own, as toonmesh.load reads a file's convention, else y)",
    )
    .optional(),
    Field::new("lights", Kind::Lights, "a Light or a list of up to 8"),
    Field::new("ambient", Kind::Color, "the ambient light's sRGB colour"),
    Field::new("background", Kind::Rgba, "sRGB or sRGBA where no mesh is"),
    Field::new("width", Kind::Int { min: 1, max: 16384 }, "the image's width in pixels, 1 to the device's limit"),
    Field::new("height", Kind::Int { min: 1, max: 16384 }, "the image's height in pixels, 1 to the device's limit"),
    Field::new(
        "outputs",
        Kind::Names(&Output::NAMES),
        "the outputs computed and read back, and only those ('outline' and 'lines' need outlines, 'shadow' a light with shadows)",
    ),
    Field::new("msaa", Kind::Int { min: 1, max: 4 }, "samples per pixel: 1 or 4"),
    Field::new(
        "supersample",
        Kind::Int { min: 1, max: MAX_SUPERSAMPLE as i64 },
        "render this many times larger in each direction and average down",
    ),
    Field::float(
        "pixel_ratio",
        PIXEL_RATIOS.0,
        PIXEL_RATIOS.1,
        "output pixels per pixel of the widths, spacings and scales given in pixels: 2 with twice the width and height draws the same picture, sharper (a 2x screen)",
    ),
    Field::new(
        "band_antialias",
        Kind::Bool,
        "blend across each band border over about one pixel, from the screen-space change of the shading term: smooth tone borders at no extra samples (False: the papers' hard borders)",
    ),
    Field::new(
        "outlines",
        Kind::Setting("Outlines"),
        "ink outlines: None, 'mesh', 'image', 'both' or an Outlines",
    )
    .optional(),
];

/// Its own fields, then the frame effects' (`effects::scene_settings`).
const FIELDS: &[Field] =
    &concat::<_, { OWN_FIELDS.len() + effects::FIELDS.len() }>(OWN_FIELDS, effects::FIELDS);

const OWN_PARAMS: &[&str] = &[
    "material",
    "transform",
    "camera",
    "up",
    "lights",
    "ambient",
    "background",
    "width",
    "height",
    "outputs",
    "msaa",
    "supersample",
    "pixel_ratio",
    "band_antialias",
    "outlines",
];

const PARAMS: &[&str] = &concat::<_, { OWN_PARAMS.len() + effects::NAMES.len() }>(OWN_PARAMS, effects::NAMES);

fn count(field: &str, v: Value, at_least: i64, what: &str) -> Result<u32> {
    let n = v.int(field)?;
    if n < at_least {
        return Err(Error::invalid(field, format!("must be at least {at_least}{what}, got {n}")));
    }
    u32::try_from(n).map_err(|_| Error::invalid(field, format!("{n} is too large")))
}

impl Described for RenderOptions {
    const PARAMETER: Option<&'static str> = Some("a render option");

    const FIELDS: &'static [Field] = FIELDS;

    const CONSTRUCTORS: &'static [Constructor] = &[Constructor::only(PARAMS, 0)];

    fn start(_: &str) -> Self {
        RenderOptions::default()
    }

    fn get(&self, field: &str) -> Value {
        let f = &self.frame;
        match field {
            "material" => Value::setting(Setting::Material(self.material.clone())),
            "transform" => Value::Matrix(self.transform),
            "camera" => Value::setting(Setting::Camera(self.camera)),
            "up" => self.up.map_or(Value::None, |a| a.name().into()),
            "lights" => Value::Lights(self.lights.clone()),
            "ambient" => self.ambient.into(),
            "background" => Value::Rgba(f.background.map(|c| format!("{c}").parse().unwrap_or(c as f64))),
            "width" => Value::Int(f.width as i64),
            "height" => Value::Int(f.height as i64),
            "outputs" => Value::Names(f.outputs.iter().map(|o| o.name().to_string()).collect()),
            "msaa" => Value::Int(f.msaa as i64),
            "supersample" => Value::Int(f.supersample as i64),
            "pixel_ratio" => f.pixel_ratio.into(),
            "band_antialias" => f.band_antialias.into(),
            "outlines" => self.outlines.clone().map_or(Value::None, |o| Value::setting(Setting::Outlines(o))),
            other => self.effects.get(other).unwrap_or(Value::None),
        }
    }

    fn set(&mut self, field: &str, v: Value) -> Result<()> {
        if effects::NAMES.contains(&field) {
            return self.effects.set(field, v).expect("a frame effect's keyword");
        }
        let f = &mut self.frame;
        match (field, v) {
            ("transform", Value::Matrix(m)) => self.transform = m,
            ("up", Value::None) => self.up = None,
            ("up", v) => self.up = Some(Axis::parse(field, &v.text(field)?)?),
            ("lights", Value::Lights(l)) => self.lights = l,
            ("ambient", v) => self.ambient = v.triple(field)?,
            ("background", Value::Rgba(c)) => f.background = c.map(|x| x as f32),
            ("width" | "height", v) => {
                let n = count(field, v, 1, " pixel")?;
                *if field == "width" { &mut f.width } else { &mut f.height } = n;
            }
            ("msaa", v) => f.msaa = count(field, v, 0, "")?,
            ("supersample", v) => f.supersample = count(field, v, 0, "")?,
            ("pixel_ratio", v) => f.pixel_ratio = v.float(field)?,
            ("band_antialias", v) => f.band_antialias = v.bool(field)?,
            ("outputs", Value::Names(names)) => {
                let mut o = Outputs::default();
                for n in &names {
                    o.insert(Output::parse(field, n)?);
                }
                o.validate()?;
                f.outputs = o;
            }
            ("outlines", Value::None) => self.outlines = None,
            ("outlines", Value::Text(kind)) => {
                let (mesh, image) = Outlines::parse_kind(field, &kind)?;
                self.outlines = Some(Outlines::new(mesh, image));
            }
            (_, Value::Setting(s)) => match (field, *s) {
                ("material", Setting::Material(m)) => self.material = m,
                ("camera", Setting::Camera(c)) => self.camera = c,
                ("outlines", Setting::Outlines(o)) => self.outlines = Some(o),
                (_, other) => return Err(mismatch(field, &Value::setting(other))),
            },
            (_, other) => return Err(mismatch(field, &other)),
        }
        Ok(())
    }

    /// Sizes, samples and outputs are checked against the device when it renders.
    fn check(&self) -> Result<()> {
        Ok(())
    }
}

//! What a render can return, in one table: each output's name, what one pixel of it holds, and
//! the order outputs are listed and read back in.

use serde::{Deserialize, Serialize};

use crate::error::{Error, Result};

#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub enum Output {
    /// (H, W, 4) sRGB colour, uint8.
    Color,
    /// (H, W, 3) view-space unit normals, float32.
    Normal,
    /// (H, W) linear view depth, float32.
    Depth,
    /// (H, W) ink coverage of the outlines in [0, 1], float32.
    Outline,
    /// The visible mesh-space lines as polylines in pixel coordinates.
    Lines,
    /// (H, W) visibility of the shadow-casting light in [0, 1], float32: 1 lit, 0 shadowed (or
    /// facing away from the light), 1 where no mesh is.
    Shadow,
}

/// What one pixel of an image output holds.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Pixel {
    /// `n` bytes (uint8).
    Bytes(usize),
    /// `n` float32 values.
    Floats(usize),
}

impl Output {
    /// Every output, in the order they are listed and read back.
    pub const ALL: [Output; 6] =
        [Output::Color, Output::Normal, Output::Depth, Output::Outline, Output::Lines, Output::Shadow];

    /// The names of `ALL`, in its order.
    pub const NAMES: [&'static str; 6] = ["color", "normal", "depth", "outline", "lines", "shadow"];

    pub fn name(self) -> &'static str {
        Self::NAMES[self as usize]
    }

    /// The pixel of an image output; None for the lines, which are polylines.
    pub fn pixel(self) -> Option<Pixel> {
        match self {
            Output::Color => Some(Pixel::Bytes(4)),
            Output::Normal => Some(Pixel::Floats(3)),
            Output::Depth | Output::Outline | Output::Shadow => Some(Pixel::Floats(1)),
            Output::Lines => None,
        }
    }

    /// The shape of this output's image of a `height` x `width` frame after the `leading` axes:
    /// (H, W, 4) colour, (H, W, 3) normals, (H, W) for the others; None without an image.
    pub fn shape(self, leading: &[usize], height: u32, width: u32) -> Option<Vec<usize>> {
        let channels = match self.pixel()? {
            Pixel::Bytes(c) => Some(c),
            Pixel::Floats(c) => (c > 1).then_some(c),
        };
        Some(leading.iter().copied().chain([height as usize, width as usize]).chain(channels).collect())
    }

    pub fn parse(arg: &str, name: &str) -> Result<Self> {
        Self::ALL.into_iter().find(|o| o.name() == name).ok_or_else(|| {
            Error::invalid(
                arg,
                format!(
                    "unknown output {name:?}; use {}",
                    Self::ALL.map(|o| format!("'{}'", o.name())).join(", ")
                ),
            )
        })
    }
}

/// A set of outputs.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash, Serialize, Deserialize)]
#[serde(into = "Vec<String>", try_from = "Vec<String>")]
pub struct Outputs(u8);

impl Outputs {
    pub fn of(outputs: &[Output]) -> Self {
        let mut s = Outputs::default();
        for &o in outputs {
            s.insert(o);
        }
        s
    }

    pub fn has(self, o: Output) -> bool {
        self.0 & (1 << o as u8) != 0
    }

    pub fn insert(&mut self, o: Output) {
        self.0 |= 1 << o as u8;
    }

    pub fn is_empty(self) -> bool {
        self.0 == 0
    }

    /// The outputs in the set, in `Output::ALL` order.
    pub fn iter(self) -> impl Iterator<Item = Output> {
        Output::ALL.into_iter().filter(move |o| self.has(*o))
    }

    pub fn validate(self) -> Result<()> {
        if self.is_empty() {
            return Err(Error::invalid(
                "outputs",
                "ask for at least one output ('color', 'normal', 'depth', ...)",
            ));
        }
        Ok(())
    }
}

impl From<Outputs> for Vec<String> {
    fn from(o: Outputs) -> Self {
        o.iter().map(|o| o.name().to_string()).collect()
    }
}

impl TryFrom<Vec<String>> for Outputs {
    type Error = Error;
    fn try_from(names: Vec<String>) -> Result<Self> {
        let mut s = Outputs::default();
        for n in &names {
            s.insert(Output::parse("outputs", n)?);
        }
        Ok(s)
    }
}

/// A field of names (`RenderOptions.outputs`): at least one.
impl crate::render::settings::FieldValue for Outputs {
    fn to_value(&self) -> crate::render::settings::Value {
        crate::render::settings::Value::Names(Vec::from(*self))
    }

    fn from_value(field: &str, value: crate::render::settings::Value) -> Result<Self> {
        match value {
            crate::render::settings::Value::Names(names) => {
                let mut o = Outputs::default();
                for n in &names {
                    o.insert(Output::parse(field, n)?);
                }
                o.validate()?;
                Ok(o)
            }
            other => Err(crate::render::settings::mismatch(field, &other)),
        }
    }
}

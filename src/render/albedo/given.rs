//! A mesh's colour as a front end gives it (`Renderer.add_mesh`'s colour keywords): colours and
//! texels as sRGB arrays of 8-bit codes or of floats in [0, 1], texture coordinates, and the
//! texture's sampling by name; checked and made into an `Albedo` (decoded to linear light) here.

use super::{check_unit_floats, linear_colors, Albedo, Colors, Filter, Sampling, Texture, Wrap};
use crate::error::{Error, Result};

/// The values of an sRGB array, as given.
pub enum Values {
    Codes(Vec<u8>),
    /// Floats, which must lie in [0, 1].
    Unit(Vec<f64>),
}

/// An sRGB array: its shape and its values, row-major.
pub struct Channels {
    pub shape: Vec<usize>,
    pub values: Values,
}

impl Channels {
    /// Checks the shape of the argument `arg`: as many axes as `rank`, the last of 3 or 4
    /// channels, none empty (`what`: the shapes it takes).
    fn check_shape(&self, arg: &str, rank: usize, what: &str) -> Result<()> {
        let s = &self.shape;
        if s.len() != rank || !matches!(s[rank - 1], 3 | 4) || s.contains(&0) {
            return Err(Error::invalid(arg, format!("expected shape {what}, got {s:?}")));
        }
        Ok(())
    }

    /// The values in [0, 1] (codes divided by 255).
    fn unit(self, arg: &str) -> Result<Vec<f32>> {
        match self.values {
            Values::Codes(c) => Ok(c.into_iter().map(|c| c as f32 / 255.0).collect()),
            Values::Unit(v) => check_unit_floats(arg, &v).map(|()| v.into_iter().map(|x| x as f32).collect()),
        }
    }

    /// (K, 3|4) colours as linear RGBA (alpha 1 when absent).
    fn colors(self, arg: &str, what: &str) -> Result<Vec<[f32; 4]>> {
        self.check_shape(arg, 2, what)?;
        let channels = self.shape[1];
        Ok(linear_colors(&self.unit(arg)?, channels))
    }

    /// An (H, W, 3|4) image, top row first, as 8-bit codes (floats rounded to the nearest).
    fn texture(self) -> Result<Texture> {
        self.check_shape("texture", 3, "(H, W, 3) or (H, W, 4)")?;
        let shape = self.shape.clone();
        match self.values {
            Values::Codes(codes) => Texture::from_codes(&shape, &codes),
            Values::Unit(_) => Texture::from_unit(&shape, &self.unit("texture")?),
        }
    }
}

/// The value named `name` (`parse` reads it), or the default when not given.
fn named<T: Default>(arg: &str, name: Option<String>, parse: fn(&str, &str) -> Result<T>) -> Result<T> {
    name.map_or(Ok(T::default()), |n| parse(arg, &n))
}

/// The colour keywords given (None: not given).
#[derive(Default)]
pub struct Given {
    pub vertex_colors: Option<Channels>,
    pub face_colors: Option<Channels>,
    pub uv: Option<Vec<[f32; 2]>>,
    pub texture: Option<Channels>,
    pub texture_filter: Option<String>,
    pub texture_wrap: Option<String>,
    pub alpha_cutoff: Option<f64>,
    pub alpha_blend: Option<bool>,
}

impl Given {
    /// The keywords, in the order they are checked.
    pub const KEYWORDS: [&str; 8] = [
        "vertex_colors",
        "face_colors",
        "uv",
        "texture",
        "texture_filter",
        "texture_wrap",
        "alpha_cutoff",
        "alpha_blend",
    ];

    /// The albedo of what was given (None: no colour).
    pub fn albedo(self) -> Result<Option<Albedo>> {
        let sampling = Sampling {
            filter: named("texture_filter", self.texture_filter, Filter::parse)?,
            wrap: named("texture_wrap", self.texture_wrap, Wrap::parse)?,
            alpha_cutoff: self.alpha_cutoff.map(|c| c as f32),
            alpha_blend: self.alpha_blend.unwrap_or(false),
        };
        sampling.check()?;
        let colors = match (self.vertex_colors, self.face_colors) {
            (Some(_), Some(_)) => {
                return Err(Error::invalid("vertex_colors, face_colors", "give one of them, not both"))
            }
            (Some(c), None) => Some(Colors::Vertex(c.colors("vertex_colors", "(N, 3) or (N, 4)")?)),
            (None, Some(c)) => Some(Colors::Face(c.colors("face_colors", "(M, 3) or (M, 4)")?)),
            (None, None) => None,
        };
        let texture = self.texture.map(Channels::texture).transpose()?;
        let a = Albedo { colors, uv: self.uv, texture, sampling };
        Ok((a.is_used() || a.uv.is_some()).then_some(a))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn given(texture: Values, shape: Vec<usize>) -> Given {
        let texture = Some(Channels { shape, values: texture });
        Given {
            vertex_colors: None,
            face_colors: None,
            uv: None,
            texture,
            texture_filter: None,
            texture_wrap: Some("clamp".into()),
            alpha_cutoff: None,
            alpha_blend: None,
        }
    }

    #[test]
    fn codes_and_floats_make_the_same_texture() {
        let codes = given(Values::Codes(vec![0, 51, 255]), vec![1, 1, 3]).albedo().unwrap().unwrap();
        let floats = given(Values::Unit(vec![0.0, 0.2, 1.0]), vec![1, 1, 3]).albedo().unwrap().unwrap();
        assert_eq!(codes, floats);
        let e = given(Values::Unit(vec![0.0, 2.0, 1.0]), vec![1, 1, 3]).albedo().unwrap_err();
        assert!(e.to_string().starts_with("texture: float values must be in [0, 1]"));
        let e = given(Values::Codes(vec![0, 0]), vec![1, 1, 2]).albedo().unwrap_err();
        assert!(e.to_string().starts_with("texture: expected shape (H, W, 3) or (H, W, 4)"));
    }
}

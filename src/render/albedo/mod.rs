//! Colour on the surface: per-vertex or per-face colours, texture coordinates and a texture,
//! with glTF's sampling settings. The albedo of a point is the product of its colour and its
//! texture sample, both decoded from sRGB to linear light; it multiplies the material's ambient
//! and diffuse colours in every shading model (`shade` in common.wgsl, `reference::shade`).
//!
//! Plain data and its CPU twins (`texture`: the mip chain, `sampling`: the sampling rule); the
//! device side is `render::gpu_albedo`.

pub mod given;
pub mod sampling;
pub mod texture;

use crate::error::{Error, Result};

pub use sampling::{Filter, Sampling, Wrap};
pub use texture::Texture;

/// sRGB channel values in [0, 1], `channels` (3 or 4) a colour, as linear-light RGBA (alpha 1
/// when absent).
pub fn linear_colors(values: &[f32], channels: usize) -> Vec<[f32; 4]> {
    let decode = |c: f32| crate::render::color::srgb_to_linear(c as f64) as f32;
    let colour = |c: &[f32]| [decode(c[0]), decode(c[1]), decode(c[2]), c.get(3).copied().unwrap_or(1.0)];
    values.chunks_exact(channels).map(colour).collect()
}

/// Checks colour channels given as floats (the argument `arg`): each in [0, 1].
pub fn check_unit_floats(arg: &str, values: &[f64]) -> Result<()> {
    match values.iter().find(|x| !(x.is_finite() && (0.0..=1.0).contains(*x))) {
        Some(bad) => {
            let hint = if bad.is_finite() && *bad > 1.0 { " (for 0-255 codes, use uint8)" } else { "" };
            Err(Error::invalid(arg, format!("float values must be in [0, 1], got {bad}{hint}")))
        }
        None => Ok(()),
    }
}

/// Linear-light RGBA colours, one per vertex or one per face.
#[derive(Clone, Debug, PartialEq)]
pub enum Colors {
    Vertex(Vec<[f32; 4]>),
    Face(Vec<[f32; 4]>),
}

/// What a mesh carries besides its geometry for its colour (each part optional).
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Albedo {
    pub colors: Option<Colors>,
    /// Texture coordinates per vertex: u to the right, v up from the image's bottom row (OBJ,
    /// trimesh); the texture's rows are read top first, so (u, v) reads row (1 - v) * height.
    pub uv: Option<Vec<[f32; 2]>>,
    pub texture: Option<Texture>,
    pub sampling: Sampling,
}

impl Albedo {
    /// Whether there is anything to draw with (otherwise the mesh renders as before).
    pub fn is_used(&self) -> bool {
        self.colors.is_some() || self.texture.is_some()
    }

    /// A fingerprint of the surface's material, for the lines between scene items (a border
    /// is a material border where two items' looks differ): the texture and its sampling, and
    /// the colour where it is one colour throughout. Colours that vary count as one look, as
    /// they show their own changes.
    pub fn look(&self) -> u64 {
        use std::hash::{Hash, Hasher};
        let mut h = std::collections::hash_map::DefaultHasher::new();
        let colors = match &self.colors {
            Some(Colors::Vertex(c) | Colors::Face(c)) => Some(c),
            None => None,
        };
        match colors.map(|c| (c.first(), c.iter().all(|x| Some(x) == c.first()))) {
            None => 0u8.hash(&mut h),
            Some((first, true)) => (1u8, first.map(|c| c.map(f32::to_bits))).hash(&mut h),
            Some((_, false)) => 2u8.hash(&mut h),
        }
        if let Some(t) = &self.texture {
            // the texels as one run of bytes: one write, not one per texel
            (t.width, t.height, bytemuck::cast_slice::<[u8; 4], u8>(&t.texels)).hash(&mut h);
            format!("{:?}", self.sampling).hash(&mut h);
        }
        h.finish()
    }

    /// The face colours of the faces flagged in `keep` (see `mesh::back_to_back`); the other
    /// parts are per vertex or per mesh, so they stay.
    pub fn keeping_faces(mut self, keep: &[bool]) -> Albedo {
        if let Some(Colors::Face(c)) = &self.colors {
            self.colors = Some(Colors::Face(crate::mesh::back_to_back::kept(c, keep)));
        }
        self
    }

    /// Checks the parts against a mesh of `n_vertices` vertices and `n_faces` faces.
    pub fn check(&self, n_vertices: usize, n_faces: usize) -> Result<()> {
        match &self.colors {
            Some(Colors::Vertex(c)) if c.len() != n_vertices => {
                return Err(Error::invalid(
                    "vertex_colors",
                    format!("expected one colour per vertex ({n_vertices}), got {}", c.len()),
                ))
            }
            Some(Colors::Face(c)) if c.len() != n_faces => {
                return Err(Error::invalid(
                    "face_colors",
                    format!("expected one colour per face ({n_faces}), got {}", c.len()),
                ))
            }
            _ => {}
        }
        match (&self.uv, &self.texture) {
            (Some(uv), Some(_)) => {
                if uv.len() != n_vertices {
                    return Err(Error::invalid(
                        "uv",
                        format!("expected one (u, v) per vertex ({n_vertices}), got {}", uv.len()),
                    ));
                }
                if let Some(i) = uv.iter().position(|p| !p.iter().all(|x| x.is_finite())) {
                    return Err(Error::invalid("uv", format!("row {i} is not finite: {:?}", uv[i])));
                }
            }
            (Some(_), None) => {
                return Err(Error::invalid("uv, texture", "uv given without a texture to look up"))
            }
            (None, Some(_)) => return Err(Error::invalid("uv, texture", "a texture needs uv coordinates")),
            (None, None) => {}
        }
        self.sampling.check()
    }
}

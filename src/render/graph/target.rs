//! The textures a frame may use, named by what they hold. A pass declares which it writes and
//! reads (`Use`); the frame's resources are allocated from those declarations, with the usage
//! flags every declaring pass needs and nothing else.

use super::glass_layer as glass;
use crate::render::device::COLOR_FORMAT;

/// The depth buffer used for visibility.
pub const DEPTH_FORMAT: wgpu::TextureFormat = wgpu::TextureFormat::Depth32Float;
/// Ink coverage of the outlines.
pub const OUTLINE_FORMAT: wgpu::TextureFormat = wgpu::TextureFormat::R8Unorm;
/// The light's visibility: f32 bits in an integer texel (GL cannot render to float formats).
pub const SHADOW_FORMAT: wgpu::TextureFormat = wgpu::TextureFormat::R32Uint;
/// Which boundaries of a pixel are image-space edges: bit 0 the one with its right neighbour,
/// bit 1 the one with the neighbour below.
pub const EDGE_BITS_FORMAT: wgpu::TextureFormat = wgpu::TextureFormat::R8Uint;

/// What the geometry target holds, as f32 bit patterns in 32-bit integer texels (GL cannot
/// render to 32-bit float formats; it can to integer ones, which keeps the values exact).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub enum GeometryLayout {
    /// View-space unit normal in xyz and linear depth in w: 16 bytes a pixel.
    NormalDepth,
    /// Linear depth only: 4 bytes a pixel.
    Depth,
}

impl GeometryLayout {
    pub fn format(self) -> wgpu::TextureFormat {
        match self {
            Self::NormalDepth => wgpu::TextureFormat::Rgba32Uint,
            Self::Depth => wgpu::TextureFormat::R32Uint,
        }
    }

    pub fn words_per_pixel(self) -> usize {
        match self {
            Self::NormalDepth => 4,
            Self::Depth => 1,
        }
    }

    /// The texel component that holds the linear depth.
    pub fn depth_component(self) -> usize {
        self.words_per_pixel() - 1
    }
}

#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub enum Target {
    /// Multisampled colour of the shading pass, resolved at its end.
    ColorMs,
    /// Single-sample colour at the supersampled size, averaged down by `downsample`.
    ColorHi,
    /// Colour at the output size: what ink is drawn over and what is read back.
    Color,
    /// Depth buffer of the shading pass (its size and samples).
    ShadeDepth,
    /// Depth buffer of a separate geometry pass.
    GeometryDepth,
    /// Normal and/or linear depth at the output size, one sample per pixel.
    Geometry,
    /// Ink coverage at the output size.
    Outline,
    /// Depth from the shadow-casting light (`Shape::shadow_size` square).
    ShadowMap,
    /// The light's visibility at the output size, as f32 bits (like the geometry target).
    Shadow,
    /// The image-space edges between pixels at the output size (`EDGE_BITS_FORMAT`).
    EdgeBits,
    /// One peeled layer of glass, premultiplied (`passes::glass`), at the output size.
    GlassLayer,
    /// The glass layers so far, added front to back, premultiplied.
    GlassSum,
    /// The depths of the layers peeled, as f32 bits: one peel writes one while the next reads
    /// the other.
    Peeled(u8),
}

/// Everything the frame's textures depend on.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub struct Shape {
    pub width: u32,
    pub height: u32,
    pub msaa: u32,
    pub supersample: u32,
    pub geometry: Option<GeometryLayout>,
    /// Side of the shadow map, when a light casts shadows.
    pub shadow_size: Option<u32>,
}

#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub struct TextureDesc {
    pub size: (u32, u32),
    pub samples: u32,
    pub format: wgpu::TextureFormat,
}

impl Target {
    pub fn desc(self, s: &Shape) -> TextureDesc {
        let out = (s.width, s.height);
        let hi = (s.width * s.supersample, s.height * s.supersample);
        let (size, samples, format) = match self {
            Target::ColorMs => (hi, s.msaa, COLOR_FORMAT),
            Target::ColorHi => (hi, 1, COLOR_FORMAT),
            Target::Color => (out, 1, COLOR_FORMAT),
            Target::ShadeDepth => (hi, s.msaa, DEPTH_FORMAT),
            Target::GeometryDepth => (out, 1, DEPTH_FORMAT),
            Target::Geometry => {
                (out, 1, s.geometry.expect("a frame with a geometry target has a layout").format())
            }
            Target::Outline => (out, 1, OUTLINE_FORMAT),
            Target::ShadowMap => {
                let side = s.shadow_size.expect("a frame with a shadow map has its size");
                ((side, side), 1, DEPTH_FORMAT)
            }
            Target::Shadow => (out, 1, SHADOW_FORMAT),
            Target::EdgeBits => (out, 1, EDGE_BITS_FORMAT),
            Target::GlassLayer | Target::GlassSum => (out, 1, glass::LAYER_FORMAT),
            Target::Peeled(_) => (out, 1, glass::PEELED_FORMAT),
        };
        TextureDesc { size, samples, format }
    }
}

/// How a pass uses a target.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Access {
    /// Rendered to (a colour, resolve or depth attachment).
    Attach,
    /// Read in a shader.
    Sample,
    /// Copied out to host memory.
    CopyFrom,
}

impl Access {
    pub fn usage(self) -> wgpu::TextureUsages {
        match self {
            Access::Attach => wgpu::TextureUsages::RENDER_ATTACHMENT,
            Access::Sample => wgpu::TextureUsages::TEXTURE_BINDING,
            Access::CopyFrom => wgpu::TextureUsages::COPY_SRC,
        }
    }
}

/// One target a pass uses, and how.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub struct Use(pub Target, pub Access);

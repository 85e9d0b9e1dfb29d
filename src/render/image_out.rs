//! PNG encoding of colour images.

use image::ImageEncoder;

use crate::error::{Error, Result};

/// Decodes a PNG file's bytes into (height, width, channels, pixels, rows top first): 8-bit grey
/// (1 channel), grey and alpha (2), RGB (3) or RGBA (4) as the file stores them; other kinds
/// (16-bit, palette with transparency, ...) as the `image` crate expands them, to 8 bits.
pub fn decode_png(data: &[u8]) -> Result<(u32, u32, usize, Vec<u8>)> {
    use image::DynamicImage;
    let decoded = image::load_from_memory_with_format(data, image::ImageFormat::Png)
        .map_err(|e| Error::invalid("data", format!("not a readable PNG file ({e})")))?;
    let (width, height) = (decoded.width(), decoded.height());
    let (channels, pixels) = match decoded {
        DynamicImage::ImageLuma8(b) => (1, b.into_raw()),
        DynamicImage::ImageLumaA8(b) => (2, b.into_raw()),
        DynamicImage::ImageRgb8(b) => (3, b.into_raw()),
        DynamicImage::ImageRgba8(b) => (4, b.into_raw()),
        DynamicImage::ImageLuma16(_) => (1, decoded.into_luma8().into_raw()),
        DynamicImage::ImageLumaA16(_) => (2, decoded.into_luma_alpha8().into_raw()),
        DynamicImage::ImageRgb16(_) => (3, decoded.into_rgb8().into_raw()),
        other => (4, other.into_rgba8().into_raw()),
    };
    Ok((height, width, channels, pixels))
}

/// Encodes tightly packed RGBA8 rows (top row first) as a PNG file's bytes.
pub fn encode_png(width: u32, height: u32, rgba: &[u8]) -> Result<Vec<u8>> {
    if width == 0 || height == 0 || rgba.len() as u64 != width as u64 * height as u64 * 4 {
        return Err(Error::invalid(
            "image",
            format!("expected {width} x {height} RGBA pixels, got {} bytes", rgba.len()),
        ));
    }
    let mut out = Vec::new();
    image::codecs::png::PngEncoder::new(&mut out)
        .write_image(rgba, width, height, image::ExtendedColorType::Rgba8)
        .map_err(|e| Error::Internal(format!("PNG encoding failed: {e}")))?;
    Ok(out)
}

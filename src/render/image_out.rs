//! PNG encoding of colour images.

use image::ImageEncoder;

use crate::error::{Error, Result};

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

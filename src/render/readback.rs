//! Copying a texture to host memory. Rows of a texture-to-buffer copy must start on
//! 256-byte boundaries, so the buffer is padded and the padding is dropped while copying out.

use crate::error::{Error, Result};

pub fn padded_bytes_per_row(unpadded: u32) -> u32 {
    unpadded.div_ceil(wgpu::COPY_BYTES_PER_ROW_ALIGNMENT) * wgpu::COPY_BYTES_PER_ROW_ALIGNMENT
}

pub struct ReadbackBuffer {
    buffer: wgpu::Buffer,
    width: u32,
    height: u32,
    bytes_per_pixel: u32,
    padded_row: u32,
}

impl ReadbackBuffer {
    pub fn new(device: &wgpu::Device, label: &str, size: (u32, u32), bytes_per_pixel: u32) -> Self {
        let padded_row = padded_bytes_per_row(size.0 * bytes_per_pixel);
        let buffer = device.create_buffer(&wgpu::BufferDescriptor {
            label: Some(label),
            size: padded_row as u64 * size.1 as u64,
            usage: wgpu::BufferUsages::MAP_READ | wgpu::BufferUsages::COPY_DST,
            mapped_at_creation: false,
        });
        ReadbackBuffer { buffer, width: size.0, height: size.1, bytes_per_pixel, padded_row }
    }

    pub fn encode_copy(&self, encoder: &mut wgpu::CommandEncoder, texture: &wgpu::Texture) {
        encoder.copy_texture_to_buffer(
            wgpu::TexelCopyTextureInfo {
                texture,
                mip_level: 0,
                origin: wgpu::Origin3d::ZERO,
                aspect: wgpu::TextureAspect::All,
            },
            wgpu::TexelCopyBufferInfo {
                buffer: &self.buffer,
                layout: wgpu::TexelCopyBufferLayout {
                    offset: 0,
                    bytes_per_row: Some(self.padded_row),
                    rows_per_image: Some(self.height),
                },
            },
            wgpu::Extent3d { width: self.width, height: self.height, depth_or_array_layers: 1 },
        );
    }

    /// Waits for `submission` and returns the rows, top row first, without padding.
    pub fn read(&self, device: &wgpu::Device, submission: wgpu::SubmissionIndex) -> Result<Vec<u8>> {
        let (tx, rx) = std::sync::mpsc::channel();
        self.buffer.map_async(wgpu::MapMode::Read, .., move |r| {
            let _ = tx.send(r);
        });
        device
            .poll(wgpu::PollType::Wait { submission_index: Some(submission), timeout: None })
            .map_err(|e| Error::Gpu(format!("waiting for the GPU: {e}")))?;
        rx.recv()
            .map_err(|_| Error::Gpu("the readback was dropped".into()))?
            .map_err(|e| Error::Gpu(format!("reading back an image: {e}")))?;
        let row = (self.width * self.bytes_per_pixel) as usize;
        let mut out = Vec::with_capacity(row * self.height as usize);
        {
            let mapped = self
                .buffer
                .get_mapped_range(..)
                .map_err(|e| Error::Gpu(format!("reading back an image: {e}")))?;
            for y in 0..self.height as usize {
                let start = y * self.padded_row as usize;
                out.extend_from_slice(&mapped[start..start + row]);
            }
        }
        self.buffer.unmap();
        Ok(out)
    }
}

/// f32 values stored as their bit patterns in 4-byte texels: every `stride`-th of `keep` words.
pub fn words_to_f32(bytes: &[u8], words_per_pixel: usize, keep: usize) -> Vec<f32> {
    let n = bytes.len() / 4 / words_per_pixel;
    let mut out = Vec::with_capacity(n * keep);
    for px in bytes.chunks_exact(4 * words_per_pixel) {
        for k in 0..keep {
            out.push(f32::from_le_bytes([px[4 * k], px[4 * k + 1], px[4 * k + 2], px[4 * k + 3]]));
        }
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn rows_are_padded_to_256_bytes() {
        assert_eq!(padded_bytes_per_row(4), 256);
        assert_eq!(padded_bytes_per_row(256), 256);
        assert_eq!(padded_bytes_per_row(301 * 4), 1280);
    }

    #[test]
    fn words_unpack_in_order() {
        let mut b = Vec::new();
        for v in [1.0f32, 2.0, 3.0, 0.0, 4.0, 5.0, 6.0, 0.0] {
            b.extend_from_slice(&v.to_le_bytes());
        }
        assert_eq!(words_to_f32(&b, 4, 3), vec![1.0, 2.0, 3.0, 4.0, 5.0, 6.0]);
    }
}

//! Readbacks: copies of targets into the frame's one staging buffer (rows padded to 256 bytes),
//! and, once the frame is done and the buffer mapped, the copy of each region straight into the
//! caller's arrays, row bands in parallel, dropping the padding and converting as it goes.

use rayon::prelude::*;

use crate::error::Result;
use crate::render::graph::target::{Access, Target, Use};
use crate::render::graph::{FrameCtx, Pass, Recorder};

pub fn padded_bytes_per_row(unpadded: u32) -> u32 {
    unpadded.div_ceil(wgpu::COPY_BYTES_PER_ROW_ALIGNMENT) * wgpu::COPY_BYTES_PER_ROW_ALIGNMENT
}

/// Where one target's copy lies in the staging buffer.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Region {
    pub offset: u64,
    pub width: u32,
    pub height: u32,
    pub bytes_per_pixel: u32,
    pub padded_row: u32,
}

impl Region {
    /// A region for a `width` x `height` copy at the first 256-byte boundary at or after `start`.
    pub fn at(start: u64, width: u32, height: u32, bytes_per_pixel: u32) -> Region {
        let align = wgpu::COPY_BYTES_PER_ROW_ALIGNMENT as u64;
        Region {
            offset: start.div_ceil(align) * align,
            width,
            height,
            bytes_per_pixel,
            padded_row: padded_bytes_per_row(width * bytes_per_pixel),
        }
    }

    pub fn end(&self) -> u64 {
        self.offset + self.padded_row as u64 * self.height as u64
    }

    /// The rows of this region in the mapped buffer, padding included.
    fn rows<'a>(&self, mapped: &'a [u8]) -> impl IndexedParallelIterator<Item = &'a [u8]> {
        let start = self.offset as usize;
        let row = self.padded_row as usize;
        let used = (self.width * self.bytes_per_pixel) as usize;
        mapped[start..start + row * self.height as usize].par_chunks(row).map(move |r| &r[..used])
    }

    /// Bytes as they are (colour).
    pub fn copy_bytes(&self, mapped: &[u8], out: &mut [u8]) {
        let used = (self.width * self.bytes_per_pixel) as usize;
        out.par_chunks_mut(used).zip(self.rows(mapped)).for_each(|(o, r)| o.copy_from_slice(r));
    }

    /// f32 words: of each pixel's `words` words, `keep` starting at `first`, times `scale`
    /// (a power of two: exact).
    pub fn copy_words(&self, mapped: &[u8], first: usize, keep: usize, scale: f32, out: &mut [f32]) {
        let words = (self.bytes_per_pixel / 4) as usize;
        let per_row = self.width as usize * keep;
        out.par_chunks_mut(per_row).zip(self.rows(mapped)).for_each(|(o, r)| {
            for (o, px) in o.chunks_exact_mut(keep).zip(r.chunks_exact(4 * words)) {
                for (k, v) in o.iter_mut().enumerate() {
                    let w = &px[4 * (first + k)..4 * (first + k) + 4];
                    *v = f32::from_le_bytes([w[0], w[1], w[2], w[3]]) * scale;
                }
            }
        });
    }

    /// Unsigned normalised bytes as f32 in [0, 1] (the outline coverage).
    pub fn copy_unorm8(&self, mapped: &[u8], out: &mut [f32]) {
        let used = (self.width * self.bytes_per_pixel) as usize;
        out.par_chunks_mut(used).zip(self.rows(mapped)).for_each(|(o, r)| {
            for (o, &b) in o.iter_mut().zip(r) {
                *o = b as f32 / 255.0;
            }
        });
    }
}

/// Copies one target into its region of the staging buffer.
#[derive(Debug, Clone, PartialEq)]
pub struct Readback {
    pub name: &'static str,
    pub target: Target,
    pub region: Region,
}

impl Pass for Readback {
    fn name(&self) -> &'static str {
        self.name
    }

    fn uses(&self) -> Vec<Use> {
        vec![Use(self.target, Access::CopyFrom)]
    }

    fn timed(&self) -> bool {
        false
    }

    fn encode(&self, f: &FrameCtx<'_>, rec: &mut Recorder<'_>) -> Result<()> {
        let r = self.region;
        rec.encoder.copy_texture_to_buffer(
            wgpu::TexelCopyTextureInfo {
                texture: f.res.texture(self.target),
                mip_level: 0,
                origin: wgpu::Origin3d::ZERO,
                aspect: wgpu::TextureAspect::All,
            },
            wgpu::TexelCopyBufferInfo {
                buffer: f.res.staging.as_ref().expect("a frame with readbacks has a staging buffer"),
                layout: wgpu::TexelCopyBufferLayout {
                    offset: r.offset,
                    bytes_per_row: Some(r.padded_row),
                    rows_per_image: Some(r.height),
                },
            },
            wgpu::Extent3d { width: r.width, height: r.height, depth_or_array_layers: 1 },
        );
        Ok(())
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn rows_are_padded_to_256_bytes_and_regions_aligned() {
        assert_eq!(padded_bytes_per_row(4), 256);
        assert_eq!(padded_bytes_per_row(256), 256);
        assert_eq!(padded_bytes_per_row(301 * 4), 1280);
        let r = Region::at(10, 3, 2, 16);
        assert_eq!((r.offset, r.padded_row, r.end()), (256, 256, 768));
    }

    #[test]
    fn words_unpack_in_order_and_scale() {
        let r = Region::at(0, 2, 1, 16);
        let mut mapped = vec![0u8; r.end() as usize];
        for (i, v) in [1.0f32, 2.0, 3.0, 9.0, 4.0, 5.0, 6.0, 8.0].iter().enumerate() {
            mapped[4 * i..4 * i + 4].copy_from_slice(&v.to_le_bytes());
        }
        let mut normal = vec![0.0; 6];
        r.copy_words(&mapped, 0, 3, 1.0, &mut normal);
        assert_eq!(normal, vec![1.0, 2.0, 3.0, 4.0, 5.0, 6.0]);
        let mut depth = vec![0.0; 2];
        r.copy_words(&mapped, 3, 1, 0.5, &mut depth);
        assert_eq!(depth, vec![4.5, 4.0]);
    }
}

//! The textures and readback buffers of one frame, pooled by size and configuration so that
//! steady-state rendering allocates nothing and concurrent renders never share a target.

use std::sync::Mutex;

use super::readback::ReadbackBuffer;
use super::scene::{FrameSpec, Outputs};

/// Colour is stored as sRGB: shading happens in linear light and the target encodes on store.
pub const COLOR_FORMAT: wgpu::TextureFormat = wgpu::TextureFormat::Rgba8UnormSrgb;
/// View-space normal as f32 bit patterns (GL cannot render to 32-bit float formats; it can to
/// 32-bit integer ones, which keeps the outputs exact).
pub const NORMAL_FORMAT: wgpu::TextureFormat = wgpu::TextureFormat::Rgba32Uint;
/// Linear depth as an f32 bit pattern.
pub const LINEAR_DEPTH_FORMAT: wgpu::TextureFormat = wgpu::TextureFormat::R32Uint;
/// The depth buffer used for visibility.
pub const DEPTH_FORMAT: wgpu::TextureFormat = wgpu::TextureFormat::Depth32Float;

#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub struct TargetKey {
    pub width: u32,
    pub height: u32,
    pub msaa: u32,
    pub supersample: u32,
    pub outputs: Outputs,
}

impl TargetKey {
    pub fn of(frame: &FrameSpec) -> Self {
        TargetKey {
            width: frame.width,
            height: frame.height,
            msaa: frame.msaa,
            supersample: frame.supersample,
            outputs: frame.outputs,
        }
    }

    /// Whether the shading pass itself writes normal and depth (same size, one sample).
    pub fn gbuffer_in_shade(&self) -> bool {
        self.outputs.color && self.msaa == 1 && self.supersample == 1
    }
}

pub struct FrameTargets {
    pub key: TargetKey,
    /// Multisampled colour and depth of the shading pass (MSAA only).
    pub color_ms: Option<wgpu::TextureView>,
    /// Colour at the supersampled size (supersampling only): the downsample pass reads it.
    pub color_hi: Option<wgpu::TextureView>,
    /// Colour at the output size: what is read back.
    pub color: Option<wgpu::Texture>,
    /// Depth buffer of the shading pass.
    pub shade_depth: Option<wgpu::TextureView>,
    /// Depth buffer of a separate geometry pass.
    pub gbuffer_depth: Option<wgpu::TextureView>,
    pub normal: Option<wgpu::Texture>,
    pub linear_depth: Option<wgpu::Texture>,
    pub color_readback: Option<ReadbackBuffer>,
    pub normal_readback: Option<ReadbackBuffer>,
    pub depth_readback: Option<ReadbackBuffer>,
}

fn texture(
    device: &wgpu::Device,
    label: &str,
    size: (u32, u32),
    samples: u32,
    format: wgpu::TextureFormat,
    usage: wgpu::TextureUsages,
) -> wgpu::Texture {
    device.create_texture(&wgpu::TextureDescriptor {
        label: Some(label),
        size: wgpu::Extent3d { width: size.0, height: size.1, depth_or_array_layers: 1 },
        mip_level_count: 1,
        sample_count: samples,
        dimension: wgpu::TextureDimension::D2,
        format,
        usage,
        view_formats: &[],
    })
}

fn view(t: wgpu::Texture) -> wgpu::TextureView {
    t.create_view(&Default::default())
}

impl FrameTargets {
    pub fn new(device: &wgpu::Device, key: TargetKey) -> Self {
        use wgpu::TextureUsages as U;
        let out = (key.width, key.height);
        let hi = (key.width * key.supersample, key.height * key.supersample);
        let o = key.outputs;
        let ms = key.msaa > 1;
        let ss = key.supersample > 1;
        let color_ms = (o.color && ms)
            .then(|| view(texture(device, "colour msaa", hi, key.msaa, COLOR_FORMAT, U::RENDER_ATTACHMENT)));
        let color_hi = (o.color && ss).then(|| {
            view(texture(
                device,
                "colour supersampled",
                hi,
                1,
                COLOR_FORMAT,
                U::RENDER_ATTACHMENT | U::TEXTURE_BINDING,
            ))
        });
        let color = o
            .color
            .then(|| texture(device, "colour", out, 1, COLOR_FORMAT, U::RENDER_ATTACHMENT | U::COPY_SRC));
        let shade_depth = o
            .color
            .then(|| view(texture(device, "depth buffer", hi, key.msaa, DEPTH_FORMAT, U::RENDER_ATTACHMENT)));
        let gbuffer = o.normal || o.depth;
        let gbuffer_depth = (gbuffer && !key.gbuffer_in_shade()).then(|| {
            view(texture(device, "gbuffer depth buffer", out, 1, DEPTH_FORMAT, U::RENDER_ATTACHMENT))
        });
        let normal = o
            .normal
            .then(|| texture(device, "normal", out, 1, NORMAL_FORMAT, U::RENDER_ATTACHMENT | U::COPY_SRC));
        let linear_depth = o.depth.then(|| {
            texture(device, "linear depth", out, 1, LINEAR_DEPTH_FORMAT, U::RENDER_ATTACHMENT | U::COPY_SRC)
        });
        FrameTargets {
            key,
            color_ms,
            color_hi,
            color,
            shade_depth,
            gbuffer_depth,
            normal,
            linear_depth,
            color_readback: o.color.then(|| ReadbackBuffer::new(device, "colour readback", out, 4)),
            normal_readback: o.normal.then(|| ReadbackBuffer::new(device, "normal readback", out, 16)),
            depth_readback: o.depth.then(|| ReadbackBuffer::new(device, "depth readback", out, 4)),
        }
    }
}

/// Idle frame targets, most recently used last.
#[derive(Default)]
pub struct TargetPool {
    idle: Mutex<Vec<FrameTargets>>,
}

/// How many idle target sets are kept (enough for a few threads rendering at once).
const POOL_SIZE: usize = 6;

impl TargetPool {
    pub fn take(&self, device: &wgpu::Device, key: TargetKey) -> FrameTargets {
        let mut idle = self.idle.lock().unwrap_or_else(|e| e.into_inner());
        match idle.iter().rposition(|t| t.key == key) {
            Some(i) => idle.remove(i),
            None => {
                drop(idle);
                FrameTargets::new(device, key)
            }
        }
    }

    pub fn give_back(&self, targets: FrameTargets) {
        let mut idle = self.idle.lock().unwrap_or_else(|e| e.into_inner());
        idle.push(targets);
        if idle.len() > POOL_SIZE {
            idle.remove(0);
        }
    }

    pub fn clear(&self) {
        self.idle.lock().unwrap_or_else(|e| e.into_inner()).clear();
    }
}

//! A frame's resources: the textures its plan declares (with the usage flags of every pass that
//! declares them), one host-mappable staging buffer for all its readbacks, the timestamp queries,
//! and the uniform and line buffers that grow to the largest scene seen. Sets are pooled by
//! their key, so a steady stream of renders allocates nothing, and a set serves one frame at a
//! time, so concurrent renders never share one.

use std::collections::{BTreeMap, HashMap};
use std::sync::Mutex;

use crate::render::device::Device;
use crate::render::pipelines::Layouts;

use super::build::texture_group;
use super::target::{Target, TextureDesc};
use super::FrameCtx;

/// Everything a set of frame resources depends on.
#[derive(Clone, Debug, PartialEq, Eq, Hash)]
pub struct ResourceKey {
    /// The textures, each with the union of its passes' usages.
    pub textures: Vec<(Target, TextureDesc, wgpu::TextureUsages)>,
    /// Bytes of the staging buffer (readbacks and timestamps).
    pub staging_bytes: u64,
    /// Timestamp queries (two per timed pass), 0 without timestamps.
    pub queries: u32,
    /// Bytes of the frame's uniform struct and of one draw's.
    pub uniform_bytes: (u64, u64),
}

/// The frame's uniform buffers: the frame's struct, and one draw's struct per mesh at aligned
/// offsets (bound with a dynamic offset).
pub struct Uniforms {
    pub frame: wgpu::Buffer,
    pub frame_group: wgpu::BindGroup,
    pub draws: wgpu::Buffer,
    pub draw_group: wgpu::BindGroup,
    pub draw_capacity: usize,
    pub draw_stride: u64,
}

pub struct FrameResources {
    pub key: ResourceKey,
    textures: BTreeMap<Target, (wgpu::Texture, wgpu::TextureView)>,
    pub staging: Option<wgpu::Buffer>,
    pub queries: Option<(wgpu::QuerySet, wgpu::Buffer)>,
    pub uniforms: Uniforms,
    /// Vertex buffers the passes fill each frame (line instances), by name, with their sizes.
    vertex_buffers: Mutex<HashMap<&'static str, (wgpu::Buffer, u64)>>,
    /// Bind groups over this set's textures, made once by the pass that names them.
    bind_groups: Mutex<HashMap<&'static str, wgpu::BindGroup>>,
}

fn uniforms(dev: &Device, layouts: &Layouts, sizes: (u64, u64), draw_capacity: usize) -> Uniforms {
    let device = &dev.device;
    let (frame_bytes, draw_bytes) = sizes;
    let align = dev.limits.min_uniform_buffer_offset_alignment.max(16) as u64;
    let draw_stride = draw_bytes.div_ceil(align) * align;
    let buffer = |label: &str, size: u64| {
        device.create_buffer(&wgpu::BufferDescriptor {
            label: Some(label),
            size,
            usage: wgpu::BufferUsages::UNIFORM | wgpu::BufferUsages::COPY_DST,
            mapped_at_creation: false,
        })
    };
    let frame = buffer("frame uniforms", frame_bytes);
    let draws = buffer("draw uniforms", draw_stride * draw_capacity.max(1) as u64);
    let group = |label: &str, layout: &wgpu::BindGroupLayout, buffer: &wgpu::Buffer, size: Option<u64>| {
        device.create_bind_group(&wgpu::BindGroupDescriptor {
            label: Some(label),
            layout,
            entries: &[wgpu::BindGroupEntry {
                binding: 0,
                resource: wgpu::BindingResource::Buffer(wgpu::BufferBinding {
                    buffer,
                    offset: 0,
                    size: size.and_then(wgpu::BufferSize::new),
                }),
            }],
        })
    };
    Uniforms {
        frame_group: group("frame uniforms", &layouts.frame, &frame, None),
        draw_group: group("draw uniforms", &layouts.draw, &draws, Some(draw_bytes)),
        frame,
        draws,
        draw_capacity: draw_capacity.max(1),
        draw_stride,
    }
}

impl FrameResources {
    pub fn new(dev: &Device, layouts: &Layouts, key: ResourceKey) -> Self {
        let device = &dev.device;
        let textures = key
            .textures
            .iter()
            .map(|&(target, desc, usage)| {
                let texture = device.create_texture(&wgpu::TextureDescriptor {
                    label: Some(&format!("{target:?}")),
                    size: wgpu::Extent3d {
                        width: desc.size.0,
                        height: desc.size.1,
                        depth_or_array_layers: 1,
                    },
                    mip_level_count: 1,
                    sample_count: desc.samples,
                    dimension: wgpu::TextureDimension::D2,
                    format: desc.format,
                    usage,
                    view_formats: &[],
                });
                let view = texture.create_view(&Default::default());
                (target, (texture, view))
            })
            .collect();
        let staging = (key.staging_bytes > 0).then(|| {
            device.create_buffer(&wgpu::BufferDescriptor {
                label: Some("readback"),
                size: key.staging_bytes,
                usage: wgpu::BufferUsages::MAP_READ | wgpu::BufferUsages::COPY_DST,
                mapped_at_creation: false,
            })
        });
        let queries = (key.queries > 0).then(|| {
            let set = device.create_query_set(&wgpu::QuerySetDescriptor {
                label: Some("pass timestamps"),
                ty: wgpu::QueryType::Timestamp,
                count: key.queries,
            });
            let resolve = device.create_buffer(&wgpu::BufferDescriptor {
                label: Some("timestamps"),
                size: key.queries as u64 * 8,
                usage: wgpu::BufferUsages::QUERY_RESOLVE | wgpu::BufferUsages::COPY_SRC,
                mapped_at_creation: false,
            });
            (set, resolve)
        });
        FrameResources {
            key: key.clone(),
            textures,
            staging,
            queries,
            uniforms: uniforms(dev, layouts, key.uniform_bytes, 1),
            vertex_buffers: Mutex::new(HashMap::new()),
            bind_groups: Mutex::new(HashMap::new()),
        }
    }

    pub fn texture(&self, t: Target) -> &wgpu::Texture {
        &self.textures.get(&t).expect("the plan declared every target its passes use").0
    }

    pub fn view(&self, t: Target) -> &wgpu::TextureView {
        &self.textures.get(&t).expect("the plan declared every target its passes use").1
    }

    pub fn has(&self, t: Target) -> bool {
        self.textures.contains_key(&t)
    }

    /// The bind group `name`, made by `make` the first time this set needs it.
    pub fn bind_group(&self, name: &'static str, make: impl FnOnce() -> wgpu::BindGroup) -> wgpu::BindGroup {
        self.bind_groups.lock().unwrap_or_else(|e| e.into_inner()).entry(name).or_insert_with(make).clone()
    }

    /// The geometry target's bind group (`uint_texture` layout), for the passes that read it.
    pub fn geometry_group(&self, f: &FrameCtx<'_>) -> wgpu::BindGroup {
        self.bind_group("geometry", || {
            texture_group(&f.dev.device, &f.pipelines.layouts.uint_texture, self.view(Target::Geometry))
        })
    }

    /// The edge-bits target's bind group (`uint_texture` layout), for the pass that inks them.
    pub fn edge_bits_group(&self, f: &FrameCtx<'_>) -> wgpu::BindGroup {
        self.bind_group("edge_bits", || {
            texture_group(&f.dev.device, &f.pipelines.layouts.uint_texture, self.view(Target::EdgeBits))
        })
    }

    /// Makes room for `n` draws.
    pub fn reserve_draws(&mut self, dev: &Device, layouts: &Layouts, n: usize) {
        if n > self.uniforms.draw_capacity {
            self.uniforms = uniforms(dev, layouts, self.key.uniform_bytes, n.next_power_of_two());
        }
    }

    /// The dynamic offset of draw `i`'s uniforms.
    pub fn draw_offset(&self, i: usize) -> u32 {
        (i as u64 * self.uniforms.draw_stride) as u32
    }

    /// Uploads the frame's uniforms and each draw's (draw `i` at `draw_offset(i)`).
    pub fn write_uniforms(&self, dev: &Device, frame: &[u8], draws: &[Vec<u8>]) {
        dev.queue.write_buffer(&self.uniforms.frame, 0, frame);
        if draws.is_empty() {
            return;
        }
        let stride = self.uniforms.draw_stride as usize;
        let mut bytes = vec![0u8; stride * draws.len()];
        for (chunk, d) in bytes.chunks_mut(stride).zip(draws) {
            chunk[..d.len()].copy_from_slice(d);
        }
        dev.queue.write_buffer(&self.uniforms.draws, 0, &bytes);
    }

    /// The vertex buffer `name` holding `bytes` (grown when needed); None when `bytes` is empty.
    pub fn vertices(&self, dev: &Device, name: &'static str, bytes: &[u8]) -> Option<wgpu::Buffer> {
        if bytes.is_empty() {
            return None;
        }
        let mut buffers = self.vertex_buffers.lock().unwrap_or_else(|e| e.into_inner());
        let need = bytes.len() as u64;
        if buffers.get(name).is_none_or(|(_, cap)| *cap < need) {
            let cap = need.next_power_of_two();
            let buffer = dev.device.create_buffer(&wgpu::BufferDescriptor {
                label: Some(name),
                size: cap,
                usage: wgpu::BufferUsages::VERTEX | wgpu::BufferUsages::COPY_DST,
                mapped_at_creation: false,
            });
            buffers.insert(name, (buffer, cap));
        }
        let (buffer, _) = &buffers[name];
        dev.queue.write_buffer(buffer, 0, bytes);
        Some(buffer.clone())
    }
}

/// Idle frame resources, most recently used last.
#[derive(Default)]
pub struct FramePool {
    idle: Mutex<Vec<FrameResources>>,
}

/// How many idle sets are kept (enough for a few threads, or frames in flight, at once).
const POOL_SIZE: usize = 6;

impl FramePool {
    pub fn take(&self, dev: &Device, layouts: &Layouts, key: &ResourceKey) -> FrameResources {
        let mut idle = self.idle.lock().unwrap_or_else(|e| e.into_inner());
        match idle.iter().rposition(|r| &r.key == key) {
            Some(i) => idle.remove(i),
            None => {
                drop(idle);
                FrameResources::new(dev, layouts, key.clone())
            }
        }
    }

    pub fn give_back(&self, res: FrameResources) {
        let mut idle = self.idle.lock().unwrap_or_else(|e| e.into_inner());
        idle.push(res);
        if idle.len() > POOL_SIZE {
            idle.remove(0);
        }
    }
}

//! Shader modules and render pipelines, built on first use and cached per device by the pass
//! that asks for them (its name and the variant it needs), so a scene compiles only what it uses.
//! The bind group layouts that several passes share live here too.

use std::collections::HashMap;
use std::sync::{Arc, Mutex};

use wgpu::TextureSampleType;

use crate::render::effects::shadows::settings::ShadowFilter;

const FRAGMENT: wgpu::ShaderStages = wgpu::ShaderStages::FRAGMENT;
const VERTEX_FRAGMENT: wgpu::ShaderStages = wgpu::ShaderStages::VERTEX_FRAGMENT;

/// A pipeline's name in the cache: the pass that builds it, the bits of its variant, and the
/// pipeline constants that vary with the material.
#[derive(Clone, Debug, PartialEq, Eq, Hash)]
pub struct PipelineKey {
    pub pass: &'static str,
    pub bits: u64,
    pub constants: Vec<(&'static str, u64)>,
}

impl PipelineKey {
    pub fn new(pass: &'static str, bits: u64) -> Self {
        PipelineKey { pass, bits, constants: Vec::new() }
    }

    /// This key with pipeline constants (their values' bits) in it.
    pub fn with(mut self, constants: &[(&'static str, f64)]) -> Self {
        self.constants = constants.iter().map(|&(n, v)| (n, v.to_bits())).collect();
        self
    }
}

/// Bind group layouts shared by passes.
pub struct Layouts {
    /// Group 0 of every pass: the frame's uniforms (`Frame` in common.wgsl).
    pub frame: wgpu::BindGroupLayout,
    /// Group 1 of mesh and line passes: one mesh's uniforms (`Draw`), at a dynamic offset.
    pub draw: wgpu::BindGroupLayout,
    /// One unsigned-integer texture (the geometry target), read with textureLoad.
    pub uint_texture: wgpu::BindGroupLayout,
    /// One float texture, read with textureLoad.
    pub float_texture: wgpu::BindGroupLayout,
    /// The shadow map (a depth texture) and its comparison sampler.
    pub shadow: wgpu::BindGroupLayout,
}

/// A bind group layout of `entries` (binding 0, 1, ...), each seen by `visibility`.
fn layout(
    device: &wgpu::Device,
    label: &str,
    visibility: wgpu::ShaderStages,
    entries: &[wgpu::BindingType],
) -> wgpu::BindGroupLayout {
    let entries: Vec<wgpu::BindGroupLayoutEntry> = entries
        .iter()
        .enumerate()
        .map(|(i, &ty)| wgpu::BindGroupLayoutEntry { binding: i as u32, visibility, ty, count: None })
        .collect();
    device
        .create_bind_group_layout(&wgpu::BindGroupLayoutDescriptor { label: Some(label), entries: &entries })
}

fn texture(sample_type: wgpu::TextureSampleType) -> wgpu::BindingType {
    wgpu::BindingType::Texture {
        sample_type,
        view_dimension: wgpu::TextureViewDimension::D2,
        multisampled: false,
    }
}

fn uniform(dynamic: bool) -> wgpu::BindingType {
    wgpu::BindingType::Buffer {
        ty: wgpu::BufferBindingType::Uniform,
        has_dynamic_offset: dynamic,
        min_binding_size: None,
    }
}

/// The comparison sampler of a shadow filter: one nearest test, or bilinear comparisons (PCF).
fn shadow_sampler(device: &wgpu::Device, filter: ShadowFilter) -> wgpu::Sampler {
    let mode = match filter {
        ShadowFilter::Nearest => wgpu::FilterMode::Nearest,
        ShadowFilter::Pcf => wgpu::FilterMode::Linear,
    };
    device.create_sampler(&wgpu::SamplerDescriptor {
        label: Some("shadow map"),
        address_mode_u: wgpu::AddressMode::ClampToEdge,
        address_mode_v: wgpu::AddressMode::ClampToEdge,
        mag_filter: mode,
        min_filter: mode,
        // lit where the receiver's depth is at most the map's
        compare: Some(wgpu::CompareFunction::LessEqual),
        ..Default::default()
    })
}

pub struct PipelineCache {
    pub layouts: Layouts,
    /// The shadow samplers, by filter (`ShadowFilter::Nearest`, then `Pcf`).
    pub shadow_samplers: [wgpu::Sampler; 2],
    modules: Mutex<HashMap<String, wgpu::ShaderModule>>,
    pipelines: Mutex<HashMap<PipelineKey, Arc<wgpu::RenderPipeline>>>,
}

impl PipelineCache {
    pub fn new(device: &wgpu::Device) -> Self {
        PipelineCache {
            layouts: Layouts {
                frame: layout(device, "frame uniforms", VERTEX_FRAGMENT, &[uniform(false)]),
                draw: layout(device, "draw uniforms", VERTEX_FRAGMENT, &[uniform(true)]),
                uint_texture: layout(device, "uint texture", FRAGMENT, &[texture(TextureSampleType::Uint)]),
                float_texture: layout(
                    device,
                    "float texture",
                    FRAGMENT,
                    &[texture(TextureSampleType::Float { filterable: false })],
                ),
                // the vertex stage reads it too: Gouraud shading shades the vertices
                shadow: layout(
                    device,
                    "shadow map",
                    VERTEX_FRAGMENT,
                    &[
                        texture(TextureSampleType::Depth),
                        wgpu::BindingType::Sampler(wgpu::SamplerBindingType::Comparison),
                    ],
                ),
            },
            shadow_samplers: [
                shadow_sampler(device, ShadowFilter::Nearest),
                shadow_sampler(device, ShadowFilter::Pcf),
            ],
            modules: Mutex::new(HashMap::new()),
            pipelines: Mutex::new(HashMap::new()),
        }
    }

    /// The shader module called `name`, compiled from `source()` on first use.
    pub fn module(
        &self,
        device: &wgpu::Device,
        name: String,
        source: impl FnOnce() -> String,
    ) -> wgpu::ShaderModule {
        let mut modules = self.modules.lock().unwrap_or_else(|e| e.into_inner());
        modules
            .entry(name)
            .or_insert_with_key(|name| {
                device.create_shader_module(wgpu::ShaderModuleDescriptor {
                    label: Some(name),
                    source: wgpu::ShaderSource::Wgsl(source().into()),
                })
            })
            .clone()
    }

    /// The pipeline `key`, built by `build` on first use.
    pub fn get(
        &self,
        key: PipelineKey,
        build: impl FnOnce() -> wgpu::RenderPipeline,
    ) -> Arc<wgpu::RenderPipeline> {
        if let Some(p) = self.pipelines.lock().unwrap_or_else(|e| e.into_inner()).get(&key) {
            return p.clone();
        }
        // built outside the lock: compiling can take a while, and concurrent builds of the same
        // key are harmless (the first one stored wins)
        let p = Arc::new(build());
        self.pipelines.lock().unwrap_or_else(|e| e.into_inner()).entry(key).or_insert(p).clone()
    }

    pub fn layout(
        &self,
        device: &wgpu::Device,
        label: &str,
        groups: &[&wgpu::BindGroupLayout],
    ) -> wgpu::PipelineLayout {
        let groups: Vec<Option<&wgpu::BindGroupLayout>> = groups.iter().map(|g| Some(*g)).collect();
        self.layout_with_gaps(device, label, &groups)
    }

    /// `layout`, with groups the pipeline does not use left out (None).
    pub fn layout_with_gaps(
        &self,
        device: &wgpu::Device,
        label: &str,
        groups: &[Option<&wgpu::BindGroupLayout>],
    ) -> wgpu::PipelineLayout {
        device.create_pipeline_layout(&wgpu::PipelineLayoutDescriptor {
            label: Some(label),
            bind_group_layouts: groups,
            immediate_size: 0,
        })
    }
}

/// A colour target without blending.
pub fn target(format: wgpu::TextureFormat) -> Option<wgpu::ColorTargetState> {
    Some(wgpu::ColorTargetState { format, blend: None, write_mask: wgpu::ColorWrites::ALL })
}

/// A blend component that keeps the target's value (a full-screen pass over the colour keeps
/// its alpha).
pub const KEEP: wgpu::BlendComponent = wgpu::BlendComponent {
    src_factor: wgpu::BlendFactor::Zero,
    dst_factor: wgpu::BlendFactor::One,
    operation: wgpu::BlendOperation::Add,
};

/// A colour target with a blend state.
pub fn blended(format: wgpu::TextureFormat, blend: wgpu::BlendState) -> Option<wgpu::ColorTargetState> {
    Some(wgpu::ColorTargetState { format, blend: Some(blend), write_mask: wgpu::ColorWrites::ALL })
}

//! A mesh's colour on the device (`render::albedo`): a second vertex buffer (colour and
//! texture coordinates, apart from the positions and normals every pass reads, so that meshes
//! without colour upload and read nothing more) and a bind group with its texture, all its mip
//! levels made on the host, and its sampler.

use wgpu::util::DeviceExt;

use super::albedo::{Albedo, Colors, Filter, Sampling, Texture, Wrap};
use super::device::Device;

/// Where the shader reads the albedo attributes (`AlbedoIn` in shaders/albedo.wgsl): past the
/// locations the geometry's own attributes may take.
pub const COLOR_LOCATION: u32 = 8;
pub const UV_LOCATION: u32 = 9;
/// The vertex buffer slot of the albedo attributes.
pub const SLOT: u32 = 1;

#[repr(C)]
#[derive(Clone, Copy, bytemuck::Pod, bytemuck::Zeroable)]
pub struct AlbedoVertex {
    /// Linear RGBA.
    pub color: [f32; 4],
    pub uv: [f32; 2],
}

pub fn vertex_layout() -> wgpu::VertexBufferLayout<'static> {
    const ATTRS: [wgpu::VertexAttribute; 2] =
        wgpu::vertex_attr_array![COLOR_LOCATION => Float32x4, UV_LOCATION => Float32x2];
    wgpu::VertexBufferLayout {
        array_stride: std::mem::size_of::<AlbedoVertex>() as u64,
        step_mode: wgpu::VertexStepMode::Vertex,
        attributes: &ATTRS,
    }
}

/// The texture and sampler group (identical layouts are one layout to wgpu, so the pipelines
/// and the meshes may each make theirs).
pub fn bind_group_layout(device: &wgpu::Device) -> wgpu::BindGroupLayout {
    let entry = |binding, ty| wgpu::BindGroupLayoutEntry {
        binding,
        visibility: wgpu::ShaderStages::FRAGMENT,
        ty,
        count: None,
    };
    device.create_bind_group_layout(&wgpu::BindGroupLayoutDescriptor {
        label: Some("albedo texture"),
        entries: &[
            entry(
                0,
                wgpu::BindingType::Texture {
                    sample_type: wgpu::TextureSampleType::Float { filterable: true },
                    view_dimension: wgpu::TextureViewDimension::D2,
                    multisampled: false,
                },
            ),
            entry(1, wgpu::BindingType::Sampler(wgpu::SamplerBindingType::Filtering)),
        ],
    })
}

/// The sampler of glTF's filter and wrap settings.
pub fn sampler(device: &wgpu::Device, filter: Filter, wrap: Wrap) -> wgpu::Sampler {
    let address = match wrap {
        Wrap::Repeat => wgpu::AddressMode::Repeat,
        Wrap::Clamp => wgpu::AddressMode::ClampToEdge,
        Wrap::Mirror => wgpu::AddressMode::MirrorRepeat,
    };
    let (mode, mip, lod_max) = match filter {
        Filter::Linear => (wgpu::FilterMode::Linear, wgpu::MipmapFilterMode::Linear, 32.0),
        Filter::Nearest => (wgpu::FilterMode::Nearest, wgpu::MipmapFilterMode::Nearest, 0.0),
    };
    device.create_sampler(&wgpu::SamplerDescriptor {
        label: Some("albedo"),
        address_mode_u: address,
        address_mode_v: address,
        mag_filter: mode,
        min_filter: mode,
        mipmap_filter: mip,
        lod_max_clamp: lod_max,
        ..Default::default()
    })
}

/// Uploads `levels` (a mip chain, full size first) as one sRGB texture.
pub fn texture_view(dev: &Device, levels: &[Texture]) -> wgpu::TextureView {
    let full = &levels[0];
    let texture = dev.device.create_texture_with_data(
        &dev.queue,
        &wgpu::TextureDescriptor {
            label: Some("albedo"),
            size: wgpu::Extent3d { width: full.width, height: full.height, depth_or_array_layers: 1 },
            mip_level_count: levels.len() as u32,
            sample_count: 1,
            dimension: wgpu::TextureDimension::D2,
            // decoded to linear light before filtering, as the CPU reference does
            format: wgpu::TextureFormat::Rgba8UnormSrgb,
            usage: wgpu::TextureUsages::TEXTURE_BINDING,
            view_formats: &[],
        },
        wgpu::util::TextureDataOrder::MipMajor,
        &levels
            .iter()
            .flat_map(|l| bytemuck::cast_slice::<[u8; 4], u8>(&l.texels).iter().copied())
            .collect::<Vec<u8>>(),
    );
    texture.create_view(&Default::default())
}

pub struct GpuAlbedo {
    pub vertices: wgpu::Buffer,
    pub group: wgpu::BindGroup,
    /// Whether the shader samples the texture (a mesh with colours only binds a white texel).
    pub textured: bool,
    pub alpha_cutoff: Option<f32>,
    /// Its alpha multiplies the material's opacity: the mesh is glass (`passes::glass`).
    pub alpha_blend: bool,
    /// The colour and texture's fingerprint (`Albedo::look`): meshes that meet edge to edge
    /// with the same look and material are one surface to the lines.
    pub look: u64,
    /// The texture's full-size level and its sampling, for a draft drawn elsewhere
    /// (`render::draft`).
    pub texture: Option<(std::sync::Arc<Texture>, Sampling)>,
}

impl GpuAlbedo {
    /// The pipeline constants of `shaders/albedo.wgsl` for this mesh.
    pub fn constants(&self) -> Vec<(&'static str, f64)> {
        vec![
            ("TEXTURED", self.textured as u32 as f64),
            ("ALPHA_CUTOFF", self.alpha_cutoff.map_or(-1.0, f64::from)),
            ("ALPHA_BLEND", self.alpha_blend as u32 as f64),
        ]
    }

    /// Uploads `albedo` for a mesh whose uploaded vertex i is input vertex `source(i)` and, when
    /// drawn as a list, corner i of face i / 3. `albedo.texture` is already fitted to the device.
    pub fn upload(dev: &Device, albedo: &Albedo, n: usize, source: impl Fn(usize) -> usize) -> GpuAlbedo {
        let white = [1.0f32; 4];
        let vertices: Vec<AlbedoVertex> = (0..n)
            .map(|i| {
                let s = source(i);
                let color = match &albedo.colors {
                    Some(Colors::Vertex(c)) => c[s],
                    Some(Colors::Face(c)) => c[i / 3],
                    None => white,
                };
                // v up (trimesh, OBJ) to the texture's rows, top first
                let uv = albedo.uv.as_ref().map_or([0.0; 2], |uv| [uv[s][0], 1.0 - uv[s][1]]);
                AlbedoVertex { color, uv }
            })
            .collect();
        let buffer = dev.device.create_buffer_init(&wgpu::util::BufferInitDescriptor {
            label: Some("mesh albedo"),
            contents: bytemuck::cast_slice(&vertices),
            // read back for a draft drawn elsewhere (`render::draft`)
            usage: wgpu::BufferUsages::VERTEX | wgpu::BufferUsages::COPY_SRC,
        });
        let one = [Texture { width: 1, height: 1, texels: vec![[255; 4]] }];
        let levels = match &albedo.texture {
            Some(t) => t.mip_chain(),
            None => one.to_vec(),
        };
        let view = texture_view(dev, &levels);
        let sampler = sampler(&dev.device, albedo.sampling.filter, albedo.sampling.wrap);
        let group = dev.device.create_bind_group(&wgpu::BindGroupDescriptor {
            label: Some("albedo"),
            layout: &bind_group_layout(&dev.device),
            entries: &[
                wgpu::BindGroupEntry { binding: 0, resource: wgpu::BindingResource::TextureView(&view) },
                wgpu::BindGroupEntry { binding: 1, resource: wgpu::BindingResource::Sampler(&sampler) },
            ],
        });
        GpuAlbedo {
            vertices: buffer,
            group,
            textured: albedo.texture.is_some(),
            alpha_cutoff: albedo.sampling.alpha_cutoff,
            alpha_blend: albedo.sampling.alpha_blend,
            look: albedo.look(),
            texture: albedo.texture.as_ref().map(|t| (std::sync::Arc::new(t.clone()), albedo.sampling)),
        }
    }
}

//! What the frame graph must know of a layer of glass before the glass stage
//! (`passes::glass`, which draws it) is built: the formats of its targets, the bind group its
//! peel reads and the peel's WGSL, which the mesh stages' `glass` part is written with.

/// The module-scope WGSL of the `glass` stage part.
pub const PEEL_WGSL: &str = include_str!("../passes/glass/peel.wgsl");
/// Premultiplied linear colour of a layer and of their sum (GL renders and blends to it).
pub const LAYER_FORMAT: wgpu::TextureFormat = wgpu::TextureFormat::Rgba16Float;
/// Linear depth of a layer as f32 bits (GL cannot render to 32-bit float formats).
pub const PEELED_FORMAT: wgpu::TextureFormat = wgpu::TextureFormat::R32Uint;

/// The `glass` part's bindings: the opaque surface's depth and the last layer's.
pub fn peel_layout(device: &wgpu::Device) -> wgpu::BindGroupLayout {
    let entry = |binding| wgpu::BindGroupLayoutEntry {
        binding,
        visibility: wgpu::ShaderStages::FRAGMENT,
        ty: wgpu::BindingType::Texture {
            sample_type: wgpu::TextureSampleType::Uint,
            view_dimension: wgpu::TextureViewDimension::D2,
            multisampled: false,
        },
        count: None,
    };
    device.create_bind_group_layout(&wgpu::BindGroupLayoutDescriptor {
        label: Some("glass peel"),
        entries: &[entry(0), entry(1)],
    })
}

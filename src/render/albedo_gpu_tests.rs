//! Texture sampling on the real device (Vulkan and GL) held against its CPU twin
//! (`albedo::sampling`): the same texture levels and the same sampler the renderer uses, read
//! at coordinates that change linearly across the image, so that the coordinates' change per
//! pixel (which picks the mip level) is known exactly.

use super::albedo::sampling::sample;
use super::albedo::{Filter, Sampling, Texture, Wrap};
use super::device::Device;
use super::gpu_albedo::{sampler, texture_view};
use super::gpu_tests::{backends, open};

const W: u32 = 64;
const H: u32 = 24;

/// A texture of varied colours and alphas (a fixed hash of the texel's place).
fn test_texture(w: u32, h: u32) -> Texture {
    let texels = (0..w * h)
        .map(|i| {
            let x = i.wrapping_mul(2654435761).rotate_left(7);
            [x as u8, (x >> 8) as u8, (x >> 16) as u8, (x >> 24) as u8 | 0x20]
        })
        .collect();
    Texture::new(w, h, texels).unwrap()
}

/// One view of a texture: pixel (x, y) (its centre) reads uv = origin + x * a + y * b.
struct View {
    origin: [f32; 2],
    a: [f32; 2],
    b: [f32; 2],
}

impl View {
    fn uv(&self, x: f32, y: f32) -> [f32; 2] {
        std::array::from_fn(|k| self.origin[k] + x * self.a[k] + y * self.b[k])
    }
}

/// The GPU's samples, linear RGBA in 8-bit codes, row by row.
fn gpu_samples(dev: &Device, levels: &[Texture], s: &Sampling, v: &View) -> Vec<[u8; 4]> {
    let device = &dev.device;
    let f = |x: f32| format!("{x:?}");
    let source = format!(
        "@group(0) @binding(0) var t: texture_2d<f32>;\n\
         @group(0) @binding(1) var s: sampler;\n\
         @vertex fn vs(@builtin(vertex_index) vi: u32) -> @builtin(position) vec4<f32> {{\n\
           let x = f32(i32(vi & 1u) * 4 - 1); let y = f32(i32(vi >> 1u) * 4 - 1);\n\
           return vec4<f32>(x, y, 0.0, 1.0); }}\n\
         @fragment fn fs(@builtin(position) p: vec4<f32>) -> @location(0) vec4<f32> {{\n\
           let uv = vec2<f32>({}, {}) + p.x * vec2<f32>({}, {}) + p.y * vec2<f32>({}, {});\n\
           return textureSample(t, s, uv); }}\n",
        f(v.origin[0]),
        f(v.origin[1]),
        f(v.a[0]),
        f(v.a[1]),
        f(v.b[0]),
        f(v.b[1])
    );
    let module = device.create_shader_module(wgpu::ShaderModuleDescriptor {
        label: Some("sampling test"),
        source: wgpu::ShaderSource::Wgsl(source.into()),
    });
    let layout = super::gpu_albedo::bind_group_layout(device);
    let pipeline_layout = device.create_pipeline_layout(&wgpu::PipelineLayoutDescriptor {
        label: None,
        bind_group_layouts: &[Some(&layout)],
        immediate_size: 0,
    });
    let format = wgpu::TextureFormat::Rgba8Unorm;
    let pipeline = device.create_render_pipeline(&wgpu::RenderPipelineDescriptor {
        label: None,
        layout: Some(&pipeline_layout),
        vertex: wgpu::VertexState {
            module: &module,
            entry_point: Some("vs"),
            compilation_options: Default::default(),
            buffers: &[],
        },
        primitive: Default::default(),
        depth_stencil: None,
        multisample: Default::default(),
        fragment: Some(wgpu::FragmentState {
            module: &module,
            entry_point: Some("fs"),
            compilation_options: Default::default(),
            targets: &[Some(format.into())],
        }),
        multiview_mask: None,
        cache: None,
    });
    let view = texture_view(dev, levels);
    let smp = sampler(device, s.filter, s.wrap);
    let group = device.create_bind_group(&wgpu::BindGroupDescriptor {
        label: None,
        layout: &layout,
        entries: &[
            wgpu::BindGroupEntry { binding: 0, resource: wgpu::BindingResource::TextureView(&view) },
            wgpu::BindGroupEntry { binding: 1, resource: wgpu::BindingResource::Sampler(&smp) },
        ],
    });
    let target = device.create_texture(&wgpu::TextureDescriptor {
        label: None,
        size: wgpu::Extent3d { width: W, height: H, depth_or_array_layers: 1 },
        mip_level_count: 1,
        sample_count: 1,
        dimension: wgpu::TextureDimension::D2,
        format,
        usage: wgpu::TextureUsages::RENDER_ATTACHMENT | wgpu::TextureUsages::COPY_SRC,
        view_formats: &[],
    });
    let target_view = target.create_view(&Default::default());
    // W * 4 bytes is a whole number of 256-byte rows
    let staging = device.create_buffer(&wgpu::BufferDescriptor {
        label: None,
        size: (W * H * 4) as u64,
        usage: wgpu::BufferUsages::COPY_DST | wgpu::BufferUsages::MAP_READ,
        mapped_at_creation: false,
    });
    let mut enc = device.create_command_encoder(&Default::default());
    {
        let mut pass = enc.begin_render_pass(&wgpu::RenderPassDescriptor {
            label: None,
            color_attachments: &[Some(wgpu::RenderPassColorAttachment {
                view: &target_view,
                depth_slice: None,
                resolve_target: None,
                ops: wgpu::Operations {
                    load: wgpu::LoadOp::Clear(wgpu::Color::BLACK),
                    store: wgpu::StoreOp::Store,
                },
            })],
            ..Default::default()
        });
        pass.set_pipeline(&pipeline);
        pass.set_bind_group(0, &group, &[]);
        pass.draw(0..3, 0..1);
    }
    enc.copy_texture_to_buffer(
        target.as_image_copy(),
        wgpu::TexelCopyBufferInfo {
            buffer: &staging,
            layout: wgpu::TexelCopyBufferLayout {
                offset: 0,
                bytes_per_row: Some(W * 4),
                rows_per_image: None,
            },
        },
        wgpu::Extent3d { width: W, height: H, depth_or_array_layers: 1 },
    );
    let submission = dev.queue.submit([enc.finish()]);
    staging.map_async(wgpu::MapMode::Read, .., |r| r.unwrap());
    dev.wait(submission, "sampling test").unwrap();
    let bytes = staging.get_mapped_range(..).unwrap().to_vec();
    bytes.chunks_exact(4).map(|c| [c[0], c[1], c[2], c[3]]).collect()
}

/// The largest difference in 8-bit codes between the GPU's samples and the CPU's, and the
/// share of channels that differ by more than one code.
fn compare(dev: &Device, tex: &Texture, s: &Sampling, v: &View) -> (i32, f64) {
    let levels = match s.filter {
        Filter::Linear => tex.mip_chain(),
        Filter::Nearest => vec![tex.clone()],
    };
    let got = gpu_samples(dev, &levels, s, v);
    let (mut worst, mut off) = (0, 0usize);
    for y in 0..H {
        for x in 0..W {
            let uv = v.uv(x as f32 + 0.5, y as f32 + 0.5);
            let want = sample(&levels, uv, v.a, v.b, s).map(|c| (c.clamp(0.0, 1.0) * 255.0).round() as i32);
            let g = got[(y * W + x) as usize];
            for k in 0..4 {
                let d = (g[k] as i32 - want[k]).abs();
                worst = worst.max(d);
                off += (d > 1) as usize;
            }
        }
    }
    (worst, off as f64 / (4 * W * H) as f64)
}

#[test]
fn texture_sampling_matches_the_cpu_reference_on_both_backends() {
    let tex = test_texture(16, 8);
    let s = |filter, wrap| Sampling { filter, wrap, alpha_cutoff: None, alpha_blend: false };
    // (label, sampling, view, most codes off, share of channels more than one code off)
    let cases = [
        // magnified: texel edges (nearest) and bilinear blends, outside [0, 1] too
        (
            "nearest repeat",
            s(Filter::Nearest, Wrap::Repeat),
            View { origin: [-0.6, -0.3], a: [0.041, 0.0], b: [0.0, 0.07] },
        ),
        (
            "bilinear clamp",
            s(Filter::Linear, Wrap::Clamp),
            View { origin: [-0.2, -0.1], a: [0.023, 0.0], b: [0.0, 0.05] },
        ),
        (
            "bilinear mirror",
            s(Filter::Linear, Wrap::Mirror),
            View { origin: [-1.1, 0.4], a: [0.05, 0.0], b: [0.0, 0.09] },
        ),
        // minified: between levels 1 and 2, and between 2 and 3 (trilinear)
        (
            "trilinear repeat",
            s(Filter::Linear, Wrap::Repeat),
            View { origin: [0.1, 0.2], a: [0.17, 0.0], b: [0.0, 0.1] },
        ),
        (
            "trilinear mirror",
            s(Filter::Linear, Wrap::Mirror),
            View { origin: [0.3, -0.2], a: [0.31, 0.0], b: [0.0, 0.6] },
        ),
        // minified far past the smallest level: the 1 x 1 level
        (
            "smallest level",
            s(Filter::Linear, Wrap::Repeat),
            View { origin: [0.0, 0.0], a: [3.0, 0.0], b: [0.0, 2.5] },
        ),
    ];
    for backend in backends() {
        let r = open(backend).expect("a GPU adapter (install Mesa's lavapipe/llvmpipe)");
        let dev: &Device = r.context();
        for (label, sampling, view) in &cases {
            let (worst, share) = compare(dev, &tex, sampling, view);
            eprintln!("{backend:?} {label}: worst {worst} codes, {share:.4} of channels off by more than 1");
            assert!(worst <= 2 && share <= 0.005, "{backend:?} {label}: worst {worst}, {share} off");
        }
    }
}

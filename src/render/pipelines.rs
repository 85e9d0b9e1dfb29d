//! Render pipelines, built on first use and cached by everything they depend on. Each pass asks
//! for the variant it needs, so a scene compiles only what it uses.

use std::collections::HashMap;
use std::sync::{Arc, Mutex};

use super::gpu_mesh::GpuMesh;
use super::targets::{COLOR_FORMAT, DEPTH_FORMAT, LINEAR_DEPTH_FORMAT, NORMAL_FORMAT};

const COMMON_WGSL: &str = include_str!("shaders/common.wgsl");
const SHADE_WGSL: &str = include_str!("shaders/shade.wgsl");
const GBUFFER_WGSL: &str = include_str!("shaders/gbuffer.wgsl");
const DOWNSAMPLE_WGSL: &str = include_str!("shaders/downsample.wgsl");

#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum PipelineKey {
    /// The shading pass; with normal/depth targets (in that order, no gaps) when it writes them.
    Shade { samples: u32, normal: bool, depth: bool, per_vertex: bool },
    /// The geometry-only pass.
    GBuffer { normal: bool, depth: bool },
    /// Supersampling's box filter.
    Downsample { factor: u32 },
}

pub struct PipelineCache {
    pub frame_layout: wgpu::BindGroupLayout,
    pub draw_layout: wgpu::BindGroupLayout,
    pub source_layout: wgpu::BindGroupLayout,
    mesh_layout: wgpu::PipelineLayout,
    source_pipeline_layout: wgpu::PipelineLayout,
    modules: Mutex<HashMap<&'static str, wgpu::ShaderModule>>,
    pipelines: Mutex<HashMap<PipelineKey, Arc<wgpu::RenderPipeline>>>,
}

fn uniform_layout(device: &wgpu::Device, label: &str) -> wgpu::BindGroupLayout {
    device.create_bind_group_layout(&wgpu::BindGroupLayoutDescriptor {
        label: Some(label),
        entries: &[wgpu::BindGroupLayoutEntry {
            binding: 0,
            visibility: wgpu::ShaderStages::VERTEX_FRAGMENT,
            ty: wgpu::BindingType::Buffer {
                ty: wgpu::BufferBindingType::Uniform,
                has_dynamic_offset: false,
                min_binding_size: None,
            },
            count: None,
        }],
    })
}

fn target(format: wgpu::TextureFormat) -> Option<wgpu::ColorTargetState> {
    Some(wgpu::ColorTargetState { format, blend: None, write_mask: wgpu::ColorWrites::ALL })
}

impl PipelineCache {
    pub fn new(device: &wgpu::Device) -> Self {
        let frame_layout = uniform_layout(device, "frame uniforms");
        let draw_layout = uniform_layout(device, "draw uniforms");
        let source_layout = device.create_bind_group_layout(&wgpu::BindGroupLayoutDescriptor {
            label: Some("source texture"),
            entries: &[wgpu::BindGroupLayoutEntry {
                binding: 0,
                visibility: wgpu::ShaderStages::FRAGMENT,
                ty: wgpu::BindingType::Texture {
                    sample_type: wgpu::TextureSampleType::Float { filterable: false },
                    view_dimension: wgpu::TextureViewDimension::D2,
                    multisampled: false,
                },
                count: None,
            }],
        });
        let mesh_layout = device.create_pipeline_layout(&wgpu::PipelineLayoutDescriptor {
            label: Some("mesh passes"),
            bind_group_layouts: &[Some(&frame_layout), Some(&draw_layout)],
            immediate_size: 0,
        });
        let source_pipeline_layout = device.create_pipeline_layout(&wgpu::PipelineLayoutDescriptor {
            label: Some("image passes"),
            bind_group_layouts: &[Some(&source_layout)],
            immediate_size: 0,
        });
        PipelineCache {
            frame_layout,
            draw_layout,
            source_layout,
            mesh_layout,
            source_pipeline_layout,
            modules: Mutex::new(HashMap::new()),
            pipelines: Mutex::new(HashMap::new()),
        }
    }

    fn module(&self, device: &wgpu::Device, name: &'static str) -> wgpu::ShaderModule {
        let mut modules = self.modules.lock().unwrap_or_else(|e| e.into_inner());
        modules
            .entry(name)
            .or_insert_with(|| {
                let source = match name {
                    "shade" => format!("{COMMON_WGSL}\n{SHADE_WGSL}"),
                    "gbuffer" => format!("{COMMON_WGSL}\n{GBUFFER_WGSL}"),
                    _ => DOWNSAMPLE_WGSL.to_string(),
                };
                device.create_shader_module(wgpu::ShaderModuleDescriptor {
                    label: Some(name),
                    source: wgpu::ShaderSource::Wgsl(source.into()),
                })
            })
            .clone()
    }

    pub fn get(&self, device: &wgpu::Device, key: PipelineKey) -> Arc<wgpu::RenderPipeline> {
        if let Some(p) = self.pipelines.lock().unwrap_or_else(|e| e.into_inner()).get(&key) {
            return p.clone();
        }
        let p = Arc::new(self.build(device, key));
        self.pipelines.lock().unwrap_or_else(|e| e.into_inner()).entry(key).or_insert(p).clone()
    }

    fn build(&self, device: &wgpu::Device, key: PipelineKey) -> wgpu::RenderPipeline {
        let mesh_depth = Some(wgpu::DepthStencilState {
            format: DEPTH_FORMAT,
            depth_write_enabled: Some(true),
            depth_compare: Some(wgpu::CompareFunction::Less),
            stencil: Default::default(),
            bias: Default::default(),
        });
        // Both sides are drawn: a camera inside a mesh, or an open surface, shows back faces.
        let mesh_primitive =
            wgpu::PrimitiveState { cull_mode: None, front_face: wgpu::FrontFace::Ccw, ..Default::default() };
        let vertex_buffers = [Some(GpuMesh::vertex_layout())];
        match key {
            PipelineKey::Shade { samples, normal, depth, per_vertex } => {
                let module = self.module(device, "shade");
                let constants = [("PER_VERTEX", if per_vertex { 1.0 } else { 0.0 })];
                let mut targets = vec![target(COLOR_FORMAT)];
                targets.extend(normal.then(|| target(NORMAL_FORMAT)));
                targets.extend(depth.then(|| target(LINEAR_DEPTH_FORMAT)));
                let entry = match (normal, depth) {
                    (false, false) => "fs_color",
                    (true, false) => "fs_color_normal",
                    (false, true) => "fs_color_depth",
                    (true, true) => "fs_color_normal_depth",
                };
                device.create_render_pipeline(&wgpu::RenderPipelineDescriptor {
                    label: Some("shade"),
                    layout: Some(&self.mesh_layout),
                    vertex: wgpu::VertexState {
                        module: &module,
                        entry_point: Some("vs_main"),
                        compilation_options: wgpu::PipelineCompilationOptions {
                            constants: &constants,
                            ..Default::default()
                        },
                        buffers: &vertex_buffers,
                    },
                    primitive: mesh_primitive,
                    depth_stencil: mesh_depth,
                    multisample: wgpu::MultisampleState {
                        count: samples,
                        mask: !0,
                        alpha_to_coverage_enabled: false,
                    },
                    fragment: Some(wgpu::FragmentState {
                        module: &module,
                        entry_point: Some(entry),
                        compilation_options: wgpu::PipelineCompilationOptions {
                            constants: &constants,
                            ..Default::default()
                        },
                        targets: &targets,
                    }),
                    multiview_mask: None,
                    cache: None,
                })
            }
            PipelineKey::GBuffer { normal, depth } => {
                let module = self.module(device, "gbuffer");
                let mut targets = vec![];
                targets.extend(normal.then(|| target(NORMAL_FORMAT)));
                targets.extend(depth.then(|| target(LINEAR_DEPTH_FORMAT)));
                let entry = if normal && depth {
                    "fs_normal_depth"
                } else if normal {
                    "fs_normal"
                } else {
                    "fs_depth"
                };
                device.create_render_pipeline(&wgpu::RenderPipelineDescriptor {
                    label: Some("gbuffer"),
                    layout: Some(&self.mesh_layout),
                    vertex: wgpu::VertexState {
                        module: &module,
                        entry_point: Some("vs_main"),
                        compilation_options: Default::default(),
                        buffers: &vertex_buffers,
                    },
                    primitive: mesh_primitive,
                    depth_stencil: mesh_depth,
                    multisample: Default::default(),
                    fragment: Some(wgpu::FragmentState {
                        module: &module,
                        entry_point: Some(entry),
                        compilation_options: Default::default(),
                        targets: &targets,
                    }),
                    multiview_mask: None,
                    cache: None,
                })
            }
            PipelineKey::Downsample { factor } => {
                let module = self.module(device, "downsample");
                let constants = [("FACTOR", factor as f64)];
                device.create_render_pipeline(&wgpu::RenderPipelineDescriptor {
                    label: Some("downsample"),
                    layout: Some(&self.source_pipeline_layout),
                    vertex: wgpu::VertexState {
                        module: &module,
                        entry_point: Some("vs_fullscreen"),
                        compilation_options: Default::default(),
                        buffers: &[],
                    },
                    primitive: Default::default(),
                    depth_stencil: None,
                    multisample: Default::default(),
                    fragment: Some(wgpu::FragmentState {
                        module: &module,
                        entry_point: Some("fs_downsample"),
                        compilation_options: wgpu::PipelineCompilationOptions {
                            constants: &constants,
                            ..Default::default()
                        },
                        targets: &[target(COLOR_FORMAT)],
                    }),
                    multiview_mask: None,
                    cache: None,
                })
            }
        }
    }
}

//! A renderer: meshes kept on the device, rendered in any number of scenes and views.
//! Everything here may be called from several threads at once.

use std::collections::HashMap;
use std::sync::atomic::{AtomicU64, Ordering};
use std::sync::{Arc, Mutex};
use std::time::Instant;

use wgpu::util::DeviceExt;

use crate::error::{Error, Result};
use crate::real::{Real, Vec3};

use super::camera::ResolvedCamera;
use super::color::srgb_to_linear;
use super::context::{context, BackendChoice, GpuContext, GpuInfo};
use super::gpu_mesh::{GpuMesh, NormalMode};
use super::passes::{self, Draw, DrawList};
use super::plan::{plan, Output, Pass};
use super::readback::words_to_f32;
use super::scene::{FrameSpec, Scene};
use super::targets::{FrameTargets, TargetKey};
use super::uniforms::{draw_block, frame_block};

/// What a render returns. Images are row-major with the top row first.
#[derive(Debug, Clone, Default)]
pub struct RenderOutput {
    pub width: u32,
    pub height: u32,
    /// (H, W, 4) sRGB colour with alpha.
    pub color: Option<Vec<u8>>,
    /// (H, W, 3) view-space unit normals, facing the camera; 0 where no mesh is.
    pub normal: Option<Vec<f32>>,
    /// (H, W) linear depth: distance from the camera plane along the view axis; +inf where no mesh is.
    pub depth: Option<Vec<f32>>,
    /// The passes that ran, in order, with their wall-clock seconds.
    pub timings: Vec<(&'static str, f64)>,
    /// The camera used: row-major world -> view and view -> clip matrices, clip distances.
    pub view: [[f64; 4]; 4],
    pub proj: [[f64; 4]; 4],
    pub near: f64,
    pub far: f64,
}

pub struct Renderer {
    ctx: Arc<GpuContext>,
    meshes: Mutex<HashMap<u64, Arc<GpuMesh>>>,
    next_id: AtomicU64,
}

fn rows(m: glam::DMat4) -> [[f64; 4]; 4] {
    m.transpose().to_cols_array_2d()
}

impl Renderer {
    /// A renderer on the process-wide context of `backend` (created on first use).
    pub fn new(backend: BackendChoice) -> Result<Self> {
        Ok(Renderer {
            ctx: context(backend)?,
            meshes: Mutex::new(HashMap::new()),
            next_id: AtomicU64::new(1),
        })
    }

    pub fn info(&self) -> &GpuInfo {
        &self.ctx.info
    }

    pub fn context(&self) -> &Arc<GpuContext> {
        &self.ctx
    }

    /// Uploads a mesh (faces already checked against `positions`) and returns its id.
    pub fn add_mesh<T: Real>(
        &self,
        positions: &[Vec3<T>],
        faces: &[[u32; 3]],
        normals: NormalMode,
    ) -> Result<u64> {
        crate::mesh::check_positions("vertices", positions)?;
        if let Some(bad) = faces.iter().flatten().find(|&&i| i as usize >= positions.len()) {
            return Err(Error::out_of_range(
                "faces",
                format!("vertex index {bad} is outside [0, {})", positions.len()),
            ));
        }
        let mesh = GpuMesh::upload(&self.ctx, positions, faces, normals)?;
        let id = self.next_id.fetch_add(1, Ordering::Relaxed);
        self.meshes.lock().unwrap_or_else(|e| e.into_inner()).insert(id, Arc::new(mesh));
        Ok(id)
    }

    pub fn mesh(&self, id: u64) -> Result<Arc<GpuMesh>> {
        self.meshes.lock().unwrap_or_else(|e| e.into_inner()).get(&id).cloned().ok_or_else(|| {
            Error::invalid("mesh", format!("no mesh with id {id} in this renderer (removed?)"))
        })
    }

    /// Frees a mesh's device memory once no render in flight uses it. False if unknown.
    pub fn remove_mesh(&self, id: u64) -> bool {
        self.meshes.lock().unwrap_or_else(|e| e.into_inner()).remove(&id).is_some()
    }

    pub fn mesh_count(&self) -> usize {
        self.meshes.lock().unwrap_or_else(|e| e.into_inner()).len()
    }

    /// Renders `scene` as `frame` asks, running only the passes its plan lists.
    pub fn render(&self, scene: &Scene, frame: &FrameSpec) -> Result<RenderOutput> {
        frame.validate(self.ctx.info.max_texture_size, &self.ctx.info.msaa_samples)?;
        scene.validate()?;
        let cam = scene.camera.resolve(scene.bounding_sphere(), frame.width as f64 / frame.height as f64)?;
        let device = &self.ctx.device;
        // Error scopes are per thread, so concurrent renders each see only their own errors.
        let validation = device.push_error_scope(wgpu::ErrorFilter::Validation);
        let memory = device.push_error_scope(wgpu::ErrorFilter::OutOfMemory);
        let result = self.run(scene, frame, &cam);
        let memory_error = pollster::block_on(memory.pop());
        let validation_error = pollster::block_on(validation.pop());
        if let Some(e) = memory_error {
            return Err(Error::Gpu(format!("the GPU ran out of memory: {e}")));
        }
        if let Some(e) = validation_error {
            return Err(Error::Gpu(format!("the GPU rejected the work: {e}")));
        }
        result
    }

    fn draw_list(&self, scene: &Scene, cam: &ResolvedCamera) -> DrawList {
        let device = &self.ctx.device;
        let uniforms = |label: &str, bytes: &[u8], layout: &wgpu::BindGroupLayout| {
            let buffer = device.create_buffer_init(&wgpu::util::BufferInitDescriptor {
                label: Some(label),
                contents: bytes,
                usage: wgpu::BufferUsages::UNIFORM,
            });
            device.create_bind_group(&wgpu::BindGroupDescriptor {
                label: Some(label),
                layout,
                entries: &[wgpu::BindGroupEntry { binding: 0, resource: buffer.as_entire_binding() }],
            })
        };
        let pipelines = &self.ctx.pipelines;
        DrawList {
            frame_uniforms: uniforms(
                "frame",
                bytemuck::bytes_of(&frame_block(scene, cam)),
                &pipelines.frame_layout,
            ),
            draws: scene
                .items
                .iter()
                .map(|item| Draw {
                    mesh: item.mesh.clone(),
                    uniforms: uniforms(
                        "draw",
                        bytemuck::bytes_of(&*draw_block(item, cam)),
                        &pipelines.draw_layout,
                    ),
                    per_vertex: item.material.per_vertex,
                })
                .collect(),
        }
    }

    fn run(&self, scene: &Scene, frame: &FrameSpec, cam: &ResolvedCamera) -> Result<RenderOutput> {
        let ctx = &*self.ctx;
        let device = &ctx.device;
        let targets = ctx.targets.take(device, TargetKey::of(frame));
        let list = self.draw_list(scene, cam);
        let bg = frame.background;
        let background = wgpu::Color {
            r: srgb_to_linear(bg[0] as f64),
            g: srgb_to_linear(bg[1] as f64),
            b: srgb_to_linear(bg[2] as f64),
            a: bg[3] as f64,
        };
        let mut out = RenderOutput {
            width: frame.width,
            height: frame.height,
            view: rows(cam.view),
            proj: rows(cam.proj),
            near: cam.near,
            far: cam.far,
            ..Default::default()
        };
        for pass in plan(frame) {
            let start = Instant::now();
            let mut encoder =
                device.create_command_encoder(&wgpu::CommandEncoderDescriptor { label: Some(pass.name()) });
            match pass {
                Pass::Shade { gbuffer } => {
                    passes::shade::encode(ctx, &mut encoder, &targets, &list, gbuffer, background)
                }
                Pass::GBuffer => passes::gbuffer::encode(ctx, &mut encoder, &targets, &list),
                Pass::Downsample { factor } => {
                    passes::downsample::encode(ctx, &mut encoder, &targets, factor)
                }
                Pass::Readback(o) => {
                    let (buffer, texture) = readback_of(&targets, o);
                    buffer.encode_copy(&mut encoder, texture);
                }
            }
            let submission = ctx.queue.submit([encoder.finish()]);
            match pass {
                Pass::Readback(o) => {
                    let bytes = readback_of(&targets, o).0.read(device, submission)?;
                    match o {
                        Output::Color => out.color = Some(bytes),
                        Output::Normal => out.normal = Some(words_to_f32(&bytes, 4, 3)),
                        Output::Depth => out.depth = Some(words_to_f32(&bytes, 1, 1)),
                    }
                }
                _ => {
                    device
                        .poll(wgpu::PollType::Wait { submission_index: Some(submission), timeout: None })
                        .map_err(|e| Error::Gpu(format!("waiting for the {} pass: {e}", pass.name())))?;
                }
            }
            out.timings.push((pass.name(), start.elapsed().as_secs_f64()));
        }
        ctx.targets.give_back(targets);
        Ok(out)
    }
}

fn readback_of(t: &FrameTargets, o: Output) -> (&super::readback::ReadbackBuffer, &wgpu::Texture) {
    let missing = "the plan reads back only targets the frame has";
    match o {
        Output::Color => (t.color_readback.as_ref().expect(missing), t.color.as_ref().expect(missing)),
        Output::Normal => (t.normal_readback.as_ref().expect(missing), t.normal.as_ref().expect(missing)),
        Output::Depth => (t.depth_readback.as_ref().expect(missing), t.linear_depth.as_ref().expect(missing)),
    }
}

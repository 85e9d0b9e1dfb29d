//! A renderer: meshes kept on the device, rendered in any number of scenes and views. A frame
//! is planned (`plan`), recorded into one command encoder, submitted once, and its readbacks
//! are mapped once and copied straight into the caller's arrays.
//! Everything here may be called from several threads at once.

use std::collections::HashMap;
use std::sync::atomic::{AtomicU64, Ordering};
use std::sync::{Arc, Mutex};
use std::time::Instant;

use glam::{DMat4, DVec3};

use crate::cancel::Cancel;
use crate::edges::chains::chain_edges;
use crate::edges::outlines::Outline;
use crate::edges::View;
use crate::error::{Error, Result};
use crate::real::{Real, Vec3};

use super::color::srgb_to_linear;
use super::context::{context, GpuContext};
use super::culling::culls;
use super::device::{BackendChoice, GpuInfo};
use super::gpu_mesh::{GpuMesh, NormalMode};
use super::graph::resources::FrameResources;
use super::graph::{DrawItem, FrameCtx, LineDraw, ShadingVariant};
use super::mesh_lines::MeshLines;
use super::passes::lines::visibility::{visible_runs, DepthImage, Projector, Visibility};
use super::plan::{plan, Features, Plan, SILHOUETTES, VISIBLE_LINES};
use super::scene::camera::Camera;
use super::scene::camera::{ResolvedCamera, Sphere};
use super::scene::light::shadow_caster;
use super::scene::outlines::Outlines;
use super::scene::{FrameSpec, MeshId, Scene, SceneItem};
use super::uniforms::{draw_block, footprint, frame_block, model_view, point_light_bits, LineInstance};

/// A mesh the renderer holds.
pub struct MeshRecord {
    pub gpu: GpuMesh,
    pub lines: MeshLines,
}

/// Where a render writes its images: (H, W, 4) colour, (H, W, 3) normals, (H, W) depth and
/// (H, W) outline coverage, row-major, top row first. Each must be given exactly when its
/// output is asked for.
#[derive(Default)]
pub struct OutputBuffers<'a> {
    pub color: Option<&'a mut [u8]>,
    pub normal: Option<&'a mut [f32]>,
    pub depth: Option<&'a mut [f32]>,
    pub outline: Option<&'a mut [f32]>,
    pub shadow: Option<&'a mut [f32]>,
}

/// One visible mesh-space polyline in pixel coordinates, and its kind.
#[derive(Clone, Debug, PartialEq)]
pub struct Polyline {
    pub kind: usize,
    pub points: Vec<[f64; 2]>,
}

/// What a render reports besides its images.
#[derive(Clone, Debug, Default)]
pub struct FrameReport {
    /// Every step that ran, in order (host steps included).
    pub passes: Vec<&'static str>,
    /// Seconds per step: GPU passes from timestamps where the device has them, host steps and
    /// `readback` (waiting for the frame and copying it out) by the wall clock, and `frame`,
    /// the whole render's wall time.
    pub timings: Vec<(&'static str, f64)>,
    /// Whether the GPU passes were timed on the GPU.
    pub gpu_timed: bool,
    /// The camera used: row-major world -> view and view -> clip matrices, clip distances.
    pub view: [[f64; 4]; 4],
    pub proj: [[f64; 4]; 4],
    pub near: f64,
    pub far: f64,
    /// The visible mesh-space lines, when asked for.
    pub lines: Option<Vec<Polyline>>,
    /// Per mesh, whether the camera's passes skipped its inner sides (`render::culling`).
    pub culled: Vec<bool>,
}

/// A render's images in vectors (see `Renderer::render`).
#[derive(Clone, Debug, Default)]
pub struct RenderOutput {
    pub width: u32,
    pub height: u32,
    pub color: Option<Vec<u8>>,
    pub normal: Option<Vec<f32>>,
    pub depth: Option<Vec<f32>>,
    pub outline: Option<Vec<f32>>,
    pub shadow: Option<Vec<f32>>,
    pub report: FrameReport,
}

pub struct Renderer {
    ctx: Arc<GpuContext>,
    meshes: Mutex<HashMap<MeshId, Arc<MeshRecord>>>,
    next_id: AtomicU64,
}

fn rows(m: DMat4) -> [[f64; 4]; 4] {
    m.transpose().to_cols_array_2d()
}

/// Depth is returned in float32: scenes whose size lies outside these powers of two cannot be.
const DEPTH_SCALE_RANGE: std::ops::RangeInclusive<f64> = 1.0e-30..=1.0e30;

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
        faces: Vec<[u32; 3]>,
        normals: NormalMode,
    ) -> Result<MeshId> {
        self.ctx.check_process()?;
        crate::mesh::check_positions("vertices", positions)?;
        if let Some(bad) = faces.iter().flatten().find(|&&i| i as usize >= positions.len()) {
            return Err(Error::out_of_range(
                "faces",
                format!("vertex index {bad} is outside [0, {})", positions.len()),
            ));
        }
        let (gpu, host) = crate::parallel::install(|| GpuMesh::upload(&self.ctx, positions, faces, normals))?;
        let id = self.next_id.fetch_add(1, Ordering::Relaxed);
        let record = MeshRecord { gpu, lines: MeshLines::new(host) };
        self.meshes.lock().unwrap_or_else(|e| e.into_inner()).insert(id, Arc::new(record));
        Ok(id)
    }

    pub fn mesh(&self, id: MeshId) -> Result<Arc<MeshRecord>> {
        self.meshes.lock().unwrap_or_else(|e| e.into_inner()).get(&id).cloned().ok_or_else(|| {
            Error::invalid("mesh", format!("no mesh with id {id} in this renderer (removed?)"))
        })
    }

    /// Frees a mesh's device memory once no render in flight uses it. False if unknown.
    pub fn remove_mesh(&self, id: MeshId) -> bool {
        self.meshes.lock().unwrap_or_else(|e| e.into_inner()).remove(&id).is_some()
    }

    pub fn mesh_count(&self) -> usize {
        self.meshes.lock().unwrap_or_else(|e| e.into_inner()).len()
    }

    /// Renders into newly allocated vectors.
    pub fn render(&self, scene: &Scene, frame: &FrameSpec) -> Result<RenderOutput> {
        let n = frame.width as usize * frame.height as usize;
        let o = frame.outputs;
        let mut color = o.color.then(|| vec![0u8; 4 * n]);
        let mut normal = o.normal.then(|| vec![0f32; 3 * n]);
        let mut depth = o.depth.then(|| vec![0f32; n]);
        let mut outline = o.outline.then(|| vec![0f32; n]);
        let mut shadow = o.shadow.then(|| vec![0f32; n]);
        let report = self.render_into(
            scene,
            frame,
            OutputBuffers {
                color: color.as_deref_mut(),
                normal: normal.as_deref_mut(),
                depth: depth.as_deref_mut(),
                outline: outline.as_deref_mut(),
                shadow: shadow.as_deref_mut(),
            },
        )?;
        Ok(RenderOutput {
            width: frame.width,
            height: frame.height,
            color,
            normal,
            depth,
            outline,
            shadow,
            report,
        })
    }

    /// Checks a scene and frame before any work: everything a render would refuse.
    pub fn check(&self, scene: &Scene, frame: &FrameSpec) -> Result<()> {
        self.ctx.check_process()?;
        frame.validate(self.ctx.info.max_texture_size, &self.ctx.info.msaa_samples)?;
        scene.validate()?;
        let o = frame.outputs;
        if o.outline && scene.outlines.is_none() {
            return Err(Error::invalid(
                "outputs",
                "'outline' needs outlines (outlines='mesh', 'image' or 'both')",
            ));
        }
        if o.lines && !scene.mesh_lines() {
            return Err(Error::invalid(
                "outputs",
                "'lines' needs mesh-space outlines (outlines='mesh' or 'both', with some kind of line drawn)",
            ));
        }
        if o.shadow && shadow_caster(&scene.lights).is_none() {
            return Err(Error::invalid(
                "outputs",
                "'shadow' needs a light that casts shadows (Light.directional(..., shadows=True))",
            ));
        }
        for (i, item) in scene.items.iter().enumerate() {
            self.mesh(item.mesh).map_err(|e| match e {
                Error::InvalidValue { reason, .. } => Error::invalid(format!("meshes[{i}]"), reason),
                other => other,
            })?;
        }
        Ok(())
    }

    /// Everything a frame needs before the GPU: the meshes, the camera, the plan and each mesh's
    /// lines for this view (the `silhouettes` step).
    pub(crate) fn prepare(&self, scene: &Scene, frame: &FrameSpec) -> Result<Prepared> {
        self.check(scene, frame)?;
        let records: Vec<Arc<MeshRecord>> =
            scene.items.iter().map(|i| self.mesh(i.mesh)).collect::<Result<_>>()?;
        let sphere = scene.bounding_sphere(|id| Ok(self.mesh(id)?.gpu.sphere()))?;
        let cam = scene.camera.resolve(sphere, frame.width as f64 / frame.height as f64)?;
        if frame.outputs.depth && !DEPTH_SCALE_RANGE.contains(&cam.scale) {
            return Err(Error::invalid(
                "outputs",
                format!(
                    "'depth': the scene's depths (about {:e}) are outside float32's range; \
                     render the colour or normals, or rescale the scene",
                    cam.scale
                ),
            ));
        }
        let plan = plan(Features::of(scene), frame);
        let culls = scene
            .items
            .iter()
            .zip(&records)
            .map(|(item, rec)| {
                let g = &rec.gpu;
                culls(item, g.enclosure, g.placement.origin.into(), g.radius, &cam)
            })
            .collect();
        let outlines = scene.outlines.clone().unwrap_or_else(|| Outlines::new(false, false));
        let t = Instant::now();
        let views: Vec<Option<Outline>> = if plan.silhouettes {
            scene
                .items
                .iter()
                .zip(&records)
                .map(|(item, rec)| {
                    let view = stored_view(&cam, item.model_matrix(), &rec.gpu);
                    rec.lines.outline(view, &outlines).map(Some)
                })
                .collect::<Result<_>>()?
        } else {
            vec![None; records.len()]
        };
        Ok(Prepared {
            records,
            culls,
            cam,
            sphere,
            plan,
            views,
            outlines,
            silhouette_seconds: t.elapsed().as_secs_f64(),
        })
    }

    /// Renders `scene` as `frame` asks, running only the passes its plan lists, into `out`.
    pub fn render_into(
        &self,
        scene: &Scene,
        frame: &FrameSpec,
        out: OutputBuffers<'_>,
    ) -> Result<FrameReport> {
        let f = self.submit(scene.clone(), *frame)?;
        self.finish(f, out)
    }

    /// Renders `scene` once from each of `cameras` into `outs` (one set of buffers a view),
    /// keeping `IN_FLIGHT` frames submitted at once so that the GPU draws one while the host
    /// reads the last back. Gives the same bits as rendering each view alone. `cancel` is
    /// checked between frames: once raised, the frames in flight are waited for and dropped and
    /// the call returns `Error::Interrupted`.
    pub fn render_views(
        &self,
        scene: &Scene,
        cameras: &[Camera],
        frame: &FrameSpec,
        outs: Vec<OutputBuffers<'_>>,
        cancel: &Cancel,
    ) -> Result<Vec<FrameReport>> {
        if outs.len() != cameras.len() {
            return Err(Error::Internal("render_views: one set of output buffers a camera".into()));
        }
        let mut in_flight: std::collections::VecDeque<InFlight> = Default::default();
        let mut outs = outs.into_iter();
        let mut reports = Vec::with_capacity(cameras.len());
        let mut run = || -> Result<()> {
            for camera in cameras {
                cancel.check()?;
                let view = Scene { camera: *camera, ..scene.clone() };
                in_flight.push_back(self.submit(view, *frame)?);
                if in_flight.len() >= IN_FLIGHT {
                    let f = in_flight.pop_front().expect("just pushed");
                    reports.push(self.finish(f, outs.next().expect("one a camera"))?);
                }
            }
            while let Some(f) = in_flight.pop_front() {
                reports.push(self.finish(f, outs.next().expect("one a camera"))?);
            }
            Ok(())
        };
        let result = run();
        // frames left in flight by an error: wait for them, then free their resources
        for f in in_flight {
            let _ = self.ctx.wait(f.submission.clone(), "an abandoned frame");
            if let Some(staging) = &f.res.staging {
                staging.unmap();
            }
            self.ctx.frames.give_back(f.res);
        }
        result.map(|_| reports)
    }

    /// Prepares, records and submits one frame, and asks for its readback to be mapped.
    fn submit(&self, scene: Scene, frame: FrameSpec) -> Result<InFlight> {
        let start = Instant::now();
        let p = self.prepare(&scene, &frame)?;
        let mut report = FrameReport {
            passes: p.plan.names(),
            view: rows(p.cam.view),
            proj: rows(p.cam.proj),
            near: p.cam.near,
            far: p.cam.far,
            culled: p.culls.iter().map(|c| c.0.is_some()).collect(),
            ..Default::default()
        };
        if p.plan.silhouettes {
            report.timings.push((SILHOUETTES, p.silhouette_seconds));
        }
        let ctx = &*self.ctx;
        let device = &ctx.device;
        let key = p.plan.resource_key(ctx.info.timestamps);
        let mut res = ctx.frames.take(ctx, &ctx.pipelines.layouts, &key);
        // Error scopes are per thread, so concurrent renders each see only their own errors.
        let validation = device.push_error_scope(wgpu::ErrorFilter::Validation);
        let memory = device.push_error_scope(wgpu::ErrorFilter::OutOfMemory);
        let recorded = self.record_and_submit(&scene, &frame, &p, &mut res);
        let memory_error = pollster::block_on(memory.pop());
        let validation_error = pollster::block_on(validation.pop());
        let error = match (memory_error, validation_error, &recorded) {
            (Some(e), _, _) => Some(Error::Gpu(format!("the GPU ran out of memory: {e}"))),
            (_, Some(e), _) => Some(Error::Gpu(format!("the GPU rejected the work: {e}"))),
            (_, _, Err(e)) => Some(e.clone()),
            _ => None,
        };
        if let Some(e) = error {
            if let Ok((submission, _)) = recorded {
                let _ = ctx.wait(submission, "a failed frame");
            }
            ctx.frames.give_back(res);
            return Err(e);
        }
        let (submission, timed) = recorded.expect("no error");
        let mapped = res.staging.as_ref().map(|staging| {
            let (tx, rx) = std::sync::mpsc::channel();
            staging.map_async(wgpu::MapMode::Read, .., move |r| {
                let _ = tx.send(r);
            });
            rx
        });
        Ok(InFlight { scene, frame, prepared: p, res, submission, mapped, timed, start, report })
    }

    /// Waits for a submitted frame, copies its readbacks into `out`, and finishes its report.
    fn finish(&self, f: InFlight, out: OutputBuffers<'_>) -> Result<FrameReport> {
        let InFlight { scene, frame, prepared: p, res, submission, mapped, timed, start, mut report } = f;
        let t = Instant::now();
        let read = self.read_back(&frame, &p, &res, submission, mapped, &timed, out);
        if let Some(staging) = &res.staging {
            staging.unmap();
        }
        self.ctx.frames.give_back(res);
        let part = read?;
        report.timings.extend(part.timings);
        report.timings.push(("readback", t.elapsed().as_secs_f64()));
        report.gpu_timed = part.gpu_timed;
        if p.plan.visible_lines {
            let t = Instant::now();
            let depth = part.line_depth.as_deref().expect("the plan reads depth back for visible lines");
            report.lines = Some(self.visible_lines(&scene, &frame, &p, depth));
            report.timings.push((VISIBLE_LINES, t.elapsed().as_secs_f64()));
        }
        report.timings.push(("frame", start.elapsed().as_secs_f64()));
        Ok(report)
    }

    /// Records the frame's passes into one command encoder and submits it. Returns the
    /// submission and the passes timed on the GPU, in order.
    fn record_and_submit(
        &self,
        scene: &Scene,
        frame: &FrameSpec,
        p: &Prepared,
        res: &mut FrameResources,
    ) -> Result<(wgpu::SubmissionIndex, Vec<&'static str>)> {
        let (plan, cam, records, views) = (&p.plan, &p.cam, &p.records, &p.views);
        let ctx = &*self.ctx;
        let layouts = &ctx.pipelines.layouts;
        // uniforms and line instances
        res.reserve_draws(ctx, layouts, scene.items.len());
        let stride = res.uniforms.draw_stride as u32;
        let blocks: Vec<_> = scene
            .items
            .iter()
            .zip(records)
            .map(|(item, rec)| draw_block(item, &rec.gpu.placement, cam))
            .collect();
        res.write_uniforms(ctx, &frame_block(scene, cam, frame, p.sphere), &blocks);
        let mut instances = Vec::new();
        let mut line_draws = Vec::new();
        for (i, (view, rec)) in views.iter().zip(records).enumerate() {
            if let Some(outline) = view {
                let first = instances.len() as u32;
                let p = rec.lines.positions();
                instances.extend(outline.edges.iter().zip(&outline.kinds).map(|(e, k)| LineInstance {
                    a: p[e[0] as usize].map(|x| x as f32),
                    kind: *k as u32,
                    b: p[e[1] as usize].map(|x| x as f32),
                    pad: 0,
                }));
                line_draws.push(LineDraw {
                    uniform_offset: i as u32 * stride,
                    instances: first..instances.len() as u32,
                });
            }
        }
        res.write_lines(ctx, &instances);
        let draws: Vec<DrawItem> = scene
            .items
            .iter()
            .zip(records)
            .zip(&p.culls)
            .enumerate()
            .map(|(i, ((item, rec), &(cull, light_cull)))| DrawItem {
                mesh: &rec.gpu,
                uniform_offset: i as u32 * stride,
                variant: ShadingVariant::of(&item.material),
                cull,
                light_cull,
            })
            .collect();
        let bg = frame.background;
        let f = FrameCtx {
            dev: ctx,
            pipelines: &ctx.pipelines,
            res,
            shape: plan.shape,
            draws: &draws,
            lines: &line_draws,
            background: wgpu::Color {
                r: srgb_to_linear(bg[0] as f64),
                g: srgb_to_linear(bg[1] as f64),
                b: srgb_to_linear(bg[2] as f64),
                a: bg[3] as f64,
            },
            lights: scene.lights.len() as u32,
            point_lights: point_light_bits(&scene.lights),
            shadow_filter: shadow_caster(&scene.lights).map(|(_, _, s)| s.filter),
        };
        let mut encoder =
            ctx.device.create_command_encoder(&wgpu::CommandEncoderDescriptor { label: Some("frame") });
        let mut timed = Vec::new();
        for pass in &plan.passes {
            let timing = match (&f.res.queries, pass.timed()) {
                (Some((set, _)), true) => {
                    let i = 2 * timed.len() as u32;
                    timed.push(pass.name());
                    Some(wgpu::RenderPassTimestampWrites {
                        query_set: set,
                        beginning_of_pass_write_index: Some(i),
                        end_of_pass_write_index: Some(i + 1),
                    })
                }
                _ => None,
            };
            pass.encode(&f, &mut encoder, timing)?;
        }
        if let (Some((set, resolve)), Some(staging)) = (&f.res.queries, &f.res.staging) {
            let n = 2 * timed.len() as u32;
            if n > 0 {
                encoder.resolve_query_set(set, 0..n, resolve, 0);
                encoder.copy_buffer_to_buffer(resolve, 0, staging, plan.timestamp_offset(), n as u64 * 8);
            }
        }
        Ok((ctx.queue.submit([encoder.finish()]), timed))
    }

    /// Waits for the frame, then copies its mapped readbacks into `out`.
    #[allow(clippy::too_many_arguments)]
    fn read_back(
        &self,
        frame: &FrameSpec,
        p: &Prepared,
        res: &FrameResources,
        submission: wgpu::SubmissionIndex,
        mapped: Option<MapReceiver>,
        timed: &[&'static str],
        out: OutputBuffers<'_>,
    ) -> Result<GpuPart> {
        let ctx = &*self.ctx;
        let (plan, cam) = (&p.plan, &p.cam);
        let mut part = GpuPart::default();
        ctx.wait(submission, "the frame")?;
        let (Some(staging), Some(rx)) = (&res.staging, mapped) else {
            return Ok(part);
        };
        rx.recv()
            .map_err(|_| Error::Gpu("the readback was dropped".into()))?
            .map_err(|e| Error::Gpu(format!("reading the frame back: {e}")))?;
        let mapped =
            staging.get_mapped_range(..).map_err(|e| Error::Gpu(format!("reading the frame back: {e}")))?;
        let scale = cam.scale as f32;
        crate::parallel::install(|| {
            if let (Some(r), Some(o)) = (plan.color, out.color) {
                r.copy_bytes(&mapped, o);
            }
            if let Some(r) = plan.geometry {
                let layout = plan.shape.geometry.expect("a geometry readback has a layout");
                if let Some(o) = out.normal {
                    r.copy_words(&mapped, 0, 3, 1.0, o);
                }
                if let Some(o) = out.depth {
                    r.copy_words(&mapped, layout.depth_component(), 1, scale, o);
                }
                if plan.visible_lines {
                    let mut d = vec![0f32; frame.width as usize * frame.height as usize];
                    r.copy_words(&mapped, layout.depth_component(), 1, 1.0, &mut d);
                    part.line_depth = Some(d);
                }
            }
            if let (Some(r), Some(o)) = (plan.outline, out.outline) {
                r.copy_unorm8(&mapped, o);
            }
            if let (Some(r), Some(o)) = (plan.shadow, out.shadow) {
                r.copy_words(&mapped, 0, 1, 1.0, o);
            }
        });
        if !timed.is_empty() {
            let at = plan.timestamp_offset() as usize;
            let ticks: Vec<u64> = mapped[at..at + 16 * timed.len()]
                .chunks_exact(8)
                .map(|b| u64::from_le_bytes(b.try_into().expect("8 bytes")))
                .collect();
            part.set_gpu_times(timed, &ticks, ctx.queue.get_timestamp_period() as f64);
        }
        Ok(part)
    }

    /// The visible mesh-space lines as polylines, chained per kind.
    fn visible_lines(&self, scene: &Scene, frame: &FrameSpec, p: &Prepared, depth: &[f32]) -> Vec<Polyline> {
        let rule = p.visibility(frame);
        let img = DepthImage { depth, width: frame.width as usize, height: frame.height as usize };
        let mut out = Vec::new();
        for ((item, rec), view) in scene.items.iter().zip(&p.records).zip(&p.views) {
            let Some(outline) = view else { continue };
            let projector = p.projector(item, rec, frame);
            let positions = rec.lines.positions();
            let mut kinds: Vec<usize> = outline.kinds.iter().map(|&k| k as usize).collect();
            kinds.sort_unstable();
            kinds.dedup();
            for kind in kinds {
                let edges: Vec<[u32; 2]> = outline
                    .edges
                    .iter()
                    .zip(&outline.kinds)
                    .filter(|(_, k)| **k as usize == kind)
                    .map(|(e, _)| *e)
                    .collect();
                let (flat, starts) = chain_edges(&edges);
                for w in starts.windows(2) {
                    let chain = &flat[w[0] as usize..w[1] as usize];
                    let screen: Vec<_> = chain
                        .windows(2)
                        .filter_map(|s| {
                            projector.project(positions[s[0] as usize], positions[s[1] as usize], kind)
                        })
                        .collect();
                    out.extend(
                        visible_runs(&screen, p.cam.orthographic, &img, rule)
                            .into_iter()
                            .map(|points| Polyline { kind, points }),
                    );
                }
            }
        }
        out
    }
}

/// Frames a stream of views keeps submitted at once.
pub const IN_FLIGHT: usize = 3;

type MapReceiver = std::sync::mpsc::Receiver<std::result::Result<(), wgpu::BufferAsyncError>>;

/// A frame submitted to the GPU whose readback is not yet copied out.
struct InFlight {
    scene: Scene,
    frame: FrameSpec,
    prepared: Prepared,
    res: FrameResources,
    submission: wgpu::SubmissionIndex,
    mapped: Option<MapReceiver>,
    timed: Vec<&'static str>,
    start: Instant,
    report: FrameReport,
}

/// A frame's host-side preparation.
pub(crate) struct Prepared {
    pub records: Vec<Arc<MeshRecord>>,
    /// Per mesh, the faces the camera's passes and the shadow map skip (`render::culling`).
    pub culls: Vec<(Option<wgpu::Face>, Option<wgpu::Face>)>,
    pub cam: ResolvedCamera,
    /// What the scene's meshes fill (world space).
    pub sphere: Sphere,
    pub plan: Plan,
    /// Each mesh's lines for this view (when the plan draws or returns them).
    pub views: Vec<Option<Outline>>,
    pub outlines: Outlines,
    silhouette_seconds: f64,
}

impl Prepared {
    /// Projects one mesh's lines to pixels, in normalised view units (like the GPU).
    pub fn projector(&self, item: &SceneItem, rec: &MeshRecord, frame: &FrameSpec) -> Projector {
        Projector {
            model_view: model_view(item, &rec.gpu.placement, &self.cam),
            proj: self.cam.normalized_proj(),
            width: frame.width as f64,
            height: frame.height as f64,
            orthographic: self.cam.orthographic,
            near: self.cam.near / self.cam.scale,
        }
    }

    /// The hidden-line rule of this frame (depths in normalised view units).
    pub fn visibility(&self, frame: &FrameSpec) -> Visibility {
        Visibility {
            offset: self.outlines.depth_offset as f64,
            footprint: footprint(&self.cam, frame.height),
        }
    }
}

/// What the GPU half of a frame reports.
#[derive(Default)]
struct GpuPart {
    timings: Vec<(&'static str, f64)>,
    gpu_timed: bool,
    /// Normalised linear depth, for the visible-line step.
    line_depth: Option<Vec<f32>>,
}

impl GpuPart {
    /// GPU durations from begin/end tick pairs, kept only when they are plausible (some
    /// drivers report zeros or ticks that run backwards).
    fn set_gpu_times(&mut self, names: &[&'static str], ticks: &[u64], period_ns: f64) {
        let times: Vec<f64> =
            ticks.chunks_exact(2).map(|t| (t[1] as f64 - t[0] as f64) * period_ns * 1e-9).collect();
        let plausible = times.iter().all(|&s| s >= 0.0 && s < 3600.0) && times.iter().any(|&s| s > 0.0);
        if plausible {
            self.timings.extend(names.iter().copied().zip(times));
            self.gpu_timed = true;
        }
    }
}

/// The view of `cam` in a mesh's stored coordinates (for its silhouette test). The mesh's
/// placement is undone by subtracting and dividing, not by inverting a matrix whose
/// determinant may be out of float64's range.
fn stored_view(cam: &ResolvedCamera, model: DMat4, mesh: &GpuMesh) -> View {
    let to_model = model.inverse();
    let p = mesh.placement;
    if cam.orthographic {
        let d = to_model.transform_vector3(cam.forward);
        View::Direction(super::scene::camera::direction_of(d).to_array())
    } else {
        let e = (to_model.transform_point3(cam.eye) - DVec3::from_array(p.origin)) / p.scale;
        View::Eye(e.to_array())
    }
}

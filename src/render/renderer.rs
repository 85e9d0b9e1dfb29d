//! A renderer: meshes kept on the device, rendered in any number of scenes and views. A frame
//! is checked once (`CheckedScene`), planned (`plan`), its host steps run, recorded into one
//! command encoder, submitted once, and its readbacks are mapped once and copied straight into
//! the caller's arrays. The renderer runs whatever steps the plan lists without knowing which
//! effect they come from. Everything here may be called from several threads at once.

use std::collections::HashMap;
use std::sync::atomic::{AtomicU64, Ordering};
use std::sync::{Arc, Mutex};
use std::time::Instant;

use glam::DMat4;

use crate::cancel::Cancel;
use crate::error::{Error, Result};
use crate::mesh::back_to_back::{back_to_back_faces, kept};
use crate::real::{Real, Vec3};

use super::albedo::Albedo;
use super::color::srgb_to_linear;
use super::context::{context, GpuContext};
use super::culling::culls;
use super::derived_vertices::derived_buffer;
use super::device::{BackendChoice, GpuInfo};
use super::effects::frame::{check as check_effects, frame_bytes};
use super::framing::{flat_normal, scene_support, with_lines};
use super::gpu_mesh::{GpuMesh, MeshNormals};
use super::graph::effect::{FrameInputs, HostInputs, HostStep};
use super::graph::report::FrameReport;
use super::graph::resources::FrameResources;
use super::graph::target::Access;
use super::graph::{DrawItem, FrameCtx, Recorder};
use super::mesh_record::MeshRecord;
use super::passes::shade::variant::ShadingVariant;
use super::plan::{plan, Copy, Dest, Plan};
use super::scene::camera::{Camera, ResolvedCamera, SceneBounds, Sphere};
use super::scene::checked::{CheckedScene, DeviceLimits};
use super::scene::outputs::{Output, Pixel};
use super::scene::sequence::{sequence, SequenceFrame};
use super::scene::{FrameSpec, MeshId, Scene};
use super::shader::preamble;
use super::uniforms::draw_bytes;

/// The frame's background as the colour target is cleared to: linear RGB and alpha.
pub fn background_linear(frame: &FrameSpec) -> [f64; 4] {
    let bg = frame.background;
    [srgb_to_linear(bg[0] as f64), srgb_to_linear(bg[1] as f64), srgb_to_linear(bg[2] as f64), bg[3] as f64]
}

/// Where a render writes one image output, row-major, top row first.
pub enum ImageMut<'a> {
    Bytes(&'a mut [u8]),
    Floats(&'a mut [f32]),
}

/// Where a render writes its images: one buffer for each image output asked for, of the
/// output's size ((H, W, 4) colour, (H, W, 3) normals, (H, W) for the others).
#[derive(Default)]
pub struct OutputBuffers<'a> {
    images: HashMap<Output, ImageMut<'a>>,
}

impl<'a> OutputBuffers<'a> {
    pub fn set(&mut self, output: Output, image: ImageMut<'a>) {
        self.images.insert(output, image);
    }
}

/// An image output in a vector (see `Renderer::render`).
#[derive(Clone, Debug)]
pub enum Image {
    Bytes(Vec<u8>),
    Floats(Vec<f32>),
}

impl Image {
    /// Zeros for an `n`-pixel image of `output` (in huge pages where large, as NumPy's arrays).
    pub fn zeros(output: Output, n: usize) -> Option<Image> {
        Some(match output.pixel()? {
            Pixel::Bytes(k) => Image::Bytes(crate::huge_pages::filled_vec(k * n, 0)),
            Pixel::Floats(k) => Image::Floats(crate::huge_pages::filled_vec(k * n, 0.0)),
        })
    }

    pub fn as_mut(&mut self) -> ImageMut<'_> {
        match self {
            Image::Bytes(v) => ImageMut::Bytes(v),
            Image::Floats(v) => ImageMut::Floats(v),
        }
    }
}

/// The image outputs of one or more frames of one size, each output one vector that holds every
/// view's image in turn, so that a front end hands each to its arrays without a copy.
pub struct ViewImages {
    /// How many views; None for one whose images have no views' axis.
    views: Option<usize>,
    size: (u32, u32),
    /// Every image output, in `Output::ALL`'s order; None where the frame did not ask for it.
    images: Vec<(Output, Option<Image>)>,
}

impl ViewImages {
    /// Zeros for the image outputs of `views` frames of `frame` (None: one).
    pub fn zeros(frame: &FrameSpec, views: Option<usize>) -> ViewImages {
        let n = views.unwrap_or(1) * frame.width as usize * frame.height as usize;
        let image = |o| frame.outputs.has(o).then(|| Image::zeros(o, n)).flatten();
        let images = Output::ALL.into_iter().filter(|o| o.pixel().is_some()).map(|o| (o, image(o))).collect();
        ViewImages { views, size: (frame.height, frame.width), images }
    }

    /// One set of output buffers for each view (`Renderer::render_views`).
    pub fn buffers(&mut self) -> Vec<OutputBuffers<'_>> {
        let views = self.views.unwrap_or(1);
        let mut sets: Vec<OutputBuffers<'_>> = (0..views).map(|_| OutputBuffers::default()).collect();
        fn per_view<T>(v: &mut [T], views: usize) -> std::slice::ChunksMut<'_, T> {
            let n = (v.len() / views.max(1)).max(1);
            v.chunks_mut(n)
        }
        for (o, image) in &mut self.images {
            let views: Vec<ImageMut<'_>> = match image {
                Some(Image::Bytes(v)) => per_view(v, views).map(ImageMut::Bytes).collect(),
                Some(Image::Floats(v)) => per_view(v, views).map(ImageMut::Floats).collect(),
                None => continue,
            };
            for (set, v) in sets.iter_mut().zip(views) {
                set.set(*o, v);
            }
        }
        sets
    }

    /// Each image output with its shape (the views' axis first where there is one) and, where
    /// it was asked for, its values.
    pub fn shaped(self) -> impl Iterator<Item = (Output, Vec<usize>, Option<Image>)> {
        let (leading, (h, w)) = (self.views.into_iter().collect::<Vec<_>>(), self.size);
        self.images.into_iter().map(move |(o, image)| (o, o.shape(&leading, h, w).unwrap_or_default(), image))
    }
}

/// A render's images in vectors.
#[derive(Clone, Debug, Default)]
pub struct RenderOutput {
    pub width: u32,
    pub height: u32,
    pub images: HashMap<Output, Image>,
    pub report: FrameReport,
}

impl RenderOutput {
    pub fn bytes(&self, o: Output) -> Option<&[u8]> {
        match self.images.get(&o)? {
            Image::Bytes(v) => Some(v),
            Image::Floats(_) => None,
        }
    }

    pub fn floats(&self, o: Output) -> Option<&[f32]> {
        match self.images.get(&o)? {
            Image::Floats(v) => Some(v),
            Image::Bytes(_) => None,
        }
    }
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
        normals: impl Into<MeshNormals>,
    ) -> Result<MeshId> {
        self.add_mesh_with(positions, faces, normals, None).map(|(id, _)| id)
    }

    /// `add_mesh` with the mesh's colour and texture. Returns the id and notes for the caller
    /// (a texture larger than the device holds, downscaled).
    pub fn add_mesh_with<T: Real>(
        &self,
        positions: &[Vec3<T>],
        faces: Vec<[u32; 3]>,
        normals: impl Into<MeshNormals>,
        albedo: Option<Albedo>,
    ) -> Result<(MeshId, Vec<String>)> {
        self.upload(positions, faces, normals.into(), albedo, false)
    }

    /// Every upload: a mesh (`add_mesh_with`), or a point cloud's splats (`add_points`).
    pub(crate) fn upload<T: Real>(
        &self,
        positions: &[Vec3<T>],
        faces: Vec<[u32; 3]>,
        normals: MeshNormals,
        albedo: Option<Albedo>,
        splats: bool,
    ) -> Result<(MeshId, Vec<String>)> {
        self.ctx.check_process()?;
        crate::mesh::check_positions("vertices", positions)?;
        if let Some(bad) = faces.iter().flatten().find(|&&i| i as usize >= positions.len()) {
            return Err(Error::out_of_range(
                "faces",
                format!("vertex index {bad} is outside [0, {})", positions.len()),
            ));
        }
        let mut notes = vec![];
        let albedo = match albedo {
            Some(mut a) => {
                a.check(positions.len(), faces.len())?;
                let max = self.ctx.limits.max_texture_dimension_2d;
                if let Some(t) = a.texture.take() {
                    let (w, h) = (t.width, t.height);
                    let fitted = t.fitted(max);
                    if (fitted.width, fitted.height) != (w, h) {
                        notes.push(format!(
                            "texture: {h} x {w} pixels is larger than this GPU's limit of {max}; \
                             downscaled to {} x {}",
                            fitted.height, fitted.width
                        ));
                    }
                    a.texture = Some(fitted);
                }
                Some(a)
            }
            None => None,
        };
        // a sheet stored double-sided is drawn once, or its shared vertices' normals cancel
        // (splats share no vertices and carry their own normals: nothing to look for)
        let twins =
            if splats { None } else { crate::parallel::install(|| back_to_back_faces(&faces, None))? };
        let (faces, albedo) = match twins {
            Some(keep) => {
                let twins = keep.iter().filter(|k| !**k).count();
                notes.push(format!(
                    "{twins} of the {} faces lie back to back with another face (a sheet stored \
                     double-sided); each pair is drawn once, as the first of the two",
                    faces.len()
                ));
                (kept(&faces, &keep), albedo.map(|a| a.keeping_faces(&keep)))
            }
            None => (faces, albedo),
        };
        let (gpu, host) = crate::parallel::install(|| {
            GpuMesh::upload_with(&self.ctx, positions, faces, normals, albedo.as_ref())
        })?;
        let id = self.next_id.fetch_add(1, Ordering::Relaxed);
        self.meshes
            .lock()
            .unwrap_or_else(|e| e.into_inner())
            .insert(id, Arc::new(MeshRecord::new(gpu, host).marked_splats(splats)));
        Ok((id, notes))
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

    /// Checks a scene and frame before any work: everything a render would refuse.
    pub fn check(&self, scene: Scene, frame: FrameSpec) -> Result<CheckedScene> {
        self.ctx.check_process()?;
        let info = &self.ctx.info;
        let limits =
            DeviceLimits { max_texture_size: info.max_texture_size, msaa_samples: info.msaa_samples.clone() };
        let mut checked = CheckedScene::check(scene, frame, &limits)?;
        check_effects(&checked)?;
        for (i, item) in checked.scene.items.iter_mut().enumerate() {
            let rec = self.mesh(item.mesh).map_err(|e| match e {
                Error::InvalidValue { reason, .. } => Error::invalid(format!("meshes[{i}]"), reason),
                other => other,
            })?;
            item.splats = rec.splats;
        }
        Ok(checked)
    }

    /// Renders into newly allocated vectors.
    pub fn render(&self, scene: &Scene, frame: &FrameSpec) -> Result<RenderOutput> {
        let n = frame.width as usize * frame.height as usize;
        let mut images: HashMap<Output, Image> =
            frame.outputs.iter().filter_map(|o| Some((o, Image::zeros(o, n)?))).collect();
        let mut out = OutputBuffers::default();
        for (o, image) in images.iter_mut() {
            out.set(*o, image.as_mut());
        }
        let report = self.render_into(scene, frame, out)?;
        Ok(RenderOutput { width: frame.width, height: frame.height, images, report })
    }

    /// Renders `scene` as `frame` asks, running only the steps its plan lists, into `out`.
    pub fn render_into(
        &self,
        scene: &Scene,
        frame: &FrameSpec,
        out: OutputBuffers<'_>,
    ) -> Result<FrameReport> {
        self.render_checked(self.check(scene.clone(), *frame)?, out)
    }

    /// Renders a scene `check` passed into `out`.
    pub fn render_checked(&self, scene: CheckedScene, out: OutputBuffers<'_>) -> Result<FrameReport> {
        let f = self.submit(scene)?;
        self.finish(f, out)
    }

    /// Renders a checked scene once from each of `cameras` into `outs` (one set of buffers a
    /// view), keeping `IN_FLIGHT` frames submitted at once so that the GPU draws one while the
    /// host reads the last back. Gives the same bits as rendering each view alone, except for
    /// suggestive contours with coherence on (`Outlines::suggestive_coherence`), which hold
    /// still across related views (`edges::coherence`). `cancel` is
    /// checked between frames: once raised, the frames in flight are waited for and dropped and
    /// the call returns `Error::Interrupted`.
    pub fn render_views(
        &self,
        scene: &CheckedScene,
        cameras: &[Camera],
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
            let mut frames = self.sequence(scene, cameras)?.into_iter();
            for camera in cameras {
                cancel.check()?;
                let frame = scene.with_camera(*camera).in_sequence(frames.next());
                in_flight.push_back(self.submit(frame)?);
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

    /// Each frame's place in the sequence of `cameras`, where their suggestive contours hold
    /// still (`sequence`); nothing for one camera or a scene without them.
    fn sequence(&self, scene: &CheckedScene, cameras: &[Camera]) -> Result<Vec<SequenceFrame>> {
        if cameras.len() < 2 || !scene.scene.outlines.as_ref().is_some_and(|o| o.holds_suggestive_still()) {
            return Ok(Vec::new());
        }
        let resolved: Vec<ResolvedCamera> =
            cameras.iter().map(|c| Ok(self.resolve(&scene.with_camera(*c))?.2)).collect::<Result<_>>()?;
        Ok(sequence(&resolved, scene.scene.items.len()))
    }

    /// The scene's meshes (in the order of its items), its bounds, and its camera resolved for
    /// them and the frame's aspect.
    pub(crate) fn resolve(
        &self,
        scene: &CheckedScene,
    ) -> Result<(Vec<Arc<MeshRecord>>, SceneBounds, ResolvedCamera)> {
        let records: Vec<Arc<MeshRecord>> =
            scene.scene.items.iter().map(|i| self.mesh(i.mesh)).collect::<Result<_>>()?;
        let bounds = scene
            .scene
            .bounds(|id| Ok(self.mesh(id)?.gpu.sphere()), |id| Ok(self.mesh(id)?.gpu.bounding_box()))?;
        let frame = &scene.frame;
        let cam = {
            let (items, center) = (&scene.scene.items, bounds.sphere.center);
            let support = with_lines(scene_support(items, &records, center), &scene.scene.lines, center);
            // only a fitted camera given no direction looks for a flat scene's front
            let flat =
                scene.scene.camera.fits_by_default().then(|| flat_normal(items, &records, center, &support));
            scene.scene.camera.resolve_with(
                &bounds,
                &support,
                flat.flatten(),
                frame.width as f64 / frame.height as f64,
            )?
        };
        Ok((records, bounds, cam))
    }

    /// Everything a frame needs before the GPU: the meshes, the camera, the plan, and its host
    /// steps before the frame (timed into `report`).
    pub(crate) fn prepare(&self, mut scene: CheckedScene, report: &mut FrameReport) -> Result<Prepared> {
        let (records, bounds, cam) = self.resolve(&scene)?;
        scene.mark_blended(|i| records[i].gpu.albedo.as_ref().is_some_and(|a| a.alpha_blend));
        let frame = &scene.frame;
        if frame.outputs.has(Output::Depth) && !DEPTH_SCALE_RANGE.contains(&cam.scale) {
            return Err(Error::invalid(
                "outputs",
                format!(
                    "'depth': the scene's depths (about {:e}) are outside float32's range; \
                     render the colour or normals, or rescale the scene",
                    cam.scale
                ),
            ));
        }
        let plan = plan(&scene);
        // each item's culling, and the vertex data its shading derives from the mesh
        let (culls, derived): (Vec<_>, Vec<_>) = scene
            .scene
            .items
            .iter()
            .zip(&records)
            .map(|(item, rec)| {
                let g = &rec.gpu;
                let variant = ShadingVariant::of(&item.material, g.albedo.as_ref());
                let derived: Result<Vec<_>> = variant
                    .derived()
                    .map(|part| {
                        Ok((
                            part.buffer.as_ref().map_or(0, |b| b.slot),
                            derived_buffer(&self.ctx, rec, part)?,
                        ))
                    })
                    .collect();
                (culls(item, g.enclosure, g.placement.origin.into(), g.radius, &cam), derived)
            })
            .unzip();
        let derived = derived.into_iter().collect::<Result<_>>()?;
        let p = Prepared { scene, records, culls, cam, sphere: bounds.sphere, plan, derived };
        p.run_host(&p.plan.host_before, None, report)?;
        Ok(p)
    }

    /// Prepares, records and submits one frame, and asks for its readback to be mapped.
    fn submit(&self, scene: CheckedScene) -> Result<InFlight> {
        let start = Instant::now();
        let (width, height, up) = (scene.frame.width, scene.frame.height, scene.scene.up.name());
        let mut report = FrameReport { width, height, up, ..Default::default() };
        let p = self.prepare(scene, &mut report)?;
        report.passes = p.plan.names();
        report.view = rows(p.cam.view);
        report.proj = rows(p.cam.proj);
        report.near = p.cam.near;
        report.far = p.cam.far;
        report.culled = p.culls.iter().map(|c| c.0.is_some()).collect();
        let ctx = &*self.ctx;
        let device = &ctx.device;
        let key = p.plan.resource_key(ctx.info.timestamps);
        let mut res = ctx.frames.take(ctx, &ctx.pipelines.layouts, &key);
        // Error scopes are per thread, so concurrent renders each see only their own errors.
        let validation = device.push_error_scope(wgpu::ErrorFilter::Validation);
        let memory = device.push_error_scope(wgpu::ErrorFilter::OutOfMemory);
        let recorded = self.record_and_submit(&p, &mut res);
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
        Ok(InFlight { prepared: p, res, submission, mapped, timed, start, report })
    }

    /// Waits for a submitted frame, copies its readbacks into `out`, runs the host steps after
    /// the frame, and finishes its report.
    fn finish(&self, f: InFlight, out: OutputBuffers<'_>) -> Result<FrameReport> {
        let InFlight { prepared: p, res, submission, mapped, timed, start, mut report } = f;
        let t = Instant::now();
        let read = self.read_back(&p, &res, submission, mapped, &timed, out);
        if let Some(staging) = &res.staging {
            staging.unmap();
        }
        self.ctx.frames.give_back(res);
        let part = read?;
        report.timings.extend(part.timings);
        report.timings.push(("readback", t.elapsed().as_secs_f64()));
        report.gpu_timed = part.gpu_timed;
        p.run_host(&p.plan.host_after, part.host_depth.as_deref(), &mut report)?;
        report.timings.push(("frame", start.elapsed().as_secs_f64()));
        Ok(report)
    }

    /// Records the frame's passes into one command encoder and submits it. Returns the
    /// submission and the passes timed on the GPU, in order.
    fn record_and_submit(
        &self,
        p: &Prepared,
        res: &mut FrameResources,
    ) -> Result<(wgpu::SubmissionIndex, Vec<&'static str>)> {
        let (scene, plan, cam, records) = (&p.scene, &p.plan, &p.cam, &p.records);
        let ctx = &*self.ctx;
        let layouts = &ctx.pipelines.layouts;
        let items = &scene.scene.items;
        res.reserve_draws(ctx, layouts, items.len());
        let draws: Vec<Vec<u8>> =
            items.iter().zip(records).map(|(item, rec)| draw_bytes(item, &rec.gpu.placement, cam)).collect();
        let frame = frame_bytes(&FrameInputs { scene, cam, sphere: p.sphere });
        res.write_uniforms(ctx, &frame, &draws);
        let draws: Vec<DrawItem> = items
            .iter()
            .zip(records)
            .zip(&p.culls)
            .enumerate()
            .map(|(i, ((item, rec), &(cull, light_cull)))| DrawItem {
                mesh: &rec.gpu,
                uniform_offset: res.draw_offset(i),
                material: &item.material,
                cull,
                light_cull,
                derived: &p.derived[i],
                glass: scene.glass[i],
            })
            .collect();
        let [r, g, b, a] = background_linear(&scene.frame);
        let f = FrameCtx {
            dev: ctx,
            pipelines: &ctx.pipelines,
            res,
            shape: plan.shape,
            draws: &draws,
            preamble: preamble(),
            background: wgpu::Color { r, g, b, a },
            lights: scene.shader_lights.len() as u32,
            point_lights: scene.point_lights,
        };
        let mut encoder =
            ctx.device.create_command_encoder(&wgpu::CommandEncoderDescriptor { label: Some("frame") });
        let mut timed = Vec::new();
        let mut drawn = false;
        for pass in &plan.passes {
            if ctx.is_gl && !drawn && pass.uses().iter().any(|u| u.1 == Access::CopyFrom) {
                // GL (Mesa's llvmpipe): a copy out of a texture recorded after the passes that
                // draw it may read it as the last frame left it (1 frame in 4 in a test); the
                // drawing is submitted and waited for first, so the copies read this frame's.
                drawn = true;
                let next = ctx
                    .device
                    .create_command_encoder(&wgpu::CommandEncoderDescriptor { label: Some("readback") });
                let drawing = ctx.queue.submit([std::mem::replace(&mut encoder, next).finish()]);
                ctx.wait(drawing, "the frame")?;
            }
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
            pass.encode(&f, &mut Recorder { encoder: &mut encoder, timing })?;
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
    fn read_back(
        &self,
        p: &Prepared,
        res: &FrameResources,
        submission: wgpu::SubmissionIndex,
        mapped: Option<MapReceiver>,
        timed: &[&'static str],
        mut out: OutputBuffers<'_>,
    ) -> Result<GpuPart> {
        let ctx = &*self.ctx;
        let plan = &p.plan;
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
        let scale = p.cam.scale as f32;
        let n = p.scene.frame.width as usize * p.scene.frame.height as usize;
        crate::parallel::install(|| {
            for read in &plan.reads {
                for &(dest, copy) in &read.copies {
                    match dest {
                        Dest::Output(o) => {
                            if let Some(image) = out.images.get_mut(&o) {
                                copy_region(&read.region, &mapped, copy, scale, reborrow(image));
                            }
                        }
                        Dest::HostDepth => {
                            let mut depth = vec![0f32; n];
                            copy_region(&read.region, &mapped, copy, scale, ImageMut::Floats(&mut depth));
                            part.host_depth = Some(depth);
                        }
                    }
                }
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
}

fn reborrow<'a>(image: &'a mut ImageMut<'_>) -> ImageMut<'a> {
    match image {
        ImageMut::Bytes(b) => ImageMut::Bytes(b),
        ImageMut::Floats(f) => ImageMut::Floats(f),
    }
}

/// Copies one region of the mapped readback into an image, as `copy` says (`scale` takes
/// normalised depths to world units).
fn copy_region(
    region: &crate::render::passes::readback::Region,
    mapped: &[u8],
    copy: Copy,
    scale: f32,
    image: ImageMut<'_>,
) {
    match (copy, image) {
        (Copy::Bytes, ImageMut::Bytes(o)) => region.copy_bytes(mapped, o),
        (Copy::Words { first, keep, world }, ImageMut::Floats(o)) => {
            region.copy_words(mapped, first, keep, if world { scale } else { 1.0 }, o)
        }
        (Copy::Unorm8, ImageMut::Floats(o)) => region.copy_unorm8(mapped, o),
        (copy, _) => unreachable!("{copy:?} into an image of the other element type"),
    }
}

/// Frames a stream of views keeps submitted at once.
pub const IN_FLIGHT: usize = 3;

type MapReceiver = std::sync::mpsc::Receiver<std::result::Result<(), wgpu::BufferAsyncError>>;

/// A frame submitted to the GPU whose readback is not yet copied out.
struct InFlight {
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
    pub scene: CheckedScene,
    pub records: Vec<Arc<MeshRecord>>,
    /// Per mesh, the faces the camera's passes and the shadow map skip (`render::culling`).
    pub culls: Vec<(Option<wgpu::Face>, Option<wgpu::Face>)>,
    pub cam: ResolvedCamera,
    /// What the scene's meshes fill (world space).
    pub sphere: Sphere,
    pub plan: Plan,
    /// Per mesh, the vertex buffers its shading derives from it, each with its slot.
    pub derived: Vec<Vec<(u32, Arc<wgpu::Buffer>)>>,
}

impl Prepared {
    /// Runs host steps in order, each timed under its name.
    fn run_host(
        &self,
        steps: &[Box<dyn HostStep>],
        depth: Option<&[f32]>,
        report: &mut FrameReport,
    ) -> Result<()> {
        let cx = HostInputs { scene: &self.scene, cam: &self.cam, records: &self.records, depth };
        for step in steps {
            let t = Instant::now();
            step.run(&cx, report)?;
            report.timings.push((step.name(), t.elapsed().as_secs_f64()));
        }
        Ok(())
    }
}

/// What the GPU half of a frame reports.
#[derive(Default)]
struct GpuPart {
    timings: Vec<(&'static str, f64)>,
    gpu_timed: bool,
    /// Normalised linear depth, for the host steps after the frame.
    host_depth: Option<Vec<f32>>,
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

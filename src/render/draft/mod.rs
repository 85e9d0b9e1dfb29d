//! Drafts drawn elsewhere: what a WebGL2 page needs to draw a scene with the renderer's own
//! shaders while the view moves, the exact frame following from the renderer.
//!
//! `Renderer::draft` gives, for a checked scene: the GL programs (the shading pass's stages for
//! each mesh's variant, and the image-space ink's two fragment passes, `edge_bits` and `edges`,
//! around `vs_fullscreen`), all translated from the composed WGSL by naga (`glsl`); the bytes of
//! the `Frame` uniform struct and of each mesh's `Draw`, with where each field lies in them, so
//! that the page rewrites only the camera's fields per frame; the meshes' vertex, index and
//! colour buffers as the renderer uploaded them, with their layouts; the lights as they are
//! before the view turns them; and the steps of the exact frame the draft leaves out (mesh-space
//! lines, hatching, shadows, paper, multisampling, supersampling); and, for a scene of more faces
//! than a small draft has pixels, a coarse copy of its large meshes (`lod`) that the page draws
//! while it draws smaller than the exact frame. The page's own code is plumbing: GL calls, and
//! the camera's matrices from its eye, target and up.

pub mod glsl;
pub mod lines;
pub mod lod;

use std::collections::BTreeMap;

use glam::DMat4;
use serde::Serialize;

use crate::edges::outlines::LineKind;
use crate::error::{Error, Result};
use crate::render::block::BlockLayout;
use crate::render::derived_vertices::derived_buffer;
use crate::render::effects::frame::{frame_bytes, frame_members};
use crate::render::effects::outlines::ink::INK_OVER;
use crate::render::effects::outlines::settings::ImageRule;
use crate::render::effects::outlines::settings::{DEFAULT_WIDTH, INK_KINDS};
use crate::render::effects::outlines::{edge_bits, edges, EFFECT as OUTLINES};
use crate::render::gpu_albedo;
use crate::render::gpu_mesh::GpuMesh;
use crate::render::graph::build::nearest_wins;
use crate::render::graph::effect::{FrameEffect, FrameInputs};
use crate::render::graph::mesh_stages::MeshStages;
use crate::render::graph::target::GeometryLayout;
use crate::render::graph::{geometry_clear, mesh_pass_wgsl, module_wgsl};
use crate::render::passes::shade::{self, variant::ShadingVariant};
use crate::render::plan::plan;
use crate::render::renderer::{background_linear, Renderer};
use crate::render::scene::checked::CheckedScene;
use crate::render::scene::light::Space;
use crate::render::shader::preamble;
use crate::render::stage_part::{Part, VertexData};
use crate::render::uniforms::{draw_bytes, draw_members, lighting_block, model_matrix, LightSlot, Members};

use glsl::GlslProgram;

/// The passes of the exact frame a draft draws too (or that give nothing to see).
const DRAWN: &[&str] = &["shade", "edge_bits", "edges", "silhouettes", "lines", "gbuffer", "clear_outline"];

/// What a draft leaves out of a scene with `Lines` items.
const LINE_ITEMS: &str = "the scene's own lines (tm.Lines)";

/// What a step of the exact frame that a draft leaves out draws, in the words a tooltip uses.
fn described(step: &str) -> &str {
    match step {
        "visible_lines" => "mesh-space lines",
        "shadow_map" | "shadow" => "shadows",
        "downsample" => "supersampling",
        "intersections" => "intersection lines",
        "glass_clear" | "glass_peel" | "glass_under" | "glass_composite" => "exact transparency",
        "glass_lines" => "glass's own lines",
        "item_lines" => LINE_ITEMS,
        other => other,
    }
}

/// A field of a uniform struct: its byte offset and size.
#[derive(Clone, Debug, Serialize)]
pub struct Field {
    pub name: String,
    pub offset: usize,
    pub size: usize,
}

/// Where a stretch of the draft's data lies in its one byte blob.
#[derive(Clone, Copy, Debug, Serialize)]
pub struct Span {
    pub offset: usize,
    pub length: usize,
}

/// A vertex attribute: its location, its component count (4-byte floats, or unsigned integers
/// where `integer`), its byte offset in its buffer.
#[derive(Clone, Debug, Serialize)]
pub struct Attribute {
    pub location: u32,
    pub components: u32,
    pub offset: u64,
    pub integer: bool,
}

/// A vertex buffer a program reads: which of the mesh's buffers, its stride, its attributes.
#[derive(Clone, Debug, Serialize)]
pub struct VertexBuffer {
    /// The stage part that reads it: "position" (positions and normals: the mesh's `vertices`),
    /// "albedo" (colour and texture coordinates), a part of `DraftMesh::derived` ("field": the
    /// hatching's stripe values), or "lines" and "contours" (`DraftLines`: one record per
    /// strip).
    pub buffer: &'static str,
    pub stride: u64,
    pub attributes: Vec<Attribute>,
}

/// A mesh's texture: its full-size level (sRGB RGBA8, rows top first) and its sampling.
#[derive(Clone, Debug, Serialize)]
pub struct DraftTexture {
    pub width: u32,
    pub height: u32,
    pub texels: Span,
    /// "linear" (mipmapped) or "nearest".
    pub filter: &'static str,
    /// "repeat", "clamp" or "mirror".
    pub wrap: &'static str,
}

/// A mesh's coarse copy (`lod`): its vertex and albedo buffers, in the layouts of the mesh's
/// own, and its u32 indices.
#[derive(Clone, Debug, Serialize)]
pub struct DraftCoarse {
    pub vertices: Span,
    pub albedo: Option<Span>,
    pub indices: Span,
    pub count: u32,
    /// The smooth contours drawn with it (where the mesh's are): those of a copy coarser still
    /// (`CONTOUR_COARSENING`), its vertices in the layout of the mesh's own.
    pub contours: Option<DraftContours>,
}

/// How many times fewer faces the copy whose smooth contours a smaller draft draws has than the
/// coarse copy it shades: each contour face is a strip of four vertices whose stage traces the
/// face's zero set, the costliest part of a small draft where the browser draws on the CPU
/// (SwiftShader: a quarter-size 512x512 bunny with ink took 47 ms with the shaded copy's
/// contours, 16 ms without them; 27 ms with a copy of a quarter of the faces, 18 ms without
/// its contours), and a face per 64 pixels of the exact frame is still one per two pixels of a
/// quarter-size draft's width.
const CONTOUR_COARSENING: usize = 8;

/// The output pixels of the exact frame a face of the coarse copies stands for: a draft at a
/// quarter of its width and height (the page's least) has about one and a third faces a pixel
/// (at 8, two, the drafts that draw mesh lines kept 73% of a plain WebGL2 program's frame rate
/// in the viewer's benchmark; at 12, 81-84%).
const PIXELS_PER_COARSE_FACE: usize = 12;

/// One mesh of the scene.
#[derive(Clone, Debug, Serialize)]
pub struct DraftMesh {
    /// Its program in `Draft::programs`.
    pub program: usize,
    pub vertex_buffers: Vec<VertexBuffer>,
    pub vertices: Span,
    pub albedo: Option<Span>,
    /// u32 indices (None: the vertices are drawn as a list).
    pub indices: Option<Span>,
    pub count: u32,
    /// Its `Draw` struct's bytes.
    pub draw: Span,
    /// Stored coordinates -> world, column-major: the page's model-view is the normalised view
    /// times this.
    pub model: [f64; 16],
    pub texture: Option<DraftTexture>,
    /// The vertex data its stages derive from it (the hatching field's stripe values), by the
    /// stage part that reads each, per vertex of `vertices`.
    pub derived: BTreeMap<&'static str, Span>,
    /// Its coarse copy, drawn instead while a draft is drawn smaller than the exact frame (None:
    /// the mesh is small enough as it is, or its stages read derived data, which the copy has
    /// not).
    pub coarse: Option<DraftCoarse>,
    /// Its mesh-space lines (`lines`), drawn with the `Draft::lines` program, and the mesh its
    /// smooth contours are traced on, drawn with `Draft::contours`.
    pub lines: Option<DraftLines>,
    pub contours: Option<DraftContours>,
    /// Glass (`checked::is_glass`): its material's opacity, which the page blends it by, drawn
    /// after the opaque meshes without writing depth or the geometry target (the exact frame
    /// composites every layer in depth order, and the colour's own alpha); None: opaque.
    pub opacity: Option<f64>,
}

/// A mesh for smooth contours (`lines::ContourFaces`): its vertices (`Draft::contour_vertices`)
/// and its u32 faces, of which the page gathers each face's `lines::FaceContour` record.
#[derive(Clone, Debug, Serialize)]
pub struct DraftContours {
    pub vertices: Span,
    pub faces: Span,
    pub count: u32,
}

/// The records of a lines program: `lines::ViewEdge` or `lines::FaceContour`, each drawn as a
/// strip of 4 vertices (two triangles) that all read it.
#[derive(Clone, Debug, Serialize)]
pub struct DraftLines {
    pub instances: Span,
    pub count: u32,
}

/// A light's slot as the view turns it: `world` lights turn with the view (in the lighting
/// block they are given as seen from an unturned view), camera lights stay.
#[derive(Clone, Debug, Serialize)]
pub struct DraftLight {
    pub world: bool,
    /// The byte offset in the frame's bytes of its position (xyz, w: 0 a direction, 1 a point).
    pub position: usize,
}

/// The camera the draft's bytes were written for.
#[derive(Clone, Debug, Serialize)]
pub struct DraftCamera {
    /// The normalisation: the GPU works in view space divided by it.
    pub scale: f64,
    pub orthographic: bool,
    /// The vertical field of view (radians) or the view's height (world units).
    pub fov_or_height: f64,
    pub near: f64,
    pub far: f64,
    pub eye: [f64; 3],
    pub forward: [f64; 3],
    /// The output size the view block was written for, and its pixel ratio (the ink's widths
    /// in `pixel_widths` include it).
    pub width: u32,
    pub height: u32,
    pub pixel_ratio: f64,
    /// The sphere around the scene (world): clip planes that enclose it.
    pub center: [f64; 3],
    pub radius: f64,
}

/// Everything a page needs to draw drafts of a scene.
#[derive(Clone, Debug, Serialize)]
pub struct Draft {
    /// The shading programs, then `edge_bits` and `edges` when the scene has image-space ink.
    pub programs: Vec<GlslProgram>,
    /// `edge_bits` and `edges` in `programs` (the image-space ink), and the rule: under the
    /// paper's the edges read the geometry target directly (no `edge_bits`).
    pub edge_bits: Option<usize>,
    pub edges: Option<usize>,
    /// The mesh-space lines' program in `programs` (the exact frame's `lines` pass, its
    /// silhouettes decided per view: `lines`), and the layout of each mesh's `DraftLines`.
    pub lines: Option<usize>,
    pub line_buffer: Option<VertexBuffer>,
    /// The smooth contours' program (`vs_face_contour` with the lines' `fs_color`), the layout
    /// of its face records, and that of the vertices they are gathered from (the mesh's own).
    pub contours: Option<usize>,
    pub contour_buffer: Option<VertexBuffer>,
    pub contour_vertices: Option<VertexBuffer>,
    pub meshes: Vec<DraftMesh>,
    pub frame: Span,
    pub frame_fields: Vec<Field>,
    pub draw_fields: Vec<Field>,
    /// The byte offsets in the frame's bytes of the f32s measured in output pixels (the ink's
    /// widths): a draft drawn smaller scales them.
    pub pixel_widths: Vec<usize>,
    /// The same in each draw's bytes (the dither's cell).
    pub draw_pixel_lengths: Vec<usize>,
    /// A draft drawn smaller draws the ink at least this many of its pixels wide (or as wide as
    /// the style, where that is less): the default line's width, so lines stay visible.
    pub least_ink_width: f32,
    pub lights: Vec<DraftLight>,
    pub camera: DraftCamera,
    /// The colour target's clear value (linear RGBA) and the geometry target's (u32 bits), and
    /// the geometry target's GL format (the shading pass writes it; the ink reads it).
    pub background: [f64; 4],
    pub geometry_clear: Option<[u32; 4]>,
    pub geometry_format: Option<&'static str>,
    /// GL state the translated stages assume: the winding GL calls front (the y flip of
    /// `ADJUST_COORDINATE_SPACE` turns wgpu's counter-clockwise around) and the depth test.
    pub front_face: &'static str,
    pub depth_compare: &'static str,
    /// The image ink's blending over the colour (GL's source and destination factors).
    pub ink_blend: [&'static str; 2],
    /// What the exact frame draws that the draft leaves out.
    pub left_to_exact: Vec<String>,
    /// The page draws the coarse copies while they have a face for at most this many of the
    /// draft's pixels (a draft smaller than the frame they were made for).
    pub pixels_per_coarse_face: usize,
}

fn fields(members: &Members) -> Vec<Field> {
    let mut out = Vec::new();
    let mut at = 0;
    for (member, block) in members {
        let BlockLayout { size, fields, .. } = block;
        for (name, offset, len) in fields {
            out.push(Field { name: format!("{member}.{name}"), offset: at + offset, size: *len });
        }
        at += size;
    }
    out
}

/// GL's name of a depth test.
fn gl_compare(c: Option<wgpu::CompareFunction>) -> &'static str {
    match c {
        Some(wgpu::CompareFunction::Less) => "LESS",
        Some(wgpu::CompareFunction::LessEqual) => "LEQUAL",
        _ => "ALWAYS",
    }
}

/// GL's name of a blend factor the ink uses.
fn gl_factor(f: wgpu::BlendFactor) -> &'static str {
    match f {
        wgpu::BlendFactor::One => "ONE",
        wgpu::BlendFactor::OneMinusSrcAlpha => "ONE_MINUS_SRC_ALPHA",
        wgpu::BlendFactor::SrcAlpha => "SRC_ALPHA",
        _ => "ZERO",
    }
}

fn cols(m: DMat4) -> [f64; 16] {
    m.to_cols_array()
}

/// The bytes of a device buffer.
fn read_buffer(r: &Renderer, buffer: &wgpu::Buffer) -> Result<Vec<u8>> {
    let dev = r.context();
    let staging = dev.device.create_buffer(&wgpu::BufferDescriptor {
        label: Some("draft readback"),
        size: buffer.size(),
        usage: wgpu::BufferUsages::MAP_READ | wgpu::BufferUsages::COPY_DST,
        mapped_at_creation: false,
    });
    let mut enc = dev.device.create_command_encoder(&wgpu::CommandEncoderDescriptor { label: Some("draft") });
    enc.copy_buffer_to_buffer(buffer, 0, &staging, 0, buffer.size());
    let submission = dev.queue.submit([enc.finish()]);
    staging.map_async(wgpu::MapMode::Read, .., |_| {});
    dev.wait(submission, "a draft's mesh")?;
    let bytes = staging
        .get_mapped_range(..)
        .map_err(|e| Error::Internal(format!("reading a mesh back for a draft: {e}")))?
        .to_vec();
    Ok(bytes)
}

/// The blob the draft's spans point into.
#[derive(Default)]
struct Blob(Vec<u8>);

impl Blob {
    /// Appends `bytes` (4-byte aligned, for typed arrays over it).
    fn push(&mut self, bytes: &[u8]) -> Span {
        while self.0.len() % 4 != 0 {
            self.0.push(0);
        }
        let span = Span { offset: self.0.len(), length: bytes.len() };
        // grown to what it holds, not doubled: a freed block of twice the size would raise the
        // allocator's threshold for giving memory back (glibc's dynamic mmap threshold), and a
        // kernel making drafts would keep more of its memory
        self.0.reserve_exact(bytes.len());
        self.0.extend_from_slice(bytes);
        span
    }

    /// Appends what `write` appends (4-byte aligned), without a copy in between.
    fn push_with(&mut self, write: impl FnOnce(&mut Vec<u8>)) -> Span {
        while self.0.len() % 4 != 0 {
            self.0.push(0);
        }
        let offset = self.0.len();
        write(&mut self.0);
        Span { offset, length: self.0.len() - offset }
    }
}

/// The buffer `name` of `layout`, as the page reads it.
fn vertex_buffer(name: &'static str, layout: &wgpu::VertexBufferLayout) -> VertexBuffer {
    use wgpu::VertexFormat as V;
    let attributes = layout
        .attributes
        .iter()
        .map(|a| Attribute {
            location: a.shader_location,
            components: (a.format.size() / 4) as u32,
            offset: a.offset,
            integer: matches!(a.format, V::Uint32 | V::Uint32x2 | V::Uint32x3 | V::Uint32x4),
        })
        .collect();
    VertexBuffer { buffer: name, stride: layout.array_stride, attributes }
}

fn vertex_buffers(stages: &MeshStages) -> Vec<VertexBuffer> {
    let buffer = |(part, data): (&'static Part, &VertexData)| vertex_buffer(part.name, &(data.layout)());
    stages.buffers().into_iter().map(buffer).collect()
}

/// The pixel lengths of a mesh's `Draw` (fields measured in output pixels), which a draft drawn
/// smaller scales: the dither's cell, the hatching's spacing and stroke width.
const DRAW_PIXEL_LENGTHS: &[&str] = &["dither.cell", "hatching.spacing", "hatching.width"];

/// The geometry target's GL format.
fn gl_geometry_format(layout: GeometryLayout) -> &'static str {
    match layout.format() {
        wgpu::TextureFormat::Rgba32Uint => "RGBA32UI",
        _ => "R32UI",
    }
}

/// The lines' records in `blob` (None: none).
fn line_records<T: bytemuck::Pod>(blob: &mut Blob, records: &[T]) -> Option<DraftLines> {
    (!records.is_empty()).then(|| DraftLines {
        instances: blob.push(bytemuck::cast_slice(records)),
        count: records.len() as u32,
    })
}

/// The coarse copy (`lod`) of a mesh as uploaded, with at most `most_faces` faces.
fn coarse_copy(
    vertices: &[u8],
    indices: Option<&[u8]>,
    albedo: Option<&[u8]>,
    count: u32,
    most_faces: usize,
) -> Option<lod::Coarse> {
    let layout = GpuMesh::vertex_layout();
    let [position, normal] = [0, 1].map(|k| layout.attributes.get(k).map(|a| a.offset as usize));
    let layout = lod::PositionLayout { stride: layout.array_stride as usize, position: position?, normal };
    let indices: Option<Vec<u32>> =
        indices.map(|b| b.chunks_exact(4).map(|x| u32::from_le_bytes([x[0], x[1], x[2], x[3]])).collect());
    let albedo = albedo.map(|a| (a, gpu_albedo::vertex_layout().array_stride as usize));
    let mesh = lod::Uploaded { vertices, layout, albedo, indices: indices.as_deref(), count: count as usize };
    lod::coarse(&mesh, most_faces)
}

impl Renderer {
    /// The draft of `scene` from its camera (see the module's documentation), and the blob of
    /// bytes its spans point into.
    pub fn draft(&self, scene: &CheckedScene) -> Result<(Draft, Vec<u8>)> {
        let (records, bounds, cam) = self.resolve(scene)?;
        let frame = &scene.frame;
        let image_edges = scene.scene.outlines.as_ref().filter(|o| o.draws_image_edges());
        let line_rules = scene.scene.outlines.as_ref().filter(|o| o.draws_mesh_lines());
        // the exact frame's geometry target: what the ink passes read
        let geometry = OUTLINES.geometry(scene);
        let mut blob = Blob::default();
        let mut programs: Vec<GlslProgram> = Vec::new();
        let mut keys: Vec<(MeshStages, Vec<(&'static str, f64)>)> = Vec::new();
        let mut meshes = Vec::new();
        // the coarse copies' faces, shared among the meshes as their own faces are
        let faces: usize = records.iter().map(|r| r.gpu.draw_count as usize / 3).sum();
        let coarse_faces = (frame.width as usize * frame.height as usize) / PIXELS_PER_COARSE_FACE;
        for ((item, rec), glass) in scene.scene.items.iter().zip(&records).zip(&scene.glass) {
            let g = &rec.gpu;
            let shading = ShadingVariant::of(&item.material, g.albedo.as_ref());
            let stages = shading.stages(geometry);
            let constants = shading.frame_constants(scene.shader_lights.len() as u32, scene.point_lights);
            let key = (stages, constants);
            let program = match keys.iter().position(|k| *k == key) {
                Some(i) => i,
                None => {
                    let wgsl = module_wgsl(preamble(), &mesh_pass_wgsl(shade::WGSL, stages), None);
                    let name = format!("shade ({})", stages.name());
                    programs.push(glsl::program(&name, &wgsl, "vs_mesh", "fs_mesh", &key.1)?);
                    keys.push(key);
                    programs.len() - 1
                }
            };
            let vertex_bytes = read_buffer(self, &g.vertices)?;
            let index_bytes = match &g.indices {
                Some(b) => Some(read_buffer(self, b)?),
                None => None,
            };
            let albedo_bytes = match &g.albedo {
                Some(a) if stages.albedo => Some(read_buffer(self, &a.vertices)?),
                _ => None,
            };
            let mut derived = BTreeMap::new();
            for part in shading.derived() {
                let buffer = derived_buffer(self.context(), rec, part)?;
                derived.insert(part.name, read_buffer(self, &buffer)?);
            }
            let share = coarse_faces * (g.draw_count as usize / 3) / faces.max(1);
            let coarse = if faces > coarse_faces.max(1) && derived.is_empty() {
                coarse_copy(
                    &vertex_bytes,
                    index_bytes.as_deref(),
                    albedo_bytes.as_deref(),
                    g.draw_count,
                    share,
                )
            } else {
                None
            };
            let vertices = blob.push(&vertex_bytes);
            let indices = index_bytes.as_deref().map(|b| blob.push(b));
            let albedo = albedo_bytes.as_deref().map(|b| blob.push(b));
            let texture =
                g.albedo.as_ref().filter(|a| a.textured).and_then(|a| a.texture.as_ref()).map(|(t, s)| {
                    DraftTexture {
                        width: t.width,
                        height: t.height,
                        texels: blob.push(bytemuck::cast_slice(&t.texels)),
                        filter: s.filter.name(),
                        wrap: s.wrap.name(),
                    }
                });
            let drawn = match line_rules {
                Some(o) => lines::mesh_lines(rec, o)?,
                None => lines::DraftMeshLines::default(),
            };
            let contours = drawn.contours.as_ref().map(|c| DraftContours {
                vertices: blob.push_with(|out| lines::contour_vertices(&c.mesh, out)),
                faces: blob.push(bytemuck::cast_slice(c.mesh.faces())),
                count: c.mesh.faces().len() as u32,
            });
            let lines = line_records(&mut blob, &drawn.edges);
            // smooth contours of a coarser copy still: as many faces fewer to test, and the
            // lines near where the shaded copy's surface is
            let contour_copy = match (&coarse, &contours) {
                (Some(_), Some(_)) => coarse_copy(
                    &vertex_bytes,
                    index_bytes.as_deref(),
                    None,
                    g.draw_count,
                    (share / CONTOUR_COARSENING).max(1),
                ),
                _ => None,
            };
            let coarse = coarse.map(|c| DraftCoarse {
                vertices: blob.push(&c.vertices),
                albedo: c.albedo.as_deref().map(|a| blob.push(a)),
                count: c.indices.len() as u32,
                indices: blob.push(bytemuck::cast_slice(&c.indices)),
                contours: contour_copy.map(|k| DraftContours {
                    vertices: blob.push(&k.vertices),
                    count: (k.indices.len() / 3) as u32,
                    faces: blob.push(bytemuck::cast_slice(&k.indices)),
                }),
            });
            let model = model_matrix(item, &g.placement);
            meshes.push(DraftMesh {
                program,
                vertex_buffers: vertex_buffers(&stages),
                vertices,
                albedo,
                indices,
                count: g.draw_count,
                draw: blob.push(&draw_bytes(item, &g.placement, &cam)),
                model: cols(model),
                texture,
                derived: derived.into_iter().map(|(k, b)| (k, blob.push(&b))).collect(),
                coarse,
                lines,
                contours,
                opacity: glass.then_some(item.material.opacity as f64),
            });
        }
        let (mut edge_bits_program, mut edges_program) = (None, None);
        if let Some(o) = image_edges {
            if o.image_rule == ImageRule::Discontinuity {
                let wgsl = module_wgsl(preamble(), edge_bits::WGSL, None);
                programs.push(glsl::program("edge_bits", &wgsl, "vs_fullscreen", "fs_edge_bits", &[])?);
                edge_bits_program = Some(programs.len() - 1);
            }
            let wgsl = module_wgsl(preamble(), edges::WGSL, None);
            programs.push(glsl::program("edges", &wgsl, "vs_fullscreen", "fs_color", &[])?);
            edges_program = Some(programs.len() - 1);
        }
        let (mut lines_program, mut contours_program) = (None, None);
        if let (Some(_), Some(layout)) = (line_rules, geometry) {
            let wgsl = module_wgsl(preamble(), &lines::module(), None);
            let constants = [("DEPTH_COMPONENT", layout.depth_component() as f64)];
            if meshes.iter().any(|m| m.lines.is_some()) {
                programs.push(glsl::program("lines", &wgsl, "vs_view_edge", "fs_color", &constants)?);
                lines_program = Some(programs.len() - 1);
            }
            if meshes.iter().any(|m| m.contours.is_some()) {
                programs.push(glsl::program("contours", &wgsl, "vs_face_contour", "fs_color", &constants)?);
                contours_program = Some(programs.len() - 1);
            }
        }
        // the frame's bytes, the lights as an unturned view sees them (the page turns them)
        let mut bytes = frame_bytes(&FrameInputs { scene, cam: &cam, sphere: bounds.sphere });
        let mut unturned = cam;
        unturned.view = DMat4::IDENTITY;
        let lighting = lighting_block(scene, &unturned);
        let members = frame_members();
        let lighting_at: usize =
            members.iter().take_while(|(n, _)| *n != "lighting").map(|(_, b)| b.size).sum();
        let lighting_bytes = crate::render::block::Block::bytes(&lighting);
        bytes[lighting_at..lighting_at + lighting_bytes.len()].copy_from_slice(&lighting_bytes);
        let frame_span = blob.push(&bytes);
        let frame_fields = fields(&members);
        let field_at = |name: &str| frame_fields.iter().find(|f| f.name == name).map(|f| f.offset);
        let lights_at =
            field_at("lighting.lights").ok_or_else(|| Error::Internal("no lighting.lights".into()))?;
        let lights = scene
            .shader_lights
            .iter()
            .enumerate()
            .map(|(k, l)| DraftLight {
                world: l.space == Space::World,
                position: lights_at
                    + k * std::mem::size_of::<LightSlot>()
                    + std::mem::offset_of!(LightSlot, position),
            })
            .collect();
        // the w of each ink kind's [r, g, b, width]
        let pixel_widths = field_at("outlines.ink").map_or(vec![], |at| {
            (0..INK_KINDS).map(|k| at + k * std::mem::size_of::<[f32; 4]>() + 12).collect()
        });
        let mut left: Vec<String> = Vec::new();
        let mut leave = |what: &str| {
            if !left.iter().any(|l| l == what) {
                left.push(what.to_string());
            }
        };
        for name in plan(scene).names() {
            if !DRAWN.contains(&name) && !name.starts_with("readback") {
                leave(described(name));
            }
        }
        if !scene.scene.lines.is_empty() {
            leave(LINE_ITEMS);
        }
        if let Some(o) = line_rules {
            let draws = |k: LineKind| o.styles[k as usize].is_some();
            if draws(LineKind::Suggestive) {
                leave("suggestive contours");
            }
            if draws(LineKind::Material) && records.len() > 1 {
                leave("borders between meshes");
            }
            if !o.stroke_width.is_constant() {
                leave("taper and width by depth");
            }
            if o.draws_hidden() {
                leave("hidden lines");
            }
            if o.styles.iter().flatten().any(|s| s.dash > 0.0) {
                leave("dashed lines");
            }
        }
        if frame.msaa > 1 {
            leave("multisampling");
        }
        let to3 = |v: glam::DVec3| v.to_array();
        let draw_fields = fields(&draw_members());
        let draft = Draft {
            programs,
            edge_bits: edge_bits_program,
            edges: edges_program,
            lines: lines_program,
            line_buffer: lines_program.map(|_| vertex_buffer("lines", &lines::layout())),
            contours: contours_program,
            contour_buffer: contours_program.map(|_| vertex_buffer("contours", &lines::face_layout())),
            contour_vertices: contours_program.map(|_| vertex_buffer("position", &GpuMesh::vertex_layout())),
            meshes,
            frame: frame_span,
            frame_fields,
            pixel_widths,
            least_ink_width: DEFAULT_WIDTH,
            draw_pixel_lengths: draw_fields
                .iter()
                .filter(|f| DRAW_PIXEL_LENGTHS.contains(&f.name.as_str()))
                .map(|f| f.offset)
                .collect(),
            draw_fields,
            lights,
            camera: DraftCamera {
                scale: cam.scale,
                orthographic: cam.orthographic,
                fov_or_height: cam.fov_or_height,
                near: cam.near,
                far: cam.far,
                eye: to3(cam.eye),
                forward: to3(cam.forward),
                width: frame.width,
                height: frame.height,
                pixel_ratio: frame.pixel_ratio,
                center: to3(bounds.sphere.center),
                radius: bounds.sphere.radius,
            },
            background: background_linear(frame),
            geometry_clear: geometry.map(|g| {
                let c = geometry_clear(g);
                [c.r, c.g, c.b, c.a].map(|x| x as u32)
            }),
            geometry_format: geometry.map(gl_geometry_format),
            front_face: "CW",
            depth_compare: gl_compare(nearest_wins().and_then(|d| d.depth_compare)),
            ink_blend: [gl_factor(INK_OVER.color.src_factor), gl_factor(INK_OVER.color.dst_factor)],
            left_to_exact: left,
            pixels_per_coarse_face: PIXELS_PER_COARSE_FACE,
        };
        Ok((draft, blob.0))
    }
}

#[cfg(test)]
mod tests;

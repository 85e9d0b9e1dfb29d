//! The core's uniform blocks (`shaders/common.wgsl`): the camera and image, the lights, where a
//! mesh is, and its material; and how the frame's and the draws' uniform structs gather the core
//! blocks with every effect's (`Frame`, `Draw`), one block after another.
//!
//! Everything the GPU sees is in normalised view space: view space divided by the camera's
//! `scale` (a power of two near the scene's size), so that float32 keeps its precision for
//! scenes of any size and distance (see `ResolvedCamera::scale`).

use crate::render::scene::FrameSpec;
use glam::{DMat3, DMat4};

use super::block::{vec4, Block, BlockLayout};
use super::color::to_linear;
use super::effects::surface;
use super::gpu_mesh::Placement;
use super::scene::camera::ResolvedCamera;
use super::scene::checked::CheckedScene;
use super::scene::light::{ViewLight, MAX_LIGHTS};
use super::scene::material::Material;
use super::scene::model::{Highlight, Model, MAX_LUT};
use super::scene::SceneItem;

crate::uniform_block! {
    /// `frame.view`: the camera and the image.
    pub struct ViewBlock as "ViewBlock" {
        pub proj: [[f32; 4]; 4],
        /// Output size in pixels.
        pub size: [f32; 2],
        /// A pixel's world size at normalised depth z is `z * footprint[0] + footprint[1]`.
        pub footprint: [f32; 2],
        /// The near plane, in normalised view units.
        pub near: f32,
        pub orthographic: u32,
        /// 1: blend across band borders over about a pixel (`FrameSpec::band_antialias`).
        pub band_antialias: u32,
        pub _pad1: f32,
    }
}

#[repr(C)]
#[derive(Clone, Copy, Debug, PartialEq, bytemuck::Pod, bytemuck::Zeroable)]
pub struct LightSlot {
    /// w = 0: xyz is the unit vector toward the light; w = 1: a point.
    pub position: [f32; 4],
    /// Linear rgb, intensity included.
    pub color: [f32; 4],
}

crate::uniform_block! {
    /// `frame.lighting`: the scene's lights, the shadow-casting one first.
    pub struct LightingBlock as "LightingBlock" {
        pub ambient: [f32; 4],
        pub lights: [LightSlot; MAX_LIGHTS],
    }
}

crate::uniform_block! {
    /// `draw.mesh`: where one mesh is.
    pub struct MeshBlock as "MeshBlock" {
        pub model_view: [[f32; 4]; 4],
        pub normal_matrix: [[f32; 4]; 4],
        /// 1 when the transform mirrors (flips the winding).
        pub mirrored: u32,
        pub _pad0: u32,
        pub _pad1: u32,
        pub _pad2: u32,
    }
}

crate::uniform_block! {
    /// `draw.material`: its material's coefficients and its model's parameters.
    pub struct MaterialBlock as "MaterialBlock" {
        pub ambient: [f32; 4],
        pub diffuse: [f32; 4],
        pub specular: [f32; 4],
        pub shininess: f32,
        pub t_h: f32,
        pub t_s: f32,
        /// The highlight: 1 Blinn's (n.h), 0 the paper's (L.v).
        pub blinn: u32,
        pub band_count: u32,
        pub table_size: u32,
        /// The material's opacity (`Material::opacity`), read by the glass stage only.
        pub opacity: f32,
        pub _pad1: u32,
        pub thresholds: [[f32; 4]; 2],
        pub values: [[f32; 4]; 3],
        pub table: [[f32; 4]; MAX_LUT],
    }
}

fn f32_cols(m: DMat4) -> [[f32; 4]; 4] {
    m.as_mat4().to_cols_array_2d()
}

/// The world size of one output pixel at normalised depth z is `a z + b` (in normalised units).
pub fn footprint(cam: &ResolvedCamera, height: u32) -> (f64, f64) {
    let per_unit = 2.0 / (cam.proj.y_axis.y * height as f64);
    if cam.orthographic {
        (0.0, per_unit / cam.scale)
    } else {
        (per_unit, 0.0)
    }
}

pub fn view_block(cam: &ResolvedCamera, frame: &FrameSpec) -> ViewBlock {
    let (width, height) = (frame.width, frame.height);
    let (a, b) = footprint(cam, height);
    ViewBlock {
        band_antialias: frame.band_antialias as u32,
        proj: f32_cols(cam.normalized_proj()),
        size: [width as f32, height as f32],
        footprint: [a as f32, b as f32],
        near: (cam.near / cam.scale) as f32,
        orthographic: cam.orthographic as u32,
        ..bytemuck::Zeroable::zeroed()
    }
}

pub fn lighting_block(scene: &CheckedScene, cam: &ResolvedCamera) -> LightingBlock {
    let mut b: LightingBlock = bytemuck::Zeroable::zeroed();
    b.ambient = vec4(to_linear(scene.scene.ambient));
    for (slot, light) in b.lights.iter_mut().zip(&scene.shader_lights) {
        let position = match light.to_view(&cam.view) {
            ViewLight::Toward(l) => [l.x as f32, l.y as f32, l.z as f32, 0.0],
            ViewLight::At(p) => {
                let p = p / cam.scale;
                [p.x as f32, p.y as f32, p.z as f32, 1.0]
            }
        };
        *slot = LightSlot { position, color: vec4(light.radiance()) };
    }
    b
}

/// Stored coordinates -> world for an item: its model matrix after the mesh's storage
/// placement.
pub fn model_matrix(item: &SceneItem, placement: &Placement) -> DMat4 {
    item.model_matrix()
        * DMat4::from_translation(placement.origin.into())
        * DMat4::from_scale(glam::DVec3::splat(placement.scale))
}

/// Model -> normalised view for an item, including the mesh's storage placement.
pub fn model_view(item: &SceneItem, placement: &Placement, cam: &ResolvedCamera) -> DMat4 {
    cam.normalized_view() * model_matrix(item, placement)
}

pub fn mesh_block(item: &SceneItem, placement: &Placement, cam: &ResolvedCamera) -> MeshBlock {
    let mv = model_view(item, placement, cam);
    MeshBlock {
        model_view: f32_cols(mv),
        normal_matrix: f32_cols(DMat4::from_mat3(DMat3::from_mat4(mv).inverse().transpose())),
        mirrored: item.mirrors() as u32,
        ..bytemuck::Zeroable::zeroed()
    }
}

pub fn material_block(m: &Material) -> MaterialBlock {
    let mut b: MaterialBlock = bytemuck::Zeroable::zeroed();
    b.ambient = vec4(m.ambient_linear());
    b.diffuse = vec4(m.diffuse_linear());
    b.specular = vec4(m.specular_linear());
    b.opacity = m.opacity;
    match &m.model {
        Model::Lambert => {}
        Model::Phong { shininess } => b.shininess = *shininess,
        Model::ThresholdedPhong { t_h, t_s, highlight } => {
            b.t_h = *t_h;
            b.t_s = *t_s;
            b.blinn = (*highlight == Highlight::Blinn) as u32;
        }
        Model::Bands { thresholds, values } => {
            b.band_count = thresholds.len() as u32;
            for (i, t) in thresholds.iter().enumerate() {
                b.thresholds[i / 4][i % 4] = *t;
            }
            for (i, v) in values.iter().enumerate() {
                b.values[i / 4][i % 4] = *v;
            }
        }
        Model::Lut { table } => {
            b.table_size = table.len() as u32;
            for (slot, c) in b.table.iter_mut().zip(table) {
                *slot = vec4(*c);
            }
        }
    }
    b
}

/// A uniform struct that gathers blocks one after another (`Frame`, `Draw`): each member's
/// name and block.
pub type Members = Vec<(&'static str, BlockLayout)>;

/// The WGSL of a struct of `members`.
pub fn struct_wgsl(name: &str, members: &Members) -> String {
    let fields: String = members.iter().map(|(n, b)| format!("    {n}: {},\n", b.wgsl)).collect();
    format!("struct {name} {{\n{fields}}};\n")
}

/// The members of `Draw`: the mesh's and material's blocks, then every per-pixel effect's.
pub fn draw_members() -> Members {
    let mut m = vec![("mesh", MeshBlock::layout()), ("material", MaterialBlock::layout())];
    m.extend(surface::blocks());
    m
}

/// One draw's uniforms: `Draw` for `item`, as bytes.
pub fn draw_bytes(item: &SceneItem, placement: &Placement, cam: &ResolvedCamera) -> Vec<u8> {
    let m = &item.material;
    let mut bytes = mesh_block(item, placement, cam).bytes();
    bytes.extend(material_block(m).bytes());
    bytes.extend(m.effects.block_bytes());
    bytes
}

//! The uniform blocks of `shaders/common.wgsl`, laid out byte for byte.

use glam::{DMat3, DMat4};

use super::camera::ResolvedCamera;
use super::light::{ViewLight, MAX_LIGHTS};
use super::material::{Highlight, Model, MAX_LUT};
use super::scene::{Scene, SceneItem};

#[repr(C)]
#[derive(Clone, Copy, bytemuck::Pod, bytemuck::Zeroable)]
pub struct LightBlock {
    pub position: [f32; 4],
    pub color: [f32; 4],
}

#[repr(C)]
#[derive(Clone, Copy, bytemuck::Pod, bytemuck::Zeroable)]
pub struct FrameBlock {
    pub proj: [[f32; 4]; 4],
    pub ambient: [f32; 4],
    pub info: [u32; 4],
    pub lights: [LightBlock; MAX_LIGHTS],
}

#[repr(C)]
#[derive(Clone, Copy, bytemuck::Pod, bytemuck::Zeroable)]
pub struct DrawBlock {
    pub model_view: [[f32; 4]; 4],
    pub normal_matrix: [[f32; 4]; 4],
    pub ambient: [f32; 4],
    pub diffuse: [f32; 4],
    pub specular: [f32; 4],
    pub params: [f32; 4],
    pub model: [u32; 4],
    pub flags: [u32; 4],
    pub thresholds: [[f32; 4]; 2],
    pub values: [[f32; 4]; 3],
    pub table: [[f32; 4]; MAX_LUT],
}

fn f32_cols(m: DMat4) -> [[f32; 4]; 4] {
    m.as_mat4().to_cols_array_2d()
}

fn rgb0(c: [f32; 3]) -> [f32; 4] {
    [c[0], c[1], c[2], 0.0]
}

pub fn frame_block(scene: &Scene, cam: &ResolvedCamera) -> FrameBlock {
    let mut lights = [LightBlock { position: [0.0; 4], color: [0.0; 4] }; MAX_LIGHTS];
    for (slot, light) in lights.iter_mut().zip(&scene.lights) {
        let position = match light.to_view(&cam.view) {
            ViewLight::Toward(l) => [l.x as f32, l.y as f32, l.z as f32, 0.0],
            ViewLight::At(p) => [p.x as f32, p.y as f32, p.z as f32, 1.0],
        };
        *slot = LightBlock { position, color: rgb0(light.color) };
    }
    FrameBlock {
        proj: f32_cols(cam.proj),
        ambient: rgb0(scene.ambient),
        info: [scene.lights.len() as u32, cam.orthographic as u32, 0, 0],
        lights,
    }
}

/// Model -> view for an item, including the mesh's storage offset.
pub fn model_view(item: &SceneItem, cam: &ResolvedCamera) -> DMat4 {
    cam.view * item.model_matrix() * DMat4::from_translation(item.mesh.origin.into())
}

pub fn draw_block(item: &SceneItem, cam: &ResolvedCamera) -> Box<DrawBlock> {
    let mv = model_view(item, cam);
    let normal_matrix = DMat4::from_mat3(DMat3::from_mat4(mv).inverse().transpose());
    let mirrored = DMat3::from_mat4(item.model_matrix()).determinant() < 0.0;
    let m = &item.material;
    let mut b: Box<DrawBlock> = Box::new(bytemuck::Zeroable::zeroed());
    b.model_view = f32_cols(mv);
    b.normal_matrix = f32_cols(normal_matrix);
    b.ambient = rgb0(m.ambient);
    b.diffuse = rgb0(m.diffuse);
    b.specular = rgb0(m.specular);
    b.flags = [mirrored as u32, 0, 0, 0];
    b.model[0] = m.model.id();
    match &m.model {
        Model::Lambert => {}
        Model::Phong { shininess } => b.params[0] = *shininess,
        Model::ThresholdedPhong { t_h, t_s, highlight } => {
            b.params[1] = *t_h;
            b.params[2] = *t_s;
            b.model[1] = (*highlight == Highlight::Blinn) as u32;
        }
        Model::Bands { thresholds, values } => {
            b.model[2] = thresholds.len() as u32;
            for (i, t) in thresholds.iter().enumerate() {
                b.thresholds[i / 4][i % 4] = *t;
            }
            for (i, v) in values.iter().enumerate() {
                b.values[i / 4][i % 4] = *v;
            }
        }
        Model::Lut { table } => {
            b.model[3] = table.len() as u32;
            for (slot, c) in b.table.iter_mut().zip(table) {
                *slot = rgb0(*c);
            }
        }
    }
    b
}

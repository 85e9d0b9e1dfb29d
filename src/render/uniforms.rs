//! The uniform blocks and instance data of `shaders/common.wgsl`, laid out byte for byte.
//!
//! Everything the GPU sees is in normalised view space: view space divided by the camera's
//! `scale` (a power of two near the scene's size), so that float32 keeps its precision for
//! scenes of any size and distance (see `ResolvedCamera::scale`).

use glam::{DMat3, DMat4, DVec3};

use super::gpu_mesh::Placement;
use super::scene::camera::{ResolvedCamera, Sphere};
use super::scene::light::{shadow_caster, Light, LightKind, ViewLight, MAX_LIGHTS};
use super::scene::material::{Highlight, Material, Model, MAX_LUT};
use super::scene::outlines::{Outlines, INK_KINDS};
use super::scene::shadows::MAX_BIAS_SLOPE;
use super::scene::{FrameSpec, Scene, SceneItem};

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
    pub viewport: [f32; 4],
    pub outline: [f32; 4],
    pub ink: [[f32; 4]; INK_KINDS],
    pub lights: [LightBlock; MAX_LIGHTS],
    /// Normalised view space -> the shadow-casting light's clip space (the first light's).
    pub shadow: [[f32; 4]; 4],
    /// x: depth tolerance per unit of receiver slope, y: the largest slope biased, z: how far
    /// (normalised view units) a receiver moves along its normal before the test.
    pub shadow_bias: [f32; 4],
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
    /// x: dither amount, y: dither cell in pixels, z: hatch spacing, w: hatch width (pixels).
    pub style: [f32; 4],
    /// Linear ink of the hatching.
    pub ink: [f32; 4],
}

/// One mesh-space line: its end points in the mesh's stored coordinates and its kind.
#[repr(C)]
#[derive(Clone, Copy, Debug, PartialEq, bytemuck::Pod, bytemuck::Zeroable)]
pub struct LineInstance {
    pub a: [f32; 3],
    pub kind: u32,
    pub b: [f32; 3],
    pub pad: u32,
}

fn f32_cols(m: DMat4) -> [[f32; 4]; 4] {
    m.as_mat4().to_cols_array_2d()
}

fn rgb0(c: [f32; 3]) -> [f32; 4] {
    [c[0], c[1], c[2], 0.0]
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

/// The lights in the order the shader sees them: the shadow-casting light first.
pub fn shader_lights(lights: &[Light]) -> Vec<&Light> {
    let caster = shadow_caster(lights).map(|(i, _, _)| i);
    let first = caster.map(|i| &lights[i]);
    first
        .into_iter()
        .chain(lights.iter().enumerate().filter(|(i, _)| Some(*i) != caster).map(|(_, l)| l))
        .collect()
}

/// Bit k set when the shader's light k (in `shader_lights` order) is a point light.
pub fn point_light_bits(lights: &[Light]) -> u32 {
    shader_lights(lights)
        .iter()
        .enumerate()
        .filter(|(_, l)| matches!(l.kind, LightKind::Point { .. }))
        .fold(0, |bits, (k, _)| bits | 1 << k)
}

/// Normalised view space -> the clip space of an orthographic view along the unit vector
/// `toward` the light that just holds the sphere `c`, `r` (normalised view space): x and y in
/// [-1, 1] across it, depth 0 on the side nearest the light and 1 on the far side.
pub fn shadow_matrix(toward: DVec3, c: DVec3, r: f64) -> DMat4 {
    let w = toward;
    let helper = if w.x.abs() < 0.9 { DVec3::X } else { DVec3::Y };
    let u = w.cross(helper).normalize();
    let v = w.cross(u);
    let rows = [
        [u.x / r, u.y / r, u.z / r, -u.dot(c) / r],
        [v.x / r, v.y / r, v.z / r, -v.dot(c) / r],
        [-w.x / (2.0 * r), -w.y / (2.0 * r), -w.z / (2.0 * r), (w.dot(c) + r) / (2.0 * r)],
        [0.0, 0.0, 0.0, 1.0],
    ];
    DMat4::from_cols_array_2d(&rows).transpose()
}

/// The frame's uniforms; `sphere` holds the scene (world space), for fitting the shadow map.
pub fn frame_block(scene: &Scene, cam: &ResolvedCamera, frame: &FrameSpec, sphere: Sphere) -> FrameBlock {
    let mut lights = [LightBlock { position: [0.0; 4], color: [0.0; 4] }; MAX_LIGHTS];
    for (slot, light) in lights.iter_mut().zip(shader_lights(&scene.lights)) {
        let position = match light.to_view(&cam.view) {
            ViewLight::Toward(l) => [l.x as f32, l.y as f32, l.z as f32, 0.0],
            ViewLight::At(p) => {
                let p = p / cam.scale;
                [p.x as f32, p.y as f32, p.z as f32, 1.0]
            }
        };
        *slot = LightBlock { position, color: rgb0(light.radiance()) };
    }
    let mut shadow = [[0.0f32; 4]; 4];
    let mut shadow_bias = [0.0f32; 4];
    if let Some((_, light, settings)) = shadow_caster(&scene.lights) {
        if let ViewLight::Toward(l) = light.to_view(&cam.view) {
            let c = cam.normalized_view().transform_point3(sphere.center);
            let r = sphere.radius / cam.scale;
            shadow = f32_cols(shadow_matrix(l, c, r));
            // the map's side spans the sphere's diameter
            let offset = settings.normal_offset() * 2.0 * r;
            shadow_bias = [settings.tolerance() as f32, MAX_BIAS_SLOPE as f32, offset as f32, 0.0];
        }
    }
    let (a, b) = footprint(cam, frame.height);
    let outlines = scene.outlines.clone().unwrap_or_else(|| Outlines::new(false, false));
    let mut ink = [[0.0f32; 4]; INK_KINDS];
    for (slot, style) in ink.iter_mut().zip(&outlines.styles) {
        if let Some(s) = style {
            let c = crate::render::color::to_linear(s.color);
            *slot = [c[0], c[1], c[2], s.width];
        }
    }
    FrameBlock {
        proj: f32_cols(cam.normalized_proj()),
        ambient: rgb0(crate::render::color::to_linear(scene.ambient)),
        info: [scene.lights.len() as u32, cam.orthographic as u32, 0, 0],
        viewport: [frame.width as f32, frame.height as f32, a as f32, b as f32],
        outline: [
            outlines.depth_offset,
            outlines.normal_threshold,
            (outlines.depth_threshold as f64 / cam.scale) as f32,
            (cam.near / cam.scale) as f32,
        ],
        ink,
        lights,
        shadow,
        shadow_bias,
    }
}

/// Model -> normalised view for an item, including the mesh's storage placement.
pub fn model_view(item: &SceneItem, placement: &Placement, cam: &ResolvedCamera) -> DMat4 {
    cam.normalized_view()
        * item.model_matrix()
        * DMat4::from_translation(placement.origin.into())
        * DMat4::from_scale(glam::DVec3::splat(placement.scale))
}

pub fn draw_block(item: &SceneItem, placement: &Placement, cam: &ResolvedCamera) -> DrawBlock {
    let mv = model_view(item, placement, cam);
    let normal_matrix = DMat4::from_mat3(DMat3::from_mat4(mv).inverse().transpose());
    let mirrored = item.mirrors();
    let m: &Material = &item.material;
    let mut b: DrawBlock = bytemuck::Zeroable::zeroed();
    b.model_view = f32_cols(mv);
    b.normal_matrix = f32_cols(normal_matrix);
    b.ambient = rgb0(m.ambient_linear());
    b.diffuse = rgb0(m.diffuse_linear());
    b.specular = rgb0(m.specular_linear());
    b.flags = [mirrored as u32, 0, 0, 0];
    if let Some(d) = &m.dither {
        b.style[0] = d.amount as f32;
        b.style[1] = d.scale as f32;
    }
    if let Some(h) = &m.hatching {
        b.style[2] = h.spacing as f32;
        b.style[3] = h.width as f32;
        b.ink = rgb0(crate::render::color::to_linear(h.ink));
    }
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

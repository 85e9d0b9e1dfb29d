//! CPU reference of the shading formulas in `shaders/common.wgsl` (see `scene/model.rs`), used by
//! tests to hold the GPU's pixels against. f32 like the shader; linear light in, linear out.

use glam::Vec3;

use super::scene::material::Material;
use super::scene::model::{Highlight, Model};

/// A light in view space, as the shader receives it.
#[derive(Clone, Copy, Debug)]
pub enum RefLight {
    /// Unit vector toward the light.
    Toward(Vec3, Vec3),
    /// Position, colour.
    At(Vec3, Vec3),
}

/// The view vector v (unit, from the surface toward the eye) at view-space point `p`.
pub fn view_dir(p: Vec3, orthographic: bool) -> Vec3 {
    if orthographic {
        Vec3::Z
    } else {
        (-p).normalize()
    }
}

fn thresh(a: f32, b: f32) -> f32 {
    if a >= b {
        1.0
    } else {
        0.0
    }
}

/// Linear RGB colour of a surface point with unit view-space normal `n` at view-space `p`.
pub fn shade(
    m: &Material,
    n: Vec3,
    p: Vec3,
    orthographic: bool,
    ambient_light: Vec3,
    lights: &[RefLight],
) -> Vec3 {
    let v = view_dir(p, orthographic);
    let mut c = ambient_light * Vec3::from(m.ambient_linear());
    for light in lights {
        let (l, color) = match *light {
            RefLight::Toward(l, c) => (l, c),
            RefLight::At(q, c) => ((q - p).normalize(), c),
        };
        let d = n.dot(l);
        let (f, s): (Vec3, f32) = match &m.model {
            Model::Lambert => (Vec3::splat(d.max(0.0)), 0.0),
            Model::Phong { shininess } => {
                let r = 2.0 * d * n - l;
                let s = if d > 0.0 { r.dot(v).max(0.0).powf(*shininess) } else { 0.0 };
                (Vec3::splat(d.max(0.0)), s)
            }
            Model::ThresholdedPhong { t_h, t_s, highlight } => {
                let hl = match highlight {
                    Highlight::Paper => l.dot(v),
                    Highlight::Blinn => {
                        let h = l + v;
                        if h.length_squared() > 1e-12 {
                            n.dot(h.normalize())
                        } else {
                            -1.0
                        }
                    }
                };
                (Vec3::splat(thresh(d, *t_h)), thresh(hl, *t_s))
            }
            Model::Bands { thresholds, values } => {
                let k = thresholds.iter().filter(|&&t| d >= t).count();
                (Vec3::splat(values[k]), 0.0)
            }
            Model::Lut { table } => {
                let x = d.clamp(0.0, 1.0);
                let i = ((x * table.len() as f32).floor() as usize).min(table.len() - 1);
                (Vec3::from(table[i]), 0.0)
            }
        };
        c += f * color * Vec3::from(m.diffuse_linear()) + s * color * Vec3::from(m.specular_linear());
    }
    c
}

//! CPU reference of the shading formulas in `shaders/common.wgsl` (see `scene/model.rs`), used by
//! tests to hold the GPU's pixels against. f32 like the shader; linear light in, linear out.

use glam::Vec3;

use super::scene::material::Material;
use super::scene::model::{step_aa, Highlight, Model};

/// A light in view space, as the shader receives it.
#[derive(Clone, Copy, Debug)]
pub enum RefLight {
    /// Unit vector toward the light.
    Toward(Vec3, Vec3),
    /// Position, colour.
    At(Vec3, Vec3),
}

impl RefLight {
    /// The unit vector from view-space point `p` toward the light, and its colour
    /// (`light_toward` in the shader).
    pub fn toward(&self, p: Vec3) -> (Vec3, Vec3) {
        match *self {
            RefLight::Toward(l, c) => (l, c),
            RefLight::At(q, c) => ((q - p).normalize(), c),
        }
    }
}

/// The view vector v (unit, from the surface toward the eye) at view-space point `p`.
pub fn view_dir(p: Vec3, orthographic: bool) -> Vec3 {
    if orthographic {
        Vec3::Z
    } else {
        (-p).normalize()
    }
}

/// The change of a per-pixel quantity across a pixel in x and y, as the shader's fine
/// derivatives take it: within each 2x2 quad of pixels (even x and y first), the difference
/// along its row and along its column. `at(x, y)` is the quantity; None outside the image.
pub fn quad_derivatives<T: Copy + std::ops::Sub<Output = T>>(
    at: impl Fn(usize, usize) -> Option<T>,
    x: usize,
    y: usize,
) -> Option<[T; 2]> {
    let (x0, y0) = (x & !1, y & !1);
    Some([at(x0 + 1, y)? - at(x0, y)?, at(x, y0 + 1)? - at(x, y0)?])
}

/// Linear RGB colour of a surface point with unit view-space normal `n` at view-space `p`, its
/// band borders blended over the pixel: `dn` the normal's change across the pixel in x and y
/// (`quad_derivatives`; zero: hard borders). `albedo` (linear) multiplies the ambient and
/// diffuse colours; `jitter` moves L.n before the model bands it (dithering).
#[allow(clippy::too_many_arguments)]
pub fn shade(
    m: &Material,
    n: Vec3,
    p: Vec3,
    orthographic: bool,
    ambient_light: Vec3,
    lights: &[RefLight],
    dn: [Vec3; 2],
    albedo: Vec3,
    jitter: f32,
) -> Vec3 {
    let v = view_dir(p, orthographic);
    let mut c = ambient_light * Vec3::from(m.ambient_linear()) * albedo;
    for light in lights {
        let (l, color) = light.toward(p);
        let d = n.dot(l);
        // the diffuse term's L.n, moved by the jitter (the highlight's is not)
        let dj = d + jitter;
        let w = glam::Vec2::new(dn[0].dot(l), dn[1].dot(l)).length();
        let (f, s): (Vec3, f32) = match &m.model {
            Model::Lambert => (Vec3::splat(dj.max(0.0)), 0.0),
            Model::Phong { shininess } => {
                let r = 2.0 * d * n - l;
                let s = if d > 0.0 { r.dot(v).max(0.0).powf(*shininess) } else { 0.0 };
                (Vec3::splat(dj.max(0.0)), s)
            }
            Model::ThresholdedPhong { t_h, t_s, highlight } => {
                let (hl, ws) = match highlight {
                    Highlight::Paper => (l.dot(v), 0.0),
                    Highlight::Blinn => {
                        let h = l + v;
                        if h.length_squared() > 1e-12 {
                            let u = h.normalize();
                            (n.dot(u), glam::Vec2::new(dn[0].dot(u), dn[1].dot(u)).length())
                        } else {
                            (-1.0, 0.0)
                        }
                    }
                };
                (Vec3::splat(step_aa(dj, *t_h, w)), step_aa(hl, *t_s, ws))
            }
            Model::Bands { thresholds, values } => {
                let v = thresholds
                    .iter()
                    .enumerate()
                    .fold(values[0], |v, (i, &t)| v + (values[i + 1] - values[i]) * step_aa(dj, t, w));
                (Vec3::splat(v), 0.0)
            }
            Model::Lut { table } => {
                let n = table.len();
                let cell = |x: f32| ((x.clamp(0.0, 1.0) * n as f32).floor() as usize).min(n - 1);
                let (lo, hi) = (cell(dj - 0.5 * w), cell(dj + 0.5 * w));
                if w <= 0.0 || lo == hi {
                    (Vec3::from(table[cell(dj)]), 0.0)
                } else {
                    let border = (lo + 1) as f32 / n as f32;
                    let below = ((border - (dj - 0.5 * w)) / w).clamp(0.0, 1.0);
                    (Vec3::from(table[hi]).lerp(Vec3::from(table[lo]), below), 0.0)
                }
            }
        };
        c +=
            f * color * Vec3::from(m.diffuse_linear()) * albedo + s * color * Vec3::from(m.specular_linear());
    }
    c
}

//! Lines of a mesh projected to the image (with the near plane): what the line pass draws, and
//! its CPU reference (`visibility`) and the stroke widths (`mesh_lines`) measure.

use glam::{DMat4, DVec3, DVec4};

use crate::render::gpu_mesh::Placement;
use crate::render::scene::camera::ResolvedCamera;
use crate::render::scene::SceneItem;
use crate::render::uniforms::model_view;

/// A line projected to the image: end points in pixels (x right, y down, origin at the top-left
/// corner of the image), their linear depths, and the factors of its kind's width at both ends
/// (`stroke_width`), interpolated along it on screen.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ScreenLine {
    pub a: [f64; 2],
    pub b: [f64; 2],
    pub za: f64,
    pub zb: f64,
    pub kind: usize,
    pub scale: [f64; 2],
    /// The distance along its stroke at both ends, in pixels (where dashes are measured from).
    pub along: [f64; 2],
    /// Visibility was decided on the host (`mesh_lines::EXACT`): no depth test.
    pub exact: bool,
    /// A `Lines` item's own width in pixels (`mesh_lines::OWN_INK`): solid, in place of its
    /// kind's width and dashes.
    pub own_width: Option<f64>,
}

impl ScreenLine {
    /// Point and depth at parameter t in [0, 1] (1/depth is linear on screen in perspective).
    pub fn at(&self, t: f64, orthographic: bool) -> ([f64; 2], f64) {
        let p = [self.a[0] + (self.b[0] - self.a[0]) * t, self.a[1] + (self.b[1] - self.a[1]) * t];
        let z = if orthographic {
            self.za + (self.zb - self.za) * t
        } else {
            1.0 / (1.0 / self.za + (1.0 / self.zb - 1.0 / self.za) * t)
        };
        (p, z)
    }

    /// The factor of the kind's width at parameter t (linear on screen, as the line pass has it).
    pub fn factor(&self, t: f64) -> f64 {
        self.scale[0] + (self.scale[1] - self.scale[0]) * t
    }

    /// The distance along the stroke at parameter t (linear on screen).
    pub fn along_at(&self, t: f64) -> f64 {
        self.along[0] + (self.along[1] - self.along[0]) * t
    }

    pub fn length(&self) -> f64 {
        (self.b[0] - self.a[0]).hypot(self.b[1] - self.a[1])
    }
}

/// Projects lines of one mesh: model (stored coordinates) -> view -> pixels.
pub struct Projector {
    pub model_view: DMat4,
    pub proj: DMat4,
    pub width: f64,
    pub height: f64,
    pub orthographic: bool,
    pub near: f64,
}

impl Projector {
    /// Projects the lines of `item` (a mesh stored with `placement`) into an image of
    /// `width` x `height` pixels, in normalised view units (like the GPU).
    pub fn of(
        item: &SceneItem,
        placement: &Placement,
        cam: &ResolvedCamera,
        width: u32,
        height: u32,
    ) -> Self {
        Projector { model_view: model_view(item, placement, cam), ..Projector::in_view(cam, width, height) }
    }

    /// Projects lines already in normalised view coordinates (`Lines` items').
    pub fn in_view(cam: &ResolvedCamera, width: u32, height: u32) -> Self {
        Projector {
            model_view: DMat4::IDENTITY,
            proj: cam.normalized_proj(),
            width: width as f64,
            height: height as f64,
            orthographic: cam.orthographic,
            near: cam.near / cam.scale,
        }
    }

    fn pixels(&self, v: DVec3) -> [f64; 2] {
        let c = self.proj * DVec4::new(v.x, v.y, v.z, 1.0);
        let (x, y) = (c.x / c.w, c.y / c.w);
        [(x * 0.5 + 0.5) * self.width, (0.5 - y * 0.5) * self.height]
    }

    /// The line from `a` to `b`, cut to the part in front of the near plane; None when none is.
    pub fn project(&self, a: [f64; 3], b: [f64; 3], kind: usize) -> Option<ScreenLine> {
        let mut pa = self.model_view.transform_point3(DVec3::from_array(a));
        let mut pb = self.model_view.transform_point3(DVec3::from_array(b));
        if !self.orthographic {
            let (za, zb) = (-pa.z, -pb.z);
            if za < self.near && zb < self.near {
                return None;
            }
            if za < self.near {
                pa = pa.lerp(pb, (self.near - za) / (zb - za));
            } else if zb < self.near {
                pb = pb.lerp(pa, (self.near - zb) / (za - zb));
            }
        }
        Some(ScreenLine {
            a: self.pixels(pa),
            b: self.pixels(pb),
            za: -pa.z,
            zb: -pb.z,
            kind,
            scale: [1.0; 2],
            along: [0.0; 2],
            exact: false,
            own_width: None,
        })
    }
}

//! What a material compiles into the shading pipeline: its model, Gouraud or per-pixel
//! shading, and each per-pixel effect's pipeline constants (`effects::surface`); and what the
//! mesh adds: its colour and texture (`gpu_albedo`), only for meshes that have them.

use crate::render::gpu_albedo::GpuAlbedo;
use crate::render::graph::mesh_stages::MeshStages;
use crate::render::graph::target::GeometryLayout;
use crate::render::scene::material::Material;

#[derive(Clone, Debug, Default, PartialEq)]
pub struct ShadingVariant {
    /// Every pipeline constant of the material's shading, the core's first.
    pub constants: Vec<(&'static str, f64)>,
    /// Whether the fragment stage reads the vertex stage's anchors (object coordinates and
    /// per-vertex colours: the `anchors` part of `graph::mesh_stages`).
    pub anchored: bool,
    /// Whether the stages read the mesh's colour (and texture).
    pub albedo: bool,
    /// Whether they read the hatching field's vertex buffer.
    pub field: bool,
}

impl ShadingVariant {
    pub fn of(m: &Material, albedo: Option<&GpuAlbedo>) -> Self {
        let mut v = ShadingVariant {
            constants: vec![("PER_VERTEX", m.per_vertex as u32 as f64), ("MODEL", m.model.id() as f64)],
            anchored: m.per_vertex,
            albedo: albedo.is_some(),
            field: false,
        };
        v.constants.extend(albedo.map_or(vec![], GpuAlbedo::constants));
        for part in m.effects.variants() {
            v.constants.extend(part.constants);
            v.anchored |= part.anchored;
            v.field |= part.field;
        }
        v
    }

    /// Its pipeline constants for a frame of `lights` lights, `point_lights` the bits of those
    /// that are points.
    pub fn frame_constants(&self, lights: u32, point_lights: u32) -> Vec<(&'static str, f64)> {
        let mut constants = self.constants.clone();
        constants.push(("LIGHTS", lights as f64));
        constants.push(("POINT_LIGHTS", point_lights as f64));
        constants
    }

    /// The shading pass's stages for it, writing the colour and, where given, the geometry
    /// target.
    pub fn stages(&self, geometry: Option<GeometryLayout>) -> MeshStages {
        MeshStages {
            albedo: self.albedo,
            anchors: self.anchored,
            field: self.field,
            color: true,
            geometry,
            clip: None,
        }
    }
}

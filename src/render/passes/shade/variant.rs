//! What a material compiles into the shading pipeline: its model, Gouraud or per-pixel
//! shading, and each per-pixel effect's pipeline constants (`effects::surface`); and what the
//! mesh adds: its colour and texture (`gpu_albedo`), only for meshes that have them.

use crate::render::gpu_albedo::GpuAlbedo;
use crate::render::graph::mesh_stages::{MeshStages, PartSet};
use crate::render::graph::target::GeometryLayout;
use crate::render::scene::material::Material;
use crate::render::stage_part::{Part, ANCHORS};

#[derive(Clone, Debug, Default, PartialEq)]
pub struct ShadingVariant {
    /// Every pipeline constant of the material's shading, the core's first.
    pub constants: Vec<(&'static str, f64)>,
    /// The stage parts the shading reads: the anchors (object coordinates and per-vertex
    /// colours) for Gouraud shading, and what the effects ask for.
    pub parts: PartSet,
    /// Whether the stages read the mesh's colour (and texture).
    pub albedo: bool,
}

impl ShadingVariant {
    pub fn of(m: &Material, albedo: Option<&GpuAlbedo>) -> Self {
        let mut constants = vec![("PER_VERTEX", m.per_vertex as u32 as f64), ("MODEL", m.model.id() as f64)];
        constants.extend(albedo.map_or(vec![], GpuAlbedo::constants));
        let mut parts: Vec<&'static Part> = if m.per_vertex { vec![&ANCHORS] } else { vec![] };
        for effect in m.effects.variants() {
            constants.extend(effect.constants);
            parts.extend(effect.parts);
        }
        ShadingVariant { constants, parts: PartSet::of(&parts), albedo: albedo.is_some() }
    }

    /// The parts whose vertex data is derived from the mesh (made once and kept with it).
    pub fn derived(&self) -> impl Iterator<Item = &'static Part> + '_ {
        self.parts.iter().filter(|p| p.buffer.as_ref().is_some_and(|b| b.derive.is_some()))
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
        MeshStages { albedo: self.albedo, parts: self.parts, color: true, geometry, ..Default::default() }
    }
}

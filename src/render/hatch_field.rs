//! A mesh's hatching field on the device: per uploaded vertex, the two stripe values that field
//! hatching interpolates (`effects::hatching::field`), in a vertex buffer of its own (slot
//! `FIELD_SLOT`, beside the positions and normals). Made the first time a material that hatches
//! along the field draws the mesh and kept with it (`MeshRecord::derived`): meshes that do not
//! hatch so compute and upload nothing.

use std::sync::{Arc, Mutex};

use wgpu::util::DeviceExt;

use crate::cancel::Cancel;
use crate::edges::DEFAULT_CREASE_ANGLE;
use crate::error::Result;

use super::device::Device;
use super::effects::hatching::field::hatch_stripes;
use super::gpu_mesh::{auto_split, HostMesh, NormalMode};
use super::mesh_record::MeshRecord;

/// The vertex buffer slot of the field: past the mesh's and its colour's (`gpu_albedo::SLOT`),
/// so that a coloured mesh may hatch along it too.
pub const FIELD_SLOT: u32 = 2;
/// The vertex-stage location of the stripe values (the `field` part of `graph::mesh_stages`).
pub const FIELD_LOCATION: u32 = 7;

/// The cached buffer (None until a field-hatching material first draws the mesh).
#[derive(Default)]
pub struct HatchField {
    buffer: Mutex<Option<Arc<wgpu::Buffer>>>,
}

/// The stripe values of each vertex the device holds (the normal modes split vertices
/// differently: `GpuMesh::upload`), the surface cut at the creases the normals split at (the
/// default crease angle where they split nowhere). `corners`: the upload gave every corner its
/// own vertex (a mesh coloured per face: `GpuMesh::upload_with`).
fn device_values(host: &HostMesh, normals: NormalMode, corners: bool) -> Result<Vec<[f32; 4]>> {
    let angle = match normals {
        NormalMode::Auto { crease_angle } => crease_angle,
        _ => DEFAULT_CREASE_ANGLE,
    };
    let stripes = hatch_stripes(&host.positions, &host.faces, angle, Cancel::never())?;
    // the faces over the vertices the normals give, before any split into corners
    let (vertices, faces) = match normals {
        NormalMode::Smooth | NormalMode::Given => (host.positions.len(), host.faces.clone()),
        NormalMode::Auto { crease_angle } => {
            let split = auto_split(&host.positions, &host.faces, crease_angle)?;
            (split.source.len(), split.faces)
        }
        NormalMode::Flat => {
            let corners: Vec<[u32; 3]> =
                (0..host.faces.len() as u32).map(|f| [3 * f, 3 * f + 1, 3 * f + 2]).collect();
            return Ok(stripes.per_vertex(3 * host.faces.len(), &corners));
        }
    };
    let values = stripes.per_vertex(vertices, &faces);
    Ok(if corners { faces.iter().flatten().map(|&v| values[v as usize]).collect() } else { values })
}

impl HatchField {
    /// The field buffer of `rec`, made on first use.
    pub fn of(dev: &Device, rec: &MeshRecord) -> Result<Arc<wgpu::Buffer>> {
        let cache = rec.derived(HatchField::default);
        let mut slot = cache.buffer.lock().unwrap_or_else(|e| e.into_inner());
        if let Some(b) = &*slot {
            return Ok(b.clone());
        }
        // a mesh drawn as a list without flat normals was split into corners for its face colours
        let corners = rec.gpu.indices.is_none() && !matches!(rec.gpu.normals, NormalMode::Flat);
        let per_vertex = crate::parallel::install(|| device_values(&rec.host, rec.gpu.normals, corners))?;
        let buffer = Arc::new(dev.device.create_buffer_init(&wgpu::util::BufferInitDescriptor {
            label: Some("hatching field"),
            contents: bytemuck::cast_slice(&per_vertex),
            usage: wgpu::BufferUsages::VERTEX,
        }));
        *slot = Some(buffer.clone());
        Ok(buffer)
    }

    /// The field's vertex buffer layout: one vec4 (psi of each stroke family).
    pub fn vertex_layout() -> wgpu::VertexBufferLayout<'static> {
        const ATTRS: [wgpu::VertexAttribute; 1] = wgpu::vertex_attr_array![FIELD_LOCATION => Float32x4];
        wgpu::VertexBufferLayout {
            array_stride: std::mem::size_of::<[f32; 4]>() as u64,
            step_mode: wgpu::VertexStepMode::Vertex,
            attributes: &ATTRS,
        }
    }
}

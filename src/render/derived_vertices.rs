//! Vertex data that stage parts derive from a mesh (`stage_part::VertexData::derive`: the
//! hatching field's stripe values), on the device: per uploaded vertex, in a vertex buffer of
//! its own, made the first time a material that needs it draws the mesh and kept with the mesh
//! (`MeshRecord::derived`), one buffer per part. Meshes whose materials need none compute and
//! upload nothing.

use std::collections::HashMap;
use std::sync::{Arc, Mutex};

use wgpu::util::DeviceExt;

use crate::edges::DEFAULT_CREASE_ANGLE;
use crate::error::Result;

use super::device::Device;
use super::gpu_mesh::{auto_split, NormalMode};
use super::mesh_record::MeshRecord;
use super::stage_part::{Part, UploadedMesh};

/// The buffers made so far, by part name.
#[derive(Default)]
struct DerivedVertices {
    buffers: Mutex<HashMap<&'static str, Arc<wgpu::Buffer>>>,
}

/// The contents of `part`'s buffer for `rec`: its values over the vertices the normals give,
/// gathered to the corners where the upload gave every corner its own vertex (a mesh drawn as
/// a list without flat normals was split into corners for its face colours).
fn contents(rec: &MeshRecord, part: &Part, stride: usize) -> Result<Vec<u8>> {
    let derive = part.buffer.as_ref().and_then(|b| b.derive).expect("a part with derived vertex data");
    let host = &rec.host;
    let normals = rec.gpu.normals;
    let crease_angle = match normals {
        NormalMode::Auto { crease_angle } => crease_angle,
        _ => DEFAULT_CREASE_ANGLE,
    };
    let (vertices, faces) = match normals {
        NormalMode::Smooth | NormalMode::Given => (host.positions.len(), host.faces.clone()),
        NormalMode::Auto { crease_angle } => {
            let split = auto_split(&host.positions, &host.faces, crease_angle)?;
            (split.source.len(), split.faces)
        }
        NormalMode::Flat => {
            let corners = (0..host.faces.len() as u32).map(|f| [3 * f, 3 * f + 1, 3 * f + 2]).collect();
            (3 * host.faces.len(), corners)
        }
    };
    let mesh = UploadedMesh {
        positions: &host.positions,
        faces: &host.faces,
        crease_angle,
        vertices,
        uploaded_faces: &faces,
    };
    let values = crate::parallel::install(|| derive(&mesh))?;
    debug_assert_eq!(values.len(), vertices * stride);
    let corners = rec.gpu.indices.is_none() && !matches!(normals, NormalMode::Flat);
    if !corners {
        return Ok(values);
    }
    let at = |v: u32| &values[v as usize * stride..(v as usize + 1) * stride];
    Ok(faces.iter().flatten().flat_map(|&v| at(v).iter().copied()).collect())
}

/// The buffer of `part`'s derived vertex data for `rec`, made on first use.
pub fn derived_buffer(dev: &Device, rec: &MeshRecord, part: &'static Part) -> Result<Arc<wgpu::Buffer>> {
    let cache = rec.derived(DerivedVertices::default);
    let mut buffers = cache.buffers.lock().unwrap_or_else(|e| e.into_inner());
    if let Some(b) = buffers.get(part.name) {
        return Ok(b.clone());
    }
    let layout = part.buffer.as_ref().map(|b| (b.layout)()).expect("a part with a vertex buffer");
    let bytes = contents(rec, part, layout.array_stride as usize)?;
    let buffer = Arc::new(dev.device.create_buffer_init(&wgpu::util::BufferInitDescriptor {
        label: Some(part.name),
        contents: &bytes,
        // COPY_SRC: drafts read it back (`render::draft`)
        usage: wgpu::BufferUsages::VERTEX | wgpu::BufferUsages::COPY_SRC,
    }));
    buffers.insert(part.name, buffer.clone());
    Ok(buffer)
}

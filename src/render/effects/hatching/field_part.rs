//! How field hatching's stripe values reach the shading: the `field` stage part, a vertex
//! buffer of its own (slot `FIELD_SLOT`, beside the positions and normals and the mesh's
//! colour) whose values are derived per uploaded vertex from the stripes of the mesh
//! (`field::hatch_stripes`), the surface cut where the uploaded normals split it. The core makes
//! it the first time a material that hatches along the field draws the mesh and keeps it with
//! the mesh: meshes that do not hatch so compute and upload nothing.

use crate::cancel::Cancel;
use crate::error::Result;
use crate::render::stage_part::{Part, UploadedMesh, VertexData};

use super::field::hatch_stripes;

/// The vertex buffer slot of the field: past the mesh's (0) and its colour's (1), so that a
/// coloured mesh may hatch along it too.
pub const FIELD_SLOT: u32 = 2;
/// The vertex-stage location of the stripe values.
pub const FIELD_LOCATION: u32 = 7;

/// The field's vertex buffer layout: one vec4 (psi of each stroke family).
fn vertex_layout() -> wgpu::VertexBufferLayout<'static> {
    const ATTRS: [wgpu::VertexAttribute; 1] = wgpu::vertex_attr_array![FIELD_LOCATION => Float32x4];
    wgpu::VertexBufferLayout {
        array_stride: std::mem::size_of::<[f32; 4]>() as u64,
        step_mode: wgpu::VertexStepMode::Vertex,
        attributes: &ATTRS,
    }
}

/// The stripe values of each uploaded vertex.
fn stripe_values(m: &UploadedMesh<'_>) -> Result<Vec<u8>> {
    let stripes = hatch_stripes(m.positions, m.faces, m.crease_angle, Cancel::never())?;
    Ok(bytemuck::cast_slice(&stripes.per_vertex(m.vertices, m.uploaded_faces)).to_vec())
}

/// The hatching field's stripe values, for `Fragment.stripes`.
pub static FIELD: Part = Part {
    name: "field",
    varyings: &[("stripes", "vec4<f32>")],
    buffer: Some(VertexData {
        slot: FIELD_SLOT,
        layout: vertex_layout,
        names: &["stripes"],
        derive: Some(stripe_values),
    }),
    bindings: None,
    module: "",
    vertex: &["o.stripes = stripes;"],
    fragment: &["f.stripes = i.stripes;"],
    after: &[],
};

//! A mesh on the device: interleaved positions and normals (plus indices when shared), kept
//! for as many renders as the caller wants.

use wgpu::util::DeviceExt;

use crate::error::{Error, Result};
use crate::mesh::normals::{triangle_unit_normal, vertex_normals};
use crate::mesh::Bounds;
use crate::real::{Real, Vec3};

use super::context::GpuContext;

/// Bounds of the vertices that faces refer to (unreferenced ones do not count for framing).
fn used_bounds<T: Real>(positions: &[Vec3<T>], faces: &[[u32; 3]]) -> Bounds {
    let mut b = Bounds { min: [f64::INFINITY; 3], max: [f64::NEG_INFINITY; 3] };
    for &i in faces.iter().flatten() {
        let p = positions[i as usize];
        for k in 0..3 {
            b.min[k] = b.min[k].min(p[k].to_f64());
            b.max[k] = b.max[k].max(p[k].to_f64());
        }
    }
    b
}

#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum NormalMode {
    /// Area-weighted vertex normals, interpolated across faces.
    Smooth,
    /// One normal per face (vertices are split so that faces do not share them).
    Flat,
}

impl NormalMode {
    pub fn parse(arg: &str, s: &str) -> Result<Self> {
        match s {
            "smooth" => Ok(Self::Smooth),
            "flat" => Ok(Self::Flat),
            other => Err(Error::invalid(arg, format!("must be 'smooth' or 'flat', got {other:?}"))),
        }
    }
}

#[repr(C)]
#[derive(Clone, Copy, bytemuck::Pod, bytemuck::Zeroable)]
pub struct Vertex {
    pub position: [f32; 3],
    pub normal: [f32; 3],
}

pub struct GpuMesh {
    pub vertices: wgpu::Buffer,
    pub indices: Option<wgpu::Buffer>,
    /// Indices (indexed) or vertices (flat) to draw.
    pub draw_count: u32,
    /// Positions are stored relative to this point (the centre of the bounds), so that large
    /// coordinates keep their precision in f32; the model matrix adds it back in f64.
    pub origin: [f64; 3],
    /// Bounds of the vertices the faces use, in the mesh's own coordinates.
    pub bounds: Bounds,
    /// Distance from `origin` to the farthest vertex a face uses (a tighter frame than the box).
    pub radius: f64,
    pub n_vertices: usize,
    pub n_faces: usize,
    pub normals: NormalMode,
}

impl GpuMesh {
    pub fn upload<T: Real>(
        ctx: &GpuContext,
        positions: &[Vec3<T>],
        faces: &[[u32; 3]],
        normals: NormalMode,
    ) -> Result<GpuMesh> {
        if faces.is_empty() || positions.is_empty() {
            return Err(Error::invalid("faces", "the mesh has no faces"));
        }
        let bounds = used_bounds(positions, faces);
        let origin = bounds.center();
        let radius = faces
            .iter()
            .flatten()
            .map(|&i| {
                let p = positions[i as usize];
                (0..3).map(|k| (p[k].to_f64() - origin[k]).powi(2)).sum::<f64>()
            })
            .fold(0.0f64, f64::max)
            .sqrt();
        let rel = |p: Vec3<T>| -> [f32; 3] { std::array::from_fn(|k| (p[k].to_f64() - origin[k]) as f32) };
        let (vertices, indices): (Vec<Vertex>, Option<&[[u32; 3]]>) = match normals {
            NormalMode::Smooth => {
                let n = vertex_normals(positions, faces);
                let v = positions
                    .iter()
                    .zip(&n)
                    .map(|(p, n)| Vertex { position: rel(*p), normal: n.map(|x| x as f32) })
                    .collect();
                (v, Some(faces))
            }
            NormalMode::Flat => {
                let mut v = Vec::with_capacity(faces.len() * 3);
                for f in faces {
                    let [a, b, c] = f.map(|i| positions[i as usize]);
                    let n = triangle_unit_normal(a, b, c).map(|x| x as f32);
                    v.extend([a, b, c].map(|p| Vertex { position: rel(p), normal: n }));
                }
                (v, None)
            }
        };
        let vertex_bytes: &[u8] = bytemuck::cast_slice(&vertices);
        let index_bytes: &[u8] = indices.map(bytemuck::cast_slice).unwrap_or(&[]);
        let max = ctx.limits.max_buffer_size;
        if vertex_bytes.len() as u64 > max || index_bytes.len() as u64 > max {
            return Err(Error::invalid(
                "vertices",
                format!("the mesh needs a buffer larger than this GPU's limit of {max} bytes"),
            ));
        }
        let draw_count = match indices {
            Some(f) => f.len() * 3,
            None => vertices.len(),
        };
        let draw_count =
            u32::try_from(draw_count).map_err(|_| Error::invalid("faces", "too many faces for one draw"))?;
        let device = &ctx.device;
        let vertices = device.create_buffer_init(&wgpu::util::BufferInitDescriptor {
            label: Some("mesh vertices"),
            contents: vertex_bytes,
            usage: wgpu::BufferUsages::VERTEX,
        });
        let indices = indices.map(|_| {
            device.create_buffer_init(&wgpu::util::BufferInitDescriptor {
                label: Some("mesh indices"),
                contents: index_bytes,
                usage: wgpu::BufferUsages::INDEX,
            })
        });
        Ok(GpuMesh {
            vertices,
            indices,
            draw_count,
            origin,
            bounds,
            radius,
            n_vertices: positions.len(),
            n_faces: faces.len(),
            normals,
        })
    }

    pub fn vertex_layout() -> wgpu::VertexBufferLayout<'static> {
        const ATTRS: [wgpu::VertexAttribute; 2] = wgpu::vertex_attr_array![0 => Float32x3, 1 => Float32x3];
        wgpu::VertexBufferLayout {
            array_stride: std::mem::size_of::<Vertex>() as u64,
            step_mode: wgpu::VertexStepMode::Vertex,
            attributes: &ATTRS,
        }
    }
}

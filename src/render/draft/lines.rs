//! The drafts' mesh-space lines: each mesh's lines as buffers of one record per strip, which the
//! page draws with the exact frame's strips, colours and hidden-line rule (`lines.wgsl` around the
//! outlines' `line_vertex` and `fs_color`). The view-independent lines (boundaries, creases,
//! non-manifold edges: the exact frame's `MeshLines::statics`) are drawn in every view; the
//! silhouettes are decided per view in the vertex stages, by the exact frame's rule for the mesh
//! (`ContourRule`): face edges between a face toward the eye and one not, from the edges with both
//! faces' normals (`drawn` is that rule on the CPU, `edges::silhouette`'s), or smooth contours
//! through the faces of the mesh split at its drawn creases, with the face-edge rule on those
//! creases (`contour_piece` on the CPU, `edges::zero_set`'s piece of a face).

use crate::edges::outlines::LineKind;
use crate::edges::silhouette::{face_side, View};
use crate::error::Result;
use crate::render::effects::outlines::lines as exact;
use std::mem::offset_of;
use std::sync::Arc;

use crate::edges::contours::ContourMesh;
use crate::render::effects::outlines::mesh_lines::{LineInstance, MeshLines, SplitContours};
use crate::render::effects::outlines::settings::{ContourRule, Outlines};
use crate::render::gpu_mesh::{NormalMode, Vertex};
use crate::render::mesh_record::MeshRecord;
use crate::render::wgsl;

/// The module of the drafts' lines: the exact frame's lines pass, then the vertex stages
/// `vs_view_edge` and `vs_face_contour`.
pub fn module() -> String {
    wgsl::constant_u32("SILHOUETTE", LineKind::Silhouette as u32) + exact::WGSL + include_str!("lines.wgsl")
}

/// One line of a draft: the line as the exact frame's lines pass has it (its width factors 1:
/// the draft draws constant widths) and the normals of the two faces on it (zero: drawn in every
/// view).
#[repr(C)]
#[derive(Clone, Copy, Debug, PartialEq, bytemuck::Pod, bytemuck::Zeroable)]
pub struct ViewEdge {
    pub line: LineInstance,
    pub n0: [f32; 3],
    pub n1: [f32; 3],
}

impl ViewEdge {
    /// Edge `e` (indices into `positions`) as a line of `kind` between faces with normals `n0`
    /// and `n1`.
    pub fn new(positions: &[[f64; 3]], e: &[u32; 2], kind: LineKind, n0: [f32; 3], n1: [f32; 3]) -> Self {
        let line = LineInstance::new(kind, positions[e[0] as usize], positions[e[1] as usize], [1.0; 2]);
        ViewEdge { line, n0, n1 }
    }
}

/// The lines' buffer layout (the `LineInstance` attributes, then the two normals): one record
/// per line, which the page gives to the 4 vertices of its strip.
pub fn layout() -> wgpu::VertexBufferLayout<'static> {
    const fn normal(offset: usize, shader_location: u32) -> wgpu::VertexAttribute {
        wgpu::VertexAttribute {
            format: wgpu::VertexFormat::Float32x3,
            offset: offset as u64,
            shader_location,
        }
    }
    const ATTRS: [wgpu::VertexAttribute; 6] = {
        let [a, kind, b, scale] = LineInstance::ATTRIBUTES;
        [a, kind, b, scale, normal(offset_of!(ViewEdge, n0), 4), normal(offset_of!(ViewEdge, n1), 5)]
    };
    wgpu::VertexBufferLayout {
        array_stride: std::mem::size_of::<ViewEdge>() as u64,
        step_mode: wgpu::VertexStepMode::Vertex,
        attributes: &ATTRS,
    }
}

/// Whether `vs_view_edge` draws `e` in `view` (the mesh's stored coordinates): a line of the
/// mesh, or an edge with one face toward the eye and one not (a face's plane through `e.a`).
pub fn drawn(e: &ViewEdge, view: View) -> bool {
    if e.n0 == [0.0; 3] && e.n1 == [0.0; 3] {
        return true;
    }
    let a = e.line.a.map(f64::from);
    let side = |n: [f32; 3]| {
        let n = n.map(f64::from);
        face_side(&n, n[0] * a[0] + n[1] * a[1] + n[2] * a[2], view)
    };
    side(e.n0) != side(e.n1)
}

/// A face for smooth contours: its corners' positions (the mesh's stored coordinates) and
/// normals.
#[repr(C)]
#[derive(Clone, Copy, Debug, PartialEq, bytemuck::Pod, bytemuck::Zeroable)]
pub struct FaceContour {
    pub p: [[f32; 3]; 3],
    pub n: [[f32; 3]; 3],
}

/// The faces' buffer layout (the three positions, then the three normals): one record per
/// face, which the page gives to the 4 vertices of its strip.
pub fn face_layout() -> wgpu::VertexBufferLayout<'static> {
    const ATTRS: [wgpu::VertexAttribute; 6] = wgpu::vertex_attr_array![
        0 => Float32x3, 1 => Float32x3, 2 => Float32x3, 3 => Float32x3, 4 => Float32x3, 5 => Float32x3
    ];
    wgpu::VertexBufferLayout {
        array_stride: std::mem::size_of::<FaceContour>() as u64,
        step_mode: wgpu::VertexStepMode::Vertex,
        attributes: &ATTRS,
    }
}

/// `n` made unit (a zero normal stays zero), as `vs_face_contour` does: the normals of a coarse
/// copy are means.
fn unit(n: [f32; 3]) -> [f32; 3] {
    let l2 = n[0] * n[0] + n[1] * n[1] + n[2] * n[2];
    if l2 > 0.0 {
        n.map(|x| x / l2.sqrt())
    } else {
        n
    }
}

/// The piece of smooth contour `vs_face_contour` draws in face `f` in `view` (the mesh's
/// stored coordinates): where n . (eye - p) (orthographic: -n . d), n the unit normal,
/// interpolated linearly between the corners, is zero.
pub fn contour_piece(f: &FaceContour, view: View) -> Option<[[f64; 3]; 2]> {
    let p = f.p.map(|q| q.map(f64::from));
    let g: [f64; 3] = std::array::from_fn(|i| {
        let n = unit(f.n[i]).map(f64::from);
        let v = match view {
            View::Eye(e) => [e[0] - p[i][0], e[1] - p[i][1], e[2] - p[i][2]],
            View::Direction(d) => [-d[0], -d[1], -d[2]],
        };
        n[0] * v[0] + n[1] * v[1] + n[2] * v[2]
    });
    let mut ends = Vec::new();
    for j in 0..3 {
        let k = (j + 1) % 3;
        if (g[j] > 0.0) != (g[k] > 0.0) {
            let t = (g[j] / (g[j] - g[k])).clamp(0.0, 1.0);
            ends.push(std::array::from_fn(|c| p[j][c] + t * (p[k][c] - p[j][c])));
        }
    }
    (ends.len() == 2).then(|| [ends[0], ends[1]])
}

/// A mesh's lines for drafts: lines, and the mesh smooth contours are traced on (the mesh
/// split at its drawn creases).
#[derive(Default)]
pub struct DraftMeshLines {
    pub edges: Vec<ViewEdge>,
    pub contours: Option<Arc<SplitContours>>,
}

/// The bytes of `mesh`'s vertices in the layout of `GpuMesh::vertex_layout` (a position and a
/// normal each), appended to `out`; the page gathers each face's `FaceContour` from them.
pub fn contour_vertices(mesh: &ContourMesh, out: &mut Vec<u8>) {
    out.reserve_exact(mesh.positions().len() * std::mem::size_of::<Vertex>());
    for (p, n) in mesh.positions().iter().zip(mesh.normals()) {
        let v = Vertex { position: p.map(|x| x as f32), normal: n.map(|x| x as f32) };
        out.extend_from_slice(bytemuck::bytes_of(&v));
    }
}

/// A mesh's lines for drafts under `outlines`: the view-independent lines of the kinds it
/// draws, then, where it draws silhouettes, the edges between two faces with their normals
/// (every such edge under the face-edge rule; under the smooth rule, the drawn creases among
/// them, and the faces of the mesh split at those). Width factors are 1: the draft draws
/// constant widths.
pub fn mesh_lines(rec: &MeshRecord, outlines: &Outlines) -> Result<DraftMeshLines> {
    let lines = MeshLines::of(rec);
    let index = lines.index(&rec.host, outlines.weld)?;
    let statics = lines.statics(&rec.host, outlines)?;
    let draws = |k: LineKind| outlines.styles[k as usize].is_some();
    let positions = index.positions();
    let edge = |e: &[u32; 2], kind, n0, n1| ViewEdge::new(positions, e, kind, n0, n1);
    let mut edges: Vec<ViewEdge> = statics
        .edges
        .iter()
        .zip(&statics.kinds)
        .filter(|(_, k)| draws(**k))
        .map(|(e, k)| edge(e, *k, [0.0; 3], [0.0; 3]))
        .collect();
    let mut contours = None;
    if draws(LineKind::Silhouette) {
        let flat = rec.gpu.normals == NormalMode::Flat;
        let split = match outlines.contours.resolve(flat) {
            ContourRule::Smooth => Some(lines.split_contours(&rec.host, outlines)?),
            _ => None,
        };
        let (candidates, their_faces) = index.manifold();
        let normal = |f: u32| index.normals()[f as usize].map(|x| x as f32);
        let tested = |e: &[u32; 2]| split.as_ref().is_none_or(|s| s.hard.binary_search(e).is_ok());
        edges.extend(
            candidates
                .iter()
                .zip(their_faces)
                .filter(|(e, _)| tested(e))
                .map(|(e, f)| edge(e, LineKind::Silhouette, normal(f[0]), normal(f[1]))),
        );
        if let Some(s) = split {
            contours = Some(s);
        }
    }
    Ok(DraftMeshLines { edges, contours })
}

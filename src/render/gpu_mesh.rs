//! A mesh on the device: interleaved positions and normals (plus indices when shared), and its
//! colour and texture when it has them (`gpu_albedo`, a buffer of their own), kept for as many
//! renders as the caller wants.
//!
//! Positions reach the GPU in 32-bit floats, so they are stored relative to the centre of the
//! mesh's bounds and divided by a power of two near its size: whatever the mesh's offset and
//! scale (anywhere in float64's range), the stored coordinates lie in [-1, 1] and keep float32's
//! full precision. The model matrix puts offset and scale back, in float64 (see `uniforms.rs`).

use rayon::prelude::*;
use wgpu::util::DeviceExt;

use crate::edges::crooked_creases::DEFAULT_MAX_CREASE_TURN;
use crate::edges::feature::check_crease_angle;
use crate::edges::find_feature_edges;
use crate::edges::short_creases::{keep_drawn_creases, DEFAULT_MIN_CREASE_LENGTH};
use crate::edges::DEFAULT_CREASE_ANGLE;
use crate::error::{Error, Result};
use crate::mesh::crease_normals::{split_normals, ListedEdges, SplitNormals};
use crate::mesh::enclosure::{enclosure_welded, Enclosure};
use crate::mesh::normals::{triangle_unit_normal, vertex_normals};
use crate::mesh::Bounds;
use crate::real::{Real, Vec3};

use super::albedo::{Albedo, Colors};
use super::device::Device;
use super::gpu_albedo::GpuAlbedo;

#[derive(Clone, Copy, Debug, PartialEq)]
pub enum NormalMode {
    /// Area-weighted vertex normals, interpolated across faces.
    Smooth,
    /// One normal per face (vertices are split so that faces do not share them).
    Flat,
    /// Smooth, except across the creases a drawing keeps (`auto_split`): edges sharper than
    /// `crease_angle` degrees in pieces long and straight enough, and boundary and non-manifold
    /// edges, where vertices are split (`mesh::crease_normals`): hard edges shade hard, curved
    /// parts and a scan's noise smooth.
    Auto { crease_angle: f64 },
    /// The mesh's own normals, one per vertex (`MeshNormals::Given`), interpolated across faces.
    Given,
}

impl NormalMode {
    /// The normals of a mesh given no mode and no normals of its own: split at the creases a
    /// drawing keeps, right on CAD parts (hard edges) and on scans (no noise made hard).
    pub const DEFAULT: NormalMode = NormalMode::Auto { crease_angle: DEFAULT_CREASE_ANGLE };

    /// A mode by name, as the argument `arg`; "auto" splits at `DEFAULT_CREASE_ANGLE`.
    pub fn parse(arg: &str, s: &str) -> Result<Self> {
        match s {
            "smooth" => Ok(Self::Smooth),
            "flat" => Ok(Self::Flat),
            "auto" => Ok(Self::Auto { crease_angle: DEFAULT_CREASE_ANGLE }),
            other => Err(Error::invalid(arg, format!("must be 'smooth', 'flat' or 'auto', got {other:?}"))),
        }
    }

    /// "auto" with a crease angle in degrees, checked as the argument `arg`.
    pub fn auto(arg: &str, crease_angle: f64) -> Result<Self> {
        check_crease_angle(crease_angle).map_err(|_| {
            Error::invalid(arg, format!("the crease angle must be in [0, 180] degrees, got {crease_angle}"))
        })?;
        Ok(Self::Auto { crease_angle })
    }

    /// A mode given by name with a crease angle (read by `angle`), as the argument `arg`: only
    /// "auto" takes one.
    pub fn with_angle(arg: &str, name: &str, angle: impl FnOnce() -> Result<f64>) -> Result<Self> {
        if name != "auto" {
            return Err(Error::invalid(
                arg,
                format!("only 'auto' takes a crease angle, got ({name:?}, ...)"),
            ));
        }
        Self::auto(arg, angle()?)
    }

    /// The crease angle the mode is written with: "auto" at an angle other than the default.
    pub fn written_angle(self) -> Option<f64> {
        match self {
            Self::Auto { crease_angle } if crease_angle != DEFAULT_CREASE_ANGLE => Some(crease_angle),
            _ => None,
        }
    }

    pub fn name(self) -> &'static str {
        match self {
            Self::Smooth => "smooth",
            Self::Flat => "flat",
            Self::Auto { .. } => "auto",
            Self::Given => "given",
        }
    }
}

/// The normals a mesh is uploaded with: made by a mode, or its own unit normals, one a vertex
/// (checked by `mesh::normals::given_unit_normals`).
#[derive(Clone, Debug, PartialEq)]
pub enum MeshNormals {
    Mode(NormalMode),
    Given(Vec<[f32; 3]>),
}

impl From<NormalMode> for MeshNormals {
    fn from(mode: NormalMode) -> Self {
        MeshNormals::Mode(mode)
    }
}

impl MeshNormals {
    /// The mode the mesh is drawn with (`Given` for its own normals).
    pub fn mode(&self) -> NormalMode {
        match self {
            MeshNormals::Mode(m) => *m,
            MeshNormals::Given(_) => NormalMode::Given,
        }
    }
}

/// The vertices split at the creases a drawing keeps (`NormalMode::Auto`): the crease edges
/// sharper than `crease_angle` degrees, less the pieces a scan's noise makes (shorter than
/// `DEFAULT_MIN_CREASE_LENGTH` of the bounding-box diagonal, or turning by more than
/// `DEFAULT_MAX_CREASE_TURN` on average: `edges::keep_drawn_creases`, the rule of the drawn
/// crease lines), and boundary, non-manifold and degenerate faces' edges.
pub fn auto_split(stored: &[[f64; 3]], faces: &[[u32; 3]], crease_angle: f64) -> Result<SplitNormals> {
    let (mut fe, _) = find_feature_edges(stored, faces, crease_angle, false)?;
    keep_drawn_creases(&mut fe, stored, DEFAULT_MIN_CREASE_LENGTH, DEFAULT_MAX_CREASE_TURN);
    let mut hard: Vec<[u32; 2]> = fe.crease.iter().map(|&[a, b]| [a.min(b), a.max(b)]).collect();
    hard.sort_unstable();
    split_normals(stored, faces, &ListedEdges(&hard))
}

#[repr(C)]
#[derive(Clone, Copy, bytemuck::Pod, bytemuck::Zeroable)]
pub struct Vertex {
    pub position: [f32; 3],
    pub normal: [f32; 3],
}

/// Where a mesh's stored coordinates sit in its own space: `p = origin + scale * stored`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Placement {
    pub origin: [f64; 3],
    /// A power of two, so that dividing and multiplying by it are exact.
    pub scale: f64,
}

impl Placement {
    /// Centre of `bounds`, and the power of two at or above its half diagonal.
    pub fn of(bounds: &Bounds) -> Placement {
        let origin = std::array::from_fn(|k| 0.5 * bounds.min[k] + 0.5 * bounds.max[k]);
        // half the diagonal, without squaring coordinates that may be near float64's limits
        let extent: [f64; 3] = std::array::from_fn(|k| 0.5 * bounds.max[k] - 0.5 * bounds.min[k]);
        let m = extent.iter().fold(0.0f64, |m, e| m.max(e.abs()));
        let half =
            if m > 0.0 { m * extent.iter().map(|e| (e / m) * (e / m)).sum::<f64>().sqrt() } else { 0.0 };
        let scale = if half.is_finite() && half > 0.0 { 2f64.powi(half.log2().ceil() as i32) } else { 1.0 };
        Placement { origin, scale: if scale.is_finite() && scale > 0.0 { scale } else { 1.0 } }
    }

    /// The stored (normalised) coordinates of `p`.
    pub fn to_stored<T: Real>(&self, p: Vec3<T>) -> [f64; 3] {
        std::array::from_fn(|k| (p[k].to_f64() - self.origin[k]) / self.scale)
    }
}

/// Bounds of the vertices that faces refer to (unreferenced ones do not count for framing).
fn used_bounds<T: Real>(positions: &[Vec3<T>], faces: &[[u32; 3]]) -> Bounds {
    let empty = || Bounds { min: [f64::INFINITY; 3], max: [f64::NEG_INFINITY; 3] };
    faces
        .par_chunks(8192)
        .map(|chunk| {
            let mut b = empty();
            for &i in chunk.iter().flatten() {
                let p = positions[i as usize];
                for (k, &x) in p.iter().enumerate() {
                    b.min[k] = b.min[k].min(Real::to_f64(x));
                    b.max[k] = b.max[k].max(Real::to_f64(x));
                }
            }
            b
        })
        .reduce(empty, |a, b| Bounds {
            min: std::array::from_fn(|k| a.min[k].min(b.min[k])),
            max: std::array::from_fn(|k| a.max[k].max(b.max[k])),
        })
}

/// The vertices to upload, the indices when vertices are shared (None: drawn as a list), and
/// the input vertex of each uploaded one where vertices were split by crease (None: the same
/// vertices, or for flat normals corner i of face i / 3).
type Built = (Vec<Vertex>, Option<Vec<[u32; 3]>>, Option<Vec<u32>>);

fn build_vertices(stored: &[[f64; 3]], faces: &[[u32; 3]], normals: &MeshNormals) -> Result<Built> {
    let f32s = |p: &[f64; 3]| p.map(|x| x as f32);
    let mode = match normals {
        MeshNormals::Given(n) => {
            let v =
                stored.par_iter().zip(n).map(|(p, &normal)| Vertex { position: f32s(p), normal }).collect();
            return Ok((v, None, None));
        }
        MeshNormals::Mode(mode) => *mode,
    };
    Ok(match mode {
        NormalMode::Smooth | NormalMode::Given => {
            let n = vertex_normals(stored, faces);
            let v = stored
                .par_iter()
                .zip(&n)
                .map(|(p, n)| Vertex { position: f32s(p), normal: f32s(n) })
                .collect();
            (v, None, None)
        }
        NormalMode::Auto { crease_angle } => {
            let split = auto_split(stored, faces, crease_angle)?;
            let v = split
                .source
                .par_iter()
                .zip(&split.normals)
                .map(|(&i, n)| Vertex { position: f32s(&stored[i as usize]), normal: f32s(n) })
                .collect();
            (v, Some(split.faces), Some(split.source))
        }
        NormalMode::Flat => {
            let v = faces
                .par_iter()
                .flat_map_iter(|f| {
                    let [a, b, c] = f.map(|i| stored[i as usize]);
                    let n = f32s(&triangle_unit_normal(a, b, c));
                    [a, b, c].map(|p| Vertex { position: f32s(&p), normal: n })
                })
                .collect();
            (v, None, None)
        }
    })
}

/// A mesh's geometry in stored coordinates, kept on the host for the outline analysis.
pub struct HostMesh {
    pub positions: Vec<[f64; 3]>,
    pub faces: Vec<[u32; 3]>,
}

pub struct GpuMesh {
    pub vertices: wgpu::Buffer,
    pub indices: Option<wgpu::Buffer>,
    /// Indices (indexed) or vertices (flat) to draw.
    pub draw_count: u32,
    pub placement: Placement,
    /// Bounds of the vertices the faces use, in the mesh's own coordinates.
    pub bounds: Bounds,
    /// Distance from `placement.origin` to the farthest vertex a face uses (a tighter frame
    /// than the box).
    pub radius: f64,
    pub n_vertices: usize,
    pub n_faces: usize,
    pub normals: NormalMode,
    /// How the faces enclose solids, if they do (what allows back-face culling).
    pub enclosure: Option<Enclosure>,
    /// The mesh's colour and texture, if it has any.
    pub albedo: Option<GpuAlbedo>,
}

impl GpuMesh {
    /// Uploads a mesh whose faces index `positions` (checked by the caller). Returns the
    /// device mesh and the host copy in stored coordinates.
    pub fn upload<T: Real>(
        dev: &Device,
        positions: &[Vec3<T>],
        faces: Vec<[u32; 3]>,
        normals: impl Into<MeshNormals>,
    ) -> Result<(GpuMesh, HostMesh)> {
        Self::upload_with(dev, positions, faces, normals.into(), None)
    }

    /// `upload`, with the mesh's colour and texture (checked by the caller, its texture fitted
    /// to the device). Per-face colours draw the faces as a list, each corner its own vertex.
    pub fn upload_with<T: Real>(
        dev: &Device,
        positions: &[Vec3<T>],
        faces: Vec<[u32; 3]>,
        normals: MeshNormals,
        albedo: Option<&Albedo>,
    ) -> Result<(GpuMesh, HostMesh)> {
        if faces.is_empty() || positions.is_empty() {
            return Err(Error::invalid("faces", "the mesh has no faces"));
        }
        if let MeshNormals::Given(n) = &normals {
            if n.len() != positions.len() {
                return Err(Error::invalid(
                    "normals",
                    format!("{} normals for {} vertices: give one a vertex", n.len(), positions.len()),
                ));
            }
        }
        let bounds = used_bounds(positions, &faces);
        let placement = Placement::of(&bounds);
        let stored: Vec<[f64; 3]> = positions.par_iter().map(|&p| placement.to_stored(p)).collect();
        let radius = faces
            .par_iter()
            .map(|f| {
                f.iter().map(|&i| stored[i as usize].iter().map(|x| x * x).sum::<f64>()).fold(0.0, f64::max)
            })
            .reduce(|| 0.0, f64::max)
            .sqrt()
            * placement.scale;
        // whether the faces enclose solids, found while the vertices are built
        let (encloses, built) =
            rayon::join(|| enclosure_welded(&stored, &faces), || build_vertices(&stored, &faces, &normals));
        let normals = normals.mode();
        let (mut vertices, mut indices, mut source) = built?;
        let mut indexed = !matches!(normals, NormalMode::Flat);
        let per_face = matches!(albedo.and_then(|a| a.colors.as_ref()), Some(Colors::Face(_)));
        if per_face && indexed {
            // flat colour per face: every corner its own vertex
            let list: &[[u32; 3]] = indices.as_deref().unwrap_or(&faces);
            let corners: Vec<u32> = list.iter().flatten().copied().collect();
            source = Some(corners.iter().map(|&i| source.as_ref().map_or(i, |s| s[i as usize])).collect());
            vertices = corners.iter().map(|&i| vertices[i as usize]).collect();
            (indices, indexed) = (None, false);
        }
        let vertex_bytes: &[u8] = bytemuck::cast_slice(&vertices);
        let index_bytes: &[u8] = match (&indices, indexed) {
            (Some(split), _) => bytemuck::cast_slice(split),
            (None, true) => bytemuck::cast_slice(&faces),
            (None, false) => &[],
        };
        let max = dev.limits.max_buffer_size;
        if vertex_bytes.len() as u64 > max || index_bytes.len() as u64 > max {
            return Err(Error::invalid(
                "vertices",
                format!("the mesh needs a buffer larger than this GPU's limit of {max} bytes"),
            ));
        }
        let draw_count = if indexed { faces.len() * 3 } else { vertices.len() };
        let draw_count =
            u32::try_from(draw_count).map_err(|_| Error::invalid("faces", "too many faces for one draw"))?;
        let device = &dev.device;
        let vertex_buffer = device.create_buffer_init(&wgpu::util::BufferInitDescriptor {
            label: Some("mesh vertices"),
            contents: vertex_bytes,
            // read back for a draft drawn elsewhere (`render::draft`)
            usage: wgpu::BufferUsages::VERTEX | wgpu::BufferUsages::COPY_SRC,
        });
        let index_buffer = indexed.then(|| {
            device.create_buffer_init(&wgpu::util::BufferInitDescriptor {
                label: Some("mesh indices"),
                contents: index_bytes,
                usage: wgpu::BufferUsages::INDEX | wgpu::BufferUsages::COPY_SRC,
            })
        });
        let flat = matches!(normals, NormalMode::Flat);
        let albedo = albedo.filter(|a| a.is_used()).map(|a| {
            GpuAlbedo::upload(dev, a, vertices.len(), |i| match &source {
                Some(s) => s[i] as usize,
                None if flat => faces[i / 3][i % 3] as usize,
                None => i,
            })
        });
        let mesh = GpuMesh {
            vertices: vertex_buffer,
            indices: index_buffer,
            draw_count,
            placement,
            bounds,
            radius,
            n_vertices: positions.len(),
            n_faces: faces.len(),
            normals,
            enclosure: encloses,
            albedo,
        };
        Ok((mesh, HostMesh { positions: stored, faces }))
    }

    pub fn vertex_layout() -> wgpu::VertexBufferLayout<'static> {
        const ATTRS: [wgpu::VertexAttribute; 2] = wgpu::vertex_attr_array![0 => Float32x3, 1 => Float32x3];
        wgpu::VertexBufferLayout {
            array_stride: std::mem::size_of::<Vertex>() as u64,
            step_mode: wgpu::VertexStepMode::Vertex,
            attributes: &ATTRS,
        }
    }

    /// The min and max corners of the box around the vertices the faces use, in the mesh's own
    /// coordinates.
    pub fn bounding_box(&self) -> [glam::DVec3; 2] {
        [glam::DVec3::from_array(self.bounds.min), glam::DVec3::from_array(self.bounds.max)]
    }

    /// The mesh's bounding sphere in its own coordinates.
    pub fn sphere(&self) -> super::scene::camera::Sphere {
        super::scene::camera::Sphere {
            center: glam::DVec3::from_array(self.placement.origin),
            radius: self.radius,
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn placement_keeps_stored_coordinates_within_one() {
        for (offset, size) in [(0.0, 1.0), (1e10, 1.0), (0.0, 1e-11), (-3e200, 5e190), (0.0, 1e-300)] {
            let b = Bounds { min: [offset - size; 3], max: [offset + size; 3] };
            let p = Placement::of(&b);
            assert_eq!(p.scale.log2().fract(), 0.0, "a power of two");
            let s = p.to_stored([offset + size, offset - size, offset]);
            assert!(s.iter().all(|x| x.abs() <= 1.0 && x.is_finite()), "{s:?}");
            assert!(s[0] > 0.25, "the size is kept: {s:?}");
        }
    }
}

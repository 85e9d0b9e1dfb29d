//! One part of a mesh pipeline's stages, as the core and a per-pixel effect declare it: the
//! varyings it passes from the vertex to the fragment stage, the vertex data it reads (the
//! mesh's own buffers, or values an effect derives from the mesh, made once and kept with it),
//! the bind group it reads (its variables and layout; the stages give it a group index), its
//! WGSL at module scope, and its lines of vertex and fragment code. `graph::mesh_stages` writes the stages of a draw
//! from the parts it needs; an effect asks for parts through its `Variant`
//! (`effects::surface_effect`) and lists the ones it owns in the registry (`effects::surface`).
//! Plain data: no device.

use crate::error::Result;

/// A vertex buffer a part reads.
pub struct VertexData {
    /// Its vertex-buffer slot.
    pub slot: u32,
    /// Its layout (the locations and formats of its attributes).
    pub layout: fn() -> wgpu::VertexBufferLayout<'static>,
    /// The names its attributes take in the vertex stage, in the layout's order.
    pub names: &'static [&'static str],
    /// How its values are made from the mesh (None: a buffer of the mesh's own upload, bound by
    /// the core). Made the first time a draw needs it and kept with the mesh.
    pub derive: Option<Derive>,
}

/// Makes a derived vertex buffer's contents: one element of the layout's stride per uploaded
/// vertex (`UploadedMesh::vertices`), as bytes.
pub type Derive = fn(&UploadedMesh<'_>) -> Result<Vec<u8>>;

/// What derived vertex data is made from: the mesh as stored, and as the device holds it.
pub struct UploadedMesh<'a> {
    /// The stored positions and faces (checked indices).
    pub positions: &'a [[f64; 3]],
    pub faces: &'a [[u32; 3]],
    /// The angle in degrees at which the uploaded normals split the surface (the default
    /// crease angle where they split nowhere).
    pub crease_angle: f64,
    /// The number of uploaded vertices, and the faces over them (face f is stored face f).
    pub vertices: usize,
    pub uploaded_faces: &'a [[u32; 3]],
}

/// A bind group a part reads: its variables, bound 0, 1, ... in order. The stages declare them
/// in the group they give the part (`MeshStages::groups`: after the frame's, the draw's and a
/// shading hook's), and the pipeline's layout takes `layout` there.
pub struct Bindings {
    /// Each variable's name and WGSL type, e.g. `("albedo_texture", "texture_2d<f32>")`.
    pub vars: &'static [(&'static str, &'static str)],
    /// The group's layout: one entry per variable, in order.
    pub layout: fn(&wgpu::Device) -> wgpu::BindGroupLayout,
}

/// One part of a mesh pipeline's stages.
pub struct Part {
    /// Its name: unique among parts (the stages' name, and derived data's cache key).
    pub name: &'static str,
    /// The varyings it adds (name, WGSL type).
    pub varyings: &'static [(&'static str, &'static str)],
    pub buffer: Option<VertexData>,
    pub bindings: Option<Bindings>,
    /// WGSL at module scope (functions and pipeline constants its code calls), written once
    /// into the stages that have the part.
    pub module: &'static str,
    /// Vertex code: sets its varyings on `o` from the vertex's attributes (`p`: the view-space
    /// position, after the `position` part).
    pub vertex: &'static [&'static str],
    /// Fragment code before the shading: fills in the pixel `f` (a `Fragment`) and the Gouraud
    /// colours `lit` from the varyings `i`.
    pub fragment: &'static [&'static str],
    /// Fragment code after the shading (every derivative taken).
    pub after: &'static [&'static str],
}

/// The mesh's stored coordinates and normal (what object-anchored effects, such as hatching
/// and dithering fixed to the surface, anchor to) and the Gouraud colours.
pub static ANCHORS: Part = Part {
    name: "anchors",
    varyings: &[
        ("color_front", "vec3<f32>"),
        ("color_back", "vec3<f32>"),
        ("object_pos", "vec3<f32>"),
        ("object_normal", "vec3<f32>"),
    ],
    buffer: None,
    bindings: None,
    module: "",
    vertex: &[
        "let shaded = gouraud(o.view_normal, o.view_pos);",
        "o.color_front = shaded.front;",
        "o.color_back = shaded.back;",
        "o.object_pos = position;",
        "o.object_normal = normal;",
    ],
    fragment: &[
        "f.object_pos = i.object_pos;",
        "f.object_normal = i.object_normal;",
        "lit = Gouraud(i.color_front, i.color_back);",
    ],
    after: &[],
};

// a part is known by its name (unique among parts)
impl PartialEq for Part {
    fn eq(&self, other: &Part) -> bool {
        self.name == other.name
    }
}

impl std::fmt::Debug for Part {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        write!(f, "Part({})", self.name)
    }
}

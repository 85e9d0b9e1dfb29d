//! The stages of a mesh pipeline, written for what its draw needs: the varyings struct
//! (`MeshOut`), the vertex entry point `vs_mesh` and the fragment entry point `fs_mesh`, put
//! together from one declaration per part (`render::stage_part::Part`): the core's (where the
//! vertex is, the mesh's colour and texture), those a material's effects ask for (the anchors,
//! an effect's own such as hatching's field), and the targets the pass writes (`Output`). A
//! draw passes on only the varyings it reads: a CPU rasteriser sets up every one of them for
//! every triangle, which on small triangles costs as much as the shading.

use std::sync::OnceLock;

use super::glass_layer as glass;
use crate::render::device::COLOR_FORMAT;
use crate::render::effects::surface;
use crate::render::gpu_albedo;
use crate::render::gpu_mesh::GpuMesh;
use crate::render::pipelines::target;
use crate::render::stage_part::{Bindings, Part, VertexData, ANCHORS};

use super::target::GeometryLayout;

/// What a mesh pipeline's stages read and write.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub struct MeshStages {
    /// Reads the mesh's colour and texture (`gpu_albedo`: its vertex buffer and bind group).
    pub albedo: bool,
    /// The parts the material's shading asks for (the anchors, effects' own parts).
    pub parts: PartSet,
    /// Writes the shaded colour.
    pub color: bool,
    /// Writes the geometry target (after the colour, so that the targets stay contiguous: the GL
    /// backend mishandles gaps between colour attachments).
    pub geometry: Option<GeometryLayout>,
    /// The matrix from normalised view space to where the vertices are drawn, when not the
    /// camera's projection (`frame.view.proj`): the shadow-casting light's, for the shadow map.
    pub clip: Option<&'static str>,
    /// Writes one layer of glass (`passes::glass`): the nearest fragment behind the layer
    /// peeled before and in front of the opaque surface, as premultiplied colour and the depth
    /// the next peel starts from, instead of the colour and geometry targets.
    pub glass: bool,
}

/// The first bind group the parts' bindings take: after the frame's (0), the draw's (1) and a
/// shading hook's (2).
pub const FIRST_PART_GROUP: u32 = 3;

/// The parts a material may ask for, in the order their varyings and code follow each other:
/// the anchors, then the parts the per-pixel effects declare (`effects::surface::parts`).
pub fn requestable() -> &'static [&'static Part] {
    static PARTS: OnceLock<Vec<&'static Part>> = OnceLock::new();
    PARTS.get_or_init(|| {
        let mut parts = vec![&ANCHORS];
        parts.extend(surface::parts());
        assert!(parts.len() <= 8, "PartSet holds 8 parts");
        parts
    })
}

/// A set of requestable parts (bit i: `requestable()[i]`).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub struct PartSet(u8);

impl PartSet {
    /// The set of `parts` (each requestable: an effect's part is declared in its `PARTS`).
    pub fn of(parts: &[&'static Part]) -> Self {
        let all = requestable();
        PartSet(parts.iter().fold(0, |bits, p| {
            let i = all.iter().position(|q| q == p);
            bits | 1 << i.unwrap_or_else(|| panic!("part {} is not declared by an effect", p.name))
        }))
    }

    pub fn contains(&self, part: &Part) -> bool {
        self.iter().any(|p| p == part)
    }

    /// Its parts, in `requestable()` order.
    pub fn iter(&self) -> impl Iterator<Item = &'static Part> + '_ {
        requestable().iter().enumerate().filter(|(i, _)| self.0 >> i & 1 == 1).map(|(_, p)| *p)
    }

    /// Every subset of the requestable parts.
    pub fn all() -> impl Iterator<Item = PartSet> {
        (0..1u16 << requestable().len()).map(|b| PartSet(b as u8))
    }
}

/// Where the vertex is: every mesh pipeline reads the mesh's positions and normals.
static POSITION: Part = Part {
    name: "position",
    varyings: &[("view_pos", "vec3<f32>"), ("view_normal", "vec3<f32>")],
    buffer: Some(VertexData {
        slot: 0,
        layout: GpuMesh::vertex_layout,
        names: &["position", "normal"],
        derive: None,
    }),
    bindings: None,
    module: "",
    vertex: &[
        "let p = draw.mesh.model_view * vec4<f32>(position, 1.0);",
        "o.view_pos = p.xyz;",
        "o.view_normal = (draw.mesh.normal_matrix * vec4<f32>(normal, 0.0)).xyz;",
    ],
    fragment: &[
        "var f = plain_fragment(i.clip, i.view_pos, i.view_normal, front_facing);",
        "var lit = Gouraud(vec3<f32>(0.0), vec3<f32>(0.0));",
    ],
    after: &[],
};

/// The mesh's colour and texture (shaders/albedo.wgsl), and its alpha cutoff.
pub static ALBEDO: Part = Part {
    name: "albedo",
    varyings: &[("color", "vec4<f32>"), ("uv", "vec2<f32>")],
    buffer: Some(VertexData {
        slot: gpu_albedo::SLOT,
        layout: gpu_albedo::vertex_layout,
        names: &["color", "uv"],
        derive: None,
    }),
    bindings: Some(Bindings {
        vars: &[("albedo_texture", "texture_2d<f32>"), ("albedo_sampler", "sampler")],
        layout: gpu_albedo::bind_group_layout,
    }),
    module: include_str!("../shaders/albedo.wgsl"),
    vertex: &["o.color = color;", "o.uv = uv;"],
    fragment: &["let a = albedo_sample(i.color, i.uv);", "albedo = a.rgb;"],
    after: &["if (a.a < ALPHA_CUTOFF) {", "    discard;", "}"],
};

/// Gouraud shading of a coloured mesh: the highlight apart from the rest (ambient and diffuse
/// of a white surface), so that the albedo multiplies only the rest, per pixel.
static ALBEDO_GOURAUD: Part = Part {
    name: "albedo_gouraud",
    varyings: &[("specular_front", "vec3<f32>"), ("specular_back", "vec3<f32>")],
    buffer: None,
    bindings: None,
    module: "",
    vertex: &[
        "albedo = vec3<f32>(0.0);",
        "let highlight = gouraud(o.view_normal, o.view_pos);",
        "albedo = vec3<f32>(1.0);",
        "o.color_front = o.color_front - highlight.front;",
        "o.color_back = o.color_back - highlight.back;",
        "o.specular_front = highlight.front;",
        "o.specular_back = highlight.back;",
    ],
    fragment: &["lit = Gouraud(lit.front * albedo + i.specular_front, lit.back * albedo + i.specular_back);"],
    after: &[],
};

/// A layer of glass: what it peels and how opaque it is (`passes::glass`).
pub static GLASS: Part = Part {
    name: "glass",
    varyings: &[],
    buffer: None,
    bindings: Some(Bindings {
        vars: &[("opaque_depth", "texture_2d<u32>"), ("peeled_depth", "texture_2d<u32>")],
        layout: glass::peel_layout,
    }),
    module: glass::PEEL_WGSL,
    vertex: &[],
    // outside the layer before shading: most fragments of a later layer are (a discard demotes
    // the pixel to a helper, so the shading's derivatives still have their quad)
    fragment: &[
        "if (!in_layer(i.clip.xy, depth_bits(f))) {",
        "    discard;",
        "}",
        "var opacity = draw.material.opacity;",
    ],
    after: &[],
};

/// A glass mesh's colour alpha, where it counts (glTF's alpha blend).
static GLASS_ALBEDO: Part = Part {
    name: "glass_albedo",
    varyings: &[],
    buffer: None,
    bindings: None,
    module: "",
    vertex: &[],
    fragment: &["opacity *= select(1.0, a.a, ALPHA_BLEND);"],
    after: &[],
};

/// A target the fragment stage writes: its member of `MeshTargets`, its WGSL type, its value.
struct Output {
    name: &'static str,
    ty: &'static str,
    value: &'static str,
}

const COLOR: Output = Output { name: "color", ty: "vec4<f32>", value: "shaded_color(f, lit, front_facing)" };
const NORMAL_DEPTH: Output = Output { name: "geometry", ty: "vec4<u32>", value: "normal_depth_bits(f)" };
const DEPTH: Output = Output { name: "geometry", ty: "u32", value: "depth_bits(f)" };
const LAYER: Output = Output {
    name: "layer",
    ty: "vec4<f32>",
    value: "layer_color(shaded_color(f, lit, front_facing), opacity)",
};
const PEELED: Output = Output { name: "peeled", ty: "u32", value: "depth_bits(f)" };

/// The WGSL type of a vertex attribute.
fn attribute_type(format: wgpu::VertexFormat) -> &'static str {
    match format {
        wgpu::VertexFormat::Float32x2 => "vec2<f32>",
        wgpu::VertexFormat::Float32x3 => "vec3<f32>",
        wgpu::VertexFormat::Float32x4 => "vec4<f32>",
        other => unreachable!("no mesh attribute is {other:?}"),
    }
}

fn lines(out: &mut String, code: &[&str]) {
    for line in code {
        out.push_str("    ");
        out.push_str(line);
        out.push('\n');
    }
}

impl MeshStages {
    /// Its parts, in the order their varyings and code follow each other.
    fn parts(&self) -> Vec<&'static Part> {
        let mut parts = vec![&POSITION];
        parts.extend(self.parts.iter());
        if self.albedo {
            parts.push(&ALBEDO);
            if self.parts.contains(&ANCHORS) {
                parts.push(&ALBEDO_GOURAUD);
            }
        }
        if self.glass {
            parts.push(&GLASS);
            if self.albedo {
                parts.push(&GLASS_ALBEDO);
            }
        }
        parts
    }

    fn outputs(&self) -> Vec<&'static Output> {
        if self.glass {
            return vec![&LAYER, &PEELED];
        }
        let mut outputs = Vec::new();
        if self.color {
            outputs.push(&COLOR);
        }
        match self.geometry {
            Some(GeometryLayout::NormalDepth) => outputs.push(&NORMAL_DEPTH),
            Some(GeometryLayout::Depth) => outputs.push(&DEPTH),
            None => {}
        }
        outputs
    }

    /// Whether it has a fragment stage: it writes a colour target, or a part cuts pixels (a
    /// depth-only draw of plain meshes, such as the shadow map's, needs none).
    pub fn fragment(&self) -> bool {
        !self.outputs().is_empty() || self.parts().iter().any(|p| !p.after.is_empty())
    }

    /// Its name: the parts, the clip matrix and the targets (the shader module's cache key and
    /// label).
    pub fn name(&self) -> String {
        let parts: Vec<_> = self.parts().iter().map(|p| p.name).collect();
        let mut targets: Vec<&str> = if self.color { vec!["color"] } else { vec![] };
        if self.glass {
            targets = vec!["glass layer"];
        }
        targets.extend(self.geometry.map(|g| match g {
            GeometryLayout::NormalDepth => "normal_depth",
            GeometryLayout::Depth => "depth",
        }));
        let clip = self.clip.map_or(String::new(), |c| format!(" @ {c}"));
        format!("{}{clip} -> {}", parts.join(" + "), targets.join(" + "))
    }

    /// A pipeline-cache key's bits for it (14 of them).
    pub fn bits(&self) -> u64 {
        (self.glass as u64) << 13
            | self.albedo as u64
            | (self.color as u64) << 1
            | self.geometry.map_or(0, |g| 1 + g as u64) << 2
            | (self.clip.is_some() as u64) << 4
            | (self.parts.0 as u64) << 5
    }

    /// The bind groups its parts read, each with its group index (from `FIRST_PART_GROUP`, in
    /// the parts' order).
    pub fn groups(&self) -> Vec<(u32, &'static Part)> {
        let with_bindings = self.parts().into_iter().filter(|p| p.bindings.is_some());
        (FIRST_PART_GROUP..).zip(with_bindings).collect()
    }

    /// The group index of `part`'s bindings (None: the stages do not read them).
    pub fn group_of(&self, part: &Part) -> Option<u32> {
        self.groups().into_iter().find(|(_, p)| *p == part).map(|(g, _)| g)
    }

    /// The formats of the targets it writes, in order.
    pub fn targets(&self) -> Vec<Option<wgpu::ColorTargetState>> {
        if self.glass {
            return vec![target(glass::LAYER_FORMAT), target(glass::PEELED_FORMAT)];
        }
        let mut targets = Vec::new();
        if self.color {
            targets.push(target(COLOR_FORMAT));
        }
        targets.extend(self.geometry.map(|g| target(g.format())));
        targets
    }

    /// The parts that read a vertex buffer, with it, in the parts' order.
    pub fn buffers(&self) -> Vec<(&'static Part, &'static VertexData)> {
        self.parts().into_iter().filter_map(|p| p.buffer.as_ref().map(|b| (p, b))).collect()
    }

    /// The vertex buffers it reads, each in its slot (None: a slot it leaves empty).
    pub fn vertex_buffers(&self) -> Vec<Option<wgpu::VertexBufferLayout<'static>>> {
        let mut buffers = Vec::new();
        for (_, b) in self.buffers() {
            let slot = b.slot as usize;
            buffers.resize(buffers.len().max(slot + 1), None);
            buffers[slot] = Some((b.layout)());
        }
        buffers
    }

    /// Its WGSL: `MeshOut`, `MeshTargets`, `vs_mesh` and `fs_mesh`.
    pub fn wgsl(&self) -> String {
        let parts = self.parts();
        let outputs = self.outputs();
        let mut s = format!("// written by src/render/graph/mesh_stages.rs for {}\n\n", self.name());
        for p in parts.iter().filter(|p| !p.module.is_empty()) {
            s += &format!("// {}\n{}\n", p.name, p.module);
        }
        for (group, p) in self.groups() {
            let vars = p.bindings.as_ref().map_or(&[][..], |b| b.vars);
            for (binding, (name, ty)) in vars.iter().enumerate() {
                s += &format!("@group({group}) @binding({binding}) var {name}: {ty};\n");
            }
            s += "\n";
        }
        s += "struct MeshOut {\n    @builtin(position) clip: vec4<f32>,\n";
        let varyings = parts.iter().flat_map(|p| p.varyings.iter());
        for (location, (name, ty)) in varyings.enumerate() {
            s += &format!("    @location({location}) {name}: {ty},\n");
        }
        s += "};\n\n";
        if !outputs.is_empty() {
            s += "struct MeshTargets {\n";
            for (location, o) in outputs.iter().enumerate() {
                s += &format!("    @location({location}) {}: {},\n", o.name, o.ty);
            }
            s += "};\n\n";
        }
        s += "@vertex\nfn vs_mesh(";
        let mut inputs = Vec::new();
        for b in parts.iter().filter_map(|p| p.buffer.as_ref()) {
            for (a, name) in (b.layout)().attributes.iter().zip(b.names) {
                inputs.push(format!("@location({}) {name}: {}", a.shader_location, attribute_type(a.format)));
            }
        }
        s += &inputs.join(", ");
        s += ") -> MeshOut {\n    var o: MeshOut;\n";
        for p in &parts {
            s += &format!("    // {}\n", p.name);
            lines(&mut s, p.vertex);
        }
        s += &format!("    o.clip = {} * p;\n", self.clip.unwrap_or("frame.view.proj"));
        s += "    return o;\n}\n\n@fragment\nfn fs_mesh(i: MeshOut, @builtin(front_facing) front_facing: bool)";
        s += if outputs.is_empty() { " {\n" } else { " -> MeshTargets {\n" };
        for p in parts.iter().filter(|p| !p.fragment.is_empty()) {
            s += &format!("    // {}\n", p.name);
            lines(&mut s, p.fragment);
        }
        if !outputs.is_empty() {
            s += "    var out: MeshTargets;\n";
        }
        for o in &outputs {
            s += &format!("    out.{} = {};\n", o.name, o.value);
        }
        for p in parts.iter().filter(|p| !p.after.is_empty()) {
            s += &format!("    // {}, after the shading\n", p.name);
            lines(&mut s, p.after);
        }
        s + if outputs.is_empty() { "}\n" } else { "    return out;\n}\n" }
    }

    /// Every combination: the mesh's colour or none, every set of the parts a material may ask
    /// for, and every set of targets a pass writes (a layer of glass among them).
    pub fn all() -> Vec<MeshStages> {
        let targets = [
            (true, None),
            (true, Some(GeometryLayout::NormalDepth)),
            (true, Some(GeometryLayout::Depth)),
            (false, Some(GeometryLayout::NormalDepth)),
            (false, Some(GeometryLayout::Depth)),
        ];
        let mut all = Vec::new();
        for albedo in [false, true] {
            for parts in PartSet::all() {
                for (color, geometry) in targets {
                    all.push(MeshStages { albedo, parts, color, geometry, ..Default::default() });
                }
                all.push(MeshStages { albedo, parts, glass: true, ..Default::default() });
            }
        }
        all
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn varyings_are_only_what_the_parts_add() {
        let plain = MeshStages { color: true, ..Default::default() }.wgsl();
        assert!(plain.contains("@location(1) view_normal") && !plain.contains("@location(2)"), "{plain}");
        let parts = PartSet::of(requestable());
        let all = MeshStages { albedo: true, parts, color: true, ..Default::default() };
        let s = all.wgsl();
        assert!(s.contains("@location(10) specular_back: vec3<f32>"), "{s}");
        // the attributes' locations are the vertex layouts'
        let color = gpu_albedo::COLOR_LOCATION;
        assert!(s.contains(&format!("@location({color}) color: vec4<f32>")), "{s}");
        // the albedo part's bindings, declared in the group the stages give it, and its
        // module-scope code, only where the part is
        assert_eq!(all.group_of(&ALBEDO), Some(FIRST_PART_GROUP));
        let group = format!("@group({FIRST_PART_GROUP}) @binding(1) var albedo_sampler: sampler;");
        assert!(s.contains(&group) && s.contains("fn albedo_sample"), "{s}");
        assert!(plain.find("albedo_sample").is_none() && MeshStages::default().groups().is_empty());
    }

    #[test]
    fn every_combination_has_its_own_name_and_bits() {
        let all = MeshStages::all();
        let names: std::collections::HashSet<_> = all.iter().map(MeshStages::name).collect();
        let bits: std::collections::HashSet<_> = all.iter().map(MeshStages::bits).collect();
        assert_eq!(names.len(), all.len());
        assert_eq!(bits.len(), all.len());
        assert!(all.iter().all(|s| s.bits() < 1 << 14));
    }

    #[test]
    fn parts_have_their_own_names_slots_and_locations() {
        let mut parts = vec![&POSITION, &ALBEDO, &ALBEDO_GOURAUD];
        parts.extend(requestable());
        let names: std::collections::HashSet<_> = parts.iter().map(|p| p.name).collect();
        assert_eq!(names.len(), parts.len());
        let buffers: Vec<_> = parts.iter().filter_map(|p| p.buffer.as_ref()).collect();
        let slots: std::collections::HashSet<_> = buffers.iter().map(|b| b.slot).collect();
        assert_eq!(slots.len(), buffers.len());
        let locations: Vec<u32> =
            buffers.iter().flat_map(|b| (b.layout)().attributes.iter().map(|a| a.shader_location)).collect();
        let distinct: std::collections::HashSet<_> = locations.iter().collect();
        assert_eq!(distinct.len(), locations.len(), "{locations:?}");
    }
}

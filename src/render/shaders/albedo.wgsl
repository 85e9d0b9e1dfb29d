
// Colour on the surface (src/render/gpu_albedo.rs): the mesh's colour (per vertex, or flat per
// face) times its texture sample, both in linear light, is the albedo that multiplies the
// material's ambient and diffuse colours (`albedo` in common.wgsl). Only pipelines of meshes
// that have colour use these entry points, so other meshes read no more than before. The
// shading pass (shade/albedo.wgsl) and the geometry pass (its alpha cutoff) share this part.

// Whether the mesh has a texture (otherwise its colour alone).
override TEXTURED: bool = false;
// glTF's alpha mask: pixels whose alpha is below it are not drawn; negative: opaque.
override ALPHA_CUTOFF: f32 = -1.0;

@group(3) @binding(0) var albedo_texture: texture_2d<f32>;
@group(3) @binding(1) var albedo_sampler: sampler;

struct AlbedoIn {
    @location(8) color: vec4<f32>,   // linear rgba
    @location(9) uv: vec2<f32>,
};

// `VsOut` and the albedo's varyings (locations past those `VsOut` may take).
struct VsOutAlbedo {
    @builtin(position) clip: vec4<f32>,
    @location(0) view_pos: vec3<f32>,
    @location(1) view_normal: vec3<f32>,
    @location(2) color_front: vec3<f32>,
    @location(3) color_back: vec3<f32>,
    @location(4) object_pos: vec3<f32>,
    @location(5) object_normal: vec3<f32>,
    @location(10) color: vec4<f32>,
    @location(11) uv: vec2<f32>,
    // Gouraud: the highlight, apart from `color_*` (ambient and diffuse of a white surface),
    // so that the albedo multiplies only the latter, per pixel
    @location(12) specular_front: vec3<f32>,
    @location(13) specular_back: vec3<f32>,
};

// The vertex stage of a coloured mesh, everything `VsOut` has.
fn albedo_vertex(v: VsIn, a: AlbedoIn) -> VsOutAlbedo {
    var specular = VsOut();
    if (PER_VERTEX) {
        albedo = vec3<f32>(0.0);
        specular = mesh_vertex(v);
        albedo = vec3<f32>(1.0);
    }
    let o = mesh_vertex(v);
    return VsOutAlbedo(
        o.clip, o.view_pos, o.view_normal,
        o.color_front - specular.color_front, o.color_back - specular.color_back,
        o.object_pos, o.object_normal, a.color, a.uv, specular.color_front, specular.color_back,
    );
}

@vertex
fn vs_albedo_anchored(v: VsIn, a: AlbedoIn) -> VsOutAlbedo {
    return albedo_vertex(v, a);
}

// What a material that needs no anchors (`ShadingVariant::anchored`) reads: four varyings
// instead of ten, since a CPU rasteriser sets up each one for every triangle.
struct VsOutAlbedoLean {
    @builtin(position) clip: vec4<f32>,
    @location(0) view_pos: vec3<f32>,
    @location(1) view_normal: vec3<f32>,
    @location(10) color: vec4<f32>,
    @location(11) uv: vec2<f32>,
};

@vertex
fn vs_albedo(v: VsIn, a: AlbedoIn) -> VsOutAlbedoLean {
    let o = albedo_vertex(v, a);
    return VsOutAlbedoLean(o.clip, o.view_pos, o.view_normal, o.color, o.uv);
}

fn unlean(v: VsOutAlbedoLean) -> VsOutAlbedo {
    let o = vec3<f32>(0.0);
    return VsOutAlbedo(v.clip, v.view_pos, v.view_normal, o, o, o, o, v.color, v.uv, o, o);
}

// The albedo's alpha at a pixel: colour alpha times texture alpha.
fn albedo_sample(color: vec4<f32>, uv: vec2<f32>) -> vec4<f32> {
    var a = color;
    if (TEXTURED) {
        a *= textureSample(albedo_texture, albedo_sampler, uv);
    }
    return a;
}


// Colour on the surface (src/render/gpu_albedo.rs): the mesh's colour (per vertex, or flat per
// face) times its texture sample, both in linear light, is the albedo that multiplies the
// material's ambient and diffuse colours (`albedo` in common.wgsl). Only pipelines of meshes
// that have colour use these entry points, so other meshes read no more than before.

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

@vertex
fn vs_albedo(v: VsIn, a: AlbedoIn) -> VsOutAlbedo {
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

// The shaded colour of a coloured mesh's pixel; alpha: the albedo's, for the cutoff.
fn albedo_shaded(v: VsOutAlbedo, front_facing: bool) -> vec4<f32> {
    var a = v.color;
    if (TEXTURED) {
        a *= textureSample(albedo_texture, albedo_sampler, v.uv);
    }
    albedo = a.rgb;
    let anchors = Anchors(
        v.color_front * a.rgb + v.specular_front,
        v.color_back * a.rgb + v.specular_back,
        v.object_pos,
        v.object_normal,
    );
    return vec4<f32>(shaded_color(Varyings(v.clip, v.view_pos, v.view_normal), anchors, front_facing).rgb, a.a);
}

// Drops the pixel when alpha is below the cutoff (after every derivative is taken).
fn albedo_cut(c: vec4<f32>) -> vec4<f32> {
    if (c.a < ALPHA_CUTOFF) {
        discard;
    }
    return vec4<f32>(c.rgb, 1.0);
}

@fragment
fn fs_color_albedo(v: VsOutAlbedo, @builtin(front_facing) front_facing: bool) -> @location(0) vec4<f32> {
    return albedo_cut(albedo_shaded(v, front_facing));
}

@fragment
fn fs_color_normal_depth_albedo(v: VsOutAlbedo, @builtin(front_facing) front_facing: bool) -> ColorNormalDepth {
    let c = albedo_cut(albedo_shaded(v, front_facing));
    return ColorNormalDepth(c, normal_depth_bits(Varyings(v.clip, v.view_pos, v.view_normal), front_facing));
}

@fragment
fn fs_color_depth_albedo(v: VsOutAlbedo, @builtin(front_facing) front_facing: bool) -> ColorDepth {
    let c = albedo_cut(albedo_shaded(v, front_facing));
    return ColorDepth(c, depth_bits(Varyings(v.clip, v.view_pos, v.view_normal)));
}

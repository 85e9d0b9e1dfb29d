
// Colour on the surface (src/render/gpu_albedo.rs): the mesh's colour (per vertex, or flat per
// face) times its texture sample, both in linear light, is the albedo that multiplies the
// material's ambient and diffuse colours (`albedo` in common.wgsl). The module-scope code of the
// `albedo` stage part (src/render/graph/mesh_stages.rs), which also declares the texture and
// its sampler (`albedo_texture`, `albedo_sampler`) in a group of their own: only the stages of
// meshes that have colour have it, so other meshes read no more than before. The shading pass,
// the geometry pass and the shadow map (the alpha cutoff) share this part.

// Whether the mesh has a texture (otherwise its colour alone).
override TEXTURED: bool = false;
// glTF's alpha mask: pixels whose alpha is below it are not drawn; negative: opaque.
override ALPHA_CUTOFF: f32 = -1.0;
// glTF's alpha blend: the alpha multiplies the material's opacity (read by the glass stage).
override ALPHA_BLEND: bool = false;

// The albedo's alpha at a pixel: colour alpha times texture alpha.
fn albedo_sample(color: vec4<f32>, uv: vec2<f32>) -> vec4<f32> {
    var a = color;
    if (TEXTURED) {
        a *= textureSample(albedo_texture, albedo_sampler, uv);
    }
    return a;
}

// One layer of glass (src/render/passes/glass): the module-scope code of the `glass` stage part
// (src/render/graph/mesh_stages.rs), written after the shading pass's WGSL. A fragment is in
// the layer when it lies strictly behind the layer peeled before (`peeled_depth`, cleared to 0
// for the first) and in front of the opaque surface (`opaque_depth`, the geometry target); of
// those the depth test keeps the nearest. Depths are linear, as f32 bits (`depth_bits`): GL
// cannot read depth textures.

// The word of the geometry target's texel that holds the linear depth (`GeometryLayout`).
override OPAQUE_DEPTH_WORD: u32 = 0u;

fn in_layer(pixel: vec2<f32>, depth: u32) -> bool {
    let p = vec2<i32>(pixel);
    let d = bitcast<f32>(depth);
    let opaque = bitcast<f32>(textureLoad(opaque_depth, p, 0)[OPAQUE_DEPTH_WORD]);
    let peeled = bitcast<f32>(textureLoad(peeled_depth, p, 0).x);
    return d > peeled && d < opaque;
}

// The layer's colour, premultiplied by its opacity (the under and over operators take it so).
fn layer_color(c: vec4<f32>, opacity: f32) -> vec4<f32> {
    return vec4<f32>(c.rgb * opacity, opacity);
}

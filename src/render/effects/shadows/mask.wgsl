// The shadow output: the shadow-casting light's visibility at each pixel, from the view-space
// normal and depth of the geometry target (1 where no mesh is), as f32 bits.

@group(1) @binding(0) var geometry: texture_2d<u32>;

@fragment
fn fs_shadow(@builtin(position) pos: vec4<f32>) -> @location(0) u32 {
    let texel = textureLoad(geometry, vec2<i32>(floor(pos.xy)), 0);
    let z = bitcast<f32>(texel.w);
    if ((texel.w & 0x7f800000u) == 0x7f800000u) {
        return bitcast<u32>(1.0);
    }
    let n = bitcast<vec3<f32>>(texel.xyz);
    // the pixel centre back in normalised view space (the projection is symmetric)
    let ndc = vec2<f32>(pos.x / frame.view.size.x * 2.0 - 1.0, 1.0 - pos.y / frame.view.size.y * 2.0);
    let scale = vec2<f32>(frame.view.proj[0][0], frame.view.proj[1][1]);
    let xy = select(ndc * z / scale, (ndc - vec2<f32>(frame.view.proj[3][0], frame.view.proj[3][1])) / scale, frame.view.orthographic == 1u);
    let p = vec3<f32>(xy, -z);
    let d = dot(n, frame.lighting.lights[0].position.xyz);
    return bitcast<u32>(light_visibility(0u, n, p, d));
}

// Supersampling: a box filter over FACTOR x FACTOR texels. The source is sRGB, so loads decode
// to linear light and the average is taken there; the sRGB target encodes on store.

@group(1) @binding(0) var source: texture_2d<f32>;

override FACTOR: u32 = 2u;

@fragment
fn fs_downsample(@builtin(position) pos: vec4<f32>) -> @location(0) vec4<f32> {
    let base = vec2<u32>(floor(pos.xy)) * FACTOR;
    var sum = vec4<f32>(0.0);
    for (var j = 0u; j < FACTOR; j++) {
        for (var i = 0u; i < FACTOR; i++) {
            sum += textureLoad(source, vec2<i32>(base + vec2<u32>(i, j)), 0);
        }
    }
    return sum / f32(FACTOR * FACTOR);
}

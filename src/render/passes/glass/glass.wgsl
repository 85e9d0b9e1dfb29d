// Glass compositing (src/render/passes/glass): each peeled layer is added under the layers
// before it (front to back, `fs_under`, with the blend state `UNDER`), then the whole is laid
// over the opaque colour (`fs_composite`, blend state `OVER`). Colours are premultiplied,
// in linear light. CPU twin: src/render/passes/glass/reference.rs.

@group(1) @binding(0) var source: texture_2d<f32>;

@fragment
fn fs_glass(@builtin(position) p: vec4<f32>) -> @location(0) vec4<f32> {
    return textureLoad(source, vec2<i32>(p.xy), 0);
}

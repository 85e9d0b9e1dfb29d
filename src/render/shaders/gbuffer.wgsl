// The geometry pass: view-space normal and linear depth only, one sample per pixel. It runs
// when those outputs are asked for but the shading pass cannot write them (multisampled or
// supersampled colour), or when no colour is asked for at all.

struct GBufferOut {
    @location(0) normal: vec4<u32>,
    @location(1) depth: u32,
};

@fragment
fn fs_gbuffer(i: VsOut, @builtin(front_facing) front_facing: bool) -> GBufferOut {
    var o: GBufferOut;
    o.normal = vec4<u32>(bitcast<vec3<u32>>(facing_normal(i.view_normal, front_facing)), 0u);
    o.depth = bitcast<u32>(-i.view_pos.z);
    return o;
}

// The geometry pass: view-space normal and linear depth only, one sample per pixel. It runs
// when those outputs are asked for but the shading pass cannot write them (multisampled or
// supersampled colour), or when no colour is asked for at all. One entry point per set of
// targets, as in shade.wgsl.

fn normal_bits(i: VsOut, front_facing: bool) -> vec4<u32> {
    return vec4<u32>(bitcast<vec3<u32>>(facing_normal(i.view_normal, front_facing)), 0u);
}

fn depth_bits(i: VsOut) -> u32 {
    return bitcast<u32>(-i.view_pos.z);
}

@fragment
fn fs_normal(i: VsOut, @builtin(front_facing) front_facing: bool) -> @location(0) vec4<u32> {
    return normal_bits(i, front_facing);
}

@fragment
fn fs_depth(i: VsOut) -> @location(0) u32 {
    return depth_bits(i);
}

struct NormalDepth {
    @location(0) normal: vec4<u32>,
    @location(1) depth: u32,
};

@fragment
fn fs_normal_depth(i: VsOut, @builtin(front_facing) front_facing: bool) -> NormalDepth {
    return NormalDepth(normal_bits(i, front_facing), depth_bits(i));
}

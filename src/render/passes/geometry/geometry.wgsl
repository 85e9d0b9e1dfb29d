// The geometry pass: view-space normal and linear depth only, one sample per pixel at the
// output size. It runs when these are needed but the shading pass cannot write them
// (multisampled or supersampled colour), or when no colour is asked for at all.

@fragment
fn fs_normal_depth(i: Varyings, @builtin(front_facing) front_facing: bool) -> @location(0) vec4<u32> {
    return normal_depth_bits(i, front_facing);
}

@fragment
fn fs_depth(i: Varyings) -> @location(0) u32 {
    return depth_bits(i);
}

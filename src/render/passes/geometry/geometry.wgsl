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

// A coloured mesh with an alpha cutoff: no normal or depth where its pixels are cut
// (shaders/albedo.wgsl).
fn albedo_kept(v: VsOutAlbedoLean) {
    if (albedo_sample(v.color, v.uv).a < ALPHA_CUTOFF) {
        discard;
    }
}

@fragment
fn fs_normal_depth_albedo(v: VsOutAlbedoLean, @builtin(front_facing) front_facing: bool) -> @location(0) vec4<u32> {
    albedo_kept(v);
    return normal_depth_bits(Varyings(v.clip, v.view_pos, v.view_normal), front_facing);
}

@fragment
fn fs_depth_albedo(v: VsOutAlbedoLean) -> @location(0) u32 {
    albedo_kept(v);
    return depth_bits(Varyings(v.clip, v.view_pos, v.view_normal));
}

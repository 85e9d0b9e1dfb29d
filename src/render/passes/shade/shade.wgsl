// The shading pass: toon-shaded colour and, when this pass writes the geometry target (one
// sample per pixel at the output size), the view-space normal and linear depth as f32 bit
// patterns. One entry point per set of targets, so that the targets are always contiguous
// (the GL backend mishandles gaps between colour attachments).

fn shaded_color(i: VsOut, front_facing: bool) -> vec4<f32> {
    var c: vec3<f32>;
    if (PER_VERTEX) {
        c = select(i.color_back, i.color_front, outer_side(front_facing));
    } else {
        c = shade(facing_normal(i.view_normal, front_facing), i.view_pos);
    }
    return vec4<f32>(clamp(c, vec3<f32>(0.0), vec3<f32>(1.0)), 1.0);
}

@fragment
fn fs_color(i: VsOut, @builtin(front_facing) front_facing: bool) -> @location(0) vec4<f32> {
    return shaded_color(i, front_facing);
}

struct ColorNormalDepth {
    @location(0) color: vec4<f32>,
    @location(1) geometry: vec4<u32>,
};

@fragment
fn fs_color_normal_depth(i: VsOut, @builtin(front_facing) front_facing: bool) -> ColorNormalDepth {
    return ColorNormalDepth(shaded_color(i, front_facing), normal_depth_bits(i, front_facing));
}

struct ColorDepth {
    @location(0) color: vec4<f32>,
    @location(1) depth: u32,
};

@fragment
fn fs_color_depth(i: VsOut, @builtin(front_facing) front_facing: bool) -> ColorDepth {
    return ColorDepth(shaded_color(i, front_facing), depth_bits(i));
}

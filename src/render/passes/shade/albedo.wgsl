
// The shading of a coloured mesh (src/render/shaders/albedo.wgsl has its vertex stage).

// The shaded colour of a coloured mesh's pixel; alpha: the albedo's, for the cutoff.
fn albedo_shaded(v: VsOutAlbedo, front_facing: bool) -> vec4<f32> {
    let a = albedo_sample(v.color, v.uv);
    albedo = a.rgb;
    let anchors = Anchors(
        v.color_front * a.rgb + v.specular_front,
        v.color_back * a.rgb + v.specular_back,
        v.object_pos,
        v.object_normal,
    );
    return vec4<f32>(shaded_color(Varyings(v.clip, v.view_pos, v.view_normal), anchors, front_facing).rgb, a.a);
}

// Drops the pixel when alpha is below the cutoff (after every derivative is taken).
fn albedo_cut(c: vec4<f32>) -> vec4<f32> {
    if (c.a < ALPHA_CUTOFF) {
        discard;
    }
    return vec4<f32>(c.rgb, 1.0);
}

@fragment
fn fs_color_albedo(v: VsOutAlbedoLean, @builtin(front_facing) front_facing: bool) -> @location(0) vec4<f32> {
    return albedo_cut(albedo_shaded(unlean(v), front_facing));
}

@fragment
fn fs_color_albedo_anchored(v: VsOutAlbedo, @builtin(front_facing) front_facing: bool) -> @location(0) vec4<f32> {
    return albedo_cut(albedo_shaded(v, front_facing));
}

fn albedo_normal_depth(v: VsOutAlbedo, front_facing: bool) -> ColorNormalDepth {
    let c = albedo_cut(albedo_shaded(v, front_facing));
    return ColorNormalDepth(c, normal_depth_bits(Varyings(v.clip, v.view_pos, v.view_normal), front_facing));
}

@fragment
fn fs_color_normal_depth_albedo(v: VsOutAlbedoLean, @builtin(front_facing) front_facing: bool) -> ColorNormalDepth {
    return albedo_normal_depth(unlean(v), front_facing);
}

@fragment
fn fs_color_normal_depth_albedo_anchored(v: VsOutAlbedo, @builtin(front_facing) front_facing: bool) -> ColorNormalDepth {
    return albedo_normal_depth(v, front_facing);
}

fn albedo_depth(v: VsOutAlbedo, front_facing: bool) -> ColorDepth {
    let c = albedo_cut(albedo_shaded(v, front_facing));
    return ColorDepth(c, depth_bits(Varyings(v.clip, v.view_pos, v.view_normal)));
}

@fragment
fn fs_color_depth_albedo(v: VsOutAlbedoLean, @builtin(front_facing) front_facing: bool) -> ColorDepth {
    return albedo_depth(unlean(v), front_facing);
}

@fragment
fn fs_color_depth_albedo_anchored(v: VsOutAlbedo, @builtin(front_facing) front_facing: bool) -> ColorDepth {
    return albedo_depth(v, front_facing);
}

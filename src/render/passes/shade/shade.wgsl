// The shading pass: toon-shaded colour and, when this pass writes the geometry target (one
// sample per pixel at the output size), the view-space normal and linear depth as f32 bit
// patterns. One entry point per set of targets, so that the targets are always contiguous
// (the GL backend mishandles gaps between colour attachments). Per-pixel effects join through
// their hooks (`surface_jitter`, `surface_finish`: src/render/effects/surface.rs).

fn shaded_color(i: Varyings, a: Anchors, front_facing: bool) -> vec4<f32> {
    return shaded_color_on(i, a, vec4<f32>(0.0), front_facing);
}

// `stripes`: the hatching field's values (zero where the material does not hatch along it).
fn shaded_color_on(i: Varyings, a: Anchors, stripes: vec4<f32>, front_facing: bool) -> vec4<f32> {
    let f = Fragment(i.clip, i.view_pos, facing_normal(i.view_normal, front_facing), a.object_pos, a.object_normal,
                     stripes);
    let jitter = surface_jitter(f);
    // the normal's change across a pixel, for band borders blended over it (taken here, in
    // uniform control flow; per 2x2 quad of pixels, as `reference::quad_derivatives` does)
    var dn = array<vec3<f32>, 2>(dpdxFine(f.normal), dpdyFine(f.normal));
    if (frame.view.band_antialias == 0u) {
        dn = array<vec3<f32>, 2>(vec3<f32>(0.0), vec3<f32>(0.0));
    }
    var c: vec3<f32>;
    if (PER_VERTEX) {
        c = select(a.color_back, a.color_front, outer_side(front_facing));
    } else {
        c = shade(f.normal, i.view_pos, jitter, dn);
    }
    c = surface_finish(f, c);
    return vec4<f32>(clamp(c, vec3<f32>(0.0), vec3<f32>(1.0)), 1.0);
}

// What a material that needs no anchors sees of them (`fs_*` below; `fs_*_anchored` read them).
fn no_anchors() -> Anchors {
    let o = vec3<f32>(0.0);
    return Anchors(o, o, o, o);
}

@fragment
fn fs_color(i: Varyings, @builtin(front_facing) front_facing: bool) -> @location(0) vec4<f32> {
    return shaded_color(i, no_anchors(), front_facing);
}

@fragment
fn fs_color_anchored(v: VsOut, @builtin(front_facing) front_facing: bool) -> @location(0) vec4<f32> {
    return shaded_color(varyings(v), anchors(v), front_facing);
}

struct ColorNormalDepth {
    @location(0) color: vec4<f32>,
    @location(1) geometry: vec4<u32>,
};

@fragment
fn fs_color_normal_depth(i: Varyings, @builtin(front_facing) front_facing: bool) -> ColorNormalDepth {
    return ColorNormalDepth(shaded_color(i, no_anchors(), front_facing), normal_depth_bits(i, front_facing));
}

@fragment
fn fs_color_normal_depth_anchored(v: VsOut, @builtin(front_facing) front_facing: bool) -> ColorNormalDepth {
    let i = varyings(v);
    return ColorNormalDepth(shaded_color(i, anchors(v), front_facing), normal_depth_bits(i, front_facing));
}

struct ColorDepth {
    @location(0) color: vec4<f32>,
    @location(1) depth: u32,
};

@fragment
fn fs_color_depth(i: Varyings, @builtin(front_facing) front_facing: bool) -> ColorDepth {
    return ColorDepth(shaded_color(i, no_anchors(), front_facing), depth_bits(i));
}

@fragment
fn fs_color_depth_anchored(v: VsOut, @builtin(front_facing) front_facing: bool) -> ColorDepth {
    let i = varyings(v);
    return ColorDepth(shaded_color(i, anchors(v), front_facing), depth_bits(i));
}

// The entry points of materials that hatch along the field: the anchors and the stripe values.
fn field_varyings(v: VsFieldOut) -> Varyings {
    return Varyings(v.clip, v.view_pos, v.view_normal);
}

fn field_anchors(v: VsFieldOut) -> Anchors {
    return Anchors(v.color_front, v.color_back, v.object_pos, v.object_normal);
}

@fragment
fn fs_color_field(v: VsFieldOut, @builtin(front_facing) front_facing: bool) -> @location(0) vec4<f32> {
    return shaded_color_on(field_varyings(v), field_anchors(v), v.stripes, front_facing);
}

@fragment
fn fs_color_normal_depth_field(v: VsFieldOut, @builtin(front_facing) front_facing: bool) -> ColorNormalDepth {
    let i = field_varyings(v);
    let c = shaded_color_on(i, field_anchors(v), v.stripes, front_facing);
    return ColorNormalDepth(c, normal_depth_bits(i, front_facing));
}

@fragment
fn fs_color_depth_field(v: VsFieldOut, @builtin(front_facing) front_facing: bool) -> ColorDepth {
    let i = field_varyings(v);
    return ColorDepth(shaded_color_on(i, field_anchors(v), v.stripes, front_facing), depth_bits(i));
}

// The shading pass: toon-shaded colour, and (when asked for and not multisampled) the view-space
// normal and linear depth as f32 bit patterns. Locations without a target are dropped.

struct ShadeOut {
    @location(0) color: vec4<f32>,
    @location(1) normal: vec4<u32>,
    @location(2) depth: u32,
};

@fragment
fn fs_shade(i: VsOut, @builtin(front_facing) front_facing: bool) -> ShadeOut {
    let n = facing_normal(i.view_normal, front_facing);
    var c: vec3<f32>;
    if (PER_VERTEX) {
        c = select(i.color_back, i.color_front, outer_side(front_facing));
    } else {
        c = shade(n, i.view_pos);
    }
    var o: ShadeOut;
    o.color = vec4<f32>(clamp(c, vec3<f32>(0.0), vec3<f32>(1.0)), 1.0);
    o.normal = vec4<u32>(bitcast<vec3<u32>>(n), 0u);
    o.depth = bitcast<u32>(-i.view_pos.z);
    return o;
}

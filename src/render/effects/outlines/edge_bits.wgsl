// The discontinuity rule's edges between pixels (settings::ImageRule::Discontinuity), from the
// geometry target: bit 0 where the boundary with the right neighbour is an edge, bit 1 with the
// neighbour below. The boundary between two pixels is an edge where their normals turn by more
// than the normal angle, where their depths jump by more than `depth_jump` pixel footprints
// beyond what each side's slope predicts (1/z is linear across a plane on screen, z in
// orthographic views; the smaller of the two sides' errors), or where surface meets background.
// `edges_reference::Discontinuity::is_edge` is its CPU twin; edges.wgsl inks the result.

@group(1) @binding(0) var geometry: texture_2d<u32>;

fn finite_bits(b: u32) -> bool {
    return (b & 0x7f800000u) != 0x7f800000u;
}

fn inside(p: vec2<i32>) -> bool {
    let size = vec2<i32>(textureDimensions(geometry));
    return all(p >= vec2<i32>(0)) && all(p < size);
}

// 1/z in perspective, z in orthographic views: linear across a plane on screen.
fn depth_measure(z: f32) -> f32 {
    if (frame.view.orthographic != 0u) {
        return z;
    }
    return 1.0 / z;
}

// Whether the boundary between pixel a and pixel a + d is an edge.
fn discontinuity(a: vec2<i32>, d: vec2<i32>) -> bool {
    let b = a + d;
    if (!inside(a) || !inside(b)) {
        return false;
    }
    let ta = textureLoad(geometry, a, 0);
    let tb = textureLoad(geometry, b, 0);
    let fa = finite_bits(ta.w);
    let fb = finite_bits(tb.w);
    if (fa != fb) {
        return true;
    }
    if (!fa) {
        return false;
    }
    let na = bitcast<vec3<f32>>(ta.xyz);
    let nb = bitcast<vec3<f32>>(tb.xyz);
    if (dot(na, nb) < frame.outlines.normal_cos) {
        return true;
    }
    let za = bitcast<f32>(ta.w);
    let zb = bitcast<f32>(tb.w);
    let wa = depth_measure(za);
    let wb = depth_measure(zb);
    var err = 3.4e38;
    var seen = false;
    let a0 = a - d;
    if (inside(a0)) {
        let t = textureLoad(geometry, a0, 0).w;
        if (finite_bits(t)) {
            err = min(err, abs(wb - (2.0 * wa - depth_measure(bitcast<f32>(t)))));
            seen = true;
        }
    }
    let b1 = b + d;
    if (inside(b1)) {
        let t = textureLoad(geometry, b1, 0).w;
        if (finite_bits(t)) {
            err = min(err, abs(wa - (2.0 * wb - depth_measure(bitcast<f32>(t)))));
            seen = true;
        }
    }
    if (!seen) {
        err = abs(wb - wa);
    }
    var jump = err * za * zb;
    if (frame.view.orthographic != 0u) {
        jump = err;
    }
    let z = min(za, zb);
    return jump > frame.outlines.depth_jump * (z * frame.view.footprint.x + frame.view.footprint.y);
}


@fragment
fn fs_edge_bits(@builtin(position) pos: vec4<f32>) -> @location(0) u32 {
    let p = vec2<i32>(floor(pos.xy));
    var bits = 0u;
    if (discontinuity(p, vec2<i32>(1, 0))) {
        bits |= 1u;
    }
    if (discontinuity(p, vec2<i32>(0, 1))) {
        bits |= 2u;
    }
    return bits;
}

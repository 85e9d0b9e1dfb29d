// Image-space outlines (Borquez and Yepez), with the rule of src/edges/detect.rs: the
// unnormalised 3x3 Sobel of each buffer ('reflect' border, i.e. the nearest texel inside), an
// edge where max(|Gx|, |Gy|) exceeds that buffer's threshold. The normal gradient is the largest
// over x, y, z. A depth window that mixes background (infinite depth) and surface is always an
// edge; one all in the background never is. Edge pixels take the image ink at full coverage.

@group(1) @binding(0) var geometry: texture_2d<u32>;

fn finite_bits(b: u32) -> bool {
    return (b & 0x7f800000u) != 0x7f800000u;
}

// max(|Gx|, |Gy|) of one channel of a 3x3 window w[row][column], in the order the CPU sums it.
fn sobel(w: array<array<f32, 3>, 3>) -> f32 {
    let gx = (w[0][0] - w[0][2]) + 2.0 * (w[1][0] - w[1][2]) + (w[2][0] - w[2][2]);
    let gy = (w[0][0] - w[2][0]) + 2.0 * (w[0][1] - w[2][1]) + (w[0][2] - w[2][2]);
    return max(abs(gx), abs(gy));
}

fn is_edge(pos: vec4<f32>) -> bool {
    let size = vec2<i32>(textureDimensions(geometry));
    let c = vec2<i32>(floor(pos.xy));
    var texels: array<array<vec4<u32>, 3>, 3>;
    var background = 0u;
    for (var r = 0; r < 3; r++) {
        for (var k = 0; k < 3; k++) {
            let p = clamp(c + vec2<i32>(k - 1, r - 1), vec2<i32>(0), size - 1);
            let t = textureLoad(geometry, p, 0);
            texels[r][k] = t;
            background += select(1u, 0u, finite_bits(t.w));
        }
    }
    var gn = 0.0;
    for (var ch = 0; ch < 3; ch++) {
        var w: array<array<f32, 3>, 3>;
        for (var r = 0; r < 3; r++) {
            for (var k = 0; k < 3; k++) {
                w[r][k] = bitcast<f32>(texels[r][k][ch]);
            }
        }
        gn = max(gn, sobel(w));
    }
    if (gn > frame.outlines.normal_threshold) {
        return true;
    }
    if (background == 9u) {
        return false;
    }
    if (background > 0u) {
        return true;
    }
    var d: array<array<f32, 3>, 3>;
    for (var r = 0; r < 3; r++) {
        for (var k = 0; k < 3; k++) {
            d[r][k] = bitcast<f32>(texels[r][k].w);
        }
    }
    return sobel(d) > frame.outlines.depth_threshold;
}

fn ink() -> vec4<f32> {
    return vec4<f32>(frame.outlines.ink[IMAGE_KIND].rgb, 1.0);
}

@fragment
fn fs_color(@builtin(position) pos: vec4<f32>) -> @location(0) vec4<f32> {
    if (!is_edge(pos)) {
        discard;
    }
    return ink();
}

@fragment
fn fs_outline(@builtin(position) pos: vec4<f32>) -> @location(0) vec4<f32> {
    if (!is_edge(pos)) {
        discard;
    }
    return vec4<f32>(1.0);
}

struct Both {
    @location(0) color: vec4<f32>,
    @location(1) outline: vec4<f32>,
};

@fragment
fn fs_both(@builtin(position) pos: vec4<f32>) -> Both {
    if (!is_edge(pos)) {
        discard;
    }
    return Both(ink(), vec4<f32>(1.0));
}

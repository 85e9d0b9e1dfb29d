// Image-space outlines, by one of two rules (settings::ImageRule):
//
// - discontinuity (the default): the boundary between two neighbouring pixels is an edge where
//   their normals turn by more than the normal angle, where their depths jump by more than
//   `depth_jump` pixel footprints beyond what each side's slope predicts (1/z is linear across a
//   plane on screen, z in orthographic views), or where surface meets background. Each pixel is
//   inked by its distance to the nearest edge boundary: lines `width` pixels wide, centred on
//   the boundaries, antialiased (`edges_reference::Discontinuity` is its CPU twin).
// - paper (Borquez and Yepez), with the rule of src/edges/detect.rs: the unnormalised 3x3 Sobel
//   of each buffer ('reflect' border, i.e. the nearest texel inside), an edge where
//   max(|Gx|, |Gy|) exceeds that buffer's threshold. The normal gradient is the largest over x,
//   y, z. A depth window that mixes background (infinite depth) and surface is always an edge;
//   one all in the background never is. Edge pixels take the image ink at full coverage.

// The geometry target under the paper rule, the edge bits under the discontinuity rule.
@group(1) @binding(0) var geometry: texture_2d<u32>;

fn finite_bits(b: u32) -> bool {
    return (b & 0x7f800000u) != 0x7f800000u;
}

// max(|Gx|, |Gy|) of one channel of a 3x3 window, w[3 * row + column], in the order the CPU
// sums it (flat: GLSL ES 3.00, which the browser's drafts use, has no arrays of arrays).
fn sobel(w: array<f32, 9>) -> f32 {
    let gx = (w[0] - w[2]) + 2.0 * (w[3] - w[5]) + (w[6] - w[8]);
    let gy = (w[0] - w[6]) + 2.0 * (w[1] - w[7]) + (w[2] - w[8]);
    return max(abs(gx), abs(gy));
}

fn is_edge(pos: vec4<f32>) -> bool {
    let size = vec2<i32>(textureDimensions(geometry));
    let c = vec2<i32>(floor(pos.xy));
    var texels: array<vec4<u32>, 9>;
    var background = 0u;
    for (var r = 0; r < 3; r++) {
        for (var k = 0; k < 3; k++) {
            let p = clamp(c + vec2<i32>(k - 1, r - 1), vec2<i32>(0), size - 1);
            let t = textureLoad(geometry, p, 0);
            texels[3 * r + k] = t;
            background += select(1u, 0u, finite_bits(t.w));
        }
    }
    var gn = 0.0;
    for (var ch = 0; ch < 3; ch++) {
        var w: array<f32, 9>;
        for (var i = 0; i < 9; i++) {
            w[i] = bitcast<f32>(texels[i][ch]);
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
    var d: array<f32, 9>;
    for (var i = 0; i < 9; i++) {
        d[i] = bitcast<f32>(texels[i].w);
    }
    return sobel(d) > frame.outlines.depth_threshold;
}

// The edge bits of pixel q (edge_bits.wgsl; the bound texture holds them under the
// discontinuity rule); none outside the image.
fn edge_bits(q: vec2<i32>) -> u32 {
    let size = vec2<i32>(textureDimensions(geometry));
    if (any(q < vec2<i32>(0)) || any(q >= size)) {
        return 0u;
    }
    return textureLoad(geometry, q, 0).x;
}

// Ink coverage at a pixel: 1 within width/2 of the nearest edge boundary, falling to 0 over
// the next pixel.
fn discontinuity_coverage(pos: vec4<f32>) -> f32 {
    let reach = frame.outlines.ink[IMAGE_KIND].w * 0.5 + 0.5;
    let r = i32(ceil(reach));
    let p = vec2<i32>(floor(pos.xy));
    let c = vec2<f32>(p) + 0.5;
    var best = reach;
    for (var dy = -r; dy <= r; dy++) {
        for (var dx = -r; dx <= r; dx++) {
            let q = p + vec2<i32>(dx, dy);
            let qf = vec2<f32>(q);
            // the boundary with the right neighbour (x = q.x + 1, y in [q.y, q.y + 1]) and the
            // one with the neighbour below (y = q.y + 1, x in [q.x, q.x + 1])
            let right = length(vec2<f32>(abs(c.x - (qf.x + 1.0)), max(abs(c.y - (qf.y + 0.5)) - 0.5, 0.0)));
            let below = length(vec2<f32>(max(abs(c.x - (qf.x + 0.5)) - 0.5, 0.0), abs(c.y - (qf.y + 1.0))));
            if (min(right, below) < best) {
                let bits = edge_bits(q);
                if (right < best && (bits & 1u) != 0u) {
                    best = right;
                }
                if (below < best && (bits & 2u) != 0u) {
                    best = below;
                }
            }
        }
    }
    return clamp(reach - best, 0.0, 1.0);
}

// The ink coverage of the pixel under the frame's rule.
fn coverage(pos: vec4<f32>) -> f32 {
    if (frame.outlines.image_rule == IMAGE_RULE_PAPER) {
        return select(0.0, 1.0, is_edge(pos));
    }
    return discontinuity_coverage(pos);
}

@fragment
fn fs_color(@builtin(position) pos: vec4<f32>) -> @location(0) vec4<f32> {
    return inked(IMAGE_KIND, coverage(pos)).color;
}

@fragment
fn fs_outline(@builtin(position) pos: vec4<f32>) -> @location(0) vec4<f32> {
    return inked(IMAGE_KIND, coverage(pos)).outline;
}

@fragment
fn fs_both(@builtin(position) pos: vec4<f32>) -> Both {
    return inked(IMAGE_KIND, coverage(pos));
}

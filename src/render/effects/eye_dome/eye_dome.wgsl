// Eye-dome lighting over the shaded surfaces (src/render/effects/eye_dome/mod.rs, whose
// `shade_at` is its CPU twin): the blending multiplies the colour by the shade given here.

@group(1) @binding(0) var eye_dome_geometry: texture_2d<u32>;

// Whether the geometry target holds normals too (depth in w), else depth only (in x).
override NORMAL_DEPTH: bool = false;

const INFINITE_BITS: u32 = 0x7f800000u;

// The bits of the linear depth at pixel p (the geometry target's layout decides its channel):
// infinite on the background and outside the image.
fn eye_dome_bits(p: vec2<i32>) -> u32 {
    let size = vec2<i32>(textureDimensions(eye_dome_geometry));
    if (any(p < vec2<i32>(0)) || any(p >= size)) {
        return INFINITE_BITS;
    }
    let texel = textureLoad(eye_dome_geometry, p, 0);
    return select(texel.x, texel.w, NORMAL_DEPTH);
}

fn drawn(bits: u32) -> bool {
    return (bits & INFINITE_BITS) != INFINITE_BITS;
}

fn eye_dome_neighbour(k: u32) -> vec2<i32> {
    let row = frame.eye_dome.offsets[k / 2u];
    return select(row.zw, row.xy, k % 2u == 0u);
}

@fragment
fn fs_eye_dome(@builtin(position) pos: vec4<f32>) -> @location(0) vec4<f32> {
    let p = vec2<i32>(pos.xy);
    let bits = eye_dome_bits(p);
    if (!drawn(bits)) {
        return vec4<f32>(1.0);
    }
    let d = log2(bitcast<f32>(bits));
    var sum = 0.0;
    for (var k = 0u; k < EYE_DOME_NEIGHBOURS; k = k + 1u) {
        let n = eye_dome_bits(p + eye_dome_neighbour(k));
        if (drawn(n)) {
            sum = sum + max(0.0, d - log2(bitcast<f32>(n)));
        }
    }
    let shade = exp(-frame.eye_dome.response * sum / f32(EYE_DOME_NEIGHBOURS));
    return vec4<f32>(vec3<f32>(shade), 1.0);
}

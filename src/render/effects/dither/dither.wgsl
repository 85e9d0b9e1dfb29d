// Dithering between neighbouring bands (src/render/effects/dither/mod.rs): L.n moves by
// (t - 1/2) amount before banding, t the pattern's threshold at this pixel's cell.

struct DitherBlock {
    amount: f32,      // in L.n; 0 where the material does not dither
    cell: f32,        // pixels a pattern cell covers
    cos_angle: f32,   // the pattern's turn
    sin_angle: f32,
};

// The pattern (0 none, else `DitherPattern`'s id) and whether it is anchored to the surface.
override DITHER: u32 = 0u;
override DITHER_OBJECT: bool = false;

// The threshold in (0, 1) of dither cell c (`DitherPattern::threshold` on the CPU).
fn dither_threshold(c: vec2<u32>) -> f32 {
    if (DITHER == DITHER_BLUE) {
        return fract(R2_STEP_X * f32(c.x) + R2_STEP_Y * f32(c.y));
    }
    let bits = DITHER;  // Bayer 2, 4, 8: 1, 2, 3 bits a coordinate
    var v = 0u;
    for (var i = 0u; i < bits; i++) {
        let bx = (c.x >> i) & 1u;
        let by = (c.y >> i) & 1u;
        v |= (((bx ^ by) << 1u) | by) << (2u * (bits - 1u - i));
    }
    return (f32(v) + 0.5) / f32(1u << (2u * bits));
}

// Coordinates on the surface along the axis the normal is closest to.
fn planar(p: vec3<f32>, n: vec3<f32>) -> vec2<f32> {
    let a = abs(n);
    return select(select(p.xy, p.zx, a.y >= a.z), p.yz, a.x >= a.y && a.x >= a.z);
}

// `p` turned by the pattern's angle: counter-clockwise as seen, the pixels' y pointing down (at
// angle 0, `p` itself: cos 1 and sin 0 are exact).
fn turned(p: vec2<f32>) -> vec2<f32> {
    let c = draw.dither.cos_angle;
    let s = draw.dither.sin_angle;
    return vec2<f32>(c * p.x - s * p.y, s * p.x + c * p.y);
}

// The `jitter` hook: how far this pixel moves L.n before banding.
fn dither_jitter(f: Fragment) -> f32 {
    if (DITHER == 0u) {
        return 0.0;
    }
    let scale = draw.dither.cell;
    var cell: vec2<f32>;
    if (DITHER_OBJECT) {
        // the octave of the surface pattern whose cells are about `scale` pixels
        let q = planar(f.object_pos, f.object_normal);
        let w = max(fwidth(q.x), fwidth(q.y));
        let k = exp2(floor(log2(1.0 / max(scale * w, 1e-30))));
        cell = floor(turned(q) * k);
    } else {
        cell = floor(turned(f.clip.xy) / scale);
    }
    return (dither_threshold(bitcast<vec2<u32>>(vec2<i32>(cell))) - 0.5) * draw.dither.amount;
}

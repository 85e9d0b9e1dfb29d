// The shading pass: toon-shaded colour and, when this pass writes the geometry target (one
// sample per pixel at the output size), the view-space normal and linear depth as f32 bit
// patterns. One entry point per set of targets, so that the targets are always contiguous
// (the GL backend mishandles gaps between colour attachments).

// Shading variants (pipeline constants, so a material pays only for what it uses):
// cross-hatching, and the dither pattern (0 none, else `DitherPattern`'s id) and its space.
override HATCHING: bool = false;
override DITHER: u32 = 0u;
override DITHER_OBJECT: bool = false;

// The threshold in (0, 1) of dither cell c (`DitherPattern::threshold` on the CPU).
fn dither_threshold(c: vec2<u32>) -> f32 {
    if (DITHER == DITHER_BLUE) {
        return fract(0.7548776662466927 * f32(c.x) + 0.5698402909980532 * f32(c.y));
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

// How far this pixel moves L.n before banding: (t - 1/2) amount.
fn dither_jitter(i: Varyings, a: Anchors) -> f32 {
    if (DITHER == 0u) {
        return 0.0;
    }
    let scale = draw.style.y;
    var cell: vec2<f32>;
    if (DITHER_OBJECT) {
        // the octave of the surface pattern whose cells are about `scale` pixels
        let q = planar(a.object_pos, a.object_normal);
        let w = max(fwidth(q.x), fwidth(q.y));
        let f = exp2(floor(log2(1.0 / max(scale * w, 1e-30))));
        cell = floor(q * f);
    } else {
        cell = floor(i.clip.xy / scale);
    }
    return (dither_threshold(bitcast<vec2<u32>>(vec2<i32>(cell))) - 0.5) * draw.style.x;
}

// Coverage of one family of strokes along coordinate u: `spacing` pixels apart and `width`
// pixels wide on screen at any distance, from the two octaves of an object-space pattern that
// bracket that spacing, the finer one fading in as the surface comes nearer (a tonal art map's
// mip levels, made in code).
fn strokes(u: f32) -> f32 {
    let per_pixel = max(fwidth(u), 1e-30);
    let level = log2(1.0 / (draw.style.z * per_pixel));
    let base = floor(level);
    let f = exp2(base);
    let coarse = stroke(u * f, f * per_pixel);
    let fine = stroke(u * 2.0 * f, 2.0 * f * per_pixel);
    return max(coarse, fine * (level - base));
}

// Coverage of the stroke nearest x (strokes at the integers), `px` units of x a pixel.
fn stroke(x: f32, px: f32) -> f32 {
    let pixels = abs(fract(x + 0.5) - 0.5) / px;
    return clamp(draw.style.w * 0.5 + 0.5 - pixels, 0.0, 1.0);
}

// Each stroke layer's coverage (45, -45, 0, 90 degrees), blended over the three axis planes
// by the object normal (a triplanar mapping: no UVs needed).
fn hatch_layers(a: Anchors) -> vec4<f32> {
    let p = a.object_pos;
    let w4 = pow(abs(unit_or_zero(a.object_normal)), vec3<f32>(4.0));
    let w = w4 / max(w4.x + w4.y + w4.z, 1e-12);
    let planes = array<vec2<f32>, 3>(p.yz, p.zx, p.xy);
    let s = 0.70710678;
    var cov = vec4<f32>(0.0);
    for (var k = 0; k < 3; k++) {
        let q = planes[k];
        let layers = vec4<f32>(strokes(s * (q.x + q.y)), strokes(s * (q.x - q.y)), strokes(q.y), strokes(q.x));
        cov += w[k] * layers;
    }
    return cov;
}

// Ink over the paper colour: layer k shows where the tone is below 1 - k / (HATCH_LAYERS + 1).
fn hatched(c: vec3<f32>, layers: vec4<f32>) -> vec3<f32> {
    let paper = draw.diffuse.rgb;
    let luma = vec3<f32>(0.2126, 0.7152, 0.0722);
    let tone = dot(c, luma) / max(dot(paper, luma), 1e-6);
    var ink = 0.0;
    for (var k = 0u; k < HATCH_LAYERS; k++) {
        let shows = tone < 1.0 - f32(k + 1u) / f32(HATCH_LAYERS + 1u);
        ink = max(ink, select(0.0, layers[k], shows));
    }
    return mix(paper, draw.ink.rgb, ink);
}

fn shaded_color(i: Varyings, a: Anchors, front_facing: bool) -> vec4<f32> {
    // derivatives first, while every pixel of the quad still runs the same code
    let jitter = dither_jitter(i, a);
    var layers = vec4<f32>(0.0);
    if (HATCHING) {
        layers = hatch_layers(a);
    }
    var c: vec3<f32>;
    if (PER_VERTEX) {
        c = select(a.color_back, a.color_front, outer_side(front_facing));
    } else {
        c = shade(facing_normal(i.view_normal, front_facing), i.view_pos, jitter);
    }
    if (HATCHING) {
        c = hatched(c, layers);
    }
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
fn fs_color_anchored(i: Varyings, a: Anchors, @builtin(front_facing) front_facing: bool) -> @location(0) vec4<f32> {
    return shaded_color(i, a, front_facing);
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
fn fs_color_normal_depth_anchored(i: Varyings, a: Anchors, @builtin(front_facing) front_facing: bool) -> ColorNormalDepth {
    return ColorNormalDepth(shaded_color(i, a, front_facing), normal_depth_bits(i, front_facing));
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
fn fs_color_depth_anchored(i: Varyings, a: Anchors, @builtin(front_facing) front_facing: bool) -> ColorDepth {
    return ColorDepth(shaded_color(i, a, front_facing), depth_bits(i));
}

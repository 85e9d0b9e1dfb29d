// Cross-hatching (src/render/effects/hatching/mod.rs): layers of ink strokes over the paper
// colour, more of them where the band's tone is darker.

struct HatchingBlock {
    ink: vec4<f32>,   // linear rgb
    spacing: f32,     // pixels between the strokes of one layer
    width: f32,       // stroke width in pixels
    _pad0: f32,
    _pad1: f32,
};

override HATCHING: bool = false;

// Coverage of one family of strokes along coordinate u: `spacing` pixels apart and `width`
// pixels wide on screen at any distance, from the two octaves of an object-space pattern that
// bracket that spacing, the finer one fading in as the surface comes nearer (a tonal art map's
// mip levels, made in code).
fn strokes(u: f32) -> f32 {
    let per_pixel = max(fwidth(u), 1e-30);
    let level = log2(1.0 / (draw.hatching.spacing * per_pixel));
    let base = floor(level);
    let f = exp2(base);
    let coarse = stroke(u * f, f * per_pixel);
    let fine = stroke(u * 2.0 * f, 2.0 * f * per_pixel);
    return max(coarse, fine * (level - base));
}

// Coverage of the stroke nearest x (strokes at the integers), `px` units of x a pixel.
fn stroke(x: f32, px: f32) -> f32 {
    let pixels = abs(fract(x + 0.5) - 0.5) / px;
    return clamp(draw.hatching.width * 0.5 + 0.5 - pixels, 0.0, 1.0);
}

// Each stroke layer's coverage (45, -45, 0, 90 degrees), blended over the three axis planes
// by the object normal (a triplanar mapping: no UVs needed).
fn hatch_layers(f: Fragment) -> vec4<f32> {
    let p = f.object_pos;
    let w4 = pow(abs(unit_or_zero(f.object_normal)), vec3<f32>(4.0));
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

// The `finish` hook: ink over the paper colour, layer k where the tone is below
// 1 - k / (HATCH_LAYERS + 1) (`hatch_layers` on the CPU).
fn hatching_finish(f: Fragment, c: vec3<f32>) -> vec3<f32> {
    if (!HATCHING) {
        return c;
    }
    let layers = hatch_layers(f);
    let paper = draw.material.diffuse.rgb * albedo;
    let tone = dot(c, LUMA) / max(dot(paper, LUMA), 1e-6);
    var ink = 0.0;
    for (var k = 0u; k < HATCH_LAYERS; k++) {
        let shows = tone < 1.0 - f32(k + 1u) / f32(HATCH_LAYERS + 1u);
        ink = max(ink, select(0.0, layers[k], shows));
    }
    return mix(paper, draw.hatching.ink.rgb, ink);
}

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
// Strokes along the hatching field (`HatchMode::Field`) rather than triplanar.
override HATCH_FIELD: bool = false;

// Coverage of one family of strokes along coordinate u: `spacing` pixels apart and `width`
// pixels wide on screen at any distance, from the two octaves of an object-space pattern that
// bracket that spacing, the finer one fading in as the surface comes nearer (a tonal art map's
// mip levels, made in code).
fn strokes(u: f32) -> f32 {
    return stroke_octaves(u, fwidth(u), 0.0, -1e30);
}

// `strokes` with u's change across a pixel given, the strokes shifted by `offset` (of a
// stroke's spacing), and no octave coarser than 2^lowest (`stroke_octaves` on the CPU, which
// has lowest = 0: a phase repeats at u's integers, so coarser octaves would not line up).
fn stroke_octaves(u: f32, per_pixel: f32, offset: f32, lowest: f32) -> f32 {
    let px = max(per_pixel, 1e-30);
    let level = max(log2(1.0 / (draw.hatching.spacing * px)), lowest);
    let base = floor(level);
    let f = exp2(base);
    let coarse = stroke(u * f + offset, f * px);
    let fine = stroke(u * 2.0 * f + offset, 2.0 * f * px);
    return max(coarse, fine * (level - base));
}

// A stripe value psi's phase in turns, its change across a pixel (from psi's derivatives: no
// jump where the argument wraps) and the fade near the pattern's singular points
// (`stripe_phase` on the CPU).
fn stripe_phase(psi: vec2<f32>) -> vec3<f32> {
    let dx = dpdxFine(psi);
    let dy = dpdyFine(psi);
    let r2 = max(dot(psi, psi), 1e-12);
    let turn = 6.283185307179586;
    let ux = (psi.x * dx.y - psi.y * dx.x) / r2;
    let uy = (psi.x * dy.y - psi.y * dy.x) / r2;
    let fade = clamp((sqrt(r2) - 0.5 * FIELD_FADE) / (0.5 * FIELD_FADE), 0.0, 1.0);
    return vec3<f32>(atan2(psi.y, psi.x) / turn, (abs(ux) + abs(uy)) / turn, fade);
}

// Each layer's coverage along the field: the strokes along the first principal direction, along
// the second, then each again between its strokes (`field_coverage` on the CPU).
fn field_layers(f: Fragment) -> vec4<f32> {
    let a = stripe_phase(f.stripes.xy);
    let b = stripe_phase(f.stripes.zw);
    return vec4<f32>(
        stroke_octaves(a.x, a.y, 0.0, 0.0) * a.z,
        stroke_octaves(b.x, b.y, 0.0, 0.0) * b.z,
        stroke_octaves(a.x, a.y, 0.5, 0.0) * a.z,
        stroke_octaves(b.x, b.y, 0.5, 0.0) * b.z,
    );
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
    var layers: vec4<f32>;
    if (HATCH_FIELD) {
        layers = field_layers(f);
    } else {
        layers = hatch_layers(f);
    }
    let paper = draw.material.diffuse.rgb * albedo;
    let tone = dot(c, LUMA) / max(dot(paper, LUMA), 1e-6);
    var ink = 0.0;
    for (var k = 0u; k < HATCH_LAYERS; k++) {
        let shows = tone < 1.0 - f32(k + 1u) / f32(HATCH_LAYERS + 1u);
        ink = max(ink, select(0.0, layers[k], shows));
    }
    return mix(paper, draw.hatching.ink.rgb, ink);
}

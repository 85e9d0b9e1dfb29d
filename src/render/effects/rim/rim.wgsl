// Rim light (src/render/effects/rim/mod.rs): the rim's colour where n.v < width, added as light
// or painted over, on both sides or only where the lights reach (or do not).

struct RimBlock {
    color: vec3<f32>,   // linear rgb
    strength: f32,      // 0 where the material has no rim
    width: f32,         // in n.v
    softness: f32,      // in n.v
    side: u32,          // RimSide: 0 both, 1 lit, 2 shadowed
    blend: u32,         // RimBlend: 0 add, 1 mix
};

override RIM: bool = false;

// The largest n.l over the lights at the pixel.
fn rim_lit(f: Fragment) -> f32 {
    var lit = -1.0;
    for (var k = 0u; k < LIGHTS; k++) {
        lit = max(lit, dot(f.normal, light_toward(k, f.view_pos)));
    }
    return lit;
}

// How much of the rim the pixel takes (`rim_amount` on the CPU); aa_*: the change of n.v and of
// the lit term across the pixel, zero for hard borders.
fn rim_amount(nv: f32, lit: f32, aa_nv: f32, aa_lit: f32) -> f32 {
    let t = step_aa(draw.rim.width - nv, 0.0, max(aa_nv, draw.rim.softness));
    let on_lit = step_aa(lit, 0.0, aa_lit);
    if (draw.rim.side == 1u) {
        return t * on_lit;
    }
    if (draw.rim.side == 2u) {
        return t * (1.0 - on_lit);
    }
    return t;
}

// The `finish` hook.
fn rim_finish(f: Fragment, c: vec3<f32>) -> vec3<f32> {
    if (!RIM) {
        return c;
    }
    let nv = dot(f.normal, view_dir(f.view_pos));
    let lit = rim_lit(f);
    // taken in uniform control flow, per 2x2 quad as the bands' borders are
    var aa_nv = length(vec2<f32>(dpdxFine(nv), dpdyFine(nv)));
    var aa_lit = length(vec2<f32>(dpdxFine(lit), dpdyFine(lit)));
    if (frame.view.band_antialias == 0u) {
        aa_nv = 0.0;
        aa_lit = 0.0;
    }
    let k = rim_amount(nv, lit, aa_nv, aa_lit) * draw.rim.strength;
    if (draw.rim.blend == 1u) {
        return mix(c, draw.rim.color, k);
    }
    return c + draw.rim.color * k;
}

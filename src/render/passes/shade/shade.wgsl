// The shading pass: toon-shaded colour and, when this pass writes the geometry target (one
// sample per pixel at the output size), the view-space normal and linear depth as f32 bit
// patterns. Its stages are written for each draw (src/render/graph/mesh_stages.rs) around
// `shaded_color`. Per-pixel effects join through their hooks (`surface_jitter`,
// `surface_finish`: src/render/effects/surface.rs).

// The shaded colour of pixel `f`; `lit`: its Gouraud colours (zero unless the material shades
// per vertex).
fn shaded_color(f: Fragment, lit: Gouraud, front_facing: bool) -> vec4<f32> {
    let jitter = surface_jitter(f);
    // the normal's change across a pixel, for band borders blended over it (taken here, in
    // uniform control flow; per 2x2 quad of pixels, as `reference::quad_derivatives` does)
    var dn = array<vec3<f32>, 2>(dpdxFine(f.normal), dpdyFine(f.normal));
    if (frame.view.band_antialias == 0u) {
        dn = array<vec3<f32>, 2>(vec3<f32>(0.0), vec3<f32>(0.0));
    }
    var c: vec3<f32>;
    if (PER_VERTEX) {
        c = select(lit.back, lit.front, outer_side(front_facing));
    } else {
        c = shade(f.normal, f.view_pos, jitter, dn);
    }
    c = surface_finish(f, c);
    return vec4<f32>(clamp(c, vec3<f32>(0.0), vec3<f32>(1.0)), 1.0);
}

// What the ink passes (edges.wgsl, lines.wgsl) write at a pixel, for their fragment entry points
// (`ink::Ink::entry`: fs_color, fs_outline, fs_both): the premultiplied ink colour, the outline
// coverage, or both.

struct Both {
    @location(0) color: vec4<f32>,
    @location(1) outline: vec4<f32>,
};

// Ink of kind `kind` at coverage `a`; no fragment where the pixel is not inked.
fn inked(kind: u32, a: f32) -> Both {
    return inked_rgb(frame.outlines.ink[kind].rgb, a);
}

// Ink of linear colour `rgb` at coverage `a`; no fragment where the pixel is not inked.
fn inked_rgb(rgb: vec3<f32>, a: f32) -> Both {
    if (a <= 0.0) {
        discard;
    }
    return Both(vec4<f32>(rgb * a, a), vec4<f32>(a));
}

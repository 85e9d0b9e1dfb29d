// `frame.paper`: the paper of the frame (src/render/effects/paper/mod.rs).
struct PaperBlock {
    to_grain: mat4x4<f32>,   // normalised view space -> grain texels on the surface
    inv_proj: mat4x4<f32>,   // clip space -> normalised view space
    size: vec2<f32>,         // the output's size in pixels
    scale: f32,              // output pixels a grain texel covers
    strength: f32,           // how much pigment the grain's valleys refuse
    tone: f32,               // how much the blank paper's valleys darken it
    _pad0: u32,
    _pad1: u32,
    _pad2: u32,
};

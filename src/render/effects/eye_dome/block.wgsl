// `frame.eye_dome`: eye-dome lighting (src/render/effects/eye_dome/mod.rs).
struct EyeDomeBlock {
    offsets: array<vec4<i32>, 4>,  // the eight neighbours' offsets in pixels, two to a row
    response: f32,                 // the darkening per unit of mean log2-depth step
    _pad0: u32,
    _pad1: u32,
    _pad2: u32,
};

// `frame.outlines` (src/render/effects/outlines/mod.rs): how each kind of ink is drawn.
struct OutlinesBlock {
    ink: array<vec4<f32>, INK_KINDS>,  // per ink kind: linear rgb, width in pixels (0: not drawn)
    depth_offset: f32,                 // hidden-line tolerance in pixel footprints
    normal_threshold: f32,             // the paper's image-space rule (edges::detect)
    depth_threshold: f32,              // the same, in normalised view units
    image_rule: u32,                   // settings::ImageRule
    normal_cos: f32,                   // the discontinuity rule: cos of the normal angle,
    depth_jump: f32,                   // the depth jump in pixel footprints
    _pad0: f32,
    _pad1: f32,
    dashes: array<vec4<f32>, DASH_ROWS>, // per ink kind, four to a row: dash length in pixels (0: solid)
};

// `frame.shadows` (src/render/effects/shadows/mod.rs): the shadow-casting light's view.
struct ShadowsBlock {
    to_light: mat4x4<f32>,   // normalised view space -> the light's clip space
    tolerance: f32,          // depth tolerance per unit of receiver slope
    max_slope: f32,          // the largest receiver slope biased
    normal_offset: f32,      // how far a receiver moves along its normal before the test
    strength: f32,           // the share of the light a shadow takes away
};

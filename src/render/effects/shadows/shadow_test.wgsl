// The shadow test (Kang, Kim and Yoon's shadow z-buffer): a point is lit by the shadow-casting
// light (always light 0, see `CheckedScene::shader_lights`) when its depth from the light is at most the
// shadow map's, less a tolerance that grows with the receiver's slope to the light, the point
// first moved off the surface along its normal (so that a lit surface does not shadow itself,
// even where the light grazes it). A surface facing away from the light is in its own
// shadow. `raycast.rs` holds the truth this is measured against.

// Percentage-closer filtering: a tent over 3x3 texels (four bilinear comparisons); otherwise
// one nearest test.
override PCF: bool = true;

@group(2) @binding(0) var shadow_map: texture_depth_2d;
@group(2) @binding(1) var shadow_sampler: sampler_comparison;

// Visibility in [0, 1] of light k at view-space point p with unit normal n, where d = N . L: a
// shadow in the map takes `strength` of the light away, a surface facing away all of it.
fn light_visibility(k: u32, n: vec3<f32>, p: vec3<f32>, d: f32) -> f32 {
    if (k != 0u) {
        return 1.0;
    }
    if (d <= 0.0) {
        return 0.0;
    }
    return mix(1.0, map_visibility(n, p, d), frame.shadows.strength);
}

// The share of the map's tests at p that see the light.
fn map_visibility(n: vec3<f32>, p: vec3<f32>, d: f32) -> f32 {
    let q = frame.shadows.to_light * vec4<f32>(p + n * frame.shadows.normal_offset, 1.0);
    let uv = vec2<f32>(q.x * 0.5 + 0.5, 0.5 - q.y * 0.5);
    let slope = min(sqrt(max(1.0 - d * d, 0.0)) / d, frame.shadows.max_slope);
    let z = q.z - frame.shadows.tolerance * (1.0 + slope);
    if (!PCF) {
        return textureSampleCompareLevel(shadow_map, shadow_sampler, uv, z);
    }
    // four bilinear comparisons half a texel off centre: a tent filter over 3x3 texels
    let half = 0.5 / vec2<f32>(textureDimensions(shadow_map));
    var sum = 0.0;
    for (var j = -1; j <= 1; j += 2) {
        for (var i = -1; i <= 1; i += 2) {
            sum += textureSampleCompareLevel(shadow_map, shadow_sampler, uv + vec2<f32>(f32(i), f32(j)) * half, z);
        }
    }
    return sum / 4.0;
}

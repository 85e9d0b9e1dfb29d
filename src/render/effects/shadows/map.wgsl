// The shadow map: depth of every mesh seen from the shadow-casting light, an orthographic view
// fitted to the scene's bounding sphere (`frame.shadows.to_light`).

@vertex
fn vs_shadow(v: VsIn) -> @builtin(position) vec4<f32> {
    return frame.shadows.to_light * (draw.mesh.model_view * vec4<f32>(v.position, 1.0));
}

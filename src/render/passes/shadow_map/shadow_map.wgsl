// The shadow map: depth of every mesh seen from the shadow-casting light, an orthographic view
// fitted to the scene's bounding sphere (`frame.shadow`).

@vertex
fn vs_shadow(v: VsIn) -> @builtin(position) vec4<f32> {
    return frame.shadow * (draw.model_view * vec4<f32>(v.position, 1.0));
}

// Paper grain over the finished image (src/render/effects/paper/mod.rs): with grain height g,
// the paper takes m = 1 - strength (1 - g) of the pigment and shows its own tone
// 1 - tone (1 - g) in the rest; the blending writes paper (1 - m) + colour m.

@group(1) @binding(0) var grain_tile: texture_2d<f32>;
@group(2) @binding(0) var paper_geometry: texture_2d<u32>;

// The texel at (x, y), each at most one tile outside it (no `%` of a negative number: GLSL
// leaves it undefined).
fn grain_texel(x: i32, y: i32) -> f32 {
    let size = vec2<i32>(textureDimensions(grain_tile));
    let i = vec2<i32>(x, y);
    let wrapped = select(select(i, i - size, i >= size), i + size, i < vec2<i32>(0));
    return textureLoad(grain_tile, wrapped, 0).r;
}

// The grain at uv in texels, blended between the four nearest and wrapped around the tile
// (`grain::grain_at` on the CPU, in the same steps).
fn grain_at(uv: vec2<f32>) -> f32 {
    let size = vec2<f32>(textureDimensions(grain_tile));
    let s = uv - size * floor(uv / size) - 0.5;
    let i = floor(s);
    let f = s - i;
    let x = i32(i.x);
    let y = i32(i.y);
    let a = grain_texel(x, y) + (grain_texel(x + 1, y) - grain_texel(x, y)) * f.x;
    let b = grain_texel(x, y + 1) + (grain_texel(x + 1, y + 1) - grain_texel(x, y + 1)) * f.x;
    return a + (b - a) * f.y;
}

// The grain on the axis planes at q (texels), weighted by the unit normal's squared components.
fn surface_grain(q: vec3<f32>, n: vec3<f32>) -> f32 {
    let w = n * n;
    return w.x * grain_at(q.yz) + w.y * grain_at(q.zx) + w.z * grain_at(q.xy);
}

// What the blending takes: the paper's share (premultiplied) and the pigment's share m.
fn paper_blend(g: f32) -> vec4<f32> {
    let m = 1.0 - frame.paper.strength * (1.0 - g);
    let paper = 1.0 - frame.paper.tone * (1.0 - g);
    return vec4<f32>(vec3<f32>(paper * (1.0 - m)), m);
}

fn screen_grain(pixel: vec2<f32>) -> f32 {
    return grain_at(pixel / frame.paper.scale);
}

@fragment
fn fs_screen(@builtin(position) pos: vec4<f32>) -> @location(0) vec4<f32> {
    return paper_blend(screen_grain(pos.xy));
}

@fragment
fn fs_surface(@builtin(position) pos: vec4<f32>) -> @location(0) vec4<f32> {
    let bits = textureLoad(paper_geometry, vec2<i32>(pos.xy), 0);
    let depth = bitcast<f32>(bits.w);
    if (!(depth < 3.0e38)) {
        return paper_blend(screen_grain(pos.xy));  // the background: the screen's grain
    }
    // the surface point on the pixel's ray at linear depth `depth`
    let ndc = vec2<f32>(pos.x / frame.paper.size.x * 2.0 - 1.0, 1.0 - pos.y / frame.paper.size.y * 2.0);
    let h = frame.paper.inv_proj * vec4<f32>(ndc, 0.5, 1.0);
    let q = h.xyz / h.w;
    var p = q * (depth / -q.z);
    if (frame.view.orthographic == 1u) {
        p = vec3<f32>(q.xy, -depth);
    }
    let at = (frame.paper.to_grain * vec4<f32>(p, 1.0)).xyz;
    let n = normalize((frame.paper.to_grain * vec4<f32>(bitcast<vec3<f32>>(bits.xyz), 0.0)).xyz);
    return paper_blend(surface_grain(at, n));
}

// Shared by every pass: the core uniform blocks, the mesh vertex stage and the shading models.
// The constants (array sizes, model ids) come from the Rust side (src/render/wgsl.rs), and the
// `Frame` and `Draw` structs, which gather the core blocks and every effect's, are written from
// the effect registries (src/render/shader.rs). The formulas mirror src/render/reference.rs.
// Positions are in normalised view space: view space divided by the camera's scale.

// `frame.view`: the camera and the image (src/render/uniforms.rs).
struct ViewBlock {
    proj: mat4x4<f32>,
    size: vec2<f32>,        // output size in pixels
    footprint: vec2<f32>,   // a pixel's world size at normalised depth z: z * x + y
    near: f32,              // the near plane, normalised view units
    orthographic: u32,      // 1 for an orthographic camera
    band_antialias: u32,    // 1: blend across band borders over about a pixel
    _pad1: f32,
};

struct Light {
    position: vec4<f32>,   // w = 0: xyz is the unit vector toward the light; w = 1: a point
    color: vec4<f32>,      // linear rgb, intensity included
};

// `frame.lighting`: the scene's lights, the shadow-casting one first.
struct LightingBlock {
    ambient: vec4<f32>,    // ambient light a_l, linear rgb
    lights: array<Light, MAX_LIGHTS>,
};

// `draw.mesh`: where one mesh is.
struct MeshBlock {
    model_view: mat4x4<f32>,
    normal_matrix: mat4x4<f32>,
    mirrored: u32,         // 1 when the transform mirrors (flips the winding)
    _pad0: u32,
    _pad1: u32,
    _pad2: u32,
};

// `draw.material`: its material's coefficients and its model's parameters.
struct MaterialBlock {
    ambient: vec4<f32>,
    diffuse: vec4<f32>,
    specular: vec4<f32>,
    shininess: f32,
    t_h: f32,
    t_s: f32,
    blinn: u32,            // the highlight: 1 blinn (n.h), 0 the paper's (L.v)
    band_count: u32,       // thresholds of the bands
    table_size: u32,       // entries of the lookup table
    opacity: f32,          // read by the glass stage only (src/render/passes/glass)
    _pad1: u32,
    thresholds: array<vec4<f32>, 2>,
    values: array<vec4<f32>, 3>,
    table: array<vec4<f32>, MAX_LUT>,
};

@group(0) @binding(0) var<uniform> frame: Frame;
@group(1) @binding(0) var<uniform> draw: Draw;

// Gouraud: shade the vertices and interpolate (chosen per pipeline).
override PER_VERTEX: bool = false;
// The material's shading model and the scene's number of lights, fixed per pipeline so that the
// shading code is specialised for them (as fast as a shader written for one model).
override MODEL: u32 = 0u;
override LIGHTS: u32 = 0u;
// Bit k set when light k is a point light: only those need a direction per pixel (and the
// pixel's position).
override POINT_LIGHTS: u32 = 0u;

// The mesh's positions and normals as the shadow map reads them (`GpuMesh::vertex_layout`).
struct VsIn {
    @location(0) position: vec3<f32>,
    @location(1) normal: vec3<f32>,
};

// Gouraud shading's colours of a vertex's two sides (`gouraud`), interpolated.
struct Gouraud {
    front: vec3<f32>,
    back: vec3<f32>,
};

// What a per-pixel effect's hooks see of the pixel (src/render/effects/surface.rs).
struct Fragment {
    clip: vec4<f32>,           // the pixel centre in xy (framebuffer pixels)
    view_pos: vec3<f32>,       // normalised view space
    normal: vec3<f32>,         // the unit shading normal, turned toward the viewer
    object_pos: vec3<f32>,     // the mesh's stored coordinates (zero unless the material is anchored)
    object_normal: vec3<f32>,
    stripes: vec4<f32>,        // the hatching field's psi of each stroke family (zero without one)
};

// A pixel before the parts of its draw fill in the rest (src/render/graph/mesh_stages.rs).
fn plain_fragment(clip: vec4<f32>, view_pos: vec3<f32>, view_normal: vec3<f32>, front_facing: bool) -> Fragment {
    let o = vec3<f32>(0.0);
    return Fragment(clip, view_pos, facing_normal(view_normal, front_facing), o, o, vec4<f32>(0.0));
}

fn unit_or_zero(v: vec3<f32>) -> vec3<f32> {
    let l2 = dot(v, v);
    return v * select(0.0, inverseSqrt(l2), l2 > 0.0);
}

fn view_dir(p: vec3<f32>) -> vec3<f32> {
    if (frame.view.orthographic == 1u) {
        return vec3<f32>(0.0, 0.0, 1.0);
    }
    return normalize(-p);
}

fn thresh(a: f32, b: f32) -> f32 {
    return select(0.0, 1.0, a >= b);
}

// thresh(a, b) blended over a width w of a (about one pixel's change of a; 0: the hard step).
fn step_aa(a: f32, b: f32, w: f32) -> f32 {
    if (w > 0.0) {
        return clamp((a - b) / w + 0.5, 0.0, 1.0);
    }
    return thresh(a, b);
}

// The band value at d (thresholds ascending), each border blended over w.
fn band_value(d: f32, w: f32) -> f32 {
    var v = draw.material.values[0][0];
    for (var i = 0u; i < draw.material.band_count; i++) {
        let k = i + 1u;
        let step = draw.material.values[k / 4u][k % 4u] - draw.material.values[i / 4u][i % 4u];
        v += step * step_aa(d, draw.material.thresholds[i / 4u][i % 4u], w);
    }
    return v;
}

fn table_cell(x: f32, n: u32) -> u32 {
    return min(u32(floor(clamp(x, 0.0, 1.0) * f32(n))), n - 1u);
}

// The table's value at d, averaged over [d - w/2, d + w/2] where that spans two cells.
fn table_value(d: f32, w: f32) -> vec3<f32> {
    let n = draw.material.table_size;
    let lo = table_cell(d - 0.5 * w, n);
    let hi = table_cell(d + 0.5 * w, n);
    if (w <= 0.0 || lo == hi) {
        return draw.material.table[table_cell(d, n)].rgb;
    }
    let border = f32(lo + 1u) / f32(n);
    let below = clamp((border - (d - 0.5 * w)) / w, 0.0, 1.0);
    return mix(draw.material.table[hi].rgb, draw.material.table[lo].rgb, below);
}

// The diffuse factor of the material's model at d = N . L, its borders blended over w.
fn diffuse_term(d: f32, w: f32) -> vec3<f32> {
    switch MODEL {
        case MODEL_LAMBERT, MODEL_PHONG: {
            return vec3<f32>(max(d, 0.0));
        }
        case MODEL_THRESHOLDED_PHONG: {
            return vec3<f32>(step_aa(d, draw.material.t_h, w));
        }
        case MODEL_BANDS: {
            return vec3<f32>(band_value(d, w));
        }
        default: {
            return table_value(d, w);
        }
    }
}

// The specular factor of the material's model; dn: the normal's change across one pixel
// (x, y), for the highlight's border.
fn specular_term(n: vec3<f32>, l: vec3<f32>, v: vec3<f32>, d: f32, dn: array<vec3<f32>, 2>) -> f32 {
    switch MODEL {
        case MODEL_PHONG: {
            let r = 2.0 * d * n - l;
            if (d > 0.0) {
                return pow(max(dot(r, v), 0.0), draw.material.shininess);
            }
            return 0.0;
        }
        case MODEL_THRESHOLDED_PHONG: {
            var hl = dot(l, v);
            var w = 0.0;  // the paper's highlight does not depend on the normal
            if (draw.material.blinn == 1u) {
                let h = l + v;
                hl = -1.0;
                if (dot(h, h) > 1e-12) {
                    let u = normalize(h);
                    hl = dot(n, u);
                    w = length(vec2<f32>(dot(dn[0], u), dot(dn[1], u)));
                }
            }
            return step_aa(hl, draw.material.t_s, w);
        }
        default: {
            return 0.0;
        }
    }
}

// The surface's colour where it is drawn (linear rgb; `albedo.wgsl` sets it for a coloured
// mesh): it multiplies the material's ambient and diffuse colours.
var<private> albedo: vec3<f32> = vec3<f32>(1.0);

// The unit vector from view-space point p toward light k (`RefLight::toward` on the CPU).
fn light_toward(k: u32, p: vec3<f32>) -> vec3<f32> {
    let light = frame.lighting.lights[k];
    if (((POINT_LIGHTS >> k) & 1u) == 1u) {
        return normalize(light.position.xyz - p);
    }
    return light.position.xyz;
}

// Linear colour of a point with unit view-space normal n at view-space position p; `jitter`
// moves L.n before it is banded (dithering); dn: the normal's change across one pixel in x and
// y (zero: hard band borders).
fn shade(n: vec3<f32>, p: vec3<f32>, jitter: f32, dn: array<vec3<f32>, 2>) -> vec3<f32> {
    let v = view_dir(p);
    var c = frame.lighting.ambient.rgb * draw.material.ambient.rgb * albedo;
    for (var k = 0u; k < LIGHTS; k++) {
        let light = frame.lighting.lights[k];
        let l = light_toward(k, p);
        let d = dot(n, l);
        // how much d changes across a pixel (the light's direction changes slowly)
        let w = length(vec2<f32>(dot(dn[0], l), dot(dn[1], l)));
        var f = diffuse_term(d + jitter, w);
        var s = specular_term(n, l, v, d, dn);
        let lit = light_visibility(k, n, p, d);
        if (lit < 1.0) {
            // in shadow the light's contribution goes, as on a surface facing away from it
            // (Kang et al.: the lowest tone of the table)
            f = mix(diffuse_term(-1.0, 0.0), f, lit);
            s *= lit;
        }
        c += f * light.color.rgb * draw.material.diffuse.rgb * albedo + s * light.color.rgb * draw.material.specular.rgb;
    }
    return c;
}

// True when the fragment sees the side the normals point out of.
fn outer_side(front_facing: bool) -> bool {
    return front_facing != (draw.mesh.mirrored == 1u);
}

// The shading normal: unit, and turned toward the viewer on the inner side of a surface.
fn facing_normal(n: vec3<f32>, front_facing: bool) -> vec3<f32> {
    let u = unit_or_zero(n);
    return select(-u, u, outer_side(front_facing));
}

// Gouraud: both sides shaded at a vertex (zero unless the material shades per vertex).
fn gouraud(view_normal: vec3<f32>, view_pos: vec3<f32>) -> Gouraud {
    if (!PER_VERTEX) {
        return Gouraud(vec3<f32>(0.0), vec3<f32>(0.0));
    }
    let n = unit_or_zero(view_normal);
    let hard = array<vec3<f32>, 2>(vec3<f32>(0.0), vec3<f32>(0.0));  // no derivatives per vertex
    return Gouraud(shade(n, view_pos, 0.0, hard), shade(-n, view_pos, 0.0, hard));
}

// The geometry target's texels: f32 bit patterns of the facing unit normal and the linear depth
// (distance from the camera plane, in normalised view units).
fn depth_bits(f: Fragment) -> u32 {
    return bitcast<u32>(-f.view_pos.z);
}

fn normal_depth_bits(f: Fragment) -> vec4<u32> {
    return vec4<u32>(bitcast<vec3<u32>>(f.normal), depth_bits(f));
}

// One triangle that covers the viewport (full-screen passes).
@vertex
fn vs_fullscreen(@builtin(vertex_index) vi: u32) -> @builtin(position) vec4<f32> {
    let x = f32(i32(vi & 1u) * 4 - 1);
    let y = f32(i32(vi >> 1u) * 4 - 1);
    return vec4<f32>(x, y, 0.0, 1.0);
}

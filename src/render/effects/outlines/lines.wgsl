// Mesh-space outlines (Kang, Kim and Yoon) as screen-space strips: each line is a quad around
// its projected segment, `width` output pixels wide (times its factor, interpolated between its
// ends: taper and width by depth) plus one pixel of antialiasing, with round ends so that the
// lines of a polyline join without gaps. Coverage is the distance of the pixel
// centre to the segment. Hidden lines are removed against the geometry target's depth: a point
// of the line is visible when its depth is at most the largest surface depth in the 3x3 pixels
// around it plus `depth offset` pixel footprints (settings.rs), decided at the
// nearest point of the centre line, so that the whole width of a line shows or hides together.
// A line of a rim kind (`LineKind::RIM_BITS`: silhouette, boundary, material border) with background
// among those pixels is on the rim and shows; other
// lines are tested against the surface pixels only (a crease behind the rim stays hidden).
// A line whose visibility the host decided (`flags` has EXACT: the exact rule, occluded.rs)
// is drawn as it is. A kind with a dash length is inked in dashes along its stroke. A line with
// OWN_INK (a `Lines` item's) is inked solid in its own colour and width, held against the
// surfaces only; with IN_VIEW its points are in view coordinates already.
// `visibility.rs` holds the same rules on the CPU.

@group(2) @binding(0) var geometry: texture_2d<u32>;

struct LineIn {
    @location(0) a: vec3<f32>,
    @location(1) kind: u32,
    @location(2) b: vec3<f32>,
    @location(3) scale: vec2<f32>,   // the width's factors at a and b (stroke_width.rs)
    @location(4) flags: u32,         // EXACT: visibility decided on the host
    @location(5) along: vec2<f32>,   // pixels along the stroke at a and b (dashes)
    @location(6) ink: vec4<f32>,     // OWN_INK: linear rgb, width in pixels
};


// The texel component that holds the depth: 3 in the normal + depth layout, 0 in depth only.
override DEPTH_COMPONENT: u32 = 3u;

struct LineOut {
    @builtin(position) clip: vec4<f32>,
    @location(0) @interpolate(flat) sa: vec2<f32>,
    @location(1) @interpolate(flat) sb: vec2<f32>,
    @location(2) @interpolate(flat) depths: vec2<f32>,
    @location(3) @interpolate(flat) kind: u32,
    @location(4) @interpolate(flat) scale: vec2<f32>,
    @location(5) @interpolate(flat) flags: u32,
    @location(6) @interpolate(flat) along: vec2<f32>,
    @location(7) @interpolate(flat) ink: vec4<f32>,
};

// The line's ink: its kind's (linear rgb, width in pixels), or its own (OWN_INK).
fn ink_of(kind: u32, flags: u32, own: vec4<f32>) -> vec4<f32> {
    return select(frame.outlines.ink[kind], own, (flags & OWN_INK) != 0u);
}

fn to_pixels(v: vec3<f32>) -> vec2<f32> {
    let c = frame.view.proj * vec4<f32>(v, 1.0);
    let ndc = c.xy / c.w;
    return vec2<f32>((ndc.x * 0.5 + 0.5) * frame.view.size.x, (0.5 - ndc.y * 0.5) * frame.view.size.y);
}

@vertex
fn vs_line(@builtin(vertex_index) vi: u32, l: LineIn) -> LineOut {
    return line_vertex(vi, l);
}

// Corner `vi` of the strip around line `l` (shared with the drafts' lines, src/render/draft/).
fn line_vertex(vi: u32, l: LineIn) -> LineOut {
    var o: LineOut;
    let kind = l.kind;
    o.kind = kind;
    let in_view = (l.flags & IN_VIEW) != 0u;
    var pa = select((draw.mesh.model_view * vec4<f32>(l.a, 1.0)).xyz, l.a, in_view);
    var pb = select((draw.mesh.model_view * vec4<f32>(l.b, 1.0)).xyz, l.b, in_view);
    // Keep the part in front of the near plane (perspective only). No branch tests uniforms
    // alone: for such branches lavapipe (Mesa 22) compiles a shader variant at every draw and
    // never frees it.
    let clips = frame.view.orthographic == 0u;
    let near = frame.view.near;
    let za = -pa.z;
    let zb = -pb.z;
    let cut_a = clips && za < near;
    let cut_b = clips && zb < near;
    pa = select(pa, mix(pa, pb, (near - za) / (zb - za)), cut_a && !cut_b);
    pb = select(pb, mix(pb, pa, (near - zb) / (za - zb)), cut_b && !cut_a);
    let sa = to_pixels(pa);
    let sb = to_pixels(pb);
    o.scale = l.scale;
    o.flags = l.flags;
    o.along = l.along;
    o.ink = l.ink;
    let half = ink_of(kind, l.flags, l.ink).w * max(l.scale.x, l.scale.y) * 0.5 + 1.0;
    let ab = sb - sa;
    let len = length(ab);
    var dir = vec2<f32>(1.0, 0.0);
    if (len > 1e-6) {
        dir = ab / len;
    }
    let side = vec2<f32>(-dir.y, dir.x);
    // a triangle strip: 0 and 2 at the start, 1 and 3 at the end
    let along = select(-half, len + half, (vi & 1u) == 1u);
    let across = select(-half, half, vi >= 2u);
    let s = sa + dir * along + side * across;
    o.clip = vec4<f32>(s.x / frame.view.size.x * 2.0 - 1.0, 1.0 - s.y / frame.view.size.y * 2.0, 0.0, 1.0);
    o.sa = sa;
    o.sb = sb;
    o.depths = vec2<f32>(-pa.z, -pb.z);
    // wholly behind the near plane: outside the viewport
    o.clip = select(o.clip, vec4<f32>(-2.0, -2.0, 0.0, 1.0), cut_a && cut_b);
    return o;
}

fn surface_depth(p: vec2<i32>) -> u32 {
    return textureLoad(geometry, p, 0)[DEPTH_COMPONENT];
}

// Whether the line point at pixel position `c` with depth `z` and kind `kind` is visible
// (`own_ink`: a `Lines` item's, never on a rim).
fn visible(c: vec2<f32>, z: f32, kind: u32, own_ink: bool) -> bool {
    let size = vec2<i32>(textureDimensions(geometry));
    let q = vec2<i32>(floor(c));
    let rim = ((RIM_KINDS >> kind) & 1u) == 1u && !own_ink;
    let tolerance = frame.outlines.depth_offset * (z * frame.view.footprint.x + frame.view.footprint.y) + z * DEPTH_EPSILON;
    // the pixel itself usually decides: in front of (or on) its surface, the largest depth
    // around can only agree
    let own = surface_depth(clamp(q, vec2<i32>(0), size - 1));
    let own_background = (own & 0x7f800000u) == 0x7f800000u;
    if ((own_background && rim) || (!own_background && z <= bitcast<f32>(own) + tolerance)) {
        return true;
    }
    var far = 0.0;
    var surface = false;
    for (var j = -1; j <= 1; j++) {
        for (var i = -1; i <= 1; i++) {
            let bits = surface_depth(clamp(q + vec2<i32>(i, j), vec2<i32>(0), size - 1));
            if ((bits & 0x7f800000u) == 0x7f800000u) {
                if (rim) {
                    return true;  // a rim line next to the background: nothing covers it
                }
            } else {
                surface = true;
                far = max(far, bitcast<f32>(bits));
            }
        }
    }
    return !surface || z <= far + tolerance;
}

// How much of a line dashed `dash` pixels on and off is inked `along` pixels along its stroke
// (1 where `dash` is 0): `visibility::dashed`.
fn dashed(along: f32, dash: f32) -> f32 {
    let period = 2.0 * dash;
    let c = along - dash * 0.5;
    let w = c - period * floor(c / max(period, 1e-30) + 0.5);
    return select(1.0, clamp(dash * 0.5 + 0.5 - abs(w), 0.0, 1.0), dash > 0.0);
}

// Ink coverage of this pixel by the line, 0 where it is hidden.
fn coverage(o: LineOut) -> f32 {
    let pos = o.clip;  // in the fragment stage: the pixel centre
    let ab = o.sb - o.sa;
    let l2 = dot(ab, ab);
    var t = 0.0;
    if (l2 > 0.0) {
        t = clamp(dot(pos.xy - o.sa, ab) / l2, 0.0, 1.0);
    }
    let c = o.sa + ab * t;
    let own = (o.flags & OWN_INK) != 0u;
    let width = ink_of(o.kind, o.flags, o.ink).w * mix(o.scale.x, o.scale.y, t);
    let dash = select(frame.outlines.dashes[o.kind / 4u][o.kind % 4u], 0.0, own);
    let cov = clamp(width * 0.5 + 0.5 - length(pos.xy - c), 0.0, 1.0) * dashed(mix(o.along.x, o.along.y, t), dash);
    if (cov <= 0.0) {
        return 0.0;
    }
    // in perspective 1 / depth is linear on screen (a select: see the near plane above)
    let z = select(
        mix(o.depths.x, o.depths.y, t),
        1.0 / mix(1.0 / o.depths.x, 1.0 / o.depths.y, t),
        frame.view.orthographic == 0u,
    );
    return select(0.0, cov, (o.flags & EXACT) != 0u || visible(c, z, o.kind, own));
}

// The line's ink at this pixel.
fn line_ink(o: LineOut) -> Both {
    return inked_rgb(ink_of(o.kind, o.flags, o.ink).rgb, coverage(o));
}

@fragment
fn fs_color(o: LineOut) -> @location(0) vec4<f32> {
    return line_ink(o).color;
}

@fragment
fn fs_outline(o: LineOut) -> @location(0) vec4<f32> {
    return line_ink(o).outline;
}

@fragment
fn fs_both(o: LineOut) -> Both {
    return line_ink(o);
}

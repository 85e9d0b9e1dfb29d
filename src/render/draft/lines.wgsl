// The drafts' mesh-space lines (src/render/draft/lines.rs), in two vertex stages for the two
// silhouette rules (`ContourRule`), both around the exact frame's strips
// (`line_vertex`, lines.wgsl, with its coverage and hidden-line rule in `fs_color`), each
// line given the normals of the faces on its edge. A line whose normals are zero (a boundary,
// a crease) is drawn in every view; another is a silhouette where one of its faces faces the
// eye and the other does not (edges/silhouette.rs's rule: n . V < 0 faces it, V from the eye to
// the face), and elsewhere collapses to a point outside the view. `lines::drawn` holds the
// same rule on the CPU. The page gives each record to the 4 vertices of its strip (two
// triangles), which take their corner from the vertex index's low bits.

struct ViewEdgeIn {
    @location(0) a: vec3<f32>,
    @location(1) kind: u32,
    @location(2) b: vec3<f32>,
    @location(3) scale: vec2<f32>,
    @location(4) n0: vec3<f32>,
    @location(5) n1: vec3<f32>,
};

// Whether the face of view-space normal `n` through the view-space point `p` faces the eye.
fn faces_eye(n: vec3<f32>, p: vec3<f32>) -> bool {
    let v = select(p, vec3<f32>(0.0, 0.0, -1.0), frame.view.orthographic == 1u);
    return dot(n, v) < 0.0;
}

@vertex
fn vs_view_edge(@builtin(vertex_index) vi: u32, e: ViewEdgeIn) -> LineOut {
    let p = (draw.mesh.model_view * vec4<f32>(e.a, 1.0)).xyz;
    let m = mat3x3<f32>(draw.mesh.normal_matrix[0].xyz, draw.mesh.normal_matrix[1].xyz, draw.mesh.normal_matrix[2].xyz);
    let always = all(e.n0 == vec3<f32>(0.0)) && all(e.n1 == vec3<f32>(0.0));
    var o: LineOut;
    o.clip = vec4<f32>(-2.0, -2.0, 0.0, 1.0);
    // a branch, not a select: most edges are not drawn, and the strip's work is then skipped
    if (always || faces_eye(m * e.n0, p) != faces_eye(m * e.n1, p)) {
        var l: LineIn;
        l.a = e.a;
        l.kind = e.kind;
        l.b = e.b;
        l.scale = e.scale;
        l.flags = 0u;  // the drafts' lines are tested against the depth
        l.along = vec2<f32>(0.0);
        o = line_vertex(vi & 3u, l);  // the page gives each record to 4 vertices
    }
    return o;
}

// Smooth contours (edges/contours.rs's `smooth_contours`, through `zero_set`): per face, with
// its corners' positions and normals (the mesh split at the drawn creases), the segment where
// n . (eye - p), interpolated linearly, is zero: between the points of the two edges whose ends
// differ in sign (> 0 or not). A face without one collapses to a point outside the view.
// `lines::contour_piece` holds the same rule on the CPU.

struct FaceIn {
    @location(0) p0: vec3<f32>,
    @location(1) p1: vec3<f32>,
    @location(2) p2: vec3<f32>,
    @location(3) n0: vec3<f32>,
    @location(4) n1: vec3<f32>,
    @location(5) n2: vec3<f32>,
};

// n . (eye - p) for the view-space normal `n` at the view-space point `p` (orthographic:
// -n . d, d the view direction).
fn toward_eye(n: vec3<f32>, p: vec3<f32>) -> f32 {
    return dot(n, select(-p, vec3<f32>(0.0, 0.0, 1.0), frame.view.orthographic == 1u));
}

@vertex
fn vs_face_contour(@builtin(vertex_index) vi: u32, f: FaceIn) -> LineOut {
    let ps = array<vec3<f32>, 3>(f.p0, f.p1, f.p2);
    let ns = array<vec3<f32>, 3>(f.n0, f.n1, f.n2);
    let m = mat3x3<f32>(draw.mesh.normal_matrix[0].xyz, draw.mesh.normal_matrix[1].xyz, draw.mesh.normal_matrix[2].xyz);
    var g: array<f32, 3>;
    for (var i = 0u; i < 3u; i++) {
        // unit in the mesh's coordinates, as the exact frame's (a coarse copy's are means)
        let n = ns[i] * inverseSqrt(select(1.0, dot(ns[i], ns[i]), dot(ns[i], ns[i]) > 0.0));
        g[i] = toward_eye(m * n, (draw.mesh.model_view * vec4<f32>(ps[i], 1.0)).xyz);
    }
    var ends: array<vec3<f32>, 2>;
    var n = 0u;
    for (var j = 0u; j < 3u; j++) {
        let k = (j + 1u) % 3u;
        if ((g[j] > 0.0) != (g[k] > 0.0)) {
            let t = clamp(g[j] / (g[j] - g[k]), 0.0, 1.0);
            ends[min(n, 1u)] = mix(ps[j], ps[k], t);
            n += 1u;
        }
    }
    var o: LineOut;
    o.clip = vec4<f32>(-2.0, -2.0, 0.0, 1.0);
    if (n == 2u) {
        var l: LineIn;
        l.a = ends[0];
        l.kind = SILHOUETTE;
        l.b = ends[1];
        l.scale = vec2<f32>(1.0);
        l.flags = 0u;
        l.along = vec2<f32>(0.0);
        o = line_vertex(vi & 3u, l);  // the page gives each record to 4 vertices
    }
    return o;
}

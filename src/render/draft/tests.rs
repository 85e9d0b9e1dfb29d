//! Every program a draft can hold translates to GLSL ES 3.00 (the browser test compiles them in
//! WebGL2), binding its uniform blocks and textures by the WGSL groups; the drafts' lines
//! decide silhouettes as `edges::silhouette` does.

use super::glsl::program;
use super::lines::{self, contour_piece, drawn, FaceContour, ViewEdge};
use crate::edges::outlines::LineKind;
use crate::edges::{EdgeIndex, View};
use crate::render::effects::hatching::field_part::{FIELD, FIELD_LOCATION};
use crate::render::effects::outlines::{edge_bits, edges};
use crate::render::graph::mesh_stages::MeshStages;
use crate::render::graph::{mesh_pass_wgsl, module_wgsl};
use crate::render::passes::shade;
use crate::render::shader::preamble;

#[test]
fn every_shading_variant_translates() {
    // hatching's field included: its stripe values a vertex attribute, its derivatives GLSL's
    let mut field = 0;
    for stages in MeshStages::all().into_iter().filter(|s| s.color) {
        let wgsl = module_wgsl(preamble(), &mesh_pass_wgsl(shade::WGSL, stages), None);
        for model in 0..5 {
            let mut constants = vec![("MODEL", model as f64), ("LIGHTS", 2.0), ("POINT_LIGHTS", 2.0)];
            if stages.albedo {
                constants.push(("TEXTURED", 1.0)); // the albedo part's own constant
            }
            let p = program(&stages.name(), &wgsl, "vs_mesh", "fs_mesh", &constants)
                .unwrap_or_else(|e| panic!("{}: {e}", stages.name()));
            assert!(p.vertex.source.starts_with("#version 300 es"), "{}", p.vertex.source);
            assert!(p.fragment.source.starts_with("#version 300 es"), "{}", p.fragment.source);
            // the frame's and the draw's blocks, by their groups
            let groups: Vec<u32> = p.fragment.blocks.iter().map(|b| b.group).collect();
            assert!(groups.contains(&0) && groups.contains(&1), "{:?}", p.fragment.blocks);
            assert_eq!(p.fragment.textures.len(), stages.albedo as usize, "{:?}", p.fragment.textures);
            assert!(!p.vertex.source.contains("override"), "{}", p.vertex.source);
            if stages.parts.contains(&FIELD) {
                field += 1;
                let input = format!("layout(location = {FIELD_LOCATION}) in vec4");
                assert!(p.vertex.source.contains(&input), "{}", p.vertex.source);
                assert!(p.fragment.source.contains("dFdx"), "{}", p.fragment.source);
            }
        }
    }
    assert!(field > 0, "no variant hatches along the field");
}

#[test]
fn the_lines_programs_translate() {
    let wgsl = module_wgsl(preamble(), &lines::module(), None);
    for (entry, kind) in [("vs_view_edge", true), ("vs_face_contour", false)] {
        for depth in [0.0, 3.0] {
            let p = program(entry, &wgsl, entry, "fs_color", &[("DEPTH_COMPONENT", depth)]).unwrap();
            // the instance attributes (a line's kind an unsigned integer), the geometry target by
            // its group
            for location in 0..6 {
                let input = format!("layout(location = {location}) in ");
                assert!(p.vertex.source.contains(&input), "{}", p.vertex.source);
            }
            assert_eq!(p.vertex.source.contains("in uint"), kind, "{}", p.vertex.source);
            assert_eq!(p.fragment.textures.iter().map(|t| t.group).collect::<Vec<_>>(), vec![2]);
            assert!(p.fragment.source.contains("usampler2D"), "{}", p.fragment.source);
        }
    }
}

#[test]
fn the_drafts_smooth_contours_are_the_exact_frames() {
    use crate::edges::zero_set::zero_set;
    use crate::mesh::normals::vertex_normals;
    let (v, f) = crate::mesh::shapes::icosphere(3, 0.1, 7).unwrap();
    let normals = vertex_normals(&v, &f);
    let faces: Vec<FaceContour> = f
        .iter()
        .map(|t| FaceContour {
            p: t.map(|k| v[k as usize].map(|x| x as f32)),
            n: t.map(|k| normals[k as usize].map(|x| x as f32)),
        })
        .collect();
    // the mesh as the draft holds it (float32), traced as the exact frame traces it
    let (v32, n32): (Vec<[f64; 3]>, Vec<[f64; 3]>) =
        v.iter().zip(&normals).map(|(p, n)| (p.map(|x| x as f32 as f64), n.map(|x| x as f32 as f64))).unzip();
    let dot = |a: [f64; 3], b: [f64; 3]| a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
    for view in [View::Eye([0.3, 0.5, 4.0]), View::Direction([0.2, -1.0, 0.1])] {
        let facing = |k: u32| {
            let (n, p) = (n32[k as usize], v32[k as usize]);
            match view {
                View::Eye(e) => dot(n, [e[0] - p[0], e[1] - p[1], e[2] - p[2]]),
                View::Direction(d) => -dot(n, d),
            }
        };
        let exact = zero_set(&v32, &[&f[..]], facing, |_| [], |_| 1.0);
        let length = |a: [f64; 3], b: [f64; 3]| {
            dot([a[0] - b[0], a[1] - b[1], a[2] - b[2]], [a[0] - b[0], a[1] - b[1], a[2] - b[2]]).sqrt()
        };
        let (mut pieces, mut drafted) = (0, 0.0);
        for face in &faces {
            if let Some([a, b]) = contour_piece(face, view) {
                pieces += 1;
                drafted += length(a, b);
            }
        }
        let (mut segments, mut traced) = (0, 0.0);
        for i in 0..exact.len() {
            let line = exact.line(i);
            segments += line.len() - 1;
            traced += line.windows(2).map(|w| length(w[0], w[1])).sum::<f64>();
        }
        assert!(segments > 20, "{segments}");
        assert_eq!(pieces, segments);
        // up to the float32 normals made unit again
        assert!((drafted - traced).abs() < 1e-6 * traced, "{drafted} {traced}");
    }
}

/// Every edge between two faces of a sphere with bumps, as the draft's lines hold them.
fn candidates() -> (EdgeIndex, Vec<ViewEdge>) {
    let (v, f) = crate::mesh::shapes::icosphere(3, 0.1, 7).unwrap();
    let index = EdgeIndex::build(&v, &f, false).unwrap();
    let (edges, faces) = index.manifold();
    let n = |k: u32| index.normals()[k as usize].map(|x| x as f32);
    let out = edges
        .iter()
        .zip(faces)
        .map(|(e, f)| ViewEdge::new(index.positions(), e, LineKind::Silhouette, n(f[0]), n(f[1])))
        .collect();
    (index, out)
}

#[test]
fn the_drafts_silhouettes_are_the_face_edge_silhouettes() {
    let (index, candidates) = candidates();
    for view in [View::Eye([0.3, 0.5, 4.0]), View::Eye([-3.0, 0.2, 0.4]), View::Direction([0.2, -1.0, 0.1])] {
        let mut drafted: Vec<[u32; 2]> = index
            .manifold()
            .0
            .iter()
            .zip(&candidates)
            .filter(|(_, c)| drawn(c, view))
            .map(|(e, _)| *e)
            .collect();
        drafted.sort_unstable();
        let exact = index.silhouette(view).unwrap();
        assert!(exact.len() > 20, "{}", exact.len());
        // the same edges, but for faces edge-on to within float32's rounding
        let differ = drafted.iter().filter(|e| exact.binary_search(e).is_err()).count()
            + exact.iter().filter(|e| drafted.binary_search(e).is_err()).count();
        assert!(differ <= exact.len() / 100, "{differ} of {} differ", exact.len());
    }
    // a line with no normals is drawn in every view
    let fixed = ViewEdge { n0: [0.0; 3], n1: [0.0; 3], ..candidates[0] };
    assert!(drawn(&fixed, View::Eye([0.0, 0.0, 4.0])) && drawn(&fixed, View::Direction([1.0, 0.0, 0.0])));
}

#[test]
fn the_image_ink_passes_translate() {
    for (wgsl, entry) in [(edge_bits::WGSL, "fs_edge_bits"), (edges::WGSL, "fs_color")] {
        let p = program(entry, &module_wgsl(preamble(), wgsl, None), "vs_fullscreen", entry, &[]).unwrap();
        assert_eq!(p.fragment.textures.len(), 1, "{:?}", p.fragment.textures);
        assert!(p.fragment.source.contains("usampler2D"), "{}", p.fragment.source);
    }
}

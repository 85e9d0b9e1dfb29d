//! Every program a draft can hold translates to GLSL ES 3.00 (the browser test compiles them in
//! WebGL2), binding its uniform blocks and textures by the WGSL groups.

use super::glsl::program;
use crate::render::effects::hatching::field_part::FIELD;
use crate::render::effects::outlines::{edge_bits, edges};
use crate::render::graph::mesh_stages::MeshStages;
use crate::render::graph::{mesh_pass_wgsl, module_wgsl};
use crate::render::passes::shade;
use crate::render::shader::preamble;

#[test]
fn every_shading_variant_translates() {
    // a draft leaves hatching (the field's part) to the exact frame
    for stages in MeshStages::all().into_iter().filter(|s| s.color && !s.parts.contains(&FIELD)) {
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
        }
    }
}

#[test]
fn the_image_ink_passes_translate() {
    for (wgsl, entry) in [(edge_bits::WGSL, "fs_edge_bits"), (edges::WGSL, "fs_color")] {
        let p = program(entry, &module_wgsl(preamble(), wgsl, None), "vs_fullscreen", entry, &[]).unwrap();
        assert_eq!(p.fragment.textures.len(), 1, "{:?}", p.fragment.textures);
        assert!(p.fragment.source.contains("usampler2D"), "{}", p.fragment.source);
    }
}

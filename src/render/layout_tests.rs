//! Every shader parses and validates without a device, and every Rust uniform block is laid
//! out as its WGSL struct (field order, offsets, sizes) by naga's reflection, as are the `Frame`
//! and `Draw` structs that gather them.

use crate::render::block::{Block, BlockLayout};
use crate::render::effects::frame::{frame_members, FRAME};
use crate::render::effects::outlines::{edges, lines};
use crate::render::effects::shadows::{map, mask, ShadowTest};
use crate::render::effects::surface;
use crate::render::graph::effect::ShadeHook;
use crate::render::graph::mesh_stages::MeshStages;
use crate::render::passes::{downsample, glass, shade};
use crate::render::shader::preamble;
use crate::render::uniforms::{draw_members, LightingBlock, MaterialBlock, Members, MeshBlock, ViewBlock};
use crate::render::wgsl::{compose, DEFAULT_HOOKS};

fn parse(src: &str) -> naga::Module {
    naga::front::wgsl::parse_str(src).unwrap_or_else(|e| panic!("{}", e.emit_to_string(src)))
}

/// Every module a renderer can build: each pass's WGSL with the hooks it is built with, and
/// the mesh passes' with the stages of every combination of what a draw reads and writes.
fn modules() -> Vec<String> {
    let shadowed = ShadowTest { filter: crate::render::effects::shadows::settings::ShadowFilter::Pcf };
    let p = preamble();
    let mut all: Vec<String> = [downsample::WGSL, glass::WGSL, edges::WGSL, lines::WGSL]
        .iter()
        .map(|w| compose(p, DEFAULT_HOOKS, w))
        .collect();
    all.push(compose(p, shadowed.wgsl(), mask::WGSL));
    for cut in [false, true] {
        all.push(compose(p, DEFAULT_HOOKS, &map::map_stages(cut).wgsl()));
    }
    for stages in MeshStages::all() {
        let written = stages.wgsl();
        for hooks in [DEFAULT_HOOKS, shadowed.wgsl()] {
            all.push(compose(p, hooks, &format!("{}\n{written}", shade::WGSL)));
        }
        // the geometry pass's and the shadow map's draws have no shading; a layer of glass has
        if !stages.color && !stages.glass {
            all.push(compose(p, DEFAULT_HOOKS, &written));
        }
    }
    all
}

#[test]
fn every_shader_module_parses_and_validates() {
    for src in modules() {
        let module = parse(&src);
        naga::valid::Validator::new(naga::valid::ValidationFlags::all(), naga::valid::Capabilities::all())
            .validate(&module)
            .unwrap_or_else(|e| panic!("{e:?}"));
    }
}

/// A WGSL struct's members as (name, offset, size), and its size.
fn wgsl_struct(module: &naga::Module, name: &str) -> (Vec<(String, usize, usize)>, usize) {
    let ty = module
        .types
        .iter()
        .find(|(_, t)| t.name.as_deref() == Some(name))
        .unwrap_or_else(|| panic!("no WGSL struct {name}"))
        .1;
    let naga::TypeInner::Struct { members, span } = &ty.inner else { panic!("{name} is not a struct") };
    let fields = members
        .iter()
        .map(|m| {
            let size = module.types[m.ty].inner.size(module.to_ctx()) as usize;
            (m.name.clone().unwrap_or_default(), m.offset as usize, size)
        })
        .collect();
    (fields, *span as usize)
}

fn check_block(module: &naga::Module, b: &BlockLayout) {
    let (wgsl, span) = wgsl_struct(module, b.wgsl);
    assert_eq!(span, b.size, "{}: WGSL size {span}, Rust size {}", b.wgsl, b.size);
    assert_eq!(b.size % 16, 0, "{}: blocks are 16-byte multiples", b.wgsl);
    let wgsl: Vec<_> = wgsl.into_iter().filter(|f| !f.0.starts_with('_')).collect();
    let rust: Vec<_> = b.fields.iter().map(|&(n, o, s)| (n.to_string(), o, s)).collect();
    assert_eq!(wgsl, rust, "{}: the WGSL fields (name, offset, size) differ from the Rust ones", b.wgsl);
}

fn check_members(module: &naga::Module, name: &str, members: &Members) {
    let (wgsl, span) = wgsl_struct(module, name);
    let mut offset = 0;
    let mut want = Vec::new();
    for (n, b) in members {
        want.push((n.to_string(), offset, b.size));
        offset += b.size;
    }
    assert_eq!(wgsl, want, "{name}: members are not the blocks one after another");
    assert_eq!(span, offset);
}

#[test]
fn every_uniform_block_is_laid_out_as_its_wgsl_struct() {
    let module = parse(&compose(preamble(), DEFAULT_HOOKS, ""));
    let mut blocks =
        vec![ViewBlock::layout(), LightingBlock::layout(), MeshBlock::layout(), MaterialBlock::layout()];
    blocks.extend(surface::blocks().into_iter().map(|b| b.1));
    blocks.extend(FRAME.iter().map(|e| e.block()));
    for b in &blocks {
        check_block(&module, b);
    }
    check_members(&module, "Frame", &frame_members());
    check_members(&module, "Draw", &draw_members());
}

#[test]
fn a_moved_field_is_caught() {
    // the check itself: a block whose Rust field order differs from its WGSL struct fails
    let module = parse(&compose(preamble(), DEFAULT_HOOKS, ""));
    let mut b = ViewBlock::layout();
    b.fields.swap(1, 2);
    assert!(std::panic::catch_unwind(|| check_block(&module, &b)).is_err());
}

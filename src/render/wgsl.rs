//! WGSL sources. Every shader is the prelude (constants written from the Rust values they
//! mirror, so array sizes and ids are never repeated as bare numbers), then the shared
//! `shaders/common.wgsl`, then the pass's own file.

use crate::edges::outlines::LineKind;

use super::scene::light::MAX_LIGHTS;
use super::scene::material::{Model, MAX_LUT};
use super::scene::outlines::{IMAGE_KIND, INK_KINDS};
use super::scene::style::{DitherPattern, HATCH_LAYERS};

const COMMON: &str = include_str!("shaders/common.wgsl");
/// `light_visibility` where no light casts shadows.
const UNSHADOWED: &str = include_str!("shaders/unshadowed.wgsl");

/// The constants the shaders share with Rust.
pub fn prelude() -> String {
    let mut s = String::from("// written by src/render/wgsl.rs\n");
    let mut constant = |name: &str, value: usize| s.push_str(&format!("const {name}: u32 = {value}u;\n"));
    constant("MAX_LIGHTS", MAX_LIGHTS);
    constant("MAX_LUT", MAX_LUT);
    constant("INK_KINDS", INK_KINDS);
    constant("IMAGE_KIND", IMAGE_KIND);
    constant("LINE_SILHOUETTE", LineKind::Silhouette as usize);
    constant("LINE_BOUNDARY", LineKind::Boundary as usize);
    constant("HATCH_LAYERS", HATCH_LAYERS);
    constant("DITHER_BLUE", DitherPattern::Blue as usize);
    for (id, name) in Model::NAMES.iter().enumerate() {
        constant(&format!("MODEL_{}", name.to_ascii_uppercase()), id);
    }
    s
}

/// The full source of a pass's shader module, where no light casts shadows.
pub fn source(pass: &str) -> String {
    format!("{}\n{COMMON}\n{UNSHADOWED}\n{pass}", prelude())
}

/// The full source of a pass's shader module that tests the shadow map.
pub fn source_shadowed(pass: &str) -> String {
    let test = crate::render::passes::shadow::SHADOW_TEST;
    format!("{}\n{COMMON}\n{test}\n{pass}", prelude())
}

#[cfg(test)]
mod tests {
    #[test]
    fn every_pass_shader_parses_and_validates() {
        let passes = crate::render::passes::SHADERS.iter().map(|p| super::source(p));
        let shadowed = crate::render::passes::SHADOWED_SHADERS.iter().map(|p| super::source_shadowed(p));
        for src in passes.chain(shadowed) {
            let module =
                naga::front::wgsl::parse_str(&src).unwrap_or_else(|e| panic!("{}", e.emit_to_string(&src)));
            naga::valid::Validator::new(
                naga::valid::ValidationFlags::all(),
                naga::valid::Capabilities::all(),
            )
            .validate(&module)
            .unwrap_or_else(|e| panic!("{e:?}"));
        }
    }
}

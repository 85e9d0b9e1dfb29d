//! WGSL sources. Every shader is the prelude (constants written from the Rust values they
//! mirror, so array sizes and ids are never repeated as bare numbers), then the shared
//! `shaders/common.wgsl`, then the pass's own file.

use crate::edges::outlines::LineKind;

use super::scene::light::MAX_LIGHTS;
use super::scene::material::{Model, MAX_LUT};
use super::scene::outlines::{IMAGE_KIND, INK_KINDS};

const COMMON: &str = include_str!("shaders/common.wgsl");

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
    for (id, name) in Model::NAMES.iter().enumerate() {
        constant(&format!("MODEL_{}", name.to_ascii_uppercase()), id);
    }
    s
}

/// The full source of a pass's shader module.
pub fn source(pass: &str) -> String {
    format!("{}\n{COMMON}\n{pass}", prelude())
}

#[cfg(test)]
mod tests {
    #[test]
    fn every_pass_shader_parses_and_validates() {
        for pass in crate::render::passes::SHADERS {
            let src = super::source(pass);
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

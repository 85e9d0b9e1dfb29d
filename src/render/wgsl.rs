//! WGSL sources. Every shader module is the preamble its renderer shares (`render::shader`:
//! the constants the shaders share with Rust, written from the Rust values so that array sizes
//! and ids are never repeated as bare numbers; `shaders/common.wgsl`; every effect's blocks and
//! hooks), then the shading hooks (the defaults, or a frame effect's), then the pass's own file.

use super::scene::light::MAX_LIGHTS;
use super::scene::model::{Model, MAX_LUT};

const COMMON: &str = include_str!("shaders/common.wgsl");
/// The shading hooks where no frame effect swaps its own in.
pub const DEFAULT_HOOKS: &str = include_str!("shaders/default_hooks.wgsl");

/// `const NAME: u32 = value;`
pub fn constant_u32(name: &str, value: u32) -> String {
    format!("const {name}: u32 = {value}u;\n")
}

/// `const NAME: f32 = value;`, in full precision.
pub fn constant_f32(name: &str, value: f64) -> String {
    format!("const {name}: f32 = {value:?};\n")
}

/// `const NAME: vec3<f32> = vec3<f32>(x, y, z);`
pub fn constant_vec3(name: &str, v: [f64; 3]) -> String {
    format!("const {name}: vec3<f32> = vec3<f32>({:?}, {:?}, {:?});\n", v[0], v[1], v[2])
}

/// The core's constants and `shaders/common.wgsl`.
pub fn core() -> String {
    let mut s = String::from("// written by src/render/wgsl.rs\n");
    s += &constant_u32("MAX_LIGHTS", MAX_LIGHTS as u32);
    s += &constant_u32("MAX_LUT", MAX_LUT as u32);
    for (id, name) in Model::NAMES.iter().enumerate() {
        s += &constant_u32(&format!("MODEL_{}", name.to_ascii_uppercase()), id as u32);
    }
    s + COMMON
}

/// A whole module: the shared preamble, the shading hooks, the pass's own WGSL.
pub fn compose(preamble: &str, hooks: &str, pass: &str) -> String {
    format!("{preamble}\n{hooks}\n{pass}")
}

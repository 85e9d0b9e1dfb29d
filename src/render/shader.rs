//! The WGSL every shader module of a renderer starts with: the core's constants and blocks
//! (`wgsl::core`), every per-pixel effect's WGSL and every frame effect's block, the `Frame`
//! and `Draw` structs that gather the blocks (`uniforms`), and the per-pixel hooks' dispatch.

use std::sync::OnceLock;

use super::effects::frame::{frame_members, FRAME};
use super::effects::surface;
use super::uniforms::{draw_members, struct_wgsl};
use super::wgsl;

/// The shared preamble, written once per process.
pub fn preamble() -> &'static str {
    static PREAMBLE: OnceLock<String> = OnceLock::new();
    PREAMBLE.get_or_init(|| {
        let mut s = wgsl::core();
        s += &surface::wgsl();
        for e in FRAME {
            s += &e.block_wgsl();
        }
        s += &struct_wgsl("Frame", &frame_members());
        s += &struct_wgsl("Draw", &draw_members());
        s + &surface::dispatch_wgsl()
    })
}

//! Headless toon rendering with wgpu. A scene (plain data: meshes by id, camera, lights,
//! materials, outlines) and a frame spec are checked together (`scene::checked`), become a plan
//! of passes and host steps (`plan`), recorded as one frame on a process-wide device (`context`)
//! and read back straight into the caller's arrays.
//!
//! Layers, each using only those below it (`scripts/layers.py` checks them):
//! 1. plain data: `color`, `albedo`, `block`, `wgsl`, `scene` (with the settings of every effect) and
//!    the per-pixel effects (`effects::surface`, `effects::hatching`, `effects::dither`);
//! 2. the device and meshes on it: `device`, `gpu_albedo`, `gpu_mesh`, `mesh_record`, `culling`, `reference`,
//!    `image_out`;
//! 3. `uniforms`, `pipelines`, `graph` (targets, resources, the pass and effect traits),
//!    `context`;
//! 4. `passes` and the frame effects' folders (`effects::shadows`, `effects::outlines`);
//! 5. the registries and the plan: `effects::frame`, `plan`, `shader`;
//! 6. `renderer`.

pub mod albedo;
pub mod block;
pub mod color;
pub mod context;
pub mod culling;
pub mod derived_vertices;
pub mod device;
pub mod draft;
pub mod effects;
pub mod framing;
pub mod gpu_albedo;
pub mod gpu_mesh;
pub mod graph;
pub mod image_out;
pub mod mesh_record;
pub mod passes;
pub mod pipelines;
pub mod plan;
pub mod reference;
pub mod renderer;
pub mod scene;
pub mod settings;
pub mod shader;
pub mod splats;
pub mod stage_part;
pub mod uniforms;
pub mod wgsl;

pub use device::{BackendChoice, GpuInfo};

/// The names the core accepts, each list under the name a front end knows it by, for front ends
/// to take rather than repeat.
pub fn accepted_names() -> Vec<(&'static str, Vec<&'static str>)> {
    use crate::edges::outlines::LineKind;
    use crate::smooth::options as smooth;
    use effects::dither::{DitherPattern, DitherSpace};
    use effects::outlines::settings::{ink_name, kind_names, ContourRule, ImageRule, Outlines, LINES_KIND};
    use effects::shadows::settings::ShadowFilter;
    use scene::model::{Highlight, Model};
    use scene::Output;
    let images = Output::ALL.iter().filter(|o| o.pixel().is_some()).map(|o| o.name()).collect();
    vec![
        ("OUTPUTS", Output::NAMES.to_vec()),
        ("IMAGE_OUTPUTS", images),
        ("LINE_KINDS", LineKind::ALL.map(|k| k.name()).to_vec()),
        ("INK_KINDS", kind_names().to_vec()),
        // the ink of `Lines` items, which `RenderResult.line_kinds` and the SVG name
        ("ITEM_INKS", vec![ink_name(LINES_KIND)]),
        ("OUTLINE_KINDS", Outlines::KINDS.to_vec()),
        ("CONTOUR_RULES", ContourRule::NAMES.to_vec()),
        ("IMAGE_RULES", ImageRule::NAMES.to_vec()),
        ("MODELS", Model::NAMES.to_vec()),
        ("HIGHLIGHTS", Highlight::NAMES.to_vec()),
        ("DITHER_PATTERNS", DitherPattern::NAMES.to_vec()),
        ("DITHER_SPACES", DitherSpace::NAMES.to_vec()),
        ("SHADOW_FILTERS", ShadowFilter::NAMES.to_vec()),
        ("HATCH_MODES", effects::hatching::HatchMode::NAMES.to_vec()),
        ("BACKENDS", BackendChoice::NAMES.to_vec()),
        ("UP_AXES", scene::up::Axis::NAMES.to_vec()),
        ("SMOOTH_METHODS", smooth::METHODS.map(|(n, _)| n).to_vec()),
        ("SMOOTH_WEIGHTS", smooth::WEIGHTS.map(|(n, _)| n).to_vec()),
        ("SMOOTH_BOUNDARIES", smooth::BOUNDARIES.map(|(n, _)| n).to_vec()),
        ("SMOOTH_PRESETS", smooth::PRESETS.map(|(n, _)| n).to_vec()),
    ]
}
pub use graph::report::{FrameReport, Polyline};
pub use renderer::{Image, ImageMut, OutputBuffers, RenderOutput, Renderer, ViewImages};

#[cfg(test)]
mod albedo_gpu_tests;
#[cfg(test)]
mod effect_combinations_tests;
#[cfg(test)]
mod gpu_tests;
#[cfg(test)]
mod layout_tests;

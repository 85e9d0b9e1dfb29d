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
pub mod device;
pub mod effects;
pub mod gpu_albedo;
pub mod gpu_mesh;
pub mod graph;
pub mod hatch_field;
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
pub mod uniforms;
pub mod wgsl;

pub use device::{BackendChoice, GpuInfo};
pub use graph::report::{FrameReport, Polyline};
pub use renderer::{Image, ImageMut, OutputBuffers, RenderOutput, Renderer};

#[cfg(test)]
mod albedo_gpu_tests;
#[cfg(test)]
mod gpu_tests;
#[cfg(test)]
mod layout_tests;

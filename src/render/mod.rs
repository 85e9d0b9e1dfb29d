//! Headless toon rendering with wgpu. A scene (plain data: meshes by id, camera, lights,
//! materials, outlines) and a frame spec become a plan of passes (`plan`), recorded as one frame
//! on a process-wide device (`context`) and read back straight into the caller's arrays.
//!
//! Layers, each using only those above it: `color`, `scene` (plain data) and `device`; then
//! `gpu_mesh`, `culling`, `pipelines`, `uniforms` and `wgsl`; then `graph` (targets, resources, the pass
//! trait) and `context`; then `passes`; then `plan`; then `mesh_lines` and `renderer`.

pub mod color;
pub mod context;
pub mod culling;
pub mod device;
pub mod gpu_mesh;
pub mod graph;
pub mod image_out;
pub mod mesh_lines;
pub mod passes;
pub mod pipelines;
pub mod plan;
pub mod reference;
pub mod renderer;
pub mod scene;
pub mod uniforms;
pub mod wgsl;

pub use device::{BackendChoice, GpuInfo};
pub use renderer::{FrameReport, OutputBuffers, Polyline, RenderOutput, Renderer};

#[cfg(test)]
mod gpu_tests;

//! Headless toon rendering with wgpu: a scene of meshes, a camera and lights becomes the list
//! of passes it needs (`plan`), which run on a process-wide GPU context (`context`) and are
//! read back to host memory (`readback`).

pub mod camera;
pub mod color;
pub mod context;
pub mod gpu_mesh;
pub mod image_out;
pub mod light;
pub mod material;
pub mod passes;
pub mod pipelines;
pub mod plan;
pub mod readback;
pub mod reference;
pub mod renderer;
pub mod scene;
pub mod targets;
pub mod uniforms;

pub use context::{BackendChoice, GpuInfo};
pub use renderer::{RenderOutput, Renderer};

#[cfg(test)]
mod gpu_tests;

//! Frame effects: what a scene setting adds to a frame beyond shading each mesh (shadows,
//! outlines). Each is a folder under `render::effects` with its settings, its passes and their
//! WGSL, its frame uniform block, its host steps and its CPU reference, registered in one list
//! (`effects::frame::FRAME`). The plan asks each for its steps; the renderer runs them without
//! knowing which effect they come from.

use std::sync::Arc;

use crate::error::Result;
use crate::render::block::BlockLayout;
use crate::render::mesh_record::MeshRecord;
use crate::render::pipelines::Layouts;
use crate::render::scene::camera::{ResolvedCamera, Sphere};
use crate::render::scene::checked::CheckedScene;
use crate::render::scene::Output;

use super::report::FrameReport;
use super::target::{GeometryLayout, Shape, Target, Use};
use super::{FrameCtx, Pass};

/// What a frame effect plans from.
pub struct PlanInputs<'a> {
    pub scene: &'a CheckedScene,
    /// The layout of the geometry target the frame has, if it has one.
    pub geometry: Option<GeometryLayout>,
}

/// What a frame effect's uniform block is computed from.
pub struct FrameInputs<'a> {
    pub scene: &'a CheckedScene,
    pub cam: &'a ResolvedCamera,
    /// What the scene's meshes fill (world space).
    pub sphere: Sphere,
}

/// What a host step works from.
pub struct HostInputs<'a> {
    pub scene: &'a CheckedScene,
    pub cam: &'a ResolvedCamera,
    /// The scene's meshes, in the order of its items.
    pub records: &'a [Arc<MeshRecord>],
    /// The frame's linear depth in normalised view units (after the frame, when a step asked
    /// for it with `Steps::host_depth`).
    pub depth: Option<&'a [f32]>,
}

/// A step of a frame that runs on the host: before the frame is recorded, or after it is read
/// back. Timed by the wall clock under its name.
pub trait HostStep: std::fmt::Debug + Send + Sync {
    fn name(&self) -> &'static str;
    fn run(&self, cx: &HostInputs<'_>, report: &mut FrameReport) -> Result<()>;
}

/// Shading code a frame effect swaps in for every mesh (the light's visibility in shadows):
/// WGSL that implements the hooks `wgsl::DEFAULT_HOOKS` implements by default, its bind group
/// (group 2 of the pipelines that use it), and its pipeline constants.
pub trait ShadeHook: std::fmt::Debug + Send + Sync {
    /// A name for the shader modules built with it.
    fn name(&self) -> &'static str;
    fn wgsl(&self) -> &'static str;
    fn constants(&self) -> Vec<(&'static str, f64)>;
    /// The bits of the pipeline variants it makes.
    fn key(&self) -> u64;
    fn layout<'a>(&self, layouts: &'a Layouts) -> &'a wgpu::BindGroupLayout;
    fn bind_group(&self, f: &FrameCtx<'_>) -> wgpu::BindGroup;
    /// The targets its bind group reads.
    fn uses(&self) -> Vec<Use>;
}

/// A target copied back to the host at the end of the frame, for the outputs it holds.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct ReadbackRequest {
    pub name: &'static str,
    pub target: Target,
    pub output: Output,
}

/// What the frame effects add to a frame, gathered while it is planned.
#[derive(Debug, Default)]
pub struct Steps {
    pub shape: Shape,
    /// Passes before the meshes are shaded (a shadow map), and after (masks, ink), in order.
    pub before: Vec<Box<dyn Pass>>,
    pub after: Vec<Box<dyn Pass>>,
    /// Targets to read back besides the core outputs.
    pub readbacks: Vec<ReadbackRequest>,
    /// Host steps before the frame is recorded, and after it is read back.
    pub host_before: Vec<Box<dyn HostStep>>,
    pub host_after: Vec<Box<dyn HostStep>>,
    /// What the shading swaps in.
    pub shade_hook: Option<Arc<dyn ShadeHook>>,
    /// The host steps after the frame read its depth.
    pub host_depth: bool,
    /// Whether a pass already wrote (and so cleared) the outline coverage.
    pub outline_written: bool,
    /// Passes right after the glass is composited, where the frame has glass (the glass's own
    /// ink, drawn over it).
    pub over_glass: Vec<Box<dyn Pass>>,
}

pub trait FrameEffect: Sync {
    /// Its field in the WGSL `Frame` struct.
    fn name(&self) -> &'static str;
    /// WGSL every shader includes: its frame block struct and the constants its passes share
    /// with Rust.
    fn block_wgsl(&self) -> String;
    fn block(&self) -> BlockLayout;
    /// Its frame block (zeros where the scene does not use it).
    fn frame_block(&self, cx: &FrameInputs<'_>) -> Vec<u8>;
    /// Refuses outputs the scene cannot give for lack of this effect's settings.
    fn check(&self, scene: &CheckedScene) -> Result<()>;
    /// The geometry target its passes read, if the frame runs them.
    fn geometry(&self, scene: &CheckedScene) -> Option<GeometryLayout>;
    /// Its steps for the frame.
    fn plan(&self, cx: &PlanInputs<'_>, steps: &mut Steps);
    /// Whether its passes after shading lay over the glass (`passes::glass`) rather than under
    /// it, as ink does.
    fn over_glass(&self) -> bool {
        false
    }
}

//! The passes every frame may run, whatever its effects: shading the meshes (`shade`), the
//! geometry target where shading cannot write it (`geometry`), supersampling's filter
//! (`downsample`), clearing a target no pass draws (`clear`) and the readbacks. Each is a module
//! with its WGSL beside it; `render::plan` decides which run. The passes of frame effects
//! live with them in `render::effects`.

pub mod clear;
pub mod downsample;
pub mod geometry;
pub mod glass;
pub mod readback;
pub mod shade;

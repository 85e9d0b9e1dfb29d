//! Effects: what a scene's settings add to plain shading. Each is a folder with its typed
//! settings, its uniform block, its WGSL and its CPU reference, registered in one list.
//!
//! - Per-pixel (surface) effects (`surface`: hatching, dithering, rim light) are carried by a material and
//!   compiled into the shading pipeline through hooks; they add no pass.
//! - Frame effects (`frame`: shadows, eye-dome lighting, outlines, paper) add passes and host steps to the frame
//!   (`graph::effect::FrameEffect`).

pub mod dither;
pub mod eye_dome;
pub mod frame;
pub mod hatching;
pub mod outlines;
pub mod paper;
pub mod rim;
pub mod scene_settings;
pub mod shadows;
pub mod surface;
pub mod surface_effect;

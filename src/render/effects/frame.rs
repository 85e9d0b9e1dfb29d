//! The registry of frame effects (`graph::effect::FrameEffect`): the one list the plan, the
//! frame's uniforms and the shaders' preamble take them from, in the order their passes run.

use crate::error::Result;
use crate::render::block::Block;
use crate::render::graph::effect::{FrameEffect, FrameInputs};
use crate::render::scene::checked::CheckedScene;
use crate::render::uniforms::{lighting_block, view_block, LightingBlock, Members, ViewBlock};

use super::{eye_dome, outlines, paper, shadows};

/// Every frame effect.
pub static FRAME: &[&dyn FrameEffect] =
    &[&shadows::EFFECT, &eye_dome::EFFECT, &outlines::EFFECT, &paper::EFFECT];

/// The members of `Frame`: the view's and the lights' blocks, then every frame effect's.
pub fn frame_members() -> Members {
    let mut m = vec![("view", ViewBlock::layout()), ("lighting", LightingBlock::layout())];
    m.extend(FRAME.iter().map(|e| (e.name(), e.block())));
    m
}

/// The frame's uniforms: `Frame`, as bytes.
pub fn frame_bytes(cx: &FrameInputs<'_>) -> Vec<u8> {
    let f = &cx.scene.frame;
    let mut bytes = view_block(cx.cam, f).bytes();
    bytes.extend(lighting_block(cx.scene, cx.cam).bytes());
    for e in FRAME {
        bytes.extend(e.frame_block(cx));
    }
    bytes
}

/// Refuses outputs the scene's effects cannot give.
pub fn check(scene: &CheckedScene) -> Result<()> {
    FRAME.iter().try_for_each(|e| e.check(scene))
}

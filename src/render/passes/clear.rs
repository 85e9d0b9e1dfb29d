//! Clears a target that the frame returns but no pass of it draws into.

use crate::error::Result;
use crate::render::graph::target::{Access, Target, Use};
use crate::render::graph::{cleared, FrameCtx, Pass, Recorder};

#[derive(Debug, Clone, PartialEq)]
pub struct Clear {
    pub name: &'static str,
    pub target: Target,
    pub value: wgpu::Color,
}

impl Pass for Clear {
    fn name(&self) -> &'static str {
        self.name
    }

    fn uses(&self) -> Vec<Use> {
        vec![Use(self.target, Access::Attach)]
    }

    fn encode(&self, f: &FrameCtx<'_>, rec: &mut Recorder<'_>) -> Result<()> {
        rec.begin(self.name, &[cleared(f.res.view(self.target), self.value)], None);
        Ok(())
    }
}

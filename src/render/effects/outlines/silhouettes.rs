//! The `silhouettes` step: every item's mesh-space lines for this view (`mesh_lines`), with the
//! intersection lines the `intersections` step found, then the scene's `Lines` items, cut by
//! the exact rule where it is the scene's (`occluded`), as the line instances the lines pass
//! draws. A scene whose outlines draw no mesh-space lines runs it for its `Lines` items alone,
//! as `item_lines`.

use crate::error::Result;
use crate::render::graph::effect::{HostInputs, HostStep};
use crate::render::graph::report::FrameReport;

use super::intersection_lines::IntersectionSlot;
use super::mesh_lines::{
    chains, instances, reference_depth, scene_outlines, set_chains, Chain, LineDraw, ViewLines, ViewSlot,
};
use super::occluded;
use super::projection::Projector;
use super::settings::{Outlines, VisibilityRule};

/// The `silhouettes` step: every item's lines for this view.
#[derive(Debug)]
pub struct Silhouettes {
    pub outlines: Outlines,
    pub view: ViewSlot,
    /// The `intersections` step's lines, where it runs.
    pub intersections: Option<IntersectionSlot>,
}

impl HostStep for Silhouettes {
    fn name(&self) -> &'static str {
        if self.outlines.draws_mesh_lines() {
            "silhouettes"
        } else {
            "item_lines"
        }
    }

    fn run(&self, cx: &HostInputs<'_>, _report: &mut FrameReport) -> Result<()> {
        let mut lines = ViewLines::default();
        let frame = &cx.scene.frame;
        let items = &cx.scene.scene.items;
        let by_depth = self.outlines.stroke_width.by_depth;
        let reference = if by_depth { reference_depth(items, cx.records, cx.cam) } else { 1.0 };
        let mut found: Vec<Vec<Chain>> = if self.outlines.draws_mesh_lines() {
            let outlines =
                scene_outlines(items, cx.records, cx.cam, &self.outlines, cx.scene.sequence.as_ref())?;
            outlines.iter().zip(cx.records).map(|(o, rec)| chains(o, &rec.host.positions)).collect()
        } else {
            vec![Vec::new(); items.len()]
        };
        if let Some(crossing) = self.intersections.as_ref().and_then(|slot| slot.get()) {
            for (of_item, lines) in found.iter_mut().zip(crossing) {
                of_item.extend(lines.iter().cloned());
            }
        }
        let mut projectors: Vec<Projector> = items
            .iter()
            .zip(cx.records)
            .map(|(item, rec)| Projector::of(item, &rec.gpu.placement, cx.cam, frame.width, frame.height))
            .collect();
        // the `Lines` items' lines, in view coordinates
        for set in set_chains(&cx.scene.scene.lines, cx.cam) {
            found.push(set);
            projectors.push(Projector::in_view(cx.cam, frame.width, frame.height));
        }
        if self.outlines.visibility == VisibilityRule::Exact {
            found = occluded::cut(
                found,
                (cx.records, &cx.scene.glass),
                &projectors,
                cx.cam.orthographic,
                &self.outlines,
            )?;
        }
        for (i, (chains, projector)) in found.into_iter().zip(&projectors).enumerate() {
            let first = lines.instances.len() as u32;
            lines.instances.extend(instances(&chains, projector, &self.outlines.stroke_width, reference));
            // a `Lines` item's points are in view coordinates: any draw's uniforms do
            let item = if i < items.len() { i } else { 0 };
            lines.draws.push(LineDraw { item, instances: first..lines.instances.len() as u32 });
            lines.chains.push(chains);
        }
        // a slot is filled once per frame
        let _ = self.view.set(lines);
        Ok(())
    }
}

//! Ink outlines: mesh-space lines (Kang, Kim and Yoon: silhouettes per view, boundaries,
//! creases and non-manifold edges per mesh; `lines` with its host steps in `mesh_lines` and
//! `visibility`) and image-space edges (Borquez and Yepez: Sobel on the normal and depth
//! buffers; `edges`), drawn over the colour and/or into the outline coverage (`ink`).

pub mod edge_bits;
pub mod edges;
pub mod edges_reference;
pub mod ink;
pub mod intersection_lines;
pub mod lines;
pub mod mesh_lines;
pub mod occluded;
pub mod pen;
pub mod projection;
pub mod settings;
pub mod shared_borders;
pub mod silhouettes;
pub mod stroke_width;
pub mod strokes;
pub mod visibility;

use std::sync::Arc;

use crate::edges::outlines::LineKind;
use crate::error::{Error, Result};
use crate::render::block::{Block, BlockLayout};
use crate::render::color::to_linear;
use crate::render::graph::effect::{FrameEffect, FrameInputs, PlanInputs, ReadbackRequest, Steps};
use crate::render::graph::target::{GeometryLayout, Target};
use crate::render::scene::checked::CheckedScene;
use crate::render::scene::Output;
use crate::render::wgsl;

use ink::Ink;
use settings::{IMAGE_KIND, INK_KINDS};

crate::uniform_block! {
    /// `frame.outlines`: how each kind of ink is drawn and the rules of both ink passes.
    pub struct OutlinesBlock as "OutlinesBlock" {
        /// Per ink kind: linear rgb, and the width in output pixels (0: not drawn).
        pub ink: [[f32; 4]; INK_KINDS],
        /// Hidden-line tolerance in pixel footprints (`Outlines::depth_offset`).
        pub depth_offset: f32,
        /// The paper rule's thresholds (`edges::detect`), the depth one in normalised units.
        pub normal_threshold: f32,
        pub depth_threshold: f32,
        /// The image-space rule: `ImageRule as u32`.
        pub image_rule: u32,
        /// The discontinuity rule's thresholds: cos of the normal angle, the depth jump in
        /// pixel footprints (`edges_reference::Discontinuity`).
        pub normal_cos: f32,
        pub depth_jump: f32,
        pub _pad0: f32,
        pub _pad1: f32,
        /// Per ink kind, four to a row: the dash length in output pixels (0: solid).
        pub dashes: [[f32; 4]; DASH_ROWS],
    }
}

/// Rows of `OutlinesBlock::dashes`.
pub const DASH_ROWS: usize = INK_KINDS.div_ceil(4);

pub struct OutlinesEffect;

pub static EFFECT: OutlinesEffect = OutlinesEffect;

/// The rules the line steps run under: the scene's outlines where they draw mesh-space lines;
/// for a scene with `Lines` items and no such outlines, its outlines' rules (visibility, hidden
/// lines; else the defaults) drawing no kind of mesh-space line, so that only the items' lines
/// are drawn; None: no line is drawn.
fn line_rules(scene: &CheckedScene) -> Option<settings::Outlines> {
    let outlines = scene.scene.outlines.as_ref();
    if outlines.is_some_and(settings::Outlines::draws_mesh_lines) {
        return outlines.cloned();
    }
    if scene.scene.lines.is_empty() {
        return None;
    }
    let mut rules = outlines.cloned().unwrap_or_default();
    rules.styles[..LineKind::COUNT].fill(None);
    Some(rules)
}

/// Whether the scene's lines are cut on the host (`VisibilityRule::Exact`), not against the
/// frame's depth.
fn exact(scene: &CheckedScene) -> bool {
    line_rules(scene).is_some_and(|o| o.visibility == settings::VisibilityRule::Exact)
}

/// What the scene draws: lines (mesh-space lines or `Lines` items), image-space edges. A point
/// cloud's ink is the image-space edges': a scene with one gets them even where the outlines
/// name mesh-space lines only (which its meshes keep).
fn draws(scene: &CheckedScene) -> (bool, bool) {
    let splats = scene.scene.items.iter().any(|item| item.splats);
    let outlines = scene.scene.outlines.as_ref();
    let mesh = outlines.is_some_and(settings::Outlines::draws_mesh_lines);
    let image = outlines.is_some_and(|o| o.draws_image_edges()) || (mesh && splats);
    (line_rules(scene).is_some(), image)
}

/// Whether the scene has anything mesh-space lines are found on: a mesh that is no point cloud's
/// splats, or a `Lines` item (a cloud alone has none, so its frame draws no lines pass).
fn line_sources(scene: &CheckedScene) -> bool {
    scene.scene.items.iter().any(|item| !item.splats) || !scene.scene.lines.is_empty()
}

impl FrameEffect for OutlinesEffect {
    fn name(&self) -> &'static str {
        "outlines"
    }

    fn block_wgsl(&self) -> String {
        let mut s = wgsl::constant_u32("INK_KINDS", INK_KINDS as u32);
        s += &wgsl::constant_u32("IMAGE_KIND", IMAGE_KIND as u32);
        s += &wgsl::constant_u32("DASH_ROWS", DASH_ROWS as u32);
        s += &wgsl::constant_u32("EXACT", mesh_lines::EXACT);
        s += &wgsl::constant_u32("OWN_INK", mesh_lines::OWN_INK);
        s += &wgsl::constant_u32("IN_VIEW", mesh_lines::IN_VIEW);
        s += &wgsl::constant_u32("RIM_KINDS", LineKind::RIM_BITS);
        s += &wgsl::constant_f32("DEPTH_EPSILON", visibility::DEPTH_EPSILON);
        s += &wgsl::constant_u32("IMAGE_RULE_PAPER", settings::ImageRule::Paper as u32);
        s + include_str!("block.wgsl")
    }

    fn block(&self) -> BlockLayout {
        OutlinesBlock::layout()
    }

    fn frame_block(&self, cx: &FrameInputs<'_>) -> Vec<u8> {
        let mut b: OutlinesBlock = bytemuck::Zeroable::zeroed();
        if let Some(o) = &cx.scene.scene.outlines {
            for (slot, style) in b.ink.iter_mut().zip(&o.styles) {
                if let Some(s) = style {
                    let c = to_linear(s.color);
                    *slot = [c[0], c[1], c[2], s.width];
                }
            }
            for (k, style) in o.styles.iter().enumerate() {
                b.dashes[k / 4][k % 4] = style.map_or(0.0, |s| s.dash);
            }
            b.depth_offset = o.depth_offset;
            b.normal_threshold = o.normal_threshold;
            b.depth_threshold = (o.depth_threshold as f64 / cx.cam.scale) as f32;
            b.image_rule = o.image_rule as u32;
            b.normal_cos = (o.normal_angle as f64).to_radians().cos() as f32;
            b.depth_jump = o.depth_jump;
        }
        b.bytes()
    }

    fn check(&self, scene: &CheckedScene) -> Result<()> {
        let o = scene.frame.outputs;
        if o.has(Output::Outline) && scene.scene.outlines.is_none() {
            return Err(Error::invalid(
                "outputs",
                "'outline' needs outlines (outlines='mesh', 'image' or 'both')",
            ));
        }
        if o.has(Output::Lines) && !draws(scene).0 {
            return Err(Error::invalid(
                "outputs",
                "'lines' needs mesh-space outlines (outlines='mesh' or 'both', with some kind of line drawn) \
                 or a toonmesh.Lines item",
            ));
        }
        Ok(())
    }

    fn geometry(&self, scene: &CheckedScene) -> Option<GeometryLayout> {
        let o = scene.frame.outputs;
        let ink = o.has(Output::Color) || o.has(Output::Outline);
        let (mesh, image) = draws(scene);
        if image && ink {
            Some(GeometryLayout::NormalDepth)
        } else if mesh && ((ink && line_sources(scene)) || (o.has(Output::Lines) && !exact(scene))) {
            Some(GeometryLayout::Depth)
        } else {
            None
        }
    }

    fn plan(&self, cx: &PlanInputs<'_>, steps: &mut Steps) {
        let rules = line_rules(cx.scene);
        let Some(outlines) = cx.scene.scene.outlines.as_ref().or(rules.as_ref()) else { return };
        let o = cx.scene.frame.outputs;
        let (color, outline) = (o.has(Output::Color), o.has(Output::Outline));
        let (mesh, image) = draws(cx.scene);
        let ink = |steps: &mut Steps| {
            let clear_outline = outline && !steps.outline_written;
            steps.outline_written |= outline;
            Ink { color, outline, clear_outline }
        };
        if image && (color || outline) {
            let ink = ink(steps);
            if outlines.image_rule == settings::ImageRule::Discontinuity {
                steps.after.push(Box::new(edge_bits::EdgeBits));
            }
            steps.after.push(Box::new(edges::Edges { ink, rule: outlines.image_rule }));
        }
        let lines = mesh && (color || outline) && line_sources(cx.scene);
        let visible = mesh && o.has(Output::Lines);
        if let Some(outlines) = rules.as_ref().filter(|_| lines || visible) {
            let view = Arc::default();
            let crossing = outlines.styles[LineKind::Intersection as usize].is_some()
                && cx.scene.scene.items.iter().filter(|item| !item.splats).count() > 1;
            let intersections = crossing.then(|| {
                let found = intersection_lines::IntersectionSlot::default();
                steps
                    .host_before
                    .push(Box::new(intersection_lines::Intersections { found: Arc::clone(&found) }));
                found
            });
            steps.host_before.push(Box::new(silhouettes::Silhouettes {
                outlines: outlines.clone(),
                view: Arc::clone(&view),
                intersections,
            }));
            if lines {
                let layout = cx.geometry.expect("mesh-space lines are tested against the frame's depth");
                let under = ink(steps);
                let view = Arc::clone(&view);
                if cx.scene.has_glass() {
                    // the opaque items' ink under the glass, the glass's own over it
                    let over = ink(steps);
                    let glass =
                        lines::Lines { ink: over, layout, view: Arc::clone(&view), glass: Some(true) };
                    steps.after.push(Box::new(lines::Lines { ink: under, layout, view, glass: Some(false) }));
                    steps.over_glass.push(Box::new(glass));
                } else {
                    steps.after.push(Box::new(lines::Lines { ink: under, layout, view, glass: None }));
                }
            }
            if visible {
                let exact = exact(cx.scene);
                steps.host_depth |= !exact;
                steps.host_after.push(Box::new(visibility::VisibleLines {
                    depth_offset: outlines.depth_offset,
                    gaps: strokes::gaps(outlines),
                    widths: strokes::widths(outlines),
                    join_kinds: outlines.join_kinds,
                    exact,
                    view,
                }));
            }
        }
        if outline {
            if !steps.outline_written {
                // outlines that draw nothing here: the coverage is empty
                steps.after.push(Box::new(crate::render::passes::clear::Clear {
                    name: "clear_outline",
                    target: Target::Outline,
                    value: wgpu::Color::TRANSPARENT,
                }));
                steps.outline_written = true;
            }
            steps.readbacks.push(ReadbackRequest {
                name: "readback_outline",
                target: Target::Outline,
                output: Output::Outline,
            });
        }
    }
}

//! The line pass's rules on the CPU: projecting a line to pixels (with the near plane), which
//! points of it are visible against a depth image, its ink coverage, and the visible runs of
//! lines as polylines (`RenderResult.lines`). The shader (`lines.wgsl`) follows the same rules;
//! tests hold its pixels against `coverage_image`.

use crate::edges::outlines::LineKind;
use crate::error::{Error, Result};
use crate::render::graph::effect::{HostInputs, HostStep};
use crate::render::graph::report::{FrameReport, Polyline};
use crate::render::scene::camera::ResolvedCamera;
use crate::render::uniforms::footprint;

use super::mesh_lines::{Chain, ViewSlot};
use super::projection::{Projector, ScreenLine};
use super::settings::{INK_KINDS, LINES_KIND};
use super::strokes::{drop_covered, join_runs, MIN_JOIN_GAP};

/// The relative depth tolerance of the visibility test (float rounding of the line's own depth).
pub const DEPTH_EPSILON: f64 = 1e-5;

/// A depth image: (H, W) linear depths, +inf (any non-finite value) where no surface is.
pub struct DepthImage<'a> {
    pub depth: &'a [f32],
    pub width: usize,
    pub height: usize,
}

/// The hidden-line rule.
#[derive(Clone, Copy, Debug)]
pub struct Visibility {
    /// Offset in pixel footprints.
    pub offset: f64,
    /// A pixel's footprint at depth z is `footprint.0 * z + footprint.1`.
    pub footprint: (f64, f64),
}

impl Visibility {
    /// The rule of a frame seen by `cam`, `height` pixels high (depths in normalised view units).
    pub fn of(depth_offset: f32, cam: &ResolvedCamera, height: u32) -> Self {
        Visibility { offset: depth_offset as f64, footprint: footprint(cam, height) }
    }

    /// Whether the point at pixel position `c`, depth `z`, of a line of kind `kind` is visible:
    /// its depth is at most the largest surface depth in the 3x3 pixels around it plus `offset`
    /// footprints (plus `DEPTH_EPSILON` of itself). A line of a rim kind (`LineKind::on_rim`) with background
    /// among those pixels is on the rim and visible; other kinds are held against the surface
    /// pixels only, so a crease behind the rim stays hidden. No surface around: visible.
    pub fn visible(&self, img: &DepthImage<'_>, c: [f64; 2], z: f64, kind: usize) -> bool {
        let rim = LineKind::on_rim(kind);
        let (qx, qy) = (c[0].floor() as i64, c[1].floor() as i64);
        let mut far: Option<f64> = None;
        for j in -1..=1 {
            for i in -1..=1 {
                let x = (qx + i).clamp(0, img.width as i64 - 1) as usize;
                let y = (qy + j).clamp(0, img.height as i64 - 1) as usize;
                let d = img.depth[y * img.width + x];
                if !d.is_finite() {
                    if rim {
                        return true;
                    }
                } else {
                    far = Some(far.unwrap_or(0.0).max(d as f64));
                }
            }
        }
        let footprint = z * self.footprint.0 + self.footprint.1;
        far.is_none_or(|far| z <= far + self.offset * footprint + z * DEPTH_EPSILON)
    }
}

/// How much of a dashed line is inked at `along` pixels along its stroke, with dashes `dash`
/// pixels long and gaps as long, the first dash from 0: 1 on a dash, 0 in a gap, antialiased
/// over a pixel at their ends; 1 everywhere where `dash` is 0. `lines.wgsl`'s `dashed`.
pub fn dashed(along: f64, dash: f64) -> f64 {
    if dash <= 0.0 {
        return 1.0;
    }
    let period = 2.0 * dash;
    let c = along - dash / 2.0;
    let w = c - period * (c / period + 0.5).floor();
    (dash / 2.0 + 0.5 - w.abs()).clamp(0.0, 1.0)
}

/// Ink coverage of every pixel by `lines` (widths and dash lengths in pixels per kind; a
/// `Lines` item's own width, solid), 0 where hidden (lines decided on the host,
/// `ScreenLine::exact`, are not tested): what the line pass writes into the outline output.
pub fn coverage_image(
    lines: &[ScreenLine],
    (widths, dashes): (&[f32], &[f32]),
    orthographic: bool,
    img: &DepthImage<'_>,
    rule: Visibility,
) -> Vec<f32> {
    let (w, h) = (img.width, img.height);
    let mut out = vec![0.0f32; w * h];
    for l in lines {
        let width = l.own_width.unwrap_or(widths[l.kind] as f64);
        let dash = if l.own_width.is_some() { 0.0 } else { dashes[l.kind] as f64 };
        let reach = width * l.scale[0].max(l.scale[1]) / 2.0 + 1.0;
        let x0 = (l.a[0].min(l.b[0]) - reach).floor().max(0.0) as usize;
        let y0 = (l.a[1].min(l.b[1]) - reach).floor().max(0.0) as usize;
        let x1 = ((l.a[0].max(l.b[0]) + reach).ceil().max(0.0) as usize).min(w);
        let y1 = ((l.a[1].max(l.b[1]) + reach).ceil().max(0.0) as usize).min(h);
        let ab = [l.b[0] - l.a[0], l.b[1] - l.a[1]];
        let l2 = ab[0] * ab[0] + ab[1] * ab[1];
        for y in y0..y1 {
            for x in x0..x1 {
                let p = [x as f64 + 0.5, y as f64 + 0.5];
                let t = if l2 > 0.0 {
                    (((p[0] - l.a[0]) * ab[0] + (p[1] - l.a[1]) * ab[1]) / l2).clamp(0.0, 1.0)
                } else {
                    0.0
                };
                let (c, z) = l.at(t, orthographic);
                let here = width * l.factor(t);
                let cov = (here / 2.0 + 0.5 - (p[0] - c[0]).hypot(p[1] - c[1])).clamp(0.0, 1.0)
                    * dashed(l.along_at(t), dash);
                if cov > 0.0 && (l.exact || rule.visible(img, c, z, l.kind)) {
                    let o = &mut out[y * w + x];
                    *o = o.max(cov as f32);
                }
            }
        }
    }
    out
}

/// Visible runs shorter than this many pixels are dropped from the polylines: where a hidden
/// line leaves a visible vertex, its first half pixel is visible too.
pub const MIN_RUN: f64 = 1.0;

/// The visible parts of a chain of lines (each starting where the last ended) as polylines in
/// pixel coordinates, with the ink's width at each point (`width` pixels times the line's factor
/// there, as `coverage_image` draws it): visibility is sampled every half pixel (lines decided
/// on the host, `ScreenLine::exact`, are visible wherever they are on the image), a run keeps the
/// points where it starts and stops and the ends of the lines it passes, runs are cut to the
/// image, and runs shorter than `MIN_RUN` pixels are left out.
pub fn visible_runs(
    chain: &[ScreenLine],
    orthographic: bool,
    img: &DepthImage<'_>,
    rule: Visibility,
    width: f64,
) -> Vec<Polyline> {
    let (w, h) = (img.width as f64, img.height as f64);
    let kind = chain.first().map_or(0, |l| l.kind);
    let mut runs = Vec::new();
    let mut current = Polyline { kind, points: Vec::new(), widths: Vec::new() };
    let mut close = |current: &mut Polyline| {
        let p = &current.points;
        let length: f64 = p.windows(2).map(|w| (w[1][0] - w[0][0]).hypot(w[1][1] - w[0][1])).sum();
        let run = Polyline {
            kind,
            points: std::mem::take(&mut current.points),
            widths: std::mem::take(&mut current.widths),
        };
        if length >= MIN_RUN {
            runs.push(run);
        }
    };
    let push = |current: &mut Polyline, (p, f): ([f64; 2], f64)| {
        if current.points.last() != Some(&p) {
            current.points.push(p);
            current.widths.push(width * f);
        }
    };
    for (i, l) in chain.iter().enumerate() {
        // a gap between lines (one cut by the near plane) ends the run
        if i > 0 && chain[i - 1].b != l.a {
            close(&mut current);
        }
        let n = (l.length() / 0.5).ceil().max(1.0) as usize;
        // a run's points: where it starts, the ends of lines it passes, and where it stops
        let mut last_visible: Option<([f64; 2], f64)> = None;
        for s in 0..=n {
            let t = s as f64 / n as f64;
            let (p, z) = l.at(t, orthographic);
            let inside = (0.0..=w).contains(&p[0]) && (0.0..=h).contains(&p[1]);
            let here = (p, l.factor(t));
            if inside && z > 0.0 && (l.exact || rule.visible(img, p, z, l.kind)) {
                if current.points.is_empty() || s == n {
                    push(&mut current, here);
                }
                last_visible = Some(here);
            } else {
                if let Some(q) = last_visible {
                    push(&mut current, q);
                }
                last_visible = None;
                close(&mut current);
            }
        }
    }
    close(&mut current);
    runs
}

/// The `visible_lines` step: the view's lines, chained per kind and mesh, cut to their visible
/// runs against the frame's depth, and runs of a kind that meet (within `gaps`) joined into
/// strokes, short ones covered by a longer line left out (`RenderResult.lines`).
#[derive(Debug)]
pub struct VisibleLines {
    pub depth_offset: f32,
    /// Runs of one kind whose ends are this close (pixels) are joined (`strokes::join_runs`).
    pub gaps: [f64; INK_KINDS],
    /// Each kind's width in pixels (`strokes::widths`).
    pub widths: [f64; INK_KINDS],
    /// Join strokes of different kinds too (`Outlines::join_kinds`).
    pub join_kinds: bool,
    /// The lines were cut on the host (`VisibilityRule::Exact`): the frame's depth is not read.
    pub exact: bool,
    pub view: ViewSlot,
}

impl HostStep for VisibleLines {
    fn name(&self) -> &'static str {
        "visible_lines"
    }

    fn run(&self, cx: &HostInputs<'_>, report: &mut FrameReport) -> Result<()> {
        let frame = &cx.scene.frame;
        // lines decided on the host never read it
        let none = [];
        let depth = cx.depth.map_or_else(
            || {
                if self.exact {
                    Ok(&none[..])
                } else {
                    Err(Error::Internal("visible lines without the frame's depth".into()))
                }
            },
            Ok,
        )?;
        let view = self
            .view
            .get()
            .ok_or_else(|| Error::Internal("visible lines without the view's lines".into()))?;
        let rule = Visibility::of(self.depth_offset, cx.cam, frame.height);
        let img = DepthImage { depth, width: frame.width as usize, height: frame.height as usize };
        let (mut out, mut of_item) = (Vec::new(), Vec::new());
        let items = &cx.scene.scene.items;
        for (i, (chains, draw)) in view.chains.iter().zip(&view.draws).enumerate() {
            // the meshes' lines, then each `Lines` item's (in view coordinates)
            let set = i.checked_sub(items.len());
            let projector = match set {
                None => {
                    Projector::of(&items[i], &cx.records[i].gpu.placement, cx.cam, frame.width, frame.height)
                }
                Some(_) => Projector::in_view(cx.cam, frame.width, frame.height),
            };
            // each chain's segments, in order, are the item's line instances (with their widths)
            let mut instances =
                view.instances[draw.instances.start as usize..draw.instances.end as usize].iter();
            let mut runs = Vec::new();
            for c in chains {
                let kind = c.ink();
                let screen: Vec<_> = c
                    .points
                    .windows(2)
                    .zip(instances.by_ref())
                    .filter_map(|(s, line)| {
                        let seen = projector.project(s[0], s[1], kind)?;
                        let exact = c.occlusion.is_some();
                        Some(ScreenLine { scale: line.line.scale.map(f64::from), exact, ..seen })
                    })
                    .collect();
                let width = if kind == LINES_KIND { c.own_width() } else { self.widths[kind] };
                runs.extend(visible_runs(&screen, cx.cam.orthographic, &img, rule, width));
            }
            let strokes = match set {
                None => {
                    let gap = |k: usize| self.gaps[k];
                    let strokes = drop_covered(join_runs(runs, true, gap), gap);
                    if self.join_kinds {
                        join_runs(strokes, false, gap)
                    } else {
                        strokes
                    }
                }
                // the user's own lines are drawn whole: joined where they meet, never dropped
                Some(_) => {
                    let own = chains.first().map_or(0.0, Chain::own_width);
                    let gap = |k: usize| if k == LINES_KIND { own.max(MIN_JOIN_GAP) } else { self.gaps[k] };
                    join_runs(runs, true, gap)
                }
            };
            of_item.extend(strokes.iter().map(|_| set));
            out.extend(strokes);
        }
        report.lines = Some(out);
        report.line_items = Some(of_item);
        report.line_inks = cx.scene.line_inks().iter().map(|s| (s.color, s.width)).collect();
        Ok(())
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_line_in_front_shows_and_one_behind_hides() {
        let depth = vec![2.0f32; 16 * 16];
        let img = DepthImage { depth: &depth, width: 16, height: 16 };
        let rule = Visibility { offset: 1.0, footprint: (0.01, 0.0) };
        assert!(rule.visible(&img, [8.0, 8.0], 2.0, 0), "on the surface");
        assert!(rule.visible(&img, [8.0, 8.0], 2.01, 0), "within a footprint");
        assert!(!rule.visible(&img, [8.0, 8.0], 2.1, 0), "behind it");
        // at the rim: a silhouette shows, a crease behind the surface does not
        let mut rim = depth.clone();
        rim[8 * 16 + 9] = f32::INFINITY;
        let rim_img = DepthImage { depth: &rim, width: 16, height: 16 };
        assert!(rule.visible(&rim_img, [8.0, 8.0], 3.0, LineKind::Silhouette as usize));
        assert!(!rule.visible(&rim_img, [8.0, 8.0], 3.0, LineKind::Ridge as usize));
        let line = ScreenLine {
            a: [2.0, 8.5],
            b: [14.0, 8.5],
            za: 2.0,
            zb: 2.0,
            kind: 0,
            scale: [1.0; 2],
            along: [0.0, 12.0],
            exact: false,
            own_width: None,
        };
        let cov = coverage_image(&[line], (&[1.5], &[0.0]), false, &img, rule);
        assert_eq!(cov[8 * 16 + 8], 1.0);
        assert!(cov[7 * 16 + 8] > 0.0 && cov[5 * 16 + 8] == 0.0);
        let hidden = ScreenLine { za: 3.0, zb: 3.0, ..line };
        assert!(coverage_image(&[hidden], (&[1.5], &[0.0]), false, &img, rule).iter().all(|&c| c == 0.0));
        // decided on the host: drawn whatever the depth says
        let decided = ScreenLine { exact: true, ..hidden };
        assert_eq!(coverage_image(&[decided], (&[1.5], &[0.0]), false, &img, rule), cov);
        // dashed 3 pixels on, 3 off from x = 2: ink at x = 3.5, none at 6.5, ink at 9.5
        let dashes = coverage_image(&[line], (&[1.5], &[3.0]), false, &img, rule);
        assert_eq!([dashes[8 * 16 + 3], dashes[8 * 16 + 6], dashes[8 * 16 + 9]], [1.0, 0.0, 1.0]);
        assert!((dashed(1.5, 3.0) - 1.0).abs() < 1e-12 && dashed(4.5, 3.0) == 0.0 && dashed(3.0, 3.0) == 0.5);
        let runs = visible_runs(&[line], false, &img, rule, 1.5);
        assert_eq!(runs.len(), 1);
        assert_eq!(runs[0].points.first(), Some(&[2.0, 8.5]));
        assert_eq!(runs[0].points.last(), Some(&[14.0, 8.5]));
        assert_eq!(runs[0].widths, vec![1.5, 1.5]);
        // a tapered line cut where a wall in front begins (x >= 9): the width at each point is
        // the factor there times the kind's width, where it stops too
        let mut wall = depth.clone();
        for row in wall.chunks_mut(16) {
            row[9..].fill(1.0);
        }
        let wall_img = DepthImage { depth: &wall, width: 16, height: 16 };
        let tapered = ScreenLine { scale: [0.2, 1.0], ..line };
        let runs = visible_runs(&[tapered], false, &wall_img, rule, 2.0);
        assert_eq!(runs.len(), 1);
        assert_eq!(runs[0].points, vec![[2.0, 8.5], [9.5, 8.5]]);
        let want = [0.4, 2.0 * (0.2 + 0.8 * 7.5 / 12.0)];
        assert!(runs[0].widths.iter().zip(want).all(|(w, x)| (w - x).abs() < 1e-12), "{:?}", runs[0].widths);
    }
}

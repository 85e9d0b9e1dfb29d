//! The exact rule in a frame (`VisibilityRule::Exact`): every item's lines cut where the
//! scene's surfaces hide them (`edges::occlusion`, against each mesh's hierarchy, kept with it),
//! the visible pieces drawn without the line pass's depth test and, where hidden lines are
//! asked for, the hidden ones in their own ink.

use std::sync::Arc;

use glam::DVec3;
use rayon::prelude::*;

use crate::edges::occlusion::{Occluders, Surface};
use crate::error::Result;
use crate::mesh::bvh::Bvh;
use crate::render::mesh_record::MeshRecord;

use super::mesh_lines::{largest_stretch, Chain, MeshLines};
use super::projection::Projector;
use super::settings::Outlines;

/// Visibility is sampled along a line on screen (whatever its segments' lengths) every line
/// width, and at least every this many pixels, and bisected between: a hidden stretch shorter
/// than the line is wide lies under the round ends of the ink on either side of it anyway.
pub const SAMPLE_SPACING: f64 = 1.0;
/// Pieces cut shorter than this many pixels are left out (a line grazing past an occluder's
/// corner between two samples).
pub const MIN_PIECE: f64 = 0.5;

/// `chains` (each item's, in its stored coordinates; then each `Lines` item's, seen by the
/// projectors after the meshes') cut into visible pieces and, where
/// `outlines` draws hidden lines, hidden ones (within `max_occlusion`), hidden first; each
/// piece keeps its kind and strength and carries its occlusion. Items that are `glass` hide
/// nothing.
pub fn cut(
    chains: Vec<Vec<Chain>>,
    (records, glass): (&[Arc<MeshRecord>], &[bool]),
    projectors: &[Projector],
    orthographic: bool,
    outlines: &Outlines,
) -> Result<Vec<Vec<Chain>>> {
    let hidden = outlines.draws_hidden();
    let limit = if hidden { outlines.max_occlusion.map_or(u32::MAX, |m| m.saturating_add(1)) } else { 1 };
    let lines = MeshLines::with_hierarchies(records);
    let bvhs: Vec<_> = lines.iter().zip(records).map(|(l, r)| l.bvh(&r.host)).collect();
    let surfaces = bvhs
        .iter()
        .zip(projectors)
        .zip(glass)
        .map(|((bvh, p), &glass)| Surface { bvh, from_view: p.model_view.inverse(), hides: !glass })
        .collect();
    let near = projectors.first().map_or(0.0, |p| p.near);
    let occluders = Occluders::new(surfaces, orthographic, near, scene_size(&bvhs, projectors));
    let cut_one = |item: usize, c: &Chain| -> Vec<Chain> {
        let p = &projectors[item];
        let view: Vec<DVec3> =
            c.points.iter().map(|q| p.model_view.transform_point3(DVec3::from_array(*q))).collect();
        let lengths: Vec<f64> =
            c.points.windows(2).map(|w| p.project(w[0], w[1], 0).map_or(0.0, |l| l.length())).collect();
        let width = c.width(outlines);
        let runs = occluders.runs(&view, item, c.traced, limit, (&lengths, width.max(SAMPLE_SPACING)));
        let whole = runs.len() == 1;
        // a run's length on screen, from the segments' (as `runs` measures along the line)
        let mut along = vec![0.0];
        for l in &lengths {
            along.push(along[along.len() - 1] + l);
        }
        let at = |(s, t): (usize, f64)| along[s] + t * lengths[s];
        runs.iter()
            .filter(|r| r.occlusion == 0 || (hidden && r.occlusion < limit))
            .filter(|r| whole || at(r.to) - at(r.from) >= MIN_PIECE)
            .map(|r| Chain {
                kind: c.kind,
                points: r.points(&c.points),
                strength: if c.strength.is_empty() {
                    Vec::new()
                } else {
                    r.values(&c.strength, |a, b, t| a + (b - a) * t)
                },
                traced: c.traced,
                occlusion: Some(r.occlusion),
                own: c.own,
            })
            .collect()
    };
    let out = crate::parallel::install(|| {
        chains
            .par_iter()
            .enumerate()
            .map(|(item, of_item)| {
                let mut pieces: Vec<Chain> = of_item.par_iter().flat_map_iter(|c| cut_one(item, c)).collect();
                // hidden lines under the visible ones
                pieces.sort_by_key(|c| c.occlusion == Some(0));
                pieces
            })
            .collect()
    });
    Ok(out)
}

/// The scene's size in view units: the largest diagonal of an item's box (its hierarchy's,
/// in the stored coordinates, stretched by the map to the view).
fn scene_size(bvhs: &[&Bvh], projectors: &[Projector]) -> f64 {
    bvhs.iter()
        .zip(projectors)
        .filter(|(b, _)| !b.is_empty())
        .map(|(b, p)| {
            let bounds = b.bounds();
            (bounds.hi - bounds.lo).length() * largest_stretch(&p.model_view)
        })
        .fold(0.0, f64::max)
}

//! Guidance normals (Zhang et al. 2015): for each face, the area-weighted mean normal of the
//! most consistent patch that contains it. A patch is a face with its vertex ring; candidates
//! for face i are the patches centred at i and at each face of its ring. A patch's
//! inconsistency is H = D R: D the largest |n_a - n_b| between two of its faces (see `spread`), R the largest
//! |n_a - n_b| across one of its inner edges over the sum across all of them (small when the
//! variation is spread out, as noise is, large when it is one crease through the patch).
//! A patch on one side of a crease is consistent; one across it is not, so guidance normals
//! keep creases sharp even where the noise is as strong as the feature.
//!
//! Patches, candidates, H and the guidance are the paper's, but for D's approximation (see
//! `spread`). The filter that uses the guidance (`bilateral::filter`) differs from the paper
//! where the held-out parts (`toonmesh.bench.held_out`, irregular meshes) measured it better,
//! at 20,000 faces and Gaussian noise 0.3 / 0.7 of the mean edge length:
//! - its neighbourhood is the face's vertex ring, not the faces within twice the mean distance
//!   between adjacent centroids: that radius raised the sharp sphere's errors from 4.4 / 7.2
//!   to 4.9 / 8.9 degrees and the chamfered box's from 3.5 / 5.9 to 4.0 / 7.0;
//! - `sigma_s` is in mean edge lengths, not the mean distance between adjacent centroids (about
//!   0.6 of an edge), and `sigma_r` follows the measured noise (`noise`) where the authors'
//!   code defaults to a fixed 0.35, so that one default suits every noise level;
//! - the range weight also compares the faces' own normals (`options::GUIDED_OWN_NORMALS`);
//! - the vertices are fitted after the later passes only (`options::GUIDED_NORMALS_ALONE`).
//!
//! The paper preset (`Preset::Paper`) runs the paper's rule as the authors' code has it.

use rayon::prelude::*;

use super::faces::{dist2, unit_or_zero, FaceData};
use super::rings::FaceRings;

/// Keeps R finite on a patch whose faces all agree exactly.
const EPSILON: f64 = 1e-9;

/// Per patch (one per face, centred there): its inconsistency and mean normal.
#[derive(Clone, Copy, Default)]
pub struct Patch {
    inconsistency: f64,
    mean: [f64; 3],
}

/// Buffers reused from pass to pass.
#[derive(Default)]
pub struct Scratch {
    patches: Vec<Patch>,
    /// |n_a - n_b| per entry of `rings.edge_ring`: each pair of faces sharing an edge.
    across: Vec<f64>,
}

/// Whether a face with vertices `f` is in the patch centred at the face with vertices `c`: its
/// vertex ring is the faces that share a vertex with it. Nine comparisons without branches,
/// faster than searching the ring.
#[inline]
fn shares_vertex(c: [u32; 3], f: [u32; 3]) -> bool {
    let hit = |v: u32| (f[0] == v) | (f[1] == v) | (f[2] == v);
    hit(c[0]) | hit(c[1]) | hit(c[2])
}

fn patch(
    rings: &FaceRings,
    faces: &[[u32; 3]],
    data: &[FaceData],
    normals: &[[f64; 3]],
    across: &[f64],
    centre: usize,
) -> Patch {
    let ring = rings.ring.row(centre);
    let members = || std::iter::once(centre as u32).chain(ring.iter().copied());
    let mut sum_n = [0.0; 3];
    for a in members() {
        let (na, w) = (normals[a as usize], data[a as usize].area);
        for c in 0..3 {
            sum_n[c] += w * na[c];
        }
    }
    let mean = unit_or_zero(sum_n);
    let largest = spread(members, normals, mean);
    let (mut edge_max, mut edge_sum) = (0.0f64, 0.0f64);
    for a in members() {
        let span = rings.edge_ring.span(a as usize);
        for (&b, &d) in rings.edge_ring.row(a as usize).iter().zip(&across[span]) {
            if b > a && shares_vertex(faces[centre], faces[b as usize]) {
                edge_max = edge_max.max(d);
                edge_sum += d;
            }
        }
    }
    Patch { inconsistency: largest.sqrt() * edge_max / (EPSILON + edge_sum), mean }
}

/// The largest |n_a - n_b|^2 over the patch, taken from the normal farthest from the mean
/// (exact when the normals form two clusters, as across a crease; within a factor of 4
/// otherwise): linear in the patch size, where all pairs would be quadratic, and a fan of
/// thousands of faces must not cost millions of pairs.
fn spread<I: Iterator<Item = u32>>(members: impl Fn() -> I, normals: &[[f64; 3]], mean: [f64; 3]) -> f64 {
    let (mut far, mut far_d) = (mean, -1.0);
    for a in members() {
        let d = dist2(normals[a as usize], mean);
        if d > far_d {
            (far, far_d) = (normals[a as usize], d);
        }
    }
    members().map(|a| dist2(normals[a as usize], far)).fold(0.0, f64::max)
}

/// `out[i]`: face i's guidance normal from the current `normals`. `patches` is scratch.
pub fn guidance(
    rings: &FaceRings,
    faces: &[[u32; 3]],
    data: &[FaceData],
    normals: &[[f64; 3]],
    scratch: &mut Scratch,
    out: &mut [[f64; 3]],
) {
    let Scratch { patches, across } = scratch;
    across.resize(rings.edge_ring.n_items(), 0.0);
    let edges = &rings.edge_ring;
    // Each face fills its own entries: split the flat list at the rows' ends.
    let mut rest: &mut [f64] = across;
    let mut rows: Vec<(usize, &mut [f64])> = Vec::with_capacity(normals.len());
    for i in 0..normals.len() {
        let (row, tail) = rest.split_at_mut(edges.span(i).len());
        rows.push((i, row));
        rest = tail;
    }
    rows.par_iter_mut().with_min_len(4096).for_each(|(i, row)| {
        for (d, &b) in row.iter_mut().zip(edges.row(*i)) {
            *d = dist2(normals[*i], normals[b as usize]).sqrt();
        }
    });
    let across: &[f64] = across;
    patches.resize(normals.len(), Patch::default());
    patches
        .par_iter_mut()
        .with_min_len(1024)
        .enumerate()
        .for_each(|(i, p)| *p = patch(rings, faces, data, normals, across, i));
    let patches: &[Patch] = patches;
    out.par_iter_mut().with_min_len(1024).enumerate().for_each(|(i, o)| {
        let mut best = patches[i];
        for &j in rings.ring.row(i) {
            let p = patches[j as usize];
            if p.inconsistency < best.inconsistency {
                best = p;
            }
        }
        *o = if best.mean == [0.0; 3] { normals[i] } else { best.mean };
    });
}

//! What field hatching draws along: per vertex, the stripe values (`mesh::stripes`) of its two
//! stroke families, laid along the smoothed principal directions (`mesh::line_field`).
//!
//! Family a runs along the first direction (around a cylinder): its phase grows across it,
//! along n x d1. Family b runs along the second (along a cylinder's axis): its phase grows along
//! d1. Why stripes rather than a direction per vertex: a direction needs a coordinate to lay
//! strokes along, and any local coordinate blends between neighbours (the ghost grids of
//! triplanar blending); a phase per vertex interpolates into one continuous pattern.
//!
//! Positions at the same place (seams of a UV layout, split normals) are welded first, so the
//! field runs across seams, and the surface is cut at creases, where it has no curvature
//! direction; the stripes' period is `FIELD_PERIOD_EDGES` mean edge lengths, so it
//! follows the mesh's own scale and each edge turns the phase by about a sixteenth of a turn (a
//! linear interpolation of psi then tracks the phase closely).

use crate::cancel::Cancel;
use crate::error::Result;
use crate::mesh::crease_normals::crease_normals;
use crate::mesh::edge_length::mean_edge_length;
use crate::mesh::line_field::principal_line_field;
use crate::mesh::stripes::stripe_phase;
use crate::mesh::weld::Merged;
use crate::mesh::Adjacency;
use crate::smooth::{resolve, smooth_cancellable, Args, Method};

/// Taubin iterations (lambda 0.5, mu -0.53) of the copy of the mesh whose curvature gives the
/// directions.
pub const FIELD_SMOOTHING: i64 = 100;

/// The stripes' period, in mean edge lengths (the finest pattern the shader's octaves start from).
pub const FIELD_PERIOD_EDGES: f64 = 16.0;

/// The stripe values of a mesh, per vertex of the mesh split at its creases: `values[v]` is psi
/// of family a, then of family b (re, im each), and `corners[f][k]` the split vertex at corner
/// k of face f (`NO_CORNER` for a face that repeats a vertex).
/// The corner of a face left out of the field.
pub const NO_CORNER: u32 = u32::MAX;

pub struct CornerStripes {
    pub values: Vec<[f32; 4]>,
    pub corners: Vec<[u32; 3]>,
}

impl CornerStripes {
    /// Per vertex of a mesh whose face f has vertex `faces[f][k]` at corner k (the same faces,
    /// indexed as a device mesh holds them): the value of one of its corners, the one whose
    /// split vertex has the most faces where the vertex was split (the larger side of a crease).
    pub fn per_vertex(&self, n_vertices: usize, faces: &[[u32; 3]]) -> Vec<[f32; 4]> {
        let mut fan = vec![0u32; self.values.len()];
        for &c in self.corners.iter().flatten().filter(|&&c| c != NO_CORNER) {
            fan[c as usize] += 1;
        }
        let mut best: Vec<Option<u32>> = vec![None; n_vertices];
        for (f, c) in faces.iter().zip(&self.corners) {
            if c[0] == NO_CORNER {
                continue;
            }
            for k in 0..3 {
                let b = &mut best[f[k] as usize];
                if b.is_none_or(|b| fan[c[k] as usize] > fan[b as usize]) {
                    *b = Some(c[k]);
                }
            }
        }
        best.iter().map(|b| b.map_or([1.0, 0.0, 1.0, 0.0], |c| self.values[c as usize])).collect()
    }
}

/// The stripe values of `positions` and `faces` (checked indices), the surface cut where faces
/// meet at more than `crease_angle` degrees: across a crease (a cylinder's rim) curvature has no
/// direction, and each side is hatched on its own.
pub fn hatch_stripes(
    positions: &[[f64; 3]],
    faces: &[[u32; 3]],
    crease_angle: f64,
    cancel: &Cancel,
) -> Result<CornerStripes> {
    let merged = Merged::of(positions);
    let p = merged.gather(positions);
    // faces that repeat a vertex span nothing: left out, so that they change nothing
    let welded = merged.faces(faces);
    let spans = |t: &[u32; 3]| t[0] != t[1] && t[1] != t[2] && t[2] != t[0];
    let kept: Vec<[u32; 3]> = welded.iter().copied().filter(spans).collect();
    let split = crease_normals(&p, &kept, crease_angle)?;
    let p: Vec<[f64; 3]> = split.source.iter().map(|&i| p[i as usize]).collect();
    let f = split.faces;
    // the directions from a smoothed copy: on a scanned mesh each bump a few edges wide
    // would turn the strokes
    let plan = resolve(Method::Taubin, &Args { iterations: Some(FIELD_SMOOTHING), ..Default::default() })?;
    let smoothed = smooth_cancellable(&p, &f, &plan, None, cancel, None)?;
    let field = principal_line_field(&smoothed, &f, cancel)?;
    let adj = Adjacency::build(p.len(), &f)?;
    let period = FIELD_PERIOD_EDGES * mean_edge_length(&p, &f);
    let period = if period.is_finite() && period > 0.0 { period } else { 1.0 };
    let across: Vec<[f64; 3]> = field
        .normals
        .iter()
        .zip(&field.directions)
        .map(|(n, d)| [n[1] * d[2] - n[2] * d[1], n[2] * d[0] - n[0] * d[2], n[0] * d[1] - n[1] * d[0]])
        .collect();
    let a = stripe_phase(&p, &adj, &across, period, cancel)?;
    let b = stripe_phase(&p, &adj, &field.directions, period, cancel)?;
    let values =
        a.iter().zip(&b).map(|(a, b)| [a[0] as f32, a[1] as f32, b[0] as f32, b[1] as f32]).collect();
    let mut split_faces = f.into_iter();
    let corners = welded
        .iter()
        .map(|t| if spans(t) { split_faces.next().expect("one a kept face") } else { [NO_CORNER; 3] })
        .collect();
    Ok(CornerStripes { values, corners })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn split_copies_get_the_values_of_their_welded_vertex() {
        let (v, f) = crate::mesh::shapes::icosphere(2, 0.0, 0).unwrap();
        // the first face's corners copied: a seam
        let mut v2 = v.clone();
        let mut f2 = f.clone();
        let first = f[0];
        let base = v2.len() as u32;
        v2.extend(first.map(|i| v[i as usize]));
        f2[0] = [base, base + 1, base + 2];
        let s = hatch_stripes(&v2, &f2, 30.0, Cancel::never()).unwrap().per_vertex(v2.len(), &f2);
        let whole = hatch_stripes(&v, &f, 30.0, Cancel::never()).unwrap().per_vertex(v.len(), &f);
        for k in 0..3 {
            assert_eq!(s[base as usize + k], s[first[k] as usize]);
        }
        assert_eq!(&s[..v.len()], &whole[..], "the seam changes nothing");
        assert!(s.iter().all(|x| x.iter().all(|c| c.is_finite())));
    }

    #[test]
    fn a_crease_cuts_the_field() {
        // a cylinder with a flat cap: the side's field runs around it up to the rim
        let (mut v, mut f) = crate::mesh::line_field::tests::cylinder(48, 24);
        let centre = v.len() as u32;
        v.push([0.0, 0.0, 1.0]);
        let top = 24 * 48;
        f.extend((0..48).map(|k| [centre, top + k, top + (k + 1) % 48]));
        let s = hatch_stripes(&v, &f, 30.0, Cancel::never()).unwrap();
        let values = s.per_vertex(v.len(), &f);
        // family b's phase grows along d1, around: neighbours around a row differ by about
        // the same turn, rim included
        let step = |i: usize, j: usize| {
            let (a, b) = (values[i], values[j]);
            ((a[2] * b[3] - a[3] * b[2]) as f64).atan2((a[2] * b[2] + a[3] * b[3]) as f64).abs()
        };
        let want = std::f64::consts::TAU * (std::f64::consts::TAU / 48.0)
            / (FIELD_PERIOD_EDGES * mean_edge_length(&v, &f));
        for row in [0usize, 12, 24] {
            for k in 0..48 {
                let i = row * 48 + k;
                let got = step(i, row * 48 + (k + 1) % 48);
                assert!(
                    got > 0.3 * want && got < 3.0 * want,
                    "row {row}, vertex {k}: step {got}, about {want}"
                );
            }
        }
    }
}

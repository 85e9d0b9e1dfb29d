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
//! field runs across seams; the stripes' period is `FIELD_PERIOD_EDGES` mean edge lengths, so it
//! follows the mesh's own scale and each edge turns the phase by about an eighth of a turn (a
//! linear interpolation of psi then tracks the phase closely).

use crate::cancel::Cancel;
use crate::error::Result;
use crate::mesh::line_field::principal_line_field;
use crate::mesh::stripes::stripe_phase;
use crate::mesh::weld::Merged;
use crate::mesh::Adjacency;
use crate::real::{norm, sub};

/// The stripes' period, in mean edge lengths (the finest pattern the shader's octaves start from).
pub const FIELD_PERIOD_EDGES: f64 = 8.0;

/// Mean length of the faces' edges (0 for a mesh without any).
fn mean_edge(positions: &[[f64; 3]], faces: &[[u32; 3]]) -> f64 {
    let sum: f64 = faces
        .iter()
        .map(|f| {
            (0..3)
                .map(|k| norm(sub(positions[f[k] as usize], positions[f[(k + 1) % 3] as usize])))
                .sum::<f64>()
        })
        .sum();
    sum / (3 * faces.len()).max(1) as f64
}

/// Per vertex of `positions`: psi of family a, then of family b (re, im each). `faces` are
/// checked indices.
pub fn hatch_stripes(positions: &[[f64; 3]], faces: &[[u32; 3]], cancel: &Cancel) -> Result<Vec<[f32; 4]>> {
    let merged = Merged::of(positions);
    let (p, f) = (merged.gather(positions), merged.faces(faces));
    let field = principal_line_field(&p, &f, cancel)?;
    let adj = Adjacency::build(p.len(), &f)?;
    let period = FIELD_PERIOD_EDGES * mean_edge(&p, &f);
    let period = if period.is_finite() && period > 0.0 { period } else { 1.0 };
    let across: Vec<[f64; 3]> = field
        .normals
        .iter()
        .zip(&field.directions)
        .map(|(n, d)| [n[1] * d[2] - n[2] * d[1], n[2] * d[0] - n[0] * d[2], n[0] * d[1] - n[1] * d[0]])
        .collect();
    let a = stripe_phase(&p, &adj, &across, period, cancel)?;
    let b = stripe_phase(&p, &adj, &field.directions, period, cancel)?;
    Ok(merged
        .index
        .iter()
        .map(|&m| {
            let (a, b) = (a[m as usize], b[m as usize]);
            [a[0] as f32, a[1] as f32, b[0] as f32, b[1] as f32]
        })
        .collect())
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
        let s = hatch_stripes(&v2, &f2, Cancel::never()).unwrap();
        let whole = hatch_stripes(&v, &f, Cancel::never()).unwrap();
        for k in 0..3 {
            assert_eq!(s[base as usize + k], s[first[k] as usize]);
        }
        assert_eq!(&s[..v.len()], &whole[..], "the seam changes nothing");
        assert!(s.iter().all(|x| x.iter().all(|c| c.is_finite())));
    }
}

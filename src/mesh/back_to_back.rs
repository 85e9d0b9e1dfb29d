//! Faces stored twice, back to back: a sheet (a leaf, cloth, a woven seat) saved double-sided,
//! each face once per side with the same three vertices the other way round. Drawn as given,
//! their normals cancel at the shared vertices (the smooth shading turns to noise) and every
//! edge is non-manifold; the surface is the first face of each pair.

use rayon::prelude::*;

use super::buckets::Buckets;
use super::weld::weld_faces;
use crate::error::Result;

/// Which faces to keep: false for a face back to back with an earlier one (the same three
/// vertices, after `map` where one is given, the other way round). Faces that repeat an earlier
/// one the same way round, and collapsed faces, stay. None when every face stays.
pub fn back_to_back_faces(faces: &[[u32; 3]], map: Option<&[u32]>) -> Result<Option<Vec<bool>>> {
    let welded;
    let faces = match map {
        Some(m) => {
            welded = weld_faces(faces, m);
            &welded[..]
        }
        None => faces,
    };
    let n_vertices = faces.par_iter().map(|f| f[0].max(f[1]).max(f[2]) as usize + 1).max().unwrap_or(0);
    // each face under its smallest corner, in face order: a back lies in its front's bucket
    let buckets = Buckets::faces_at_smallest(n_vertices, faces)?;
    let dropped: Vec<u32> = (0..n_vertices).into_par_iter().flat_map_iter(|v| backs(buckets.at(v))).collect();
    if dropped.is_empty() {
        return Ok(None);
    }
    let mut keep = vec![true; faces.len()];
    for f in dropped {
        keep[f as usize] = false;
    }
    Ok(Some(keep))
}

/// The faces of one bucket (`[next, prev, face]`, in face order) that are backs: the first
/// face on their corners runs the other way round.
fn backs(at: &[[u32; 3]]) -> Vec<u32> {
    let corners = |f: &[u32; 3]| (f[0].min(f[1]), f[0].max(f[1]));
    if at.len() <= 16 {
        let first = |i: usize| at[..i].iter().find(|g| corners(g) == corners(&at[i]));
        return (0..at.len())
            .filter(|&i| first(i).is_some_and(|g| g[0] != at[i][0]))
            .map(|i| at[i][2])
            .collect();
    }
    // a vertex of many faces (a fan's centre): sorted by corners, then face order
    let mut order: Vec<&[u32; 3]> = at.iter().collect();
    order.sort_unstable_by_key(|f| (corners(f), f[2]));
    order
        .chunk_by(|a, b| corners(a) == corners(b))
        .flat_map(|same| same.iter().filter(|f| f[0] != same[0][0]).map(|f| f[2]))
        .collect()
}

/// The faces without those back to back with an earlier one (see `back_to_back_faces`); None
/// when no face goes.
pub fn without_back_to_back(faces: &[[u32; 3]], map: &[u32]) -> Result<Option<Vec<[u32; 3]>>> {
    Ok(back_to_back_faces(faces, Some(map))?.map(|keep| kept(faces, &keep)))
}

/// The items whose flag in `keep` is true.
pub fn kept<T: Copy>(items: &[T], keep: &[bool]) -> Vec<T> {
    items.iter().zip(keep).filter(|(_, k)| **k).map(|(x, _)| *x).collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_face_back_to_back_with_an_earlier_one_goes() {
        let faces = [[0, 1, 2], [2, 3, 0], [1, 0, 2], [0, 3, 2], [0, 1, 2], [0, 0, 1]];
        // the second of a pair goes whichever corner it starts at; a repeat the same way round
        // and a degenerate face stay
        let keep = back_to_back_faces(&faces, None).unwrap().unwrap();
        assert_eq!(keep, [true, true, false, false, true, true]);
        assert_eq!(back_to_back_faces(&faces[..2], None).unwrap(), None);
    }

    #[test]
    fn welding_finds_twins_stored_with_their_own_vertices() {
        let faces = [[0, 1, 2], [5, 4, 3]];
        assert_eq!(back_to_back_faces(&faces, None).unwrap(), None);
        let map = [0, 1, 2, 0, 1, 2];
        assert_eq!(without_back_to_back(&faces, &map).unwrap(), Some(vec![[0, 1, 2]]));
    }

    #[test]
    fn a_double_sided_sheet_is_one_layer_and_a_single_one_is_left_alone() {
        // two triangles, stored again the other way round with their own vertices 4..8
        let faces = vec![[0, 1, 2], [0, 2, 3], [4, 6, 5], [4, 7, 6], [1, 0, 2]];
        let map = vec![0, 1, 2, 3, 0, 1, 2, 3];
        let kept = without_back_to_back(&faces, &map).unwrap().expect("the back faces go");
        // [1, 0, 2] is [0, 2, 1]: the back of [0, 1, 2]
        assert_eq!(kept, vec![[0, 1, 2], [0, 2, 3]]);
        assert!(without_back_to_back(&faces[..2], &map).unwrap().is_none());
        // the same face twice the same way round is not a back
        assert!(without_back_to_back(&[[0, 1, 2], [1, 2, 0]], &map).unwrap().is_none());
    }

    #[test]
    fn a_fan_of_many_faces_is_sorted_the_same() {
        // 40 faces around vertex 0, then each again the other way round and once more the same
        let fan: Vec<[u32; 3]> = (1..41).map(|k| [0, k, k + 1]).collect();
        let backs: Vec<[u32; 3]> = fan.iter().map(|f| [f[0], f[2], f[1]]).collect();
        let faces: Vec<[u32; 3]> = fan.iter().chain(&backs).chain(&fan).copied().collect();
        let keep = back_to_back_faces(&faces, None).unwrap().unwrap();
        assert!(
            keep[..40].iter().all(|&k| k)
                && keep[40..80].iter().all(|&k| !k)
                && keep[80..].iter().all(|&k| k)
        );
    }
}

//! Whether a mesh's faces enclose solids, and on which side: what decides that a renderer may
//! skip the faces whose inner side is turned to the camera (back-face culling) without changing
//! the image.
//!
//! A mesh encloses solids when every edge is used by exactly two faces that walk it in opposite
//! directions (closed, consistently oriented shells), no face repeats a vertex, and the signed
//! volumes of its connected shells all have the same, clear sign. Seen from outside every
//! shell, the first surface along any ray then shows its outer side: entering a solid crosses a
//! face from the side its normal points to. A two-sided sheet (each face twice, once each way)
//! is closed but encloses nothing (its volume cancels), so it does not count. A mesh split
//! along UV or normal seams (the same point stored twice) is judged once those copies are
//! merged (`enclosure_welded`).

use super::buckets::Buckets;
use super::union_find::{find, join};
use super::weld::{weld_faces, weld_map};

/// Which way a mesh's counter-clockwise normals point, relative to the solids it encloses.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Enclosure {
    /// Out of the solids: the counter-clockwise side is the outer side.
    Outward,
    /// Into them (every shell wound inside out).
    Inward,
}

/// A shell whose signed volume is below this share of the sum of its tetrahedra's absolute
/// volumes encloses nothing measurable (a sheet, or a sum lost to rounding).
const CLEAR_VOLUME: f64 = 1e-9;

/// How `faces` over `positions` enclose solids, or, failing that, how they do once vertices at
/// the same position are merged (a mesh split along UV or normal seams is closed as a surface
/// even though its indices leave it open); None when neither does.
pub fn enclosure_welded(positions: &[[f64; 3]], faces: &[[u32; 3]]) -> Option<Enclosure> {
    enclosure(positions, faces).or_else(|| {
        let map = weld_map(positions);
        let copies = map.iter().enumerate().any(|(i, &rep)| rep as usize != i);
        copies.then(|| enclosure(positions, &weld_faces(faces, &map))).flatten()
    })
}

/// How `faces` over `positions` enclose solids, or None when they do not (see the module).
/// `positions` are best centred near the origin (the volume sums are then well conditioned).
pub fn enclosure(positions: &[[f64; 3]], faces: &[[u32; 3]]) -> Option<Enclosure> {
    if faces.is_empty() || faces.iter().any(|&[a, b, c]| a == b || b == c || a == c) {
        return None;
    }
    let mut buckets = Buckets::face_edges(positions.len(), faces).ok()?;
    // Sorted entries of one edge: other end << 32 | face << 1 | reversed; exactly two, one
    // each way.
    let paired = buckets.visit_edges(
        |_| true,
        |_| {},
        |ok: &mut bool, _, uses| *ok &= uses.len() == 2 && (uses[0] ^ uses[1]) & 1 == 1,
    );
    if !paired.into_iter().all(|ok| ok) {
        return None;
    }
    let shell = shells(positions.len(), faces);
    let mut signed = vec![0.0f64; positions.len()];
    let mut absolute = vec![0.0f64; positions.len()];
    let mut is_shell = vec![false; positions.len()];
    for f in faces {
        let [a, b, c] = f.map(|i| positions[i as usize]);
        let det = a[0] * (b[1] * c[2] - b[2] * c[1]) - a[1] * (b[0] * c[2] - b[2] * c[0])
            + a[2] * (b[0] * c[1] - b[1] * c[0]);
        let s = shell[f[0] as usize] as usize;
        signed[s] += det;
        absolute[s] += det.abs();
        is_shell[s] = true;
    }
    let mut sign = None;
    for ((s, a), _) in signed.iter().zip(&absolute).zip(&is_shell).filter(|(_, &shell)| shell) {
        if s.is_nan() || s.abs() <= CLEAR_VOLUME * a {
            return None;
        }
        let this = if *s > 0.0 { Enclosure::Outward } else { Enclosure::Inward };
        if sign.is_some_and(|other| other != this) {
            return None;
        }
        sign = Some(this);
    }
    sign
}

/// Each vertex's shell: the smallest vertex index it is joined to by faces.
fn shells(n_vertices: usize, faces: &[[u32; 3]]) -> Vec<u32> {
    let mut parent: Vec<u32> = (0..n_vertices as u32).collect();
    for &[a, b, c] in faces {
        join(&mut parent, a as usize, b as usize);
        join(&mut parent, a as usize, c as usize);
    }
    for v in 0..n_vertices {
        parent[v] = find(&mut parent, v);
    }
    parent
}

#[cfg(test)]
mod tests {
    use super::*;

    fn tetra() -> (Vec<[f64; 3]>, Vec<[u32; 3]>) {
        let p = vec![[0.0, 0.0, 0.0], [1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]];
        // counter-clockwise seen from outside
        let f = vec![[0, 2, 1], [0, 1, 3], [0, 3, 2], [1, 2, 3]];
        (p, f)
    }

    fn flipped(f: &[[u32; 3]]) -> Vec<[u32; 3]> {
        f.iter().map(|&[a, b, c]| [a, c, b]).collect()
    }

    fn centred(p: &[[f64; 3]]) -> Vec<[f64; 3]> {
        p.iter().map(|q| q.map(|x| x - 0.25)).collect()
    }

    #[test]
    fn closed_shells_have_the_sign_of_their_volume() {
        let (p, f) = tetra();
        assert_eq!(enclosure(&centred(&p), &f), Some(Enclosure::Outward));
        assert_eq!(enclosure(&centred(&p), &flipped(&f)), Some(Enclosure::Inward));
        // the same with the solid far from the origin
        let far: Vec<_> = p.iter().map(|q| q.map(|x| x + 1e3)).collect();
        assert_eq!(enclosure(&far, &f), Some(Enclosure::Outward));
    }

    #[test]
    fn open_inconsistent_or_degenerate_meshes_enclose_nothing() {
        let (p, f) = tetra();
        let p = centred(&p);
        assert_eq!(enclosure(&p, &f[..3]), None, "a face missing");
        let mut one_flipped = f.clone();
        one_flipped[0] = [0, 1, 2];
        assert_eq!(enclosure(&p, &one_flipped), None, "a face wound the other way");
        let mut repeated = f.clone();
        repeated.push([0, 1, 0]);
        assert_eq!(enclosure(&p, &repeated), None, "a face repeating a vertex");
        let mut doubled = f.clone();
        doubled.extend(flipped(&f));
        assert_eq!(enclosure(&p, &doubled), None, "every edge used four times");
        assert_eq!(enclosure(&p, &[]), None);
    }

    #[test]
    fn a_mesh_split_along_a_seam_encloses_once_welded() {
        let (p, f) = tetra();
        let mut p = centred(&p);
        // vertex 3 copied: faces 1 and 3 use the copy, so edges 0-3 and 1-3 look open
        p.push(p[3]);
        let split = vec![f[0], [0, 1, 4], f[2], [1, 2, 4]];
        assert_eq!(enclosure(&p, &split), None);
        assert_eq!(enclosure_welded(&p, &split), Some(Enclosure::Outward));
        assert_eq!(enclosure_welded(&p, &split[..3]), None, "still open once welded");
    }

    #[test]
    fn a_two_sided_sheet_encloses_nothing() {
        let p = vec![[0.0, 0.0, 0.0], [1.0, 0.0, 0.0], [0.0, 1.0, 0.0]];
        assert_eq!(enclosure(&p, &[[0, 1, 2], [0, 2, 1]]), None);
    }

    #[test]
    fn every_shell_must_agree() {
        let (p, f) = tetra();
        let mut two = centred(&p);
        two.extend(centred(&p).iter().map(|q| [q[0] + 3.0, q[1], q[2]]));
        let second: Vec<[u32; 3]> = f.iter().map(|t| t.map(|i| i + 4)).collect();
        let both = [f.clone(), second.clone()].concat();
        assert_eq!(enclosure(&two, &both), Some(Enclosure::Outward));
        let mixed = [f.clone(), flipped(&second)].concat();
        assert_eq!(enclosure(&two, &mixed), None, "one shell inside out");
        let inward = [flipped(&f), flipped(&second)].concat();
        assert_eq!(enclosure(&two, &inward), Some(Enclosure::Inward));
    }
}

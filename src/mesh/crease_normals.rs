//! Vertex normals split at creases, as Blender's auto smooth makes them: hard edges shade hard
//! and curved parts stay smooth.
//!
//! The faces around each vertex v fall into *fans*: two of v's corners are in the same fan when
//! a chain of smooth edges at v joins them. An edge (v, u) is smooth when it has exactly two
//! face-edges, from two different faces that both have a normal (`mesh::normals`), and those
//! normals meet at a dihedral angle no larger than the threshold (`mesh::dihedral::CreaseTest`,
//! the rule of the crease outlines, so shading splits exactly where crease lines are drawn).
//! Boundary, non-manifold and crease edges therefore separate fans, and so do the edges of a
//! degenerate face, which has no angle to its neighbours: it becomes a fan of its own.
//!
//! Each fan becomes one output vertex whose normal is the normalised sum of its faces' cross
//! products (area weighting), summed in face order exactly as `normals::vertex_normals` sums all
//! of v's faces; a fan without a normal of its own (a degenerate face's) takes v's normal over
//! all its faces, and [0, 0, 0] only where that is zero too, as the smooth normals do. Output
//! vertices are numbered vertex by vertex, fans in the order of their first face, so where no
//! vertex splits the output is exactly the smooth normals and the input numbering, bit for bit.

use rayon::prelude::*;

use super::buckets::{fill_slot_pairs, prefix_sum, sort8, split_by, vertex_chunks, Buckets, RingCorner};
use super::dihedral::CreaseTest;
use super::edge_table::prefetch;
use super::normals::{face_normals, is_defined, unit_or_zero};
use super::union_find::{find, join};
use crate::error::{Error, Result};
use crate::huge_pages;
use crate::real::{cross, sub, to_f64, Real, Vec3};

/// Vertices split at creases: output vertex i copies input vertex `source[i]` with the unit
/// normal `normals[i]`; `faces` are the input faces re-indexed into the output vertices.
#[derive(Debug, Clone, PartialEq)]
pub struct SplitNormals {
    pub source: Vec<u32>,
    pub normals: Vec<[f64; 3]>,
    pub faces: Vec<[u32; 3]>,
}

/// Which edges split the fans (besides boundary, non-manifold and degenerate faces' edges).
pub trait HardEdges: Sync {
    /// Whether the edge (v, u) between faces with unit normals `na` and `nb` is hard.
    fn is_hard(&self, v: u32, u: u32, na: [f64; 3], nb: [f64; 3]) -> bool;
}

impl HardEdges for CreaseTest {
    fn is_hard(&self, _: u32, _: u32, na: [f64; 3], nb: [f64; 3]) -> bool {
        self.is_crease(na, nb)
    }
}

/// The edges of a list, each [smaller, larger] index, sorted.
pub struct ListedEdges<'a>(pub &'a [[u32; 2]]);

impl HardEdges for ListedEdges<'_> {
    fn is_hard(&self, v: u32, u: u32, _: [f64; 3], _: [f64; 3]) -> bool {
        self.0.binary_search(&[v.min(u), v.max(u)]).is_ok()
    }
}

/// Splits every vertex into its fans at edges sharper than `crease_angle` degrees (and at
/// boundary, non-manifold and degenerate faces' edges). Faces index `positions` (checked by
/// the caller).
pub fn crease_normals<T: Real>(
    positions: &[Vec3<T>],
    faces: &[[u32; 3]],
    crease_angle: f64,
) -> Result<SplitNormals> {
    split_normals(positions, faces, &CreaseTest::new(crease_angle)?)
}

/// Splits every vertex into its fans at the edges `hard` names (and at boundary, non-manifold
/// and degenerate faces' edges).
pub fn split_normals<T: Real>(
    positions: &[Vec3<T>],
    faces: &[[u32; 3]],
    test: &impl HardEdges,
) -> Result<SplitNormals> {
    let n = positions.len();
    let ((buckets, unit), area) = rayon::join(
        || rayon::join(|| Buckets::corners_with_ids(n, faces), || face_normals(positions, faces)),
        || area_vectors(positions, faces),
    );
    let buckets = buckets?;
    let ranges = vertex_chunks(n);
    let ring = |v: usize| buckets.at(v);

    // Pass 1: each corner's fan at its vertex (in bucket order) and each vertex's fan count.
    let mut fan: Vec<u32> = huge_pages::filled_vec(buckets.entries.len(), 0);
    let mut fans: Vec<u32> = huge_pages::filled_vec(n, 0);
    let corner_at = |r: &std::ops::Range<usize>| buckets.start[r.start] as usize;
    split_by(&mut fan, &ranges, corner_at)
        .into_par_iter()
        .zip(split_by(&mut fans, &ranges, |r| r.start))
        .zip(ranges.par_iter())
        .for_each_init(FanScratch::default, |scratch, ((fan, fans), r)| {
            let base = corner_at(r);
            for (k, v) in r.clone().enumerate() {
                // the face normals a few vertices ahead are loaded while this one is grouped
                for c in ring((v + PREFETCH_AHEAD).min(n - 1)) {
                    prefetch(&unit, (c[2] / 3) as usize);
                }
                let at = buckets.start[v] as usize - base..buckets.start[v + 1] as usize - base;
                // a closed fan is grouped by walking around it, any other by sorting
                fans[k] = match group_closed_fan(v as u32, ring(v), &unit, test, &mut fan[at.clone()]) {
                    Some(count) => count,
                    None => scratch.group_any(v as u32, ring(v), &unit, test, &mut fan[at]),
                };
            }
        });

    // Output vertices: vertex v's fans are first[v]..first[v + 1]. An unused vertex keeps one
    // (with a zero normal, as in the smooth normals), so nothing is renumbered where nothing
    // splits.
    drop(unit);
    let counts: Vec<u32> = fans.par_iter().map(|&c| c.max(1)).collect();
    drop(fans);
    let total: u64 = counts.iter().map(|&c| c as u64).sum();
    if total > u32::MAX as u64 {
        return Err(Error::invalid("faces", "too many split vertices for 32-bit indices"));
    }
    let first = prefix_sum(&counts);
    drop(counts);

    // Pass 2: each fan's normal, from its faces' area vectors in face order.
    let n_out = first[n] as usize;
    let (normals, source) = fill_slot_pairs(
        &first,
        &ranges,
        ([0.0f64; 3], 0u32),
        Vec::new,
        |sums: &mut Vec<[f64; 3]>, (normals, source), r| {
            let base = first[r.start] as usize;
            for v in r.clone() {
                for c in ring((v + PREFETCH_AHEAD).min(n - 1)) {
                    prefetch(&area, (c[2] / 3) as usize);
                }
                let out = first[v] as usize - base..first[v + 1] as usize - base;
                source[out.clone()].fill(v as u32);
                let corners = ring(v);
                let fan_of = &fan[buckets.start[v] as usize..][..corners.len()];
                fan_normals(corners, fan_of, &area, sums, &mut normals[out]);
            }
        },
    );

    // Pass 3: every corner's output vertex: first[v] where v did not split; otherwise its fan,
    // found by a binary search in v's bucket, which lists v's corners by id.
    let split_faces: Vec<[u32; 3]> = if n_out == n {
        faces.to_vec()
    } else {
        faces
            .par_iter()
            .enumerate()
            .map(|(f, face)| {
                std::array::from_fn(|j| {
                    let v = face[j] as usize;
                    if first[v + 1] - first[v] == 1 {
                        return first[v];
                    }
                    let id = (f * 3 + j) as u32;
                    let k = ring(v)
                        .binary_search_by_key(&id, |c| c[2])
                        .expect("every corner is in its vertex's bucket");
                    first[v] + fan[buckets.start[v] as usize + k]
                })
            })
            .collect()
    };
    Ok(SplitNormals { source, normals, faces: split_faces })
}

/// Each face's (b - a) x (c - a) in f64: twice its area along its normal, the weight the
/// smooth normals give it.
fn area_vectors<T: Real>(positions: &[Vec3<T>], faces: &[[u32; 3]]) -> Vec<[f64; 3]> {
    let mut out = huge_pages::filled_vec(faces.len(), [0.0; 3]);
    out.par_chunks_mut(4096).zip(faces.par_chunks(4096)).for_each(|(o, f)| {
        for (n, face) in o.iter_mut().zip(f) {
            let [a, b, c] = face.map(|i| to_f64(positions[i as usize]));
            *n = cross(sub(b, a), sub(c, a));
        }
    });
    out
}

/// How many vertices ahead to start loading face data: enough to cover a memory latency.
const PREFETCH_AHEAD: usize = 4;

/// Per-thread room for grouping one vertex's corners.
#[derive(Default)]
struct FanScratch {
    /// (neighbour << 32 | corner << 1 | side) for both face-edges of every corner.
    ends: Vec<u64>,
    parent: Vec<u32>,
    label: Vec<u32>,
}

const NO_FAN: u32 = u32::MAX;

impl FanScratch {
    /// Groups v's corners into fans, for any fan: writes each corner's fan (numbered by first
    /// corner) into `fan` and returns how many there are. The face-edges at v are sorted by
    /// their other end, so that each edge's face-edges are a run.
    fn group_any(
        &mut self,
        v: u32,
        corners: &[RingCorner],
        unit: &[[f64; 3]],
        test: &impl HardEdges,
        fan: &mut [u32],
    ) -> u32 {
        let r = corners.len();
        self.parent.clear();
        self.parent.extend(0..r as u32);
        self.ends.clear();
        for (k, &[next, prev, _]) in corners.iter().enumerate() {
            for (side, u) in [next, prev].into_iter().enumerate() {
                if u != v {
                    self.ends.push((u as u64) << 32 | (k as u64) << 1 | side as u64);
                }
            }
        }
        self.ends.sort_unstable();
        // Runs of one neighbour u are the face-edges on the edge (v, u).
        for run in self.ends.chunk_by(|a, b| a >> 32 == b >> 32) {
            if let &[a, b] = run {
                let (ka, kb) = (((a as u32) >> 1) as usize, ((b as u32) >> 1) as usize);
                join_if_smooth(&mut self.parent, corners, [v, (a >> 32) as u32], ka, kb, unit, test);
            }
        }
        self.label.clear();
        self.label.resize(r, NO_FAN);
        number_fans(&mut self.parent, &mut self.label, fan)
    }
}

/// `FanScratch::group_any` for a closed, consistently oriented fan of up to 8 corners (most
/// vertices of most meshes): each edge (v, u) then has exactly two face-edges, v -> u from the
/// corner whose next vertex is u and u -> v from the one whose previous vertex is u, so the
/// corners sorted by next and by previous vertex pair up edge by edge (as `Adjacency` finds
/// closed fans, with two sorting networks). None for any other fan.
#[inline]
fn group_closed_fan(
    v: u32,
    corners: &[RingCorner],
    unit: &[[f64; 3]],
    test: &impl HardEdges,
    fan: &mut [u32],
) -> Option<u32> {
    let r = corners.len();
    if r == 0 || r > 8 {
        return None;
    }
    // (vertex << 32 | corner); padding sorts last
    let mut after = [u64::MAX; 8];
    let mut before = [u64::MAX; 8];
    for (k, c) in corners.iter().enumerate() {
        after[k] = (c[0] as u64) << 32 | k as u64;
        before[k] = (c[1] as u64) << 32 | k as u64;
    }
    sort8(&mut after);
    sort8(&mut before);
    let mut closed = true;
    for k in 0..r {
        closed &= after[k] >> 32 == before[k] >> 32 && after[k] >> 32 != v as u64;
        if k > 0 {
            closed &= after[k - 1] >> 32 != after[k] >> 32;
        }
    }
    if !closed {
        return None;
    }
    let mut parent: [u32; 8] = std::array::from_fn(|k| k as u32);
    for (a, b) in after[..r].iter().zip(&before[..r]) {
        let edge = [v, (a >> 32) as u32];
        join_if_smooth(&mut parent, corners, edge, *a as u32 as usize, *b as u32 as usize, unit, test);
    }
    Some(number_fans(&mut parent[..r], &mut [NO_FAN; 8][..r], fan))
}

/// Joins corners `ka` and `kb` (the two face-edges of `edge`, [v, u]) when their faces are
/// different, both have normals and the edge is not hard.
#[inline]
fn join_if_smooth(
    parent: &mut [u32],
    corners: &[RingCorner],
    edge: [u32; 2],
    ka: usize,
    kb: usize,
    unit: &[[f64; 3]],
    test: &impl HardEdges,
) {
    let (fa, fb) = (corners[ka][2] / 3, corners[kb][2] / 3);
    let (na, nb) = (unit[fa as usize], unit[fb as usize]);
    if fa != fb && is_defined(na) && is_defined(nb) && !test.is_hard(edge[0], edge[1], na, nb) {
        // roots are each fan's first corner
        join(parent, ka, kb);
    }
}

/// Numbers the groups of `parent` by their first corner into `fan` (with `label`, all
/// `NO_FAN`, as room) and returns how many there are.
#[inline]
fn number_fans(parent: &mut [u32], label: &mut [u32], fan: &mut [u32]) -> u32 {
    let mut count = 0;
    for (k, f) in fan[..parent.len()].iter_mut().enumerate() {
        let root = find(parent, k) as usize;
        if label[root] == NO_FAN {
            label[root] = count;
            count += 1;
        }
        *f = label[root];
    }
    count
}

/// The unit normal of each of a vertex's fans into `out` (one per fan; one zero normal for an
/// unused vertex).
fn fan_normals(
    corners: &[RingCorner],
    fan: &[u32],
    area: &[[f64; 3]],
    sums: &mut Vec<[f64; 3]>,
    out: &mut [[f64; 3]],
) {
    let add = |s: &mut [f64; 3], n: [f64; 3]| {
        s[0] += n[0];
        s[1] += n[1];
        s[2] += n[2];
    };
    if out.len() == 1 {
        let mut s = [0.0; 3];
        for c in corners {
            add(&mut s, area[(c[2] / 3) as usize]);
        }
        out[0] = unit_or_zero(s);
        return;
    }
    sums.clear();
    sums.resize(out.len(), [0.0; 3]);
    let mut all = [0.0; 3];
    for (c, &k) in corners.iter().zip(fan) {
        let n = area[(c[2] / 3) as usize];
        add(&mut sums[k as usize], n);
        add(&mut all, n);
    }
    let fallback = unit_or_zero(all);
    for (o, s) in out.iter_mut().zip(sums.iter()) {
        let n = unit_or_zero(*s);
        *o = if is_defined(n) { n } else { fallback };
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::mesh::normals::vertex_normals;
    use crate::mesh::shapes::icosphere;

    /// A unit cube, 8 vertices and 12 outward faces.
    fn cube() -> (Vec<[f64; 3]>, Vec<[u32; 3]>) {
        let v = (0..8).map(|i| [(i & 1) as f64, (i >> 1 & 1) as f64, (i >> 2 & 1) as f64]).collect();
        let quads = [[0, 2, 3, 1], [4, 5, 7, 6], [0, 1, 5, 4], [2, 6, 7, 3], [0, 4, 6, 2], [1, 3, 7, 5]];
        let f = quads.iter().flat_map(|q| [[q[0], q[1], q[2]], [q[0], q[2], q[3]]]).collect();
        (v, f)
    }

    fn check_consistent(v: &[[f64; 3]], f: &[[u32; 3]], s: &SplitNormals) {
        assert_eq!(s.faces.len(), f.len());
        assert_eq!(s.source.len(), s.normals.len());
        for (a, b) in f.iter().zip(&s.faces) {
            for j in 0..3 {
                assert_eq!(s.source[b[j] as usize], a[j], "an output vertex copies its corner's vertex");
            }
        }
        assert!(s.normals.iter().flatten().all(|x| x.is_finite()));
        assert!(s.source.windows(2).all(|w| w[0] <= w[1]));
        assert!(s.source.len() >= v.len());
    }

    #[test]
    fn a_cube_splits_into_one_normal_per_face() {
        let (v, f) = cube();
        let s = crease_normals(&v, &f, 30.0).unwrap();
        check_consistent(&v, &f, &s);
        assert_eq!(s.normals.len(), 24, "each corner of the cube on three faces");
        let face_normal = face_normals(&v, &f);
        for (face, n) in s.faces.iter().zip(&face_normal) {
            for &i in face {
                assert_eq!(s.normals[i as usize], *n, "the corner takes its face's normal");
            }
        }
        // at 91 degrees nothing is a crease: the smooth normals, same numbering
        let smooth = crease_normals(&v, &f, 91.0).unwrap();
        assert_eq!(smooth.faces, f);
        assert_eq!(smooth.normals, vertex_normals(&v, &f));
    }

    #[test]
    fn a_smooth_sphere_is_the_smooth_normals_bit_for_bit() {
        for (sub, noise) in [(1, 0.0), (3, 0.0), (3, 0.01)] {
            let (v, f) = icosphere(sub, noise, 7).unwrap();
            let s = crease_normals(&v, &f, 30.0).unwrap();
            assert_eq!(s.faces, f);
            assert_eq!(s.source, (0..v.len() as u32).collect::<Vec<_>>());
            assert_eq!(s.normals, vertex_normals(&v, &f), "subdivisions {sub}");
        }
        // the icosahedron's faces meet at 41.8 degrees: every corner is its own fan
        let (v, f) = icosphere(0, 0.0, 0).unwrap();
        let s = crease_normals(&v, &f, 30.0).unwrap();
        assert_eq!(s.normals.len(), 60);
        assert_eq!(crease_normals(&v, &f, 45.0).unwrap().normals.len(), 12);
    }

    #[test]
    fn boundaries_degenerate_faces_and_nonmanifold_edges_stay_finite() {
        // a fan of four coplanar triangles around 0, open between faces 3 and 0, plus a
        // degenerate face (0, 1, 1), a zero-area one and a third face on edge 0-1
        let v = vec![
            [0.0, 0.0, 0.0],
            [1.0, 0.0, 0.0],
            [0.0, 1.0, 0.0],
            [-1.0, 0.0, 0.0],
            [0.0, -1.0, 0.0],
            [2.0, 0.0, 0.0],
            [0.0, 0.0, 1.0],
        ];
        let base = vec![[0, 1, 2], [0, 2, 3], [0, 3, 4], [0, 4, 1]];
        let s = crease_normals(&v, &base, 30.0).unwrap();
        assert_eq!(s.faces, base, "a flat fan, closed: one normal");
        let open = &base[..3];
        let s = crease_normals(&v, open, 30.0).unwrap();
        assert_eq!(s.faces, open, "an open fan is still one fan");
        let mut messy = base.clone();
        messy.extend([[0, 1, 1], [0, 1, 5], [0, 6, 1]]);
        let s = crease_normals(&v, &messy, 30.0).unwrap();
        check_consistent(&v, &messy, &s);
        // vertex 0: its flat fan (faces 0..3, joined by 0-2, 0-3, 0-4; 0-1 is non-manifold),
        // the degenerate (0, 1, 1), the collinear (0, 1, 5) and the upright (0, 6, 1)
        let zero: Vec<u32> = (0..s.source.len() as u32).filter(|&i| s.source[i as usize] == 0).collect();
        assert_eq!(zero.len(), 4);
        assert_eq!(s.normals[zero[0] as usize], [0.0, 0.0, 1.0]);
        for &i in &zero[1..] {
            assert!(is_defined(s.normals[i as usize]), "a degenerate fan takes the vertex normal");
        }
        // every face of a vertex degenerate: zero, as in the smooth normals
        let s = crease_normals(&v, &[[0, 1, 5], [1, 1, 2]], 30.0).unwrap();
        assert!(s.normals.iter().all(|&n| n.iter().all(|x| x.is_finite())));
        assert!(s.normals[s.faces[0][0] as usize] == [0.0; 3]);
    }

    #[test]
    fn at_zero_degrees_every_corner_takes_its_face_normal() {
        // many vertex chunks, every vertex split into one fan per face
        let (v, f) = icosphere(5, 0.0, 0).unwrap();
        let s = crease_normals(&v, &f, 0.0).unwrap();
        check_consistent(&v, &f, &s);
        assert_eq!(s.normals.len(), 3 * f.len());
        let unit = face_normals(&v, &f);
        for (face, n) in s.faces.iter().zip(&unit) {
            for &i in face {
                let m = s.normals[i as usize];
                assert!((0..3).all(|k| (m[k] - n[k]).abs() < 1e-12), "{m:?} {n:?}");
            }
        }
    }

    #[test]
    fn closed_fans_group_as_any_fan_does() {
        let (v, f) = icosphere(3, 0.05, 2).unwrap();
        let buckets = Buckets::corners_with_ids(v.len(), &f).unwrap();
        let unit = face_normals(&v, &f);
        let mut scratch = FanScratch::default();
        let mut closed_seen = 0;
        for angle in [0.0, 5.0, 10.0, 30.0] {
            let test = CreaseTest::new(angle).unwrap();
            for i in 0..v.len() {
                let ring = buckets.at(i);
                let (mut a, mut b) = (vec![0; ring.len()], vec![0; ring.len()]);
                if let Some(count) = group_closed_fan(i as u32, ring, &unit, &test, &mut a) {
                    assert_eq!(count, scratch.group_any(i as u32, ring, &unit, &test, &mut b));
                    assert_eq!(a, b);
                    closed_seen += 1;
                }
            }
        }
        assert!(closed_seen > 4 * 600, "almost every fan of a sphere is closed");
        // an open fan is not taken for a closed one
        let ring = [[1, 2, 0], [2, 3, 3]];
        assert!(group_closed_fan(
            0,
            &ring,
            &[[0.0, 0.0, 1.0]; 2],
            &CreaseTest::new(30.0).unwrap(),
            &mut [0; 2]
        )
        .is_none());
    }

    #[test]
    fn an_unused_vertex_keeps_its_place() {
        let (mut v, f) = cube();
        v.insert(0, [5.0, 5.0, 5.0]);
        let f: Vec<[u32; 3]> = f.iter().map(|t| t.map(|i| i + 1)).collect();
        let s = crease_normals(&v, &f, 30.0).unwrap();
        assert_eq!((s.source[0], s.normals[0]), (0, [0.0; 3]));
        assert_eq!(s.normals.len(), 25);
    }

    #[test]
    fn bad_angles_are_refused() {
        let (v, f) = cube();
        assert!(crease_normals(&v, &f, -1.0).is_err());
        assert!(crease_normals(&v, &f, f64::NAN).is_err());
        assert!(crease_normals(&v, &f, 180.0).is_ok());
    }
}

//! Intersection lines: where the surfaces of two meshes (or of one mesh with itself) cross, as
//! segments, one per pair of crossing triangles, found through the meshes' bounding-volume
//! hierarchies and joined into polylines.
//!
//! The rule for two triangles t and u: t's cut is where t crosses u's plane, u's cut where u
//! crosses t's plane; the crossing is the overlap of the two cuts on the planes' common line.
//! Every end point is the crossing of one triangle edge with the other triangle's plane,
//! computed from the edge's corners in a fixed order, so the pair of triangles on the other side
//! of that edge computes the same point to the bit and neighbouring segments join exactly.
//!
//! - A corner within rounding of the other plane (relative to the triangles' size and to their
//!   coordinates' magnitude) lies on it, and counts as in front of it (on the side the plane's
//!   normal points to): a triangle whose edge lies in the plane gives that edge only when it is
//!   behind the plane, so an edge shared by a triangle on each side is reported once, and two
//!   closed outward-facing meshes that merely rest on each other give nothing.
//! - Coplanar triangles give nothing, nor do degenerate ones (area at most
//!   `DEGENERATE_RELATIVE_AREA` times the longest edge squared), nor a triangle touching the
//!   other's plane at a vertex only (no segment has zero length).
//! - Triangles with two corners at the same positions (an edge shared, by index or by position)
//!   give nothing; a corner at the position of one of the other triangle's corners lies exactly
//!   on its plane, so triangles touching only there give nothing either. Where the positions are
//!   the same only to within rounding (meshes kept in coordinates of their own and moved into
//!   one frame, a part stored as pieces), a segment within `SEAM` of their size of an edge of
//!   each triangle is where they meet, not where they cross: nothing either.

use std::collections::HashMap;

use glam::{DMat4, DVec3};
use rayon::prelude::*;

use crate::cancel::Cancel;
use crate::edges::chains::chain_edges;
use crate::error::Result;
use crate::mesh::bvh::Bvh;
use crate::mesh::normals::DEGENERATE_RELATIVE_AREA;

/// Rounding allowance of a corner's side of a plane, in units of the rounding of its terms.
const SNAP: f64 = 32.0 * f64::EPSILON;
/// A segment within this fraction of its triangles' longest edge of an edge of each is where
/// they meet, not where they cross: rounding's room, well above it.
pub const SEAM: f64 = 1e-7;

/// One segment where face `faces[0]` of the first mesh meets face `faces[1]` of the second, in
/// the first mesh's frame.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Crossing {
    pub ends: [[f64; 3]; 2],
    pub faces: [u32; 2],
}

/// Every crossing of `a`'s triangles with `b`'s, `b`'s corners moved by `b_to_a` first (None:
/// the same frame), in `a`'s frame; in parallel, sorted by face pair.
pub fn between(a: &Bvh, b: &Bvh, b_to_a: Option<&DMat4>) -> Vec<Crossing> {
    let mut out = a.par_pairs(b, b_to_a, |sa, sb| {
        let ((fa, ta), (fb, tb)) = (a.triangle(sa), b.triangle(sb));
        let tb = b_to_a.map_or(tb, |m| tb.map(|p| m.transform_point3(p)));
        crossing(&ta, &tb).map(|ends| Crossing { ends, faces: [fa, fb] })
    });
    out.sort_unstable_by_key(|c| c.faces);
    out
}

/// A mesh's crossings with itself (`bvh` built over `faces`), each pair of faces once, the
/// smaller index first; pairs that share a vertex are skipped. Sorted by face pair.
pub fn within(bvh: &Bvh, faces: &[[u32; 3]]) -> Vec<Crossing> {
    let mut out = bvh.par_pairs(bvh, None, |sa, sb| {
        let ((fa, ta), (fb, tb)) = (bvh.triangle(sa), bvh.triangle(sb));
        if fa >= fb || share_vertex(faces[fa as usize], faces[fb as usize]) {
            return None;
        }
        crossing(&ta, &tb).map(|ends| Crossing { ends, faces: [fa, fb] })
    });
    out.sort_unstable_by_key(|c| c.faces);
    out
}

/// `between` without a hierarchy: every triangle of `a` against every triangle of `b` (both in
/// one frame, indexed by their place in the slices); the reference the hierarchy is held to.
pub fn brute_force(a: &[[DVec3; 3]], b: &[[DVec3; 3]]) -> Vec<Crossing> {
    all_pairs(a, b, |_, _| true)
}

/// `within` without a hierarchy (`corners` of `faces`, in face order).
pub fn brute_force_within(corners: &[[DVec3; 3]], faces: &[[u32; 3]]) -> Vec<Crossing> {
    all_pairs(corners, corners, |i, j| i < j && !share_vertex(faces[i], faces[j]))
}

fn all_pairs(
    a: &[[DVec3; 3]],
    b: &[[DVec3; 3]],
    keep: impl Fn(usize, usize) -> bool + Sync,
) -> Vec<Crossing> {
    (0..a.len())
        .into_par_iter()
        .flat_map_iter(|i| {
            let keep = &keep;
            (0..b.len()).filter_map(move |j| {
                let ends = crossing(&a[i], &b[j]).filter(|_| keep(i, j))?;
                Some(Crossing { ends, faces: [i as u32, j as u32] })
            })
        })
        .collect()
}

/// A mesh as `among` takes it: each face's corners, in face order, and the faces.
pub type Triangles<'a> = (Vec<[DVec3; 3]>, &'a [[u32; 3]]);

/// Every crossing among a scene's meshes, all given in one frame as each face's corners (in
/// face order) and the faces: each pair of meshes (i < j, in order), then with `with_self`
/// each mesh with itself. `brute_force` compares every pair of triangles instead of building
/// hierarchies (the reference).
pub fn among(
    meshes: Vec<Triangles<'_>>,
    with_self: bool,
    brute_force: bool,
    cancel: &Cancel,
) -> Result<Vec<Crossing>> {
    enum Held<'a> {
        Corners(Vec<[DVec3; 3]>, &'a [[u32; 3]]),
        Tree(Bvh, &'a [[u32; 3]]),
    }
    let held: Vec<Held<'_>> = meshes
        .into_par_iter()
        .map(|(corners, faces)| match brute_force {
            true => Held::Corners(corners, faces),
            false => Held::Tree(Bvh::of_triangles(corners), faces),
        })
        .collect();
    cancel.check()?;
    let mut out = Vec::new();
    for i in 0..held.len() {
        for j in i + 1..held.len() {
            out.extend(match (&held[i], &held[j]) {
                (Held::Tree(a, _), Held::Tree(b, _)) => between(a, b, None),
                (Held::Corners(a, _), Held::Corners(b, _)) => self::brute_force(a, b),
                _ => unreachable!("one kind for all"),
            });
            cancel.check()?;
        }
    }
    for mesh in held.iter().filter(|_| with_self) {
        out.extend(match mesh {
            Held::Tree(bvh, faces) => within(bvh, faces),
            Held::Corners(corners, faces) => brute_force_within(corners, faces),
        });
        cancel.check()?;
    }
    Ok(out)
}

/// Segments joined into polylines where their ends are the same point (to the bit, as the rule
/// makes shared ends), chained as `chains::chain_edges` chains edges; a closed loop repeats its
/// first point at the end. Where an edge of one mesh crosses an edge of the other, the segments
/// meeting there compute that point from different edges and planes: an end that meets no
/// other end is joined to the nearest such end of another segment within `WELD`.
pub fn chain(crossings: &[Crossing]) -> Vec<Vec<[f64; 3]>> {
    let mut ids: HashMap<[u64; 3], u32> = HashMap::new();
    let mut points: Vec<[f64; 3]> = Vec::new();
    let mut id = |p: [f64; 3]| {
        // + 0.0 makes -0.0 the same point as 0.0
        *ids.entry(p.map(|x| (x + 0.0).to_bits())).or_insert_with(|| {
            points.push(p);
            points.len() as u32 - 1
        })
    };
    let edges: Vec<[u32; 2]> = crossings.iter().map(|c| [id(c.ends[0]), id(c.ends[1])]).collect();
    let edges = welded(&points, edges);
    let (flat, offsets) = chain_edges(&edges);
    offsets
        .windows(2)
        .map(|w| flat[w[0] as usize..w[1] as usize].iter().map(|&i| points[i as usize]).collect())
        .collect()
}

/// How far apart two computations of one point may be, relative to the larger coordinate
/// magnitude of the two (a few units in the last place).
const WELD: f64 = 16.0 * f64::EPSILON;

/// How far apart `p` and `q` are (the largest coordinate difference), where that is within `WELD`.
fn near(p: [f64; 3], q: [f64; 3]) -> Option<f64> {
    let magnitude = |p: [f64; 3]| p.iter().fold(0.0f64, |m, c| m.max(c.abs()));
    let d = (0..3).fold(0.0f64, |m, a| m.max((p[a] - q[a]).abs()));
    (d <= WELD * magnitude(p).max(magnitude(q))).then_some(d)
}

/// `edges` between `points` with each end that no other edge shares joined to the nearest such
/// end of another edge within `WELD` (the smaller index standing for both).
fn welded(points: &[[f64; 3]], edges: Vec<[u32; 2]>) -> Vec<[u32; 2]> {
    let mut degree = vec![0u32; points.len()];
    let mut edge_of = vec![0usize; points.len()];
    for (k, e) in edges.iter().enumerate() {
        for &i in e {
            degree[i as usize] += 1;
            edge_of[i as usize] = k;
        }
    }
    let mut open: Vec<u32> = (0..points.len() as u32).filter(|&i| degree[i as usize] == 1).collect();
    open.sort_by(|&i, &j| points[i as usize][0].total_cmp(&points[j as usize][0]).then(i.cmp(&j)));
    let mut to: Vec<u32> = (0..points.len() as u32).collect();
    let mut taken = vec![false; open.len()];
    for k in 0..open.len() {
        if taken[k] {
            continue;
        }
        let (i, p) = (open[k], points[open[k] as usize]);
        let mut best: Option<(f64, usize)> = None;
        for (l, &j) in open.iter().enumerate().skip(k + 1) {
            let q = points[j as usize];
            // sorted by x: nothing further on is near
            if q[0] - p[0] > 2.0 * WELD * p.iter().fold(0.0f64, |m, c| m.max(c.abs())) {
                break;
            }
            let d = near(p, q).filter(|_| !taken[l] && edge_of[i as usize] != edge_of[j as usize]);
            if let Some(d) = d.filter(|&d| best.is_none_or(|(b, _)| d < b)) {
                best = Some((d, l));
            }
        }
        if let Some((_, l)) = best {
            taken[l] = true;
            to[open[l] as usize] = i.min(open[l]);
            to[i as usize] = i.min(open[l]);
        }
    }
    edges.into_iter().map(|e| e.map(|i| to[i as usize])).collect()
}

fn share_vertex(f: [u32; 3], g: [u32; 3]) -> bool {
    f.iter().any(|v| g.contains(v))
}

/// The segment where triangles `t` and `u` cross (see the module's rule), its ends in the
/// order of the line's main axis; None where they do not cross along a segment.
pub fn crossing(t: &[DVec3; 3], u: &[DVec3; 3]) -> Option<[[f64; 3]; 2]> {
    if t.iter().filter(|p| u.contains(p)).count() >= 2 {
        return None;
    }
    let (pt, pu) = (Plane::of(t)?, Plane::of(u)?);
    let mut a = cut(t, &pu)?;
    let mut b = cut(u, &pt)?;
    // Both cuts lie on the planes' common line: order them along its main axis, read from the
    // points themselves (exact comparisons of coordinates, at any offset).
    let (lo, hi) = [a[1], b[0], b[1]].iter().fold((a[0], a[0]), |(lo, hi), &p| (lo.min(p), hi.max(p)));
    let axis = (hi - lo).max_position();
    for c in [&mut a, &mut b] {
        if c[1][axis] < c[0][axis] {
            c.swap(0, 1);
        }
    }
    let start = if b[0][axis] > a[0][axis] { b[0] } else { a[0] };
    let end = if b[1][axis] < a[1][axis] { b[1] } else { a[1] };
    let (start, end) = (start.to_array(), end.to_array());
    // shorter than rounding: the cuts only touch (a few units in the last place long, where an
    // edge of one triangle crosses an edge of the other)
    let crosses = start[axis] < end[axis] && near(start, end).is_none();
    (crosses && !only_meet(t, u, DVec3::from_array(start), DVec3::from_array(end))).then_some([start, end])
}

/// Whether the segment p-q of triangles `t` and `u` is where they only meet: along an edge of
/// each (`SEAM`).
fn only_meet(t: &[DVec3; 3], u: &[DVec3; 3], p: DVec3, q: DVec3) -> bool {
    let longest = |t: &[DVec3; 3]| (0..3).map(|k| t[k].distance(t[(k + 1) % 3])).fold(0.0, f64::max);
    let eps = SEAM * longest(t).max(longest(u));
    let on_an_edge = |t: &[DVec3; 3]| {
        (0..3).any(|k| {
            let (a, b) = (t[k], t[(k + 1) % 3]);
            distance_to_segment(p, a, b) <= eps && distance_to_segment(q, a, b) <= eps
        })
    };
    on_an_edge(t) && on_an_edge(u)
}

fn distance_to_segment(p: DVec3, a: DVec3, b: DVec3) -> f64 {
    let ab = b - a;
    let t =
        if ab.length_squared() > 0.0 { ((p - a).dot(ab) / ab.length_squared()).clamp(0.0, 1.0) } else { 0.0 };
    p.distance(a + ab * t)
}

/// A triangle's plane as the rule reads it.
struct Plane {
    corners: [DVec3; 3],
    /// (b - a) x (c - a), not normalised.
    normal: DVec3,
    /// |b - a| |c - a|: what the normal's rounding is relative to.
    sides: f64,
    /// The largest coordinate magnitude of the corners: what their own rounding is relative to.
    magnitude: f64,
}

impl Plane {
    /// None for a degenerate triangle.
    fn of(c: &[DVec3; 3]) -> Option<Plane> {
        let (e1, e2) = (c[1] - c[0], c[2] - c[0]);
        let normal = e1.cross(e2);
        let longest = e1.length_squared().max(e2.length_squared()).max((c[2] - c[1]).length_squared());
        // written negated so that NaN counts as degenerate
        #[allow(clippy::neg_cmp_op_on_partial_ord)]
        if !(normal.length() > DEGENERATE_RELATIVE_AREA * longest) {
            return None;
        }
        let magnitude = c.iter().map(|p| p.abs().max_element()).fold(0.0, f64::max);
        Some(Plane { corners: *c, normal, sides: e1.length() * e2.length(), magnitude })
    }

    /// Which side of the plane `x` is on, as |normal| times its signed distance; exactly 0 for a
    /// corner of the triangle and for a point within rounding of the plane.
    fn side(&self, x: DVec3) -> f64 {
        if self.corners.contains(&x) {
            return 0.0;
        }
        let d = x - self.corners[0];
        let s = self.normal.dot(d);
        let rounding =
            self.sides * d.length() + self.normal.length() * self.magnitude.max(x.abs().max_element());
        if s.abs() <= SNAP * rounding {
            0.0
        } else {
            s
        }
    }
}

/// Where triangle `t` crosses `plane`: the two ends of its cut (the same point where it only
/// touches at a vertex); None where it stays on one side or lies in the plane. A corner on the
/// plane counts as in front.
fn cut(t: &[DVec3; 3], plane: &Plane) -> Option<[DVec3; 2]> {
    let s = t.map(|p| plane.side(p));
    if s == [0.0; 3] {
        return None;
    }
    let front = s.map(|v| v >= 0.0);
    if front[0] == front[1] && front[1] == front[2] {
        return None;
    }
    // the corner alone on its side
    let k = if front[0] == front[1] {
        2
    } else if front[0] == front[2] {
        1
    } else {
        0
    };
    let (i, j) = ((k + 1) % 3, (k + 2) % 3);
    Some([edge_point((t[k], s[k]), (t[i], s[i])), edge_point((t[k], s[k]), (t[j], s[j]))])
}

/// Where the edge p-q (with the sides `s` of its ends, of opposite signs or one zero) crosses the
/// plane: a corner on the plane itself, else interpolated from the lexicographically smaller
/// corner, so that both triangles on the edge compute the same point.
fn edge_point((p, sp): (DVec3, f64), (q, sq): (DVec3, f64)) -> DVec3 {
    if sp == 0.0 {
        return p;
    }
    if sq == 0.0 {
        return q;
    }
    let ((p, sp), (q, sq)) = if lexicographic(q, p) { ((q, sq), (p, sp)) } else { ((p, sp), (q, sq)) };
    p + (q - p) * (sp / (sp - sq))
}

/// Whether `a` comes before `b` by x, then y, then z.
fn lexicographic(a: DVec3, b: DVec3) -> bool {
    a.to_array() < b.to_array()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_seam_or_a_touch_within_rounding_is_no_crossing_and_a_triangle_through_another_is() {
        let v = |x: f64, y: f64, z: f64| DVec3::new(x, y, z);
        // two plates folded along x = 0 .. 1 (y = z = 0), the second a rounding away
        let ta = [v(0.0, 0.0, 0.0), v(1.0, 0.0, 0.0), v(1.0, 1.0, 0.0)];
        let tb = [v(0.0, 1e-17, 0.0), v(0.0, 0.0, -1.0), v(1.0, 0.0, 1e-17)];
        assert!(only_meet(&ta, &tb, v(0.0, 0.0, 0.0), v(1.0, 0.0, 0.0)));
        assert!(only_meet(&ta, &tb, v(0.5, 0.0, 0.0), v(0.5, 1e-18, 0.0)));
        assert_eq!(crossing(&ta, &tb), None);
        // a triangle through the middle of another: a crossing
        let tc = [v(0.2, 0.5, -1.0), v(0.9, 0.5, -1.0), v(0.6, 0.5, 1.0)];
        assert!(!only_meet(&ta, &tc, v(0.5, 0.5, 0.0), v(0.75, 0.5, 0.0)));
        assert!(crossing(&ta, &tc).is_some());
    }

    fn v(x: f64, y: f64, z: f64) -> DVec3 {
        DVec3::new(x, y, z)
    }

    /// A large triangle in z = 0, facing +z.
    fn floor() -> [DVec3; 3] {
        [v(-1.0, -1.0, 0.0), v(2.0, -1.0, 0.0), v(-1.0, 2.0, 0.0)]
    }

    #[test]
    fn a_triangle_through_another_gives_the_overlap_of_the_cuts() {
        let wall = [v(-0.5, 0.25, -1.0), v(0.5, 0.25, -1.0), v(0.0, 0.25, 1.0)];
        assert_eq!(crossing(&floor(), &wall), Some([[-0.25, 0.25, 0.0], [0.25, 0.25, 0.0]]));
        // the other way round: the same segment
        assert_eq!(crossing(&wall, &floor()), Some([[-0.25, 0.25, 0.0], [0.25, 0.25, 0.0]]));
        // a wall reaching past the floor's hypotenuse x + y = 1 is cut there
        let wide = [v(-0.5, 0.25, -1.0), v(3.5, 0.25, -1.0), v(1.5, 0.25, 1.0)];
        let [p, q] = crossing(&floor(), &wide).unwrap();
        assert_eq!(p, [0.5, 0.25, 0.0]);
        assert!((q[0] - 0.75).abs() < 1e-15 && q[1] == 0.25 && q[2] == 0.0);
        // a wall beside the floor does not reach it
        let away = wide.map(|p| p + v(0.0, 5.0, 0.0));
        assert_eq!(crossing(&floor(), &away), None);
    }

    #[test]
    fn the_rule_is_scale_free() {
        let wall = [v(-0.5, 0.25, -1.0), v(0.5, 0.25, -1.0), v(0.0, 0.25, 1.0)];
        for (scale, offset) in [(1e-3, 0.0), (1e-3, 1e6), (1.0, 1e6), (1e5, -3e7), (1e-9, 1.0)] {
            let m = |t: [DVec3; 3]| t.map(|p| p * scale + DVec3::splat(offset));
            let [p, q] = crossing(&m(floor()), &m(wall)).unwrap_or_else(|| panic!("{scale} {offset}"));
            let near =
                |a: [f64; 3], b: DVec3| (DVec3::from_array(a) - b).length() <= 1e-12 * (scale + offset.abs());
            assert!(near(p, v(-0.25, 0.25, 0.0) * scale + DVec3::splat(offset)), "{p:?}");
            assert!(near(q, v(0.25, 0.25, 0.0) * scale + DVec3::splat(offset)), "{q:?}");
        }
    }

    #[test]
    fn coplanar_and_degenerate_triangles_give_nothing() {
        let other = [v(-0.5, -0.5, 0.0), v(0.5, 0.0, 0.0), v(0.0, 0.7, 0.0)];
        assert_eq!(crossing(&floor(), &other), None);
        // coplanar after a rotation that rounds every corner
        let r = DMat4::from_euler(glam::EulerRot::XYZ, 0.3, 1.1, -0.4)
            * DMat4::from_translation(v(0.0, 0.0, 7.0));
        let turn = |t: [DVec3; 3]| t.map(|p| r.transform_point3(p));
        assert_eq!(crossing(&turn(floor()), &turn(other)), None);
        let needle = [v(0.0, 0.0, -1.0), v(0.0, 0.0, 1.0), v(0.0, 0.0, 0.5)];
        assert_eq!(crossing(&floor(), &needle), None);
        assert_eq!(crossing(&needle, &floor()), None);
    }

    #[test]
    fn touching_at_a_vertex_gives_nothing_and_an_edge_in_the_plane_is_given_once() {
        let above = [v(0.0, 0.0, 0.0), v(0.5, 0.0, 1.0), v(0.0, 0.5, 1.0)];
        let below = above.map(|p| p * v(1.0, 1.0, -1.0));
        assert_eq!(crossing(&floor(), &above), None);
        assert_eq!(crossing(&floor(), &below), None);
        // an edge lying in the floor: nothing from the triangle in front, the edge from the one behind
        let front = [v(-0.5, 0.25, 0.0), v(0.5, 0.25, 0.0), v(0.0, 0.25, 1.0)];
        let behind = front.map(|p| p * v(1.0, 1.0, -1.0));
        assert_eq!(crossing(&floor(), &front), None);
        assert_eq!(crossing(&floor(), &behind), Some([[-0.5, 0.25, 0.0], [0.5, 0.25, 0.0]]));
    }

    #[test]
    fn a_crossing_shorter_than_rounding_is_none() {
        // a wall along x + y = -2 + e, past the floor's corner (-1, -1) by e
        let wall = |e: f64| [v(-2.0, e, -1.0), v(0.0, -2.0 + e, -1.0), v(-1.0, -1.0 + e, 1.0)];
        assert_eq!(crossing(&floor(), &wall(2f64.powi(-50))), None);
        let [p, q] = crossing(&floor(), &wall(2f64.powi(-30))).unwrap();
        assert_eq!([p, q], [[-1.0, -1.0 + 2f64.powi(-30), 0.0], [-1.0 + 2f64.powi(-30), -1.0, 0.0]]);
    }

    #[test]
    fn shared_positions_touch_but_do_not_cross() {
        let f = floor();
        // folded along a shared edge
        assert_eq!(crossing(&f, &[f[0], f[1], v(0.0, 0.0, 1.0)]), None);
        // one shared corner: touching there is nothing, crossing from there is a segment
        assert_eq!(crossing(&f, &[f[0], v(0.0, 0.0, 1.0), v(0.0, 1.0, 1.0)]), None);
        let through = [f[0], v(1.0, 0.0, 1.0), v(1.0, 0.0, -1.0)];
        let [p, q] = crossing(&f, &through).unwrap();
        assert_eq!(p, f[0].to_array());
        assert!((DVec3::from_array(q) - v(1.0, 0.0, 0.0)).length() < 1e-15);
    }

    /// An octahedron of radius 1 around `c`.
    fn octahedron(c: DVec3) -> Vec<[DVec3; 3]> {
        let (x, y, z) = (DVec3::X, DVec3::Y, DVec3::Z);
        let mut out = Vec::new();
        for sx in [1.0, -1.0] {
            for sy in [1.0, -1.0] {
                for sz in [1.0, -1.0] {
                    let t = [c + x * sx, c + y * sy, c + z * sz];
                    out.push(if sx * sy * sz > 0.0 { t } else { [t[0], t[2], t[1]] });
                }
            }
        }
        out
    }

    #[test]
    fn a_plane_through_an_octahedron_chains_into_one_closed_loop() {
        let solid = Bvh::of_triangles(octahedron(v(0.1, -0.05, 0.03)));
        let m = DMat4::from_rotation_x(0.3) * DMat4::from_rotation_y(-0.2);
        let quad = [
            [v(-3.0, -3.0, 0.0), v(3.0, -3.0, 0.0), v(3.0, 3.0, 0.0)],
            [v(-3.0, -3.0, 0.0), v(3.0, 3.0, 0.0), v(-3.0, 3.0, 0.0)],
        ];
        let plane = Bvh::of_triangles(quad.to_vec());
        let found = between(&solid, &plane, Some(&m));
        assert!(found.len() >= 6, "{found:?}");
        let lines = chain(&found);
        assert_eq!(lines.len(), 1);
        assert_eq!(lines[0].len(), found.len() + 1);
        assert_eq!(lines[0].first(), lines[0].last());
        // every point on the moved plane and on the octahedron's surface |x| + |y| + |z| = 1
        let normal = m.transform_vector3(DVec3::Z);
        for p in &lines[0] {
            let p = DVec3::from_array(*p);
            assert!(normal.dot(p).abs() < 1e-14);
            assert!(((p - v(0.1, -0.05, 0.03)).abs().element_sum() - 1.0).abs() < 1e-14);
        }
    }

    #[test]
    fn chain_joins_segments_at_equal_ends() {
        let c = |a: [f64; 3], b: [f64; 3]| Crossing { ends: [a, b], faces: [0, 0] };
        let (p, q, r) = ([0.0, 0.0, 0.0], [1.0, 0.0, 0.0], [1.0, 1.0, 0.0]);
        assert_eq!(chain(&[c(p, q), c(r, q)]), vec![vec![p, q, r]]);
        assert_eq!(chain(&[c(p, q), c(q, r), c(r, p)]), vec![vec![p, q, r, p]]);
        // -0.0 is 0.0; an end a few bits away from another end is that end, one 1e-12 away is not
        assert_eq!(chain(&[c([-0.0, 0.0, 0.0], q), c(p, r)]).len(), 1);
        let bits = |x: f64, k: u64| f64::from_bits(x.to_bits() + k);
        let next = [bits(1.0, 3), bits(0.0, 1), 0.0];
        assert_eq!(chain(&[c(p, q), c(next, r)]), vec![vec![p, q, r]]);
        assert_eq!(chain(&[c(p, q), c([1.0 + 1e-12, 0.0, 0.0], r)]).len(), 2);
        // nor are a short segment's own two ends
        assert_eq!(chain(&[c(q, next)]), vec![vec![q, next]]);
        assert!(chain(&[]).is_empty());
    }

    fn soup(n: usize, seed: u64, size: f64) -> Vec<[DVec3; 3]> {
        let mut rng = crate::mesh::shapes::SplitMix64::new(seed);
        let mut next = move || rng.symmetric();
        (0..n)
            .map(|_| {
                let c = v(next(), next(), next()) * 3.0;
                let mut corner = || c + v(next(), next(), next()) * size;
                [corner(), corner(), corner()]
            })
            .collect()
    }

    #[test]
    fn the_hierarchy_finds_what_brute_force_finds() {
        let (a, b) = (soup(1500, 1, 0.6), soup(1200, 2, 0.6));
        let m = DMat4::from_rotation_z(0.4) * DMat4::from_translation(v(0.1, 0.2, -0.1));
        let moved: Vec<[DVec3; 3]> = b.iter().map(|t| t.map(|p| m.transform_point3(p))).collect();
        let mut want = brute_force(&a, &moved);
        want.sort_unstable_by_key(|c| c.faces);
        assert!(want.len() > 100, "{}", want.len());
        assert_eq!(between(&Bvh::of_triangles(a.clone()), &Bvh::of_triangles(b), Some(&m)), want);
        // a soup with itself, as a mesh whose faces share some vertices
        let faces: Vec<[u32; 3]> = (0..a.len() as u32).map(|i| [i, i + 1, i + 2].map(|k| k % 700)).collect();
        let mut want = brute_force_within(&a, &faces);
        want.sort_unstable_by_key(|c| c.faces);
        assert!(want.len() > 50, "{}", want.len());
        assert_eq!(within(&Bvh::of_triangles(a), &faces), want);
    }

    /// The figures the benchmark reports from Python, where the hierarchies cannot be kept:
    /// `cargo test --release --lib intersections::tests::timing -- --ignored --nocapture`.
    #[test]
    #[ignore]
    fn timing() {
        use std::time::Instant;
        let (p, f) = crate::mesh::shapes::icosphere(7, 0.0, 0).unwrap();
        let moved: Vec<[f64; 3]> = p.iter().map(|q| [q[0] + 0.5, q[1], q[2]]).collect();
        let best = |run: &dyn Fn() -> usize| {
            let mut times: Vec<(f64, usize)> = (0..5)
                .map(|_| {
                    let t = Instant::now();
                    let n = run();
                    (t.elapsed().as_secs_f64(), n)
                })
                .collect();
            times.sort_by(|a, b| a.0.total_cmp(&b.0));
            times[2]
        };
        let cold = best(&|| between(&Bvh::build(&p, &f), &Bvh::build(&moved, &f), None).len());
        let (a, b) = (Bvh::build(&p, &f), Bvh::build(&moved, &f));
        let warm = best(&|| between(&a, &b, None).len());
        let build = best(&|| Bvh::build(&p, &f).len());
        println!(
            "icosphere(7) x2, {} faces each: cold {:.1} ms, built {:.1} ms, one build {:.1} ms, {} crossings",
            f.len(),
            cold.0 * 1e3,
            warm.0 * 1e3,
            build.0 * 1e3,
            warm.1
        );
        let (p, f) = crate::mesh::shapes::icosphere(4, 0.0, 0).unwrap();
        let tri = |d: f64| {
            f.iter().map(|t| t.map(|i| DVec3::from_array(p[i as usize]) + DVec3::X * d)).collect::<Vec<_>>()
        };
        let (ta, tb) = (tri(0.0), tri(0.5));
        let brute = best(&|| brute_force(&ta, &tb).len());
        let tree =
            best(&|| between(&Bvh::of_triangles(ta.clone()), &Bvh::of_triangles(tb.clone()), None).len());
        assert_eq!(brute.1, tree.1);
        println!(
            "icosphere(4) x2, {} faces each: brute force {:.1} ms, hierarchy (cold) {:.2} ms, ratio {:.0}",
            f.len(),
            brute.0 * 1e3,
            tree.0 * 1e3,
            brute.0 / tree.0
        );
    }
}

//! A bounding-volume hierarchy over a mesh's triangles (axis-aligned boxes, binned surface-area
//! split, built in parallel): what exact line visibility casts its rays against and what
//! intersection lines find their pairs of triangles with. Coordinates are float64, in whatever
//! frame the corners are given (a mesh keeps its hierarchy in its stored coordinates).

use glam::{DMat4, DVec3};
use rayon::prelude::*;

use crate::real::{Real, Vec3};

/// Triangles per leaf at most.
const LEAF: usize = 4;
/// Bins of the surface-area split.
const BINS: usize = 12;
/// Subtrees with more triangles than this are built on two threads.
const PARALLEL: usize = 4096;
/// Pairs of nodes `par_pairs` splits its traversal into, at least, where the trees allow.
const PAIR_TASKS: usize = 256;
/// Barycentric slack of the ray test, so that a ray through an edge shared by two triangles
/// meets at least one of them (rounding never opens a crack).
const SLACK: f64 = 1e-12;

/// An axis-aligned box, closed.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Aabb {
    pub lo: DVec3,
    pub hi: DVec3,
}

impl Aabb {
    pub const EMPTY: Aabb = Aabb { lo: DVec3::splat(f64::INFINITY), hi: DVec3::splat(f64::NEG_INFINITY) };

    pub fn of(points: &[DVec3]) -> Aabb {
        points.iter().fold(Aabb::EMPTY, |b, &p| b.with(p))
    }

    pub fn with(self, p: DVec3) -> Aabb {
        Aabb { lo: self.lo.min(p), hi: self.hi.max(p) }
    }

    pub fn union(self, o: Aabb) -> Aabb {
        Aabb { lo: self.lo.min(o.lo), hi: self.hi.max(o.hi) }
    }

    /// Whether the two closed boxes share a point.
    pub fn overlaps(&self, o: &Aabb) -> bool {
        self.lo.cmple(o.hi).all() && o.lo.cmple(self.hi).all()
    }

    fn area(&self) -> f64 {
        let d = (self.hi - self.lo).max(DVec3::ZERO);
        d.x * d.y + d.y * d.z + d.z * d.x
    }

    /// The box around this one moved by the affine `m`.
    pub fn transformed(&self, m: &DMat4) -> Aabb {
        let mut out = Aabb::EMPTY;
        for k in 0..8 {
            let c = DVec3::new(
                if k & 1 == 0 { self.lo.x } else { self.hi.x },
                if k & 2 == 0 { self.lo.y } else { self.hi.y },
                if k & 4 == 0 { self.lo.z } else { self.hi.z },
            );
            out = out.with(m.transform_point3(c));
        }
        out
    }

    /// The ray parameters `o + t d` inside the box, cut to `[t0, t1]`; None when they are none.
    /// `inv` is `1 / d`: infinite along an axis the ray runs parallel to, where the ray is in
    /// the slab or not (a ray along one of the box's faces is in it).
    fn clip(&self, o: DVec3, inv: DVec3, t0: f64, t1: f64) -> Option<(f64, f64)> {
        let (mut near, mut far) = (t0, t1);
        for k in 0..3 {
            if inv[k].is_infinite() {
                // rounding's room, as the triangle test's SLACK gives it
                let pad = SLACK * (self.hi[k].abs() + self.lo[k].abs());
                if o[k] < self.lo[k] - pad || o[k] > self.hi[k] + pad {
                    return None;
                }
                continue;
            }
            let (a, b) = ((self.lo[k] - o[k]) * inv[k], (self.hi[k] - o[k]) * inv[k]);
            near = near.max(a.min(b));
            far = far.min(a.max(b));
        }
        (near <= far).then_some((near, far))
    }
}

/// One node: a leaf holds `count` triangles from `first` (in `Bvh::order`); an inner node
/// (`count == 0`) has its children at `first` and `first + 1`.
#[derive(Clone, Copy, Debug)]
struct Node {
    bounds: Aabb,
    first: u32,
    count: u32,
}

/// The hierarchy of a triangle soup.
pub struct Bvh {
    nodes: Vec<Node>,
    /// Triangle ids in leaf order.
    order: Vec<u32>,
    /// Each triangle's corners, in leaf order.
    corners: Vec<[DVec3; 3]>,
}

enum Tree {
    Leaf(Aabb, Vec<u32>),
    Inner(Aabb, Box<Tree>, Box<Tree>),
}

impl Bvh {
    /// The hierarchy of `faces` over `positions` (indices checked by the caller), in f64.
    pub fn build<T: Real>(positions: &[Vec3<T>], faces: &[[u32; 3]]) -> Bvh {
        Bvh::of_triangles(triangles(positions, faces))
    }

    /// The hierarchy of triangles given by their corners.
    pub fn of_triangles(corners: Vec<[DVec3; 3]>) -> Bvh {
        let boxes: Vec<Aabb> = corners.par_iter().map(|c| Aabb::of(c)).collect();
        let centres: Vec<DVec3> = boxes.par_iter().map(|b| (b.lo + b.hi) * 0.5).collect();
        let ids: Vec<u32> = (0..corners.len() as u32).collect();
        let mut nodes = Vec::with_capacity(2 * corners.len() / LEAF + 1);
        let mut order = Vec::with_capacity(corners.len());
        if corners.is_empty() {
            // an empty root: the queries return before reading it
            nodes.push(Node { bounds: Aabb::EMPTY, first: 0, count: 0 });
        } else {
            let tree = split(ids, &boxes, &centres);
            nodes.push(Node { bounds: Aabb::EMPTY, first: 0, count: 0 });
            flatten(tree, 0, &mut nodes, &mut order);
        }
        let corners = order.iter().map(|&t| corners[t as usize]).collect();
        Bvh { nodes, order, corners }
    }

    pub fn len(&self) -> usize {
        self.order.len()
    }

    pub fn is_empty(&self) -> bool {
        self.order.is_empty()
    }

    /// The box around every triangle.
    pub fn bounds(&self) -> Aabb {
        self.nodes[0].bounds
    }

    /// The triangle in leaf slot `slot` (see `pairs`): its index in the faces given, and its corners.
    pub fn triangle(&self, slot: usize) -> (u32, [DVec3; 3]) {
        (self.order[slot], self.corners[slot])
    }

    /// Calls `hit(triangle, t)` for every triangle the ray `o + t d` meets with `t0 < t < t1`
    /// (both sides of a triangle; a ray through a shared edge may meet both triangles), until
    /// `hit` returns true.
    pub fn ray(&self, o: DVec3, d: DVec3, t0: f64, t1: f64, mut hit: impl FnMut(u32, f64) -> bool) {
        if self.is_empty() {
            return;
        }
        let inv = d.recip();
        let mut stack = Vec::with_capacity(64);
        stack.push(0usize);
        while let Some(n) = stack.pop() {
            let node = self.nodes[n];
            if node.bounds.clip(o, inv, t0, t1).is_none() {
                continue;
            }
            if node.count == 0 {
                stack.push(node.first as usize);
                stack.push(node.first as usize + 1);
                continue;
            }
            for slot in node.first as usize..(node.first + node.count) as usize {
                if let Some(t) = ray_triangle(o, d, &self.corners[slot]) {
                    if t > t0 && t < t1 && hit(self.order[slot], t) {
                        return;
                    }
                }
            }
        }
    }

    /// Calls `pair(slot_a, slot_b)` (slots: see `triangle`) for every triangle of `self` and of
    /// `other` whose boxes overlap, `other`'s corners moved by `other_to_self` first (None: the
    /// same frame). Boxes of moved nodes are the boxes around their moved corners, so no pair
    /// whose triangles touch is missed.
    pub fn pairs(&self, other: &Bvh, other_to_self: Option<&DMat4>, pair: impl FnMut(usize, usize)) {
        if self.is_empty() || other.is_empty() {
            return;
        }
        self.walk(other, other_to_self, (0, 0), pair);
    }

    /// `pairs` in parallel (rayon, in the caller's pool): what `pair(slot_a, slot_b)` returns
    /// for each pair of overlapping boxes, Nones left out, in an order that depends only on the
    /// two trees.
    pub fn par_pairs<R: Send>(
        &self,
        other: &Bvh,
        other_to_self: Option<&DMat4>,
        pair: impl Fn(usize, usize) -> Option<R> + Sync,
    ) -> Vec<R> {
        if self.is_empty() || other.is_empty() {
            return Vec::new();
        }
        // breadth first until there are enough pairs of nodes to share out
        let mut tasks = vec![(0usize, 0usize)];
        loop {
            let mut next = Vec::with_capacity(2 * tasks.len());
            let mut split = false;
            for &(a, b) in &tasks {
                match self.step(other, other_to_self, a, b) {
                    Step::Apart => {}
                    Step::Leaves => next.push((a, b)),
                    Step::Into(children) => {
                        next.extend(children);
                        split = true;
                    }
                }
            }
            tasks = next;
            if !split || tasks.len() >= PAIR_TASKS {
                break;
            }
        }
        let found: Vec<Vec<R>> = tasks
            .par_iter()
            .map(|&start| {
                let mut out = Vec::new();
                self.walk(other, other_to_self, start, |sa, sb| out.extend(pair(sa, sb)));
                out
            })
            .collect();
        found.into_iter().flatten().collect()
    }

    /// What the traversal does with the pair of nodes `a` (of `self`) and `b` (of `other`).
    fn step(&self, other: &Bvh, other_to_self: Option<&DMat4>, a: usize, b: usize) -> Step {
        let (na, nb) = (self.nodes[a], other.nodes[b]);
        let moved = other_to_self.map_or(nb.bounds, |m| nb.bounds.transformed(m));
        if !na.bounds.overlaps(&moved) {
            return Step::Apart;
        }
        let (fa, fb) = (na.first as usize, nb.first as usize);
        match (na.count == 0, nb.count == 0) {
            (false, false) => Step::Leaves,
            // descend the larger box first, so both trees shrink together
            (true, true) if na.bounds.area() >= nb.bounds.area() => Step::Into([(fa, b), (fa + 1, b)]),
            (true, false) => Step::Into([(fa, b), (fa + 1, b)]),
            _ => Step::Into([(a, fb), (a, fb + 1)]),
        }
    }

    /// The pairs below the pair of nodes `start` (see `pairs`), one after another.
    fn walk(
        &self,
        other: &Bvh,
        other_to_self: Option<&DMat4>,
        start: (usize, usize),
        mut pair: impl FnMut(usize, usize),
    ) {
        let mut stack = vec![start];
        while let Some((a, b)) = stack.pop() {
            match self.step(other, other_to_self, a, b) {
                Step::Apart => {}
                Step::Into(children) => stack.extend(children),
                Step::Leaves => {
                    let (na, nb) = (self.nodes[a], other.nodes[b]);
                    for sa in na.first as usize..(na.first + na.count) as usize {
                        let ba = Aabb::of(&self.corners[sa]);
                        for sb in nb.first as usize..(nb.first + nb.count) as usize {
                            let c = other.corners[sb];
                            let c = other_to_self.map_or(c, |m| c.map(|p| m.transform_point3(p)));
                            if ba.overlaps(&Aabb::of(&c)) {
                                pair(sa, sb);
                            }
                        }
                    }
                }
            }
        }
    }
}

/// One move of the traversal of two trees.
enum Step {
    /// The boxes do not overlap.
    Apart,
    /// Two leaves: their triangles are compared.
    Leaves,
    /// Go on with these pairs of nodes.
    Into([(usize, usize); 2]),
}

/// Each face's corners in f64, in face order (indices checked by the caller).
pub fn triangles<T: Real>(positions: &[Vec3<T>], faces: &[[u32; 3]]) -> Vec<[DVec3; 3]> {
    let p = |i: u32| DVec3::from_array(positions[i as usize].map(<T as Real>::to_f64));
    faces.par_iter().map(|f| f.map(p)).collect()
}

/// Möller-Trumbore: the ray parameter where `o + t d` meets the triangle (either side), with
/// `SLACK` of barycentric room at its edges.
pub fn ray_triangle(o: DVec3, d: DVec3, [a, b, c]: &[DVec3; 3]) -> Option<f64> {
    let e1 = *b - *a;
    let e2 = *c - *a;
    let p = d.cross(e2);
    let det = e1.dot(p);
    if det == 0.0 || !det.is_finite() {
        return None;
    }
    let inv = 1.0 / det;
    let s = o - *a;
    let u = s.dot(p) * inv;
    if !(-SLACK..=1.0 + SLACK).contains(&u) {
        return None;
    }
    let q = s.cross(e1);
    let v = d.dot(q) * inv;
    if v < -SLACK || u + v > 1.0 + SLACK {
        return None;
    }
    Some(e2.dot(q) * inv)
}

fn split(ids: Vec<u32>, boxes: &[Aabb], centres: &[DVec3]) -> Tree {
    let bounds = ids.iter().fold(Aabb::EMPTY, |b, &i| b.union(boxes[i as usize]));
    if ids.len() <= LEAF {
        return Tree::Leaf(bounds, ids);
    }
    let cb = ids.iter().fold(Aabb::EMPTY, |b, &i| b.with(centres[i as usize]));
    let extent = cb.hi - cb.lo;
    let axis = if extent.x >= extent.y && extent.x >= extent.z {
        0
    } else if extent.y >= extent.z {
        1
    } else {
        2
    };
    if extent[axis] <= 0.0 || !extent[axis].is_finite() {
        // every centre at one point: halve the list
        let mut ids = ids;
        let right = ids.split_off(ids.len() / 2);
        return inner(bounds, ids, right, boxes, centres);
    }
    // the surface-area cost of splitting after each bin
    let bin_of = |i: u32| {
        let x = (centres[i as usize][axis] - cb.lo[axis]) / extent[axis] * BINS as f64;
        (x as usize).min(BINS - 1)
    };
    let mut bins = [(Aabb::EMPTY, 0usize); BINS];
    for &i in &ids {
        let b = &mut bins[bin_of(i)];
        *b = (b.0.union(boxes[i as usize]), b.1 + 1);
    }
    let mut best = (f64::INFINITY, BINS / 2);
    for cut in 1..BINS {
        let side = |r: std::ops::Range<usize>| {
            bins[r].iter().fold((Aabb::EMPTY, 0), |(b, n), (bb, bn)| (b.union(*bb), n + bn))
        };
        let ((lb, ln), (rb, rn)) = (side(0..cut), side(cut..BINS));
        if ln == 0 || rn == 0 {
            continue;
        }
        let cost = lb.area() * ln as f64 + rb.area() * rn as f64;
        if cost < best.0 {
            best = (cost, cut);
        }
    }
    let (left, right): (Vec<u32>, Vec<u32>) = ids.iter().partition(|&&i| bin_of(i) < best.1);
    if left.is_empty() || right.is_empty() {
        let mut ids = ids;
        let right = ids.split_off(ids.len() / 2);
        return inner(bounds, ids, right, boxes, centres);
    }
    inner(bounds, left, right, boxes, centres)
}

fn inner(bounds: Aabb, left: Vec<u32>, right: Vec<u32>, boxes: &[Aabb], centres: &[DVec3]) -> Tree {
    let (l, r) = if left.len() + right.len() > PARALLEL {
        rayon::join(|| split(left, boxes, centres), || split(right, boxes, centres))
    } else {
        (split(left, boxes, centres), split(right, boxes, centres))
    };
    Tree::Inner(bounds, Box::new(l), Box::new(r))
}

/// Writes `tree` into node `at` (already pushed), its children after it, depth first.
fn flatten(tree: Tree, at: usize, nodes: &mut Vec<Node>, order: &mut Vec<u32>) {
    match tree {
        Tree::Leaf(bounds, ids) => {
            nodes[at] = Node { bounds, first: order.len() as u32, count: ids.len() as u32 };
            order.extend(ids);
        }
        Tree::Inner(bounds, l, r) => {
            let first = nodes.len();
            nodes.push(Node { bounds: Aabb::EMPTY, first: 0, count: 0 });
            nodes.push(Node { bounds: Aabb::EMPTY, first: 0, count: 0 });
            nodes[at] = Node { bounds, first: first as u32, count: 0 };
            flatten(*l, first, nodes, order);
            flatten(*r, first + 1, nodes, order);
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn random_triangles(n: usize, seed: u64, size: f64) -> Vec<[DVec3; 3]> {
        let mut s = seed;
        let mut next = move || {
            s = s.wrapping_mul(6364136223846793005).wrapping_add(1442695040888963407);
            (s >> 11) as f64 / (1u64 << 53) as f64
        };
        (0..n)
            .map(|_| {
                let c = DVec3::new(next(), next(), next()) * 10.0;
                let mut corner = || c + DVec3::new(next() - 0.5, next() - 0.5, next() - 0.5) * size;
                [corner(), corner(), corner()]
            })
            .collect()
    }

    #[test]
    fn rays_meet_what_brute_force_meets() {
        let tris = random_triangles(3000, 7, 2.0);
        let bvh = Bvh::of_triangles(tris.clone());
        assert_eq!(bvh.len(), 3000);
        let rays = random_triangles(200, 99, 20.0);
        for r in &rays {
            let (o, d) = (r[0], r[1] - r[0]);
            let mut got = Vec::new();
            bvh.ray(o, d, 0.0, 1.0, |t, _| {
                got.push(t);
                false
            });
            got.sort_unstable();
            let want: Vec<u32> = (0..tris.len() as u32)
                .filter(|&i| ray_triangle(o, d, &tris[i as usize]).is_some_and(|t| t > 0.0 && t < 1.0))
                .collect();
            assert_eq!(got, want);
        }
    }

    #[test]
    fn a_ray_along_a_box_s_face_meets_what_lies_on_it() {
        // a unit square at z = 1 and a ray up the plane x = 1 (its edge), from below
        let sq = [DVec3::new(0.0, 0.0, 1.0), DVec3::new(1.0, 0.0, 1.0), DVec3::new(1.0, 1.0, 1.0)];
        let bvh = Bvh::of_triangles(vec![sq, [sq[0], sq[2], DVec3::new(0.0, 1.0, 1.0)]]);
        let mut hits = 0;
        bvh.ray(DVec3::new(1.0, 0.5, -1.0), DVec3::Z, 0.0, 10.0, |_, _| {
            hits += 1;
            false
        });
        assert_eq!(hits, 1);
    }

    #[test]
    fn pairs_are_every_pair_of_overlapping_boxes_in_any_frame() {
        let a = random_triangles(800, 1, 1.5);
        let b = random_triangles(700, 2, 1.5);
        let m = DMat4::from_rotation_z(0.3) * DMat4::from_scale(DVec3::splat(0.9));
        let (ba, bb) = (Bvh::of_triangles(a.clone()), Bvh::of_triangles(b.clone()));
        let mut got = Vec::new();
        ba.pairs(&bb, Some(&m), |sa, sb| got.push((ba.triangle(sa).0, bb.triangle(sb).0)));
        got.sort_unstable();
        let mut want = Vec::new();
        for (i, ta) in a.iter().enumerate() {
            for (j, tb) in b.iter().enumerate() {
                if Aabb::of(ta).overlaps(&Aabb::of(&tb.map(|p| m.transform_point3(p)))) {
                    want.push((i as u32, j as u32));
                }
            }
        }
        assert!(!want.is_empty());
        assert_eq!(got, want);
    }

    #[test]
    fn parallel_pairs_are_the_serial_pairs() {
        let (a, b) = (random_triangles(3000, 3, 1.0), random_triangles(2500, 4, 1.0));
        let m = DMat4::from_rotation_x(0.7) * DMat4::from_translation(DVec3::splat(0.2));
        let (ba, bb) = (Bvh::of_triangles(a), Bvh::of_triangles(b));
        let mut serial = Vec::new();
        ba.pairs(&bb, Some(&m), |sa, sb| serial.push((sa, sb)));
        let mut parallel = ba.par_pairs(&bb, Some(&m), |sa, sb| Some((sa, sb)));
        assert!(serial.len() > 1000);
        serial.sort_unstable();
        parallel.sort_unstable();
        assert_eq!(parallel, serial);
        assert!(ba.par_pairs(&Bvh::of_triangles(Vec::new()), None, |_, _| Some(())).is_empty());
    }
}

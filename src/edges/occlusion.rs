//! Exact visibility of lines against a scene's surfaces (Appel's quantitative invisibility): a
//! point of a line is hidden by every surface that a ray from it toward the camera crosses
//! before the near plane, counted against each mesh's bounding-volume hierarchy, not against a
//! depth image with a tolerance. A line is sampled along the screen and cut, by bisection,
//! where the count changes: its pieces with their occlusion (0: visible).
//!
//! Everything is in view coordinates: the camera at the origin looking down -z (perspective),
//! or looking down -z from anywhere (orthographic).

use glam::{DMat4, DVec3};

use crate::mesh::bvh::Bvh;

/// Rays start this far (relative to the scene's size) from the point they test: the surfaces
/// a line lies on meet its ray at the point itself, a rounding error away.
pub const START: f64 = 1e-9;
/// Halvings of a sample interval where the occlusion changes: to a 64th of it.
const BISECTIONS: usize = 6;
/// A line traced through faces (a smooth contour) lies on the interpolated surface, up to a
/// face away from the faceted one, which may hide it near the point: its own mesh's surfaces
/// within this many of the line's segment lengths of the point are passed over.
pub const TRACED_SLACK: f64 = 3.0;

/// One mesh of the scene: its hierarchy and the map from view coordinates into its frame.
pub struct Surface<'a> {
    pub bvh: &'a Bvh,
    pub from_view: DMat4,
    /// Whether it hides what lies behind it (glass does not: lines show through it).
    pub hides: bool,
}

/// The surfaces that hide lines, and the camera they are seen from.
pub struct Occluders<'a> {
    surfaces: Vec<Surface<'a>>,
    orthographic: bool,
    near: f64,
    start: f64,
}

/// The part of a line with one occlusion: from segment `from.0` at parameter `from.1` to
/// segment `to.0` at `to.1` (parameters in [0, 1] along each segment).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Run {
    pub occlusion: u32,
    pub from: (usize, f64),
    pub to: (usize, f64),
}

impl Run {
    /// The run's points on `points` (the line's points in any affine frame): where it starts,
    /// the line's points it passes, where it stops.
    pub fn points(&self, points: &[[f64; 3]]) -> Vec<[f64; 3]> {
        self.values(points, |a, b, t| DVec3::from_array(*a).lerp(DVec3::from_array(*b), t).to_array())
    }

    /// `values` (one per point of the line) along the run, as `points` takes its points,
    /// interpolated by `lerp` where it is cut.
    pub fn values<T: Copy + PartialEq>(&self, values: &[T], lerp: impl Fn(&T, &T, f64) -> T) -> Vec<T> {
        let at = |(s, t): (usize, f64)| {
            if t == 0.0 {
                values[s]
            } else if t == 1.0 {
                values[s + 1]
            } else {
                lerp(&values[s], &values[s + 1], t)
            }
        };
        let mut out = vec![at(self.from)];
        out.extend((self.from.0 + 1..=self.to.0).map(|i| values[i]));
        let end = at(self.to);
        if out.len() == 1 || out.last() != Some(&end) {
            out.push(end);
        }
        out
    }
}

impl<'a> Occluders<'a> {
    /// The scene's `surfaces` seen by a camera with its near plane at depth `near`; `size`: the
    /// scene's size in view units (rays start `START` of it from their point).
    pub fn new(surfaces: Vec<Surface<'a>>, orthographic: bool, near: f64, size: f64) -> Self {
        Occluders { surfaces, orthographic, near, start: START * size }
    }

    /// How many surfaces lie between view point `p` and the camera, counting to `limit` at
    /// most (crossings at one distance count once). Surfaces of mesh `own.0` within `own.1`
    /// of `p` (view units) are passed over.
    pub fn occlusion(&self, p: DVec3, limit: u32, own: Option<(usize, f64)>) -> u32 {
        let depth = -p.z;
        let (d, t1) =
            if self.orthographic { (DVec3::Z, depth - self.near) } else { (-p, 1.0 - self.near / depth) };
        if !(depth > self.near) || !p.is_finite() {
            return 0; // cut by the near plane: never drawn
        }
        let length = d.length();
        let t0 = self.start / length;
        let mut hits: Vec<f64> = Vec::new();
        for (i, s) in self.surfaces.iter().enumerate().filter(|(_, s)| s.hides) {
            let skip = own.and_then(|(m, reach)| (m == i).then_some(reach / length)).unwrap_or(0.0);
            let (o, dir) = (s.from_view.transform_point3(p), s.from_view.transform_vector3(d));
            let mut stop = false;
            s.bvh.ray(o, dir, t0.max(skip), t1, |_, t| {
                hits.push(t);
                stop = limit <= 1;
                stop
            });
            if stop {
                return 1;
            }
        }
        hits.sort_unstable_by(f64::total_cmp);
        // a ray through an edge meets both its triangles: one crossing
        let apart = self.start / length;
        let distinct = 1 + hits.windows(2).filter(|w| w[1] - w[0] > apart).count();
        if hits.is_empty() {
            0
        } else {
            (distinct as u32).min(limit)
        }
    }

    /// The runs of the polyline `points` (view coordinates, on mesh `item`) by occlusion, each
    /// to `limit` at most: the occlusion is sampled every `spacing` along the line as it is
    /// seen (`lengths`: each segment's length on screen, in the unit of `spacing`; a segment
    /// seen end on has none), at its ends too, and each change is found by bisection.
    /// `traced`: the line runs through faces (`TRACED_SLACK`).
    pub fn runs(
        &self,
        points: &[DVec3],
        item: usize,
        traced: bool,
        limit: u32,
        (lengths, spacing): (&[f64], f64),
    ) -> Vec<Run> {
        if points.len() < 2 {
            return Vec::new();
        }
        let n = points.len() - 1;
        let seg_length = |s: usize| points[s].distance(points[s + 1]);
        let own = |s: usize| {
            traced.then(|| {
                let around = seg_length(s)
                    .max(if s > 0 { seg_length(s - 1) } else { 0.0 })
                    .max(if s + 1 < n { seg_length(s + 1) } else { 0.0 });
                (item, TRACED_SLACK * around)
            })
        };
        // the distance along the line on screen at each point
        let mut along = Vec::with_capacity(n + 1);
        along.push(0.0);
        for l in &lengths[..n] {
            along.push(along[along.len() - 1] + l.max(0.0));
        }
        let total = along[n];
        // the segment and its parameter at a distance along the line
        let place = |u: f64| -> (usize, f64) {
            let s = along.partition_point(|&a| a <= u).clamp(1, n) - 1;
            let l = along[s + 1] - along[s];
            (s, if l > 0.0 { ((u - along[s]) / l).clamp(0.0, 1.0) } else { 1.0 })
        };
        let at = |u: f64| {
            let (s, t) = place(u);
            self.occlusion(points[s].lerp(points[s + 1], t), limit, own(s))
        };
        let k = (total / spacing).ceil().max(1.0) as usize;
        let mut runs = Vec::new();
        let mut start = (0usize, 0.0f64);
        let mut before = at(0.0);
        let mut u_before = 0.0;
        for j in 1..=k {
            let u = total * j as f64 / k as f64;
            let q = at(u);
            if q != before {
                let (mut lo, mut hi) = (u_before, u);
                for _ in 0..BISECTIONS {
                    let mid = 0.5 * (lo + hi);
                    if at(mid) == before {
                        lo = mid;
                    } else {
                        hi = mid;
                    }
                }
                let cut = place(0.5 * (lo + hi));
                runs.push(Run { occlusion: before, from: start, to: cut });
                start = cut;
                before = q;
            }
            u_before = u;
        }
        runs.push(Run { occlusion: before, from: start, to: (n - 1, 1.0) });
        runs
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A square of half-size `h` at height z (normal +z), as two triangles.
    fn square(z: f64, h: f64) -> Vec<[DVec3; 3]> {
        let p = [DVec3::new(-h, -h, z), DVec3::new(h, -h, z), DVec3::new(h, h, z), DVec3::new(-h, h, z)];
        vec![[p[0], p[1], p[2]], [p[0], p[2], p[3]]]
    }

    #[test]
    fn a_line_just_under_a_sheet_is_hidden_and_one_on_it_is_not() {
        // looking down from z = 0 on a sheet at z = -10 (half-size 1); a line 1e-4 under it
        let sheet = Bvh::of_triangles(square(-10.0, 1.0));
        let occ = Occluders::new(
            vec![Surface { bvh: &sheet, from_view: DMat4::IDENTITY, hides: true }],
            true,
            0.1,
            2.0,
        );
        let under = [DVec3::new(-2.0, 0.0, -10.0001), DVec3::new(2.0, 0.0, -10.0001)];
        let runs = occ.runs(&under, 1, false, 4, (&[4.0], 0.1));
        assert_eq!(runs.len(), 3, "{runs:?}");
        assert_eq!(runs.iter().map(|r| r.occlusion).collect::<Vec<_>>(), vec![0, 1, 0]);
        // the sheet's edges cut it at x = -1 and 1: a quarter and three quarters of the way
        assert!((runs[0].to.1 - 0.25).abs() < 1e-3 && (runs[1].to.1 - 0.75).abs() < 1e-3, "{runs:?}");
        // the sheet's own diagonal edge and a line on it: visible throughout
        let on = [DVec3::new(-1.0, -1.0, -10.0), DVec3::new(1.0, 1.0, -10.0)];
        assert_eq!(occ.runs(&on, 0, false, 4, (&[4.0], 0.1)).len(), 1);
        assert_eq!(occ.runs(&on, 0, false, 4, (&[4.0], 0.1))[0].occlusion, 0);
        // two sheets above a point (perspective): two, counted once each across their diagonal
        let upper = Bvh::of_triangles(square(-5.0, 1.0));
        let two = Occluders::new(
            vec![
                Surface { bvh: &sheet, from_view: DMat4::IDENTITY, hides: true },
                Surface { bvh: &upper, from_view: DMat4::IDENTITY, hides: true },
            ],
            false,
            0.1,
            2.0,
        );
        assert_eq!(two.occlusion(DVec3::new(0.0, 0.0, -20.0), 9, None), 2);
        assert_eq!(two.occlusion(DVec3::new(0.0, 0.0, -20.0), 1, None), 1);
        assert_eq!(two.occlusion(DVec3::new(0.0, 0.0, -7.0), 9, None), 1);
        // in front of the near plane: nothing hides it (it is not drawn)
        assert_eq!(two.occlusion(DVec3::new(0.0, 0.0, -0.01), 9, None), 0);
    }

    #[test]
    fn runs_give_back_their_points() {
        let pts = [[0.0, 0.0, 0.0], [1.0, 0.0, 0.0], [2.0, 0.0, 0.0]];
        let r = Run { occlusion: 0, from: (0, 0.5), to: (1, 1.0) };
        assert_eq!(r.points(&pts), vec![[0.5, 0.0, 0.0], [1.0, 0.0, 0.0], [2.0, 0.0, 0.0]]);
    }
}

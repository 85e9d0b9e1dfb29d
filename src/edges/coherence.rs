//! Suggestive contours that hold still across a sequence of views (DeCarlo, Finkelstein and
//! Rusinkiewicz 2004, "Interactive Rendering of Suggestive Contours with Temporal Coherence"):
//!
//! - *Speed*: where the view moves, the zero set of kr slides across the surface at about
//!   |d kr / dt| / |D_w kr| (the change of kr between neighbouring views over its derivative
//!   along w). A line that slides faster than `SPEED_LIMIT` feature sizes per step is cut, and
//!   slower ones fade toward that speed: lines that race across a surface are what flickers.
//! - *Hysteresis*: a line drawn in the previous view stays while its derivative test passes
//!   a weaker threshold than a new line needs to appear (`HYSTERESIS`), so a line near the
//!   threshold does not blink on and off from step to step.
//!
//! Both hold only between *related* views (`related`): consecutive eyes that turn by less than
//! `RELATED_TURN_DEGREES` about the mesh's centre and whose distance to it changes by less
//! than that angle's sine. A dataset sweep's far jumps carry nothing; a view with no related
//! neighbour is traced as it is alone.

use std::sync::atomic::{AtomicBool, Ordering};
use std::sync::{Arc, Weak};

use super::contours::{suggestive_contours_marking, test_strength, ContourMesh, SuggestiveBasis};
use super::silhouette::View;
use super::zero_set::{zero_set_marking, Polylines};
use crate::cancel::Cancel;
use crate::error::Result;
use crate::mesh::Bounds;
use crate::real::{dot, sub};

/// The fastest a suggestive contour may slide across the surface, in feature sizes per step
/// between views; its strength fades linearly to 0 at this speed, where it is cut. Measured on
/// the bunny turntable in 1-degree steps (512x512, `temporal_popping`): with `HYSTERESIS` it
/// takes the popping of suggestive contours from 0.26% to 0.18% of ink pixels per step over 90
/// steps; limits of 0.5 and 2 popped more (0.21-0.23% and 0.18-0.21% over 30 steps), and
/// without the limit hysteresis alone keeps fast lines that pop (0.25%).
pub const SPEED_LIMIT: f64 = 1.0;

/// A line drawn in the previous view stays while its derivative test passes the threshold
/// less this many times the fade `SUGGESTIVE_FADE` (both relative to the feature size
/// squared); a new one needs the threshold itself. Measured as `SPEED_LIMIT`: 0.5 popped 0.25%
/// of ink pixels per step, 1 0.25%, 4 0.17%, and 10 or 100 no less (30 steps).
pub const HYSTERESIS: f64 = 4.0;

/// Consecutive views are related (and share their motion and what was drawn) when the eye
/// turns by less than this about the mesh's centre (for a view direction: the direction turns
/// by less) and its distance changes by less than the angle's sine, relatively.
pub const RELATED_TURN_DEGREES: f64 = 10.0;

/// Whether views `a` and `b` of a mesh centred at `centre` are close enough for a line of one
/// to be a line of the other (`RELATED_TURN_DEGREES`); scale-free.
pub fn related(a: View, b: View, centre: [f64; 3]) -> bool {
    let cos_limit = RELATED_TURN_DEGREES.to_radians().cos();
    let sin_limit = RELATED_TURN_DEGREES.to_radians().sin();
    let cos_between = |x: [f64; 3], y: [f64; 3]| {
        let lengths = (dot(x, x) * dot(y, y)).sqrt();
        (lengths > 0.0).then(|| dot(x, y) / lengths)
    };
    match (a, b) {
        (View::Direction(x), View::Direction(y)) => cos_between(x, y).is_some_and(|c| c > cos_limit),
        (View::Eye(x), View::Eye(y)) => {
            let (x, y) = (sub(x, centre), sub(y, centre));
            let (lx, ly) = (dot(x, x).sqrt(), dot(y, y).sqrt());
            let turn = cos_between(x, y).is_some_and(|c| c > cos_limit);
            turn && (lx - ly).abs() < sin_limit * lx.max(ly)
        }
        _ => false,
    }
}

/// The views next to one in a sequence, where related to it (`related`).
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct Motion {
    pub before: Option<View>,
    pub after: Option<View>,
}

impl Motion {
    /// The motion of `view` of a mesh with `positions` between `before` and `after`, keeping
    /// only the related ones.
    pub fn between(before: Option<View>, view: View, after: Option<View>, positions: &[[f64; 3]]) -> Motion {
        let centre = Bounds::of(positions).center();
        let keep = |other: Option<View>| other.filter(|&o| related(o, view, centre));
        Motion { before: keep(before), after: keep(after) }
    }

    /// The change of a vertex's kr per step, from its value `now` and `at` another view:
    /// central between both neighbours, else one-sided; 0 without neighbours.
    fn rate(&self, now: f64, at: impl Fn(View) -> Option<f64>) -> f64 {
        match (self.before.and_then(&at), self.after.and_then(&at)) {
            (Some(b), Some(a)) => 0.5 * (a - b),
            (Some(b), None) => now - b,
            (None, Some(a)) => a - now,
            (None, None) => 0.0,
        }
    }
}

/// What the last view of a sequence drew: the vertices (the basis' numbering) of the faces its
/// suggestive contours ran through, for the basis they were traced on.
#[derive(Debug, Default)]
pub struct Drawn {
    basis: Weak<SuggestiveBasis>,
    vertices: Vec<bool>,
}

impl Drawn {
    /// The vertices drawn last, where they were drawn on `basis`.
    fn on(&self, basis: &Arc<SuggestiveBasis>) -> Option<&[bool]> {
        let same = self.basis.upgrade().is_some_and(|b| Arc::ptr_eq(&b, basis));
        (same && self.vertices.len() == basis.n_vertices()).then_some(&self.vertices[..])
    }
}

/// kr at a vertex from its fields; None where the view is along the normal.
fn kr(basis: &SuggestiveBasis, local: u32, view: View) -> Option<f64> {
    let r = basis.radial(local, view);
    (r.sin2 > 1e-12).then(|| r.kr_sin2 / r.sin2)
}

/// Suggestive contours of `view` in a sequence (`suggestive_contours` with speed and
/// hysteresis): `motion` its related neighbours, `drawn` what the previous view drew, replaced
/// by what this one draws. Without a related neighbour the lines are those of the view alone.
pub fn coherent_suggestive_contours(
    basis: &Arc<SuggestiveBasis>,
    view: View,
    threshold: f64,
    motion: &Motion,
    drawn: &mut Drawn,
) -> Polylines {
    let (cutoff, fade) = basis.cutoff_and_fade(threshold);
    let kept = drawn.on(basis).filter(|_| motion.before.is_some());
    let marks: Vec<AtomicBool> = (0..basis.n_vertices()).map(|_| AtomicBool::new(false)).collect();
    let mark = |f: &[u32; 3]| f.iter().for_each(|&v| marks[v as usize].store(true, Ordering::Relaxed));
    let lines = if *motion == Motion::default() {
        suggestive_contours_marking(basis, view, threshold, mark)
    } else {
        let reach = SPEED_LIMIT * basis.feature_size;
        let gap = HYSTERESIS * fade;
        // per vertex: [the derivative test (weaker where drawn last), n . v, the speed's room
        // below the limit, the limit, how far into the hysteresis' gap the vertex is]; the
        // speed's two times D_w kr / n . v so that they are finite everywhere and interpolate
        // between vertices; the last in [-1, 1] (-1: at the weaker test, 0 and up: passing the
        // new one), shifted by 2 to be carried without cutting
        let fields = |v: u32| {
            let r = basis.radial(v, view);
            let old = kept.is_some_and(|k| k[v as usize]);
            let own = if old { cutoff - gap } else { cutoff };
            let now = if r.sin2 > 1e-12 { r.kr_sin2 / r.sin2 } else { 0.0 };
            let rate = motion.rate(now, |other| kr(basis, v, other)).abs();
            let limit = reach * r.num.unwrap_or(-1.0);
            let into_gap = if gap > 0.0 { r.test(cutoff) / (gap * r.ndotv) } else { 0.0 };
            let into_gap = if into_gap.is_finite() { into_gap.clamp(-1.0, 1.0) } else { 0.0 };
            [r.test(own), r.ndotv, limit - rate * r.ndotv, limit, 2.0 + into_gap]
        };
        zero_set_marking(
            basis.positions(),
            &basis.faces_seen(view),
            |v| basis.radial(v, view).kr_sin2,
            fields,
            |[test, ndotv, room, limit, shifted]| {
                let held = (shifted - 1.0).clamp(0.0, 1.0);
                test_strength(test, ndotv, fade) * (room / limit).clamp(0.0, 1.0) * held
            },
            mark,
        )
    };
    let vertices: Vec<bool> = marks.into_iter().map(AtomicBool::into_inner).collect();
    *drawn = Drawn { basis: Arc::downgrade(basis), vertices };
    lines
}

impl ContourMesh {
    /// Suggestive contours of `view` in a sequence of views: `before` and `after` the views
    /// next to it (kept where related), `drawn` what the view before drew, replaced by what
    /// this one draws.
    pub fn coherent_suggestive(
        &self,
        (before, view, after): (Option<View>, View, Option<View>),
        threshold: f64,
        smoothing: Option<f64>,
        drawn: &mut Drawn,
        cancel: &Cancel,
    ) -> Result<Polylines> {
        let basis = self.suggestive_basis(smoothing, cancel)?;
        let motion = Motion::between(before, view, after, self.positions());
        Ok(coherent_suggestive_contours(&basis, view, threshold, &motion, drawn))
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::cancel::Cancel;
    use crate::edges::contours::{suggestive_contours, ContourMesh};
    use crate::mesh::shapes::icosphere;

    /// A sphere with bumps: saddles between them, and suggestive contours on their flanks.
    fn bumpy() -> ContourMesh {
        let (positions, faces) = icosphere(4, 0.0, 1).unwrap();
        let bumped: Vec<[f64; 3]> = positions
            .iter()
            .map(|p| {
                let r = 1.0 + 0.12 * (4.0 * p[0]).sin() * (4.0 * p[1]).sin() * (4.0 * p[2]).cos();
                p.map(|x| x * r)
            })
            .collect();
        ContourMesh::build(&bumped, &faces, false)
    }

    fn eye(degrees: f64) -> View {
        let a = degrees.to_radians();
        View::Eye([3.0 * a.sin(), 0.7, 3.0 * a.cos()])
    }

    fn length(lines: &Polylines) -> f64 {
        (0..lines.len())
            .flat_map(|i| lines.line(i).windows(2).map(|w| dot(sub(w[1], w[0]), sub(w[1], w[0])).sqrt()))
            .sum()
    }

    fn traced(
        m: &ContourMesh,
        views: (Option<View>, View, Option<View>),
        t: f64,
        drawn: &mut Drawn,
    ) -> Polylines {
        m.coherent_suggestive(views, t, None, drawn, Cancel::never()).unwrap()
    }

    #[test]
    fn far_views_carry_nothing() {
        let m = bumpy();
        let basis = m.suggestive_basis(None, Cancel::never()).unwrap();
        let alone = suggestive_contours(&basis, eye(0.0), 0.05);
        assert!(alone.len() > 0, "the bumps have suggestive contours");
        let mut drawn = Drawn::default();
        traced(&m, (None, eye(60.0), None), 0.0, &mut drawn);
        let after_a_jump = traced(&m, (Some(eye(60.0)), eye(0.0), Some(eye(-60.0))), 0.05, &mut drawn);
        assert_eq!(after_a_jump, alone, "a jump of 60 degrees relates nothing");
    }

    #[test]
    fn a_line_drawn_before_needs_a_weaker_test_to_stay() {
        let m = bumpy();
        let basis = m.suggestive_basis(None, Cancel::never()).unwrap();
        let (before, now) = (eye(0.0), eye(0.01));
        let alone = length(&suggestive_contours(&basis, now, 0.1));
        // nothing drawn before: only the (slow) motion acts, and it never adds lines
        let fresh = length(&traced(&m, (Some(before), now, None), 0.1, &mut Drawn::default()));
        assert!(fresh <= alone + 1e-12 && fresh > 0.9 * alone, "{fresh} vs {alone}");
        // the view before drew at a lower threshold: those lines stay
        let mut drawn = Drawn::default();
        traced(&m, (None, before, None), 0.0, &mut drawn);
        let held = length(&traced(&m, (Some(before), now, None), 0.1, &mut drawn));
        assert!(held > 1.2 * alone, "{held} vs {alone}");
        // what this view drew replaced what the one before did
        let again = length(&traced(&m, (Some(now), eye(0.02), None), 0.1, &mut drawn));
        assert!(again > 1.2 * alone, "{again} vs {alone}");
    }

    #[test]
    fn lines_that_slide_fast_fade_and_are_cut() {
        let m = bumpy();
        let basis = m.suggestive_basis(None, Cancel::never()).unwrap();
        let alone = suggestive_contours(&basis, eye(0.0), 0.01);
        let strength = |l: &Polylines| l.strength.iter().sum::<f64>();
        let slow = traced(&m, (Some(eye(-0.001)), eye(0.0), Some(eye(0.001))), 0.01, &mut Drawn::default());
        let fast = traced(&m, (Some(eye(-9.0)), eye(0.0), Some(eye(9.0))), 0.01, &mut Drawn::default());
        assert!(strength(&slow) > 0.99 * strength(&alone) && length(&slow) > 0.99 * length(&alone));
        assert!(strength(&fast) < 0.95 * strength(&slow), "{} vs {}", strength(&fast), strength(&slow));
        assert!(length(&fast) < length(&slow), "{} vs {}", length(&fast), length(&slow));
        assert!(slow.strength.iter().chain(&fast.strength).all(|s| (0.0..=1.0).contains(s)));
    }

    #[test]
    fn views_are_related_by_a_small_turn_at_any_scale() {
        for scale in [1e-6, 1.0, 1e6] {
            let eye = |degrees: f64, distance: f64| {
                let a = degrees.to_radians();
                View::Eye([scale * distance * a.sin(), 0.0, scale * distance * a.cos()])
            };
            let c = [0.0; 3];
            assert!(related(eye(0.0, 3.0), eye(1.0, 3.0), c));
            assert!(related(eye(0.0, 3.0), eye(9.0, 3.0), c));
            assert!(!related(eye(0.0, 3.0), eye(11.0, 3.0), c), "a far turn");
            assert!(!related(eye(0.0, 3.0), eye(0.0, 6.0), c), "a far zoom");
            assert!(related(eye(0.0, 3.0), eye(0.0, 3.1), c));
        }
        let d = |x: f64| View::Direction([x, 0.0, -1.0]);
        assert!(related(d(0.1), d(0.0), [0.0; 3]));
        assert!(!related(d(0.5), d(0.0), [0.0; 3]));
        assert!(!related(d(0.0), View::Eye([0.0, 0.0, 1.0]), [0.0; 3]));
    }

    #[test]
    fn kr_changes_per_step_from_the_related_neighbours() {
        let (b, a) = (View::Eye([0.0, 0.0, 1.0]), View::Eye([0.0, 0.0, 2.0]));
        let at = |v: View| match v {
            View::Eye(e) => Some(10.0 * e[2]),
            _ => None,
        };
        let both = Motion { before: Some(b), after: Some(a) };
        assert_eq!(both.rate(15.0, at), 5.0);
        assert_eq!(Motion { before: Some(b), after: None }.rate(15.0, at), 5.0);
        assert_eq!(Motion { before: None, after: Some(a) }.rate(16.0, at), 4.0);
        assert_eq!(Motion::default().rate(15.0, at), 0.0);
    }
}

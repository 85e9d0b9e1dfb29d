//! Visible runs joined into strokes: a line cut into runs by hidden-line removal flickers where a
//! point of it dips behind the surface for a sample or two, and lines of one kind meet end to end
//! where chains of edges and curves through faces meet. Ends of runs closer than a gap (in
//! pixels) are joined, nearest pairs first, so that a contour is drawn as one long stroke, not as
//! dashes a pixel apart; short runs that lie within the gap of a longer line of their kind (a
//! contour's spur or sliver, whose ink that line draws) are left out.

use std::collections::HashMap;

use super::settings::{Outlines, INK_KINDS};
use crate::render::graph::report::Polyline;

/// The widest gap between runs joined into one stroke, in pixels: a line's own width (a gap no
/// wider than the ink barely shows), at least 1.5 pixels (the half-pixel visibility samples of
/// `visibility::visible_runs` on both sides of a single hidden sample).
pub const MIN_JOIN_GAP: f64 = 1.5;

/// The join gap of each ink kind under `outlines`.
pub fn gaps(outlines: &Outlines) -> [f64; INK_KINDS] {
    widths(outlines).map(|w| w.max(MIN_JOIN_GAP))
}

/// The width of each ink kind under `outlines`, in pixels (0 for a kind not drawn).
pub fn widths(outlines: &Outlines) -> [f64; INK_KINDS] {
    std::array::from_fn(|k| outlines.styles[k].map_or(0.0, |s| s.width as f64))
}

/// Joins the ends of `runs` that lie within `gap(kind)` pixels of each other, nearest first,
/// each end at most once, keeping runs of different kinds apart when `by_kind`. A run whose own
/// two ends meet is closed (its first point repeated). The joined runs keep the kind of their
/// longest part, and come in the order of their first part.
pub fn join_runs(runs: Vec<Polyline>, by_kind: bool, gap: impl Fn(usize) -> f64) -> Vec<Polyline> {
    let n = runs.len();
    if n == 0 {
        return runs;
    }
    let cell = (0..n).map(|i| gap(runs[i].kind)).fold(0.0f64, f64::max).max(1e-9);
    // ends: 2 i (run i's first point) and 2 i + 1 (its last), in a grid of `cell` pixels
    let end = |e: usize| {
        let p = &runs[e / 2].points;
        if e % 2 == 0 {
            p[0]
        } else {
            p[p.len() - 1]
        }
    };
    let key = |p: [f64; 2]| ((p[0] / cell).floor() as i64, (p[1] / cell).floor() as i64);
    let mut grid: HashMap<(i64, i64), Vec<usize>> = HashMap::new();
    for e in 0..2 * n {
        if is_closed(&runs[e / 2].points) {
            continue;
        }
        grid.entry(key(end(e))).or_default().push(e);
    }
    let mut pairs: Vec<(f64, usize, usize)> = Vec::new();
    for e in 0..2 * n {
        if is_closed(&runs[e / 2].points) {
            continue;
        }
        let p = end(e);
        let (cx, cy) = key(p);
        for dy in -1..=1 {
            for dx in -1..=1 {
                for &f in grid.get(&(cx + dx, cy + dy)).into_iter().flatten() {
                    let (a, b) = (&runs[e / 2], &runs[f / 2]);
                    if f <= e || (by_kind && a.kind != b.kind) {
                        continue;
                    }
                    // a run's own ends close it only when it is longer than the gap
                    let q = end(f);
                    let d = (p[0] - q[0]).hypot(p[1] - q[1]);
                    let limit = gap(a.kind).min(gap(b.kind));
                    if d <= limit && (e / 2 != f / 2 || length(&a.points) > 2.0 * limit) {
                        pairs.push((d, e, f));
                    }
                }
            }
        }
    }
    pairs.sort_by(|a, b| a.0.total_cmp(&b.0).then(a.1.cmp(&b.1)).then(a.2.cmp(&b.2)));
    let mut partner = vec![usize::MAX; 2 * n];
    for (_, e, f) in pairs {
        if partner[e] == usize::MAX && partner[f] == usize::MAX {
            // joining would close a chain through other runs: allowed (it becomes a loop)
            partner[e] = f;
            partner[f] = e;
        }
    }
    // walk each chain from a free end (or around a loop), concatenating the runs
    let mut used = vec![false; n];
    let mut out = Vec::new();
    let mut order: Vec<usize> = (0..n).collect();
    // open chains start at a free end; loops anywhere
    order.sort_by_key(|&i| partner[2 * i] != usize::MAX && partner[2 * i + 1] != usize::MAX);
    let mut starts: Vec<(usize, Polyline)> = Vec::new();
    for &i in &order {
        if used[i] {
            continue;
        }
        // enter run i through its first point when that end is free (or in a loop), else its last
        let mut entry =
            if partner[2 * i] == usize::MAX || partner[2 * i + 1] != usize::MAX { 2 * i } else { 2 * i + 1 };
        let (mut points, mut widths, mut parts): (Vec<[f64; 2]>, Vec<f64>, Vec<(f64, usize)>) =
            (Vec::new(), Vec::new(), Vec::new());
        let mut first = i;
        loop {
            let r = entry / 2;
            if used[r] {
                // back at the start of a loop: close it
                close(&mut points, &mut widths);
                break;
            }
            used[r] = true;
            first = first.min(r);
            let run = &runs[r].points;
            let forward = entry % 2 == 0;
            let pairs = run.iter().zip(&runs[r].widths);
            let it: Box<dyn Iterator<Item = (&[f64; 2], &f64)>> =
                if forward { Box::new(pairs) } else { Box::new(pairs.rev()) };
            for (&p, &w) in it {
                if !points.last().is_some_and(|&q| same_point(p, q)) {
                    points.push(p);
                    widths.push(w);
                }
            }
            parts.push((length(run), runs[r].kind));
            let exit = entry ^ 1;
            match partner[exit] {
                usize::MAX => break,
                next if next / 2 == r => {
                    // the run's own ends meet
                    close(&mut points, &mut widths);
                    break;
                }
                next => entry = next,
            }
        }
        let kind = parts.iter().max_by(|a, b| a.0.total_cmp(&b.0)).map_or(runs[i].kind, |p| p.1);
        starts.push((first, Polyline { kind, points, widths }));
    }
    starts.sort_by_key(|s| s.0);
    out.extend(starts.into_iter().map(|s| s.1));
    out
}

/// Points closer than this (pixels) are one: where runs meet, their ends differ by rounding.
const SAME_POINT: f64 = 1e-6;

fn same_point(a: [f64; 2], b: [f64; 2]) -> bool {
    (a[0] - b[0]).hypot(a[1] - b[1]) <= SAME_POINT
}

/// Closes a loop: its first point again at its end (in place of a last point that is the first
/// but for rounding).
fn close(points: &mut Vec<[f64; 2]>, widths: &mut Vec<f64>) {
    if let (Some(&first), Some(&last)) = (points.first(), points.last()) {
        if points.len() > 1 && same_point(first, last) {
            points.pop();
            widths.pop();
        }
        points.push(first);
        widths.push(widths[0]);
    }
}

/// `runs` without the short ones that lie wholly within `gap(kind)` of a longer run of the same
/// kind: a spur where a contour branches off another for a pixel or two, or a sliver beside it,
/// whose ink the other line already draws. Only runs shorter than `SPUR_GAPS` gaps are looked at.
pub fn drop_covered(runs: Vec<Polyline>, gap: impl Fn(usize) -> f64) -> Vec<Polyline> {
    let lengths: Vec<f64> = runs.iter().map(|r| length(&r.points)).collect();
    let short: Vec<usize> = (0..runs.len()).filter(|&i| lengths[i] < SPUR_GAPS * gap(runs[i].kind)).collect();
    if short.is_empty() {
        return runs;
    }
    let cell = runs.iter().map(|r| gap(r.kind)).fold(0.0f64, f64::max).max(1e-9);
    let key = |p: [f64; 2]| ((p[0] / cell).floor() as i64, (p[1] / cell).floor() as i64);
    // every segment of every run, filed under the cells it passes within `cell` of
    let mut grid: HashMap<(i64, i64), Vec<(usize, usize)>> = HashMap::new();
    for (i, r) in runs.iter().enumerate() {
        for (j, w) in r.points.windows(2).enumerate() {
            let (a, b) = (key(w[0]), key(w[1]));
            for x in a.0.min(b.0) - 1..=a.0.max(b.0) + 1 {
                for y in a.1.min(b.1) - 1..=a.1.max(b.1) + 1 {
                    grid.entry((x, y)).or_default().push((i, j));
                }
            }
        }
    }
    let covered = |i: usize| {
        let r = &runs[i];
        let g = gap(r.kind);
        // the run's points and the middles of its segments
        let probes = r.points.iter().copied().chain(r.points.windows(2).map(|w| mid(w[0], w[1])));
        probes.into_iter().all(|p| {
            grid.get(&key(p)).into_iter().flatten().any(|&(k, j)| {
                let o = &runs[k];
                k != i && o.kind == r.kind && lengths[k] > lengths[i] && {
                    let (a, b) = (o.points[j], o.points[j + 1]);
                    segment_distance(p, a, b) <= g
                }
            })
        })
    };
    let drop: Vec<bool> = {
        let mut d = vec![false; runs.len()];
        for &i in &short {
            d[i] = covered(i);
        }
        d
    };
    runs.into_iter().zip(drop).filter(|(_, d)| !d).map(|(r, _)| r).collect()
}

/// Runs shorter than this many join gaps are dropped where another line already covers them.
pub const SPUR_GAPS: f64 = 4.0;

fn mid(a: [f64; 2], b: [f64; 2]) -> [f64; 2] {
    [(a[0] + b[0]) * 0.5, (a[1] + b[1]) * 0.5]
}

/// Distance from p to the segment ab, in pixels.
fn segment_distance(p: [f64; 2], a: [f64; 2], b: [f64; 2]) -> f64 {
    let ab = [b[0] - a[0], b[1] - a[1]];
    let l2 = ab[0] * ab[0] + ab[1] * ab[1];
    let t =
        if l2 > 0.0 { (((p[0] - a[0]) * ab[0] + (p[1] - a[1]) * ab[1]) / l2).clamp(0.0, 1.0) } else { 0.0 };
    (p[0] - a[0] - t * ab[0]).hypot(p[1] - a[1] - t * ab[1])
}

fn is_closed(points: &[[f64; 2]]) -> bool {
    points.len() > 2 && points[0] == points[points.len() - 1]
}

/// Length of a polyline in pixels.
pub fn length(points: &[[f64; 2]]) -> f64 {
    points.windows(2).map(|w| (w[1][0] - w[0][0]).hypot(w[1][1] - w[0][1])).sum()
}

#[cfg(test)]
mod tests {
    use super::*;

    fn run(kind: usize, points: &[[f64; 2]]) -> Polyline {
        Polyline { kind, points: points.to_vec(), widths: (0..points.len()).map(|i| i as f64).collect() }
    }

    #[test]
    fn runs_a_pixel_apart_become_one_stroke_and_far_ones_stay_apart() {
        let runs = vec![
            run(0, &[[0.0, 0.0], [10.0, 0.0]]),
            run(0, &[[21.0, 0.0], [11.0, 0.0]]), // reversed, 1 px after the first
            run(0, &[[40.0, 0.0], [50.0, 0.0]]), // 19 px away
            run(1, &[[21.5, 0.0], [30.0, 0.0]]), // another kind, 0.5 px after the second
        ];
        let joined = join_runs(runs.clone(), true, |_| 1.5);
        assert_eq!(joined.len(), 3);
        assert_eq!(joined[0].points, vec![[0.0, 0.0], [10.0, 0.0], [11.0, 0.0], [21.0, 0.0]]);
        assert_eq!(
            joined[0].widths,
            vec![0.0, 1.0, 1.0, 0.0],
            "each point keeps its width, reversed runs too"
        );
        assert_eq!(joined[0].kind, 0);
        let across = join_runs(runs, false, |_| 1.5);
        assert_eq!(across.len(), 2);
        assert_eq!(across[0].points.last(), Some(&[30.0, 0.0]));
        assert_eq!(across[0].kind, 0, "the kind of the longest part");
    }

    #[test]
    fn a_spur_along_another_line_goes_and_a_lone_dot_stays() {
        let runs = vec![
            run(0, &[[0.0, 0.0], [40.0, 0.0]]),
            run(0, &[[10.0, 0.5], [13.0, 1.2]]), // within 1.5 px of the long line
            run(1, &[[20.0, 0.5], [22.0, 0.5]]), // another kind: kept
            run(0, &[[30.0, 5.0], [32.0, 5.0]]), // alone: kept
        ];
        let kept = drop_covered(runs, |_| 1.5);
        assert_eq!(kept.len(), 3);
        assert!(kept.iter().all(|r| r.points[0] != [10.0, 0.5]));
    }

    #[test]
    fn a_ring_of_runs_closes_and_a_speck_does_not_close_on_itself() {
        let runs = vec![
            run(0, &[[0.0, 0.0], [10.0, 0.0], [10.0, 10.0]]),
            run(0, &[[10.0, 10.5], [0.0, 10.0], [0.0, 0.5]]),
            run(0, &[[50.0, 50.0], [50.5, 50.0]]),
        ];
        let joined = join_runs(runs, true, |_| 1.0);
        assert_eq!(joined.len(), 2);
        assert!(is_closed(&joined[0].points));
        assert_eq!(joined[0].widths.len(), joined[0].points.len());
        assert_eq!(joined[0].widths.first(), joined[0].widths.last());
        assert_eq!(joined[1].points.len(), 2);
    }
}

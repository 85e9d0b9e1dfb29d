//! The order a pen plotter draws strokes in with little travel between them: from the origin,
//! each time the undrawn stroke with the nearest end, drawn from that end (greedy nearest
//! neighbour, as vpype's `linesort` does). The ends sit in a k-d tree that counts the undrawn
//! ends under each node, so each step looks at a few nodes near the pen and skips drawn
//! regions: about n log n in all, where trying every stroke at each step is n squared.

/// The strokes with first points `starts` and last points `ends`, in the order a pen draws
/// them: (index, whether drawn from its last point). Of equally near ends, a first point goes
/// before a last one and a lower index before a higher one.
pub fn plotter_order(starts: &[[f64; 2]], ends: &[[f64; 2]]) -> Vec<(usize, bool)> {
    let n = starts.len().min(ends.len());
    // end e is stroke e % n's first point (e < n) or its last (e >= n): ascending e is the
    // order that breaks ties
    let point = |e: usize| if e < n { starts[e] } else { ends[e - n] };
    let mut tree = EndTree::new((0..2 * n).map(point).collect());
    let mut pen = [0.0, 0.0];
    let mut out = Vec::with_capacity(n);
    while let Some(e) = tree.nearest(pen) {
        let (i, reversed) = (e % n, e >= n);
        tree.remove(i);
        tree.remove(i + n);
        out.push((i, reversed));
        pen = if reversed { starts[i] } else { ends[i] };
    }
    out
}

/// A k-d tree over points laid out in one array: the node of the range [lo, hi) is its middle
/// element, with the points before it on one side of the splitting axis and those after it on
/// the other.
struct EndTree {
    points: Vec<[f64; 2]>,
    /// Point ids in tree order.
    order: Vec<usize>,
    /// Where each point id sits in `order`.
    slot: Vec<usize>,
    /// Points not yet removed under the node at each slot (its range's count).
    alive: Vec<usize>,
    removed: Vec<bool>,
}

/// The nearest point found so far: (distance, id).
type Best = Option<(f64, usize)>;

impl EndTree {
    fn new(points: Vec<[f64; 2]>) -> Self {
        let m = points.len();
        let mut order: Vec<usize> = (0..m).collect();
        build(&points, &mut order, 0);
        let mut slot = vec![0; m];
        for (s, &id) in order.iter().enumerate() {
            slot[id] = s;
        }
        let mut alive = vec![0; m];
        count(&mut alive, 0, m);
        EndTree { points, order, slot, alive, removed: vec![false; m] }
    }

    /// The id of the nearest point not removed, ties to the lowest id.
    fn nearest(&self, pen: [f64; 2]) -> Option<usize> {
        let mut best: Best = None;
        self.search(pen, 0, self.order.len(), 0, &mut best);
        best.map(|b| b.1)
    }

    fn search(&self, pen: [f64; 2], lo: usize, hi: usize, depth: usize, best: &mut Best) {
        if lo >= hi {
            return;
        }
        let mid = (lo + hi) / 2;
        if self.alive[mid] == 0 {
            return;
        }
        let id = self.order[mid];
        let p = self.points[id];
        if !self.removed[id] {
            let d = (p[0] - pen[0]).hypot(p[1] - pen[1]);
            if best.is_none_or(|(bd, bid)| d < bd || (d == bd && id < bid)) {
                *best = Some((d, id));
            }
        }
        let axis = depth % 2;
        let across = pen[axis] - p[axis];
        let (near, far) = if across < 0.0 { ((lo, mid), (mid + 1, hi)) } else { ((mid + 1, hi), (lo, mid)) };
        self.search(pen, near.0, near.1, depth + 1, best);
        // the far side's points lie at least |across| away; an equally far one may break a tie
        if best.is_none_or(|(bd, _)| across.abs() <= bd) {
            self.search(pen, far.0, far.1, depth + 1, best);
        }
    }

    fn remove(&mut self, id: usize) {
        if std::mem::replace(&mut self.removed[id], true) {
            return;
        }
        let target = self.slot[id];
        let (mut lo, mut hi) = (0, self.order.len());
        loop {
            let mid = (lo + hi) / 2;
            self.alive[mid] -= 1;
            match target.cmp(&mid) {
                std::cmp::Ordering::Equal => return,
                std::cmp::Ordering::Less => hi = mid,
                std::cmp::Ordering::Greater => lo = mid + 1,
            }
        }
    }
}

/// Arranges `ids` as the tree (median split on x, then y, in turn).
fn build(points: &[[f64; 2]], ids: &mut [usize], depth: usize) {
    if ids.len() < 2 {
        return;
    }
    let mid = ids.len() / 2;
    let axis = depth % 2;
    ids.select_nth_unstable_by(mid, |&a, &b| points[a][axis].total_cmp(&points[b][axis]));
    let (before, rest) = ids.split_at_mut(mid);
    build(points, before, depth + 1);
    build(points, &mut rest[1..], depth + 1);
}

/// Fills `alive` with the size of each node's range.
fn count(alive: &mut [usize], lo: usize, hi: usize) {
    if lo >= hi {
        return;
    }
    let mid = (lo + hi) / 2;
    alive[mid] = hi - lo;
    count(alive, lo, mid);
    count(alive, mid + 1, hi);
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The greedy rule, trying every undrawn stroke at each step.
    fn every_stroke(starts: &[[f64; 2]], ends: &[[f64; 2]]) -> Vec<(usize, bool)> {
        let n = starts.len();
        let mut todo = vec![true; n];
        let mut pen = [0.0, 0.0];
        let mut out = Vec::new();
        let dist = |p: [f64; 2], q: [f64; 2]| (p[0] - q[0]).hypot(p[1] - q[1]);
        for _ in 0..n {
            let mut best = (f64::INFINITY, usize::MAX, false);
            for (flip, points) in [(false, starts), (true, ends)] {
                for i in (0..n).filter(|&i| todo[i]) {
                    let d = dist(pen, points[i]);
                    if d < best.0 {
                        best = (d, i, flip);
                    }
                }
            }
            todo[best.1] = false;
            out.push((best.1, best.2));
            pen = if best.2 { starts[best.1] } else { ends[best.1] };
        }
        out
    }

    #[test]
    fn the_tree_finds_the_same_order_as_trying_every_stroke() {
        // a small generator, so that the test needs no crate
        let mut state = 0x2545_f491_4f6c_dd1du64;
        let mut next = || {
            state ^= state << 13;
            state ^= state >> 7;
            state ^= state << 17;
            (state >> 11) as f64 / (1u64 << 53) as f64
        };
        for n in [0, 1, 2, 7, 300] {
            let starts: Vec<[f64; 2]> = (0..n).map(|_| [100.0 * next(), 100.0 * next()]).collect();
            let ends: Vec<[f64; 2]> =
                starts.iter().map(|p| [p[0] + 5.0 * next(), p[1] + 5.0 * next()]).collect();
            assert_eq!(plotter_order(&starts, &ends), every_stroke(&starts, &ends), "{n} strokes");
        }
        // ties, on a grid of integer points: first points first, then lower indices
        let starts: Vec<[f64; 2]> = (0..50).map(|i| [(i % 5) as f64, (i / 10) as f64]).collect();
        let ends: Vec<[f64; 2]> = (0..50).map(|i| [(i % 7) as f64, (i % 3) as f64]).collect();
        assert_eq!(plotter_order(&starts, &ends), every_stroke(&starts, &ends));
    }

    #[test]
    fn a_stroke_whose_far_end_is_nearer_is_drawn_backwards() {
        let starts = [[10.0, 0.0], [11.0, 0.0]];
        let ends = [[1.0, 0.0], [20.0, 0.0]];
        assert_eq!(plotter_order(&starts, &ends), vec![(0, true), (1, false)]);
    }
}

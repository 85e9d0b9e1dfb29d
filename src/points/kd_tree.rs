//! A k-d tree over a point cloud, for each point's k nearest neighbours: built by median splits
//! on the widest axis (O(N log N)), queried with a bounded heap. Ties in distance go to the
//! smaller index, so the neighbours are the same whatever the thread count or query order.

use std::cmp::Ordering;
use std::collections::BinaryHeap;

/// Points per leaf.
const LEAF: usize = 8;

enum Node {
    Leaf { lo: u32, hi: u32 },
    Split { axis: u8, at: f64, left: u32, right: u32 },
}

pub struct KdTree<'a> {
    points: &'a [[f64; 3]],
    /// The point indices, each leaf's a contiguous range.
    order: Vec<u32>,
    nodes: Vec<Node>,
}

/// A neighbour found: squared distance, then index (the heap's order: the worst on top).
#[derive(Clone, Copy, PartialEq)]
struct Found(f64, u32);

impl Eq for Found {}

impl PartialOrd for Found {
    fn partial_cmp(&self, other: &Self) -> Option<Ordering> {
        Some(self.cmp(other))
    }
}

impl Ord for Found {
    fn cmp(&self, other: &Self) -> Ordering {
        self.0.total_cmp(&other.0).then(self.1.cmp(&other.1))
    }
}

impl<'a> KdTree<'a> {
    /// The tree of `points` (finite).
    pub fn new(points: &'a [[f64; 3]]) -> Self {
        let mut tree = KdTree { points, order: (0..points.len() as u32).collect(), nodes: vec![] };
        if !points.is_empty() {
            tree.build(0, points.len());
        }
        tree
    }

    /// Builds the node over `order[lo..hi]` and returns its index.
    fn build(&mut self, lo: usize, hi: usize) -> u32 {
        let me = self.nodes.len() as u32;
        if hi - lo <= LEAF {
            self.nodes.push(Node::Leaf { lo: lo as u32, hi: hi as u32 });
            return me;
        }
        let (mut min, mut max) = ([f64::INFINITY; 3], [f64::NEG_INFINITY; 3]);
        for &i in &self.order[lo..hi] {
            for a in 0..3 {
                min[a] = min[a].min(self.points[i as usize][a]);
                max[a] = max[a].max(self.points[i as usize][a]);
            }
        }
        let axis = (0..3).max_by(|&a, &b| (max[a] - min[a]).total_cmp(&(max[b] - min[b]))).unwrap_or(0);
        if max[axis] <= min[axis] {
            // every point the same: nothing to split
            self.nodes.push(Node::Leaf { lo: lo as u32, hi: hi as u32 });
            return me;
        }
        let mid = (lo + hi) / 2;
        let points = self.points;
        let key = |i: &u32| (points[*i as usize][axis], *i);
        self.order[lo..hi].select_nth_unstable_by(mid - lo, |a, b| {
            let (ka, kb) = (key(a), key(b));
            ka.0.total_cmp(&kb.0).then(ka.1.cmp(&kb.1))
        });
        let at = points[self.order[mid] as usize][axis];
        self.nodes.push(Node::Leaf { lo: 0, hi: 0 });
        let left = self.build(lo, mid);
        let right = self.build(mid, hi);
        self.nodes[me as usize] = Node::Split { axis: axis as u8, at, left, right };
        me
    }

    /// The `k` points nearest to `q` (fewer when the cloud has fewer), nearest first, with their
    /// squared distances; `skip` is left out (the query point itself).
    pub fn nearest(&self, q: [f64; 3], k: usize, skip: Option<u32>) -> Vec<(u32, f64)> {
        let mut heap = BinaryHeap::with_capacity(k + 1);
        if k > 0 && !self.nodes.is_empty() {
            self.search(0, q, k, skip, &mut heap);
        }
        heap.into_sorted_vec().into_iter().map(|Found(d, i)| (i, d)).collect()
    }

    fn search(&self, node: u32, q: [f64; 3], k: usize, skip: Option<u32>, heap: &mut BinaryHeap<Found>) {
        match self.nodes[node as usize] {
            Node::Leaf { lo, hi } => {
                for &i in &self.order[lo as usize..hi as usize] {
                    if Some(i) == skip {
                        continue;
                    }
                    let p = self.points[i as usize];
                    let d = (0..3).map(|a| (p[a] - q[a]) * (p[a] - q[a])).sum::<f64>();
                    let found = Found(d, i);
                    if heap.len() < k {
                        heap.push(found);
                    } else if heap.peek().is_some_and(|w| found < *w) {
                        heap.pop();
                        heap.push(found);
                    }
                }
            }
            Node::Split { axis, at, left, right } => {
                let off = q[axis as usize] - at;
                let (near, far) = if off < 0.0 { (left, right) } else { (right, left) };
                self.search(near, q, k, skip, heap);
                // points equal to the split may lie on either side: visit the far side at ties
                if heap.len() < k || heap.peek().is_some_and(|w| off * off <= w.0) {
                    self.search(far, q, k, skip, heap);
                }
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn brute(points: &[[f64; 3]], q: usize, k: usize) -> Vec<u32> {
        let mut all: Vec<Found> = (0..points.len() as u32)
            .filter(|&i| i as usize != q)
            .map(|i| {
                let p = points[i as usize];
                Found((0..3).map(|a| (p[a] - points[q][a]).powi(2)).sum(), i)
            })
            .collect();
        all.sort();
        all.into_iter().take(k).map(|f| f.1).collect()
    }

    #[test]
    fn matches_brute_force_with_duplicates_and_ties() {
        let mut points: Vec<[f64; 3]> = (0..500)
            .map(|i| {
                let t = i as f64 * 0.618;
                [(t * 7.1).sin(), (t * 3.3).cos(), ((i % 7) as f64) * 0.25]
            })
            .collect();
        // duplicates and a grid of equal distances
        points.extend_from_slice(&[[0.5, 0.5, 0.5]; 20]);
        points.extend((0..27).map(|i| [(i % 3) as f64, (i / 3 % 3) as f64, (i / 9) as f64]));
        let tree = KdTree::new(&points);
        for q in 0..points.len() {
            let got: Vec<u32> = tree.nearest(points[q], 12, Some(q as u32)).iter().map(|n| n.0).collect();
            assert_eq!(got, brute(&points, q, 12), "query {q}");
        }
    }

    #[test]
    fn fewer_points_than_asked() {
        let points = [[0.0, 0.0, 0.0], [1.0, 0.0, 0.0]];
        let tree = KdTree::new(&points);
        assert_eq!(tree.nearest(points[0], 12, Some(0)), vec![(1, 1.0)]);
        assert!(KdTree::new(&[]).nearest([0.0; 3], 3, None).is_empty());
    }
}

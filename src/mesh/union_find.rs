//! Union-find over a slice of parents (`parent[k] == k` at a root): what groups corners into
//! fans (`crease_normals`) and vertices into shells (`enclosure`).

/// The root of `k`, halving the path on the way.
#[inline]
pub fn find(parent: &mut [u32], mut k: usize) -> u32 {
    while parent[k] as usize != k {
        let up = parent[parent[k] as usize];
        parent[k] = up;
        k = up as usize;
    }
    k as u32
}

/// Merges the groups of `a` and `b`. The smaller root wins, so each group's root is its first
/// member and the result does not depend on the order of the joins.
#[inline]
pub fn join(parent: &mut [u32], a: usize, b: usize) {
    let (ra, rb) = (find(parent, a), find(parent, b));
    parent[ra.max(rb) as usize] = ra.min(rb);
}

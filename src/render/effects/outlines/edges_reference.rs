//! CPU reference of the image-space edge pass: `edges::detect`'s rule on the read-back normal and
//! depth buffers, which is what the GPU pass computes from the same values.

use crate::edges::detect::paper_gradient;
use crate::error::Result;

/// The edge mask of (H, W, 3) normals and (H, W) depths with the given thresholds.
pub fn edge_mask(
    normal: &[f32],
    depth: &[f32],
    height: usize,
    width: usize,
    thresholds: (f32, f32),
) -> Result<Vec<bool>> {
    let gn = paper_gradient(normal, height, width, 3)?;
    let gd = paper_gradient(depth, height, width, 1)?;
    Ok(gn.iter().zip(&gd).map(|(n, d)| *n > thresholds.0 || *d > thresholds.1).collect())
}

/// The discontinuity rule (`settings::ImageRule::Discontinuity`) with the pass's parameters.
#[derive(Clone, Copy, Debug)]
pub struct Discontinuity {
    /// cos of the smallest normal turn that is an edge.
    pub normal_cos: f32,
    /// The smallest depth jump that is an edge, in pixel footprints.
    pub depth_jump: f32,
    /// A pixel's size at depth z is `z * footprint[0] + footprint[1]` (in the depth's units).
    pub footprint: [f32; 2],
    pub orthographic: bool,
    /// Line width in pixels.
    pub width: f32,
}

/// The read-back buffers: (H, W, 3) normals and (H, W) depths (non-finite: background).
pub struct Buffers<'a> {
    pub normal: &'a [f32],
    pub depth: &'a [f32],
    pub width: i64,
    pub height: i64,
}

impl Buffers<'_> {
    fn inside(&self, p: (i64, i64)) -> bool {
        p.0 >= 0 && p.1 >= 0 && p.0 < self.width && p.1 < self.height
    }

    fn depth(&self, p: (i64, i64)) -> f32 {
        self.depth[(p.1 * self.width + p.0) as usize]
    }

    fn normal(&self, p: (i64, i64)) -> [f32; 3] {
        let i = (p.1 * self.width + p.0) as usize * 3;
        [self.normal[i], self.normal[i + 1], self.normal[i + 2]]
    }
}

impl Discontinuity {
    /// The rule's measure of depth: 1/z in perspective (linear across a plane on screen), z
    /// in orthographic views.
    fn measure(&self, z: f32) -> f32 {
        if self.orthographic {
            z
        } else {
            1.0 / z
        }
    }

    /// Whether the boundary between pixel a and pixel a + d is an edge (the rule of
    /// `discontinuity` in edges.wgsl).
    pub fn is_edge(&self, buf: &Buffers<'_>, a: (i64, i64), d: (i64, i64)) -> bool {
        let b = (a.0 + d.0, a.1 + d.1);
        if !buf.inside(a) || !buf.inside(b) {
            return false;
        }
        let (za, zb) = (buf.depth(a), buf.depth(b));
        if za.is_finite() != zb.is_finite() {
            return true;
        }
        if !za.is_finite() {
            return false;
        }
        let (na, nb) = (buf.normal(a), buf.normal(b));
        if na[0] * nb[0] + na[1] * nb[1] + na[2] * nb[2] < self.normal_cos {
            return true;
        }
        // the jump beyond what each side's slope predicts; the smaller of the two
        let (wa, wb) = (self.measure(za), self.measure(zb));
        let outer = |p: (i64, i64)| Some(p).filter(|&p| buf.inside(p) && buf.depth(p).is_finite());
        let mut err = f32::INFINITY;
        if let Some(a0) = outer((a.0 - d.0, a.1 - d.1)) {
            err = err.min((wb - (2.0 * wa - self.measure(buf.depth(a0)))).abs());
        }
        if let Some(b1) = outer((b.0 + d.0, b.1 + d.1)) {
            err = err.min((wa - (2.0 * wb - self.measure(buf.depth(b1)))).abs());
        }
        if err == f32::INFINITY {
            err = (wb - wa).abs();
        }
        let jump = if self.orthographic { err } else { err * za * zb };
        let z = za.min(zb);
        jump > self.depth_jump * (z * self.footprint[0] + self.footprint[1])
    }

    /// The ink coverage of pixel p: 1 within width/2 of the nearest edge boundary, falling to 0
    /// over the next pixel (the rule of `coverage` in edges.wgsl).
    pub fn coverage(&self, buf: &Buffers<'_>, p: (i64, i64)) -> f32 {
        let reach = self.width * 0.5 + 0.5;
        let r = reach.ceil() as i64;
        let c = (p.0 as f32 + 0.5, p.1 as f32 + 0.5);
        let mut best = reach;
        for dy in -r..=r {
            for dx in -r..=r {
                let q = (p.0 + dx, p.1 + dy);
                // the boundary with the right neighbour: x = q.x + 1, y in [q.y, q.y + 1]
                let right =
                    ((c.0 - (q.0 + 1) as f32).abs(), ((c.1 - (q.1 as f32 + 0.5)).abs() - 0.5).max(0.0));
                let dist = right.0.hypot(right.1);
                if dist < best && self.is_edge(buf, q, (1, 0)) {
                    best = dist;
                }
                // the boundary with the neighbour below: y = q.y + 1, x in [q.x, q.x + 1]
                let below =
                    (((c.0 - (q.0 as f32 + 0.5)).abs() - 0.5).max(0.0), (c.1 - (q.1 + 1) as f32).abs());
                let dist = below.0.hypot(below.1);
                if dist < best && self.is_edge(buf, q, (0, 1)) {
                    best = dist;
                }
            }
        }
        (reach - best).clamp(0.0, 1.0)
    }

    /// Every pixel's coverage, row-major.
    pub fn coverage_image(&self, buf: &Buffers<'_>) -> Vec<f32> {
        (0..buf.height)
            .flat_map(|y| (0..buf.width).map(move |x| (x, y)))
            .map(|p| self.coverage(buf, p))
            .collect()
    }
}

//! Axis-aligned bounding boxes, used for scale-relative tolerances and camera framing.

use crate::real::{Real, Vec3};

#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Bounds {
    pub min: [f64; 3],
    pub max: [f64; 3],
}

impl Bounds {
    /// The bounding box of the given points (all vertices, referenced or not).
    pub fn of<T: Real>(points: &[Vec3<T>]) -> Bounds {
        let mut min = [f64::INFINITY; 3];
        let mut max = [f64::NEG_INFINITY; 3];
        for p in points {
            for k in 0..3 {
                let v = p[k].to_f64();
                min[k] = min[k].min(v);
                max[k] = max[k].max(v);
            }
        }
        Bounds { min, max }
    }

    pub fn diagonal(&self) -> f64 {
        let d = [self.max[0] - self.min[0], self.max[1] - self.min[1], self.max[2] - self.min[2]];
        (d[0] * d[0] + d[1] * d[1] + d[2] * d[2]).sqrt()
    }

    pub fn center(&self) -> [f64; 3] {
        [
            0.5 * (self.min[0] + self.max[0]),
            0.5 * (self.min[1] + self.max[1]),
            0.5 * (self.min[2] + self.max[2]),
        ]
    }

    /// The largest absolute coordinate: the scale at which rounding happens.
    pub fn magnitude(&self) -> f64 {
        self.min.iter().chain(self.max.iter()).fold(0.0f64, |m, v| m.max(v.abs()))
    }
}

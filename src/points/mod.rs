//! Point clouds: each point's nearest neighbours (`kd_tree`), and what they tell of the surface
//! the points sample (`local`: a normal per point by PCA, and the cloud's spacing, which sizes
//! its splats whatever its units).

pub mod kd_tree;
pub mod local;

//! Triangle meshes: checked input, one-ring adjacency, bounding boxes and procedural shapes.

pub mod adjacency;
pub mod bounds;
pub mod input;
pub mod normals;
pub mod shapes;

pub use adjacency::Adjacency;
pub use bounds::Bounds;
pub use input::{check_faces, check_positions, Faces};

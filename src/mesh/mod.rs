//! Triangle meshes: checked input, connectivity (face items bucketed by vertex, and what is
//! derived from them: one-rings and the edge table), welding, bounding boxes, curvature and
//! procedural shapes.

pub mod adjacency;
pub mod back_to_back;
pub mod bounds;
pub mod buckets;
pub mod bvh;
pub mod crease_normals;
pub mod curvature;
pub mod diffuse;
pub mod dihedral;
pub mod edge_length;
pub mod edge_table;
pub mod enclosure;
pub mod input;
pub mod line_field;
pub mod normals;
pub mod positions;
pub mod reorder;
pub mod shapes;
pub mod stripes;
pub mod union_find;
pub mod weld;

pub use adjacency::Adjacency;
pub use bounds::Bounds;
pub use buckets::Buckets;
pub use edge_table::EdgeTable;
pub use input::{
    check_faces, check_mask, check_positions, faces_from_flat, flag_vertices, rows_of, Faces, FacesRef,
};
pub use positions::{Positions, PositionsRef};

//! Outlines: boundary, crease and non-manifold edges and silhouettes found on the mesh
//! (Kang, Kim and Yoon), and Sobel edges found in images (Borquez and Yepez).

pub mod chains;
pub mod detect;
pub mod edge_table;
pub mod feature;
pub mod index;
pub mod silhouette;
pub mod sobel;
pub mod weld;

pub use edge_table::EdgeTable;
pub use feature::FeatureEdges;
pub use index::EdgeIndex;
pub use silhouette::View;

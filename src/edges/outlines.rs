//! The outline set of one view: what a mesh-space outline pass draws (Kang, Kim and Yoon).
//! The view-independent part (boundaries, creases as ridges and valleys, non-manifold edges) is
//! found once per mesh; each view adds its silhouettes. Every edge appears once, with one kind:
//! a silhouette first, then what it is on the mesh.

use std::collections::HashMap;
use std::sync::{Arc, Mutex};

use super::feature::FeatureEdges;
use crate::error::Result;

/// Kinds of mesh-space lines, in priority order (an edge that is several is drawn as the first).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, PartialOrd, Ord)]
#[repr(u32)]
pub enum LineKind {
    Silhouette = 0,
    Boundary = 1,
    NonManifold = 2,
    /// A convex crease.
    Ridge = 3,
    /// A concave crease.
    Valley = 4,
    /// A suggestive contour (`edges::contours`): found through the faces, never an edge.
    Suggestive = 5,
    /// A border between two items of a scene (meshes, or the parts of a file with different
    /// materials): a boundary edge of one that lies on a boundary edge of another, as Blender's
    /// Line Art draws material borders. Found per scene (`outlines::shared_borders`).
    Material = 6,
    /// Where the surfaces of two scene items cross (`edges::intersections`): found per scene,
    /// through the faces, never an edge.
    Intersection = 7,
}

impl LineKind {
    pub const COUNT: usize = 8;
    pub const ALL: [LineKind; LineKind::COUNT] = [
        LineKind::Silhouette,
        LineKind::Boundary,
        LineKind::NonManifold,
        LineKind::Ridge,
        LineKind::Valley,
        LineKind::Suggestive,
        LineKind::Material,
        LineKind::Intersection,
    ];

    /// Kinds that run along an object's outline, where background next to a line point does
    /// not hide it, as bits (bit k for the kind of index k): silhouettes, boundaries and the
    /// borders between scene items (a border is a boundary of each of its two items).
    pub const RIM_BITS: u32 =
        1 << LineKind::Silhouette as u32 | 1 << LineKind::Boundary as u32 | 1 << LineKind::Material as u32;

    /// Whether the kind of index `kind` runs along the rim (`RIM_BITS`).
    pub fn on_rim(kind: usize) -> bool {
        LineKind::RIM_BITS >> kind & 1 == 1
    }

    pub fn name(self) -> &'static str {
        match self {
            LineKind::Silhouette => "silhouette",
            LineKind::Boundary => "boundary",
            LineKind::NonManifold => "nonmanifold",
            LineKind::Ridge => "ridge",
            LineKind::Valley => "valley",
            LineKind::Suggestive => "suggestive",
            LineKind::Material => "material",
            LineKind::Intersection => "intersection",
        }
    }
}

/// Edges (smaller index first, sorted lexicographically, each once) with their kinds.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Outline {
    pub edges: Vec<[u32; 2]>,
    pub kinds: Vec<LineKind>,
}

impl Outline {
    pub fn len(&self) -> usize {
        self.edges.len()
    }

    pub fn is_empty(&self) -> bool {
        self.edges.is_empty()
    }

    /// The view-independent lines of a mesh.
    pub fn statics(fe: &FeatureEdges) -> Outline {
        let creases = Outline {
            edges: fe.crease.clone(),
            kinds: fe
                .crease_convex
                .iter()
                .map(|&convex| if convex { LineKind::Ridge } else { LineKind::Valley })
                .collect(),
        };
        let of = |edges: &[[u32; 2]], kind| Outline { edges: edges.to_vec(), kinds: vec![kind; edges.len()] };
        merge(
            &merge(&of(&fe.boundary, LineKind::Boundary), &of(&fe.nonmanifold, LineKind::NonManifold)),
            &creases,
        )
    }

    /// These lines without those of `kind`.
    pub fn without(&self, kind: LineKind) -> Outline {
        let (edges, kinds) = self.edges.iter().zip(&self.kinds).filter(|(_, k)| **k != kind).unzip();
        Outline { edges, kinds }
    }

    /// These lines and a view's silhouettes (sorted), a silhouette taking precedence.
    pub fn with_silhouettes(&self, silhouettes: &[[u32; 2]]) -> Outline {
        let sil =
            Outline { edges: silhouettes.to_vec(), kinds: vec![LineKind::Silhouette; silhouettes.len()] };
        merge(&sil, self)
    }
}

/// A mesh's view-independent lines per crease rule (crease angle, shortest crease piece, largest
/// mean turn of a piece), found once each and kept, so that each view of the mesh only finds
/// its silhouettes.
#[derive(Debug, Default)]
pub struct Statics(Mutex<HashMap<[u64; 3], Arc<Outline>>>);

impl Statics {
    /// The lines at `crease_angle` with crease pieces of at least `min_crease_length` that turn
    /// by at most `max_crease_turn`, from `find` (the mesh's feature edges under that rule) the
    /// first time.
    pub fn at(
        &self,
        crease_angle: f64,
        min_crease_length: f64,
        max_crease_turn: f64,
        find: impl FnOnce() -> Result<FeatureEdges>,
    ) -> Result<Arc<Outline>> {
        let key = [crease_angle.to_bits(), min_crease_length.to_bits(), max_crease_turn.to_bits()];
        if let Some(s) = self.0.lock().unwrap_or_else(|e| e.into_inner()).get(&key) {
            return Ok(s.clone());
        }
        let s = Arc::new(Outline::statics(&find()?));
        self.0.lock().unwrap_or_else(|e| e.into_inner()).insert(key, s.clone());
        Ok(s)
    }
}

/// The union of two sorted outlines; on an edge in both, the kind of higher priority.
fn merge(a: &Outline, b: &Outline) -> Outline {
    let mut out = Outline {
        edges: Vec::with_capacity(a.len() + b.len()),
        kinds: Vec::with_capacity(a.len() + b.len()),
    };
    let (mut i, mut j) = (0, 0);
    while i < a.len() || j < b.len() {
        let take_a = j == b.len() || (i < a.len() && a.edges[i] <= b.edges[j]);
        let (e, k) = if take_a { (a.edges[i], a.kinds[i]) } else { (b.edges[j], b.kinds[j]) };
        if out.edges.last() == Some(&e) {
            let last = out.kinds.last_mut().expect("kinds follow edges");
            *last = (*last).min(k);
        } else {
            out.edges.push(e);
            out.kinds.push(k);
        }
        if take_a {
            i += 1;
        } else {
            j += 1;
        }
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn silhouettes_take_precedence_and_edges_stay_sorted_and_unique() {
        let fe = FeatureEdges {
            boundary: vec![[0, 1], [4, 5]],
            crease: vec![[1, 2], [2, 3]],
            crease_angle: vec![40.0, 50.0],
            crease_convex: vec![true, false],
            nonmanifold: vec![[3, 9]],
        };
        let s = Outline::statics(&fe);
        assert_eq!(s.edges, vec![[0, 1], [1, 2], [2, 3], [3, 9], [4, 5]]);
        use LineKind::*;
        assert_eq!(s.kinds, vec![Boundary, Ridge, Valley, NonManifold, Boundary]);
        let v = s.with_silhouettes(&[[1, 2], [7, 8]]);
        assert_eq!(v.edges, vec![[0, 1], [1, 2], [2, 3], [3, 9], [4, 5], [7, 8]]);
        assert_eq!(v.kinds, vec![Boundary, Silhouette, Valley, NonManifold, Boundary, Silhouette]);
    }
}

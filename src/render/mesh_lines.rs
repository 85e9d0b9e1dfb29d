//! A mesh's outline analysis, kept with the uploaded mesh: the edge index (built on the first
//! render that asks for mesh-space lines) and the view-independent lines for each crease angle,
//! so that each view only runs the silhouette test.

use std::collections::HashMap;
use std::sync::{Arc, Mutex, OnceLock};

use crate::edges::outlines::Outline;
use crate::edges::{EdgeIndex, View};
use crate::error::Result;

use super::gpu_mesh::HostMesh;
use super::scene::outlines::Outlines;

pub struct MeshLines {
    host: HostMesh,
    /// Without and with welding.
    indices: [OnceLock<Result<EdgeIndex>>; 2],
    statics: Mutex<HashMap<(bool, u64), Arc<Outline>>>,
}

impl MeshLines {
    pub fn new(host: HostMesh) -> Self {
        MeshLines { host, indices: [OnceLock::new(), OnceLock::new()], statics: Mutex::new(HashMap::new()) }
    }

    pub fn index(&self, weld: bool) -> Result<&EdgeIndex> {
        self.indices[weld as usize]
            .get_or_init(|| {
                crate::parallel::install(|| EdgeIndex::build(&self.host.positions, &self.host.faces, weld))
            })
            .as_ref()
            .map_err(Clone::clone)
    }

    /// The lines of one view (`view` in the mesh's stored coordinates): silhouettes, then the
    /// cached view-independent lines, keeping the kinds `outlines` draws.
    pub fn outline(&self, view: View, outlines: &Outlines) -> Result<Outline> {
        let index = self.index(outlines.weld)?;
        let key = (outlines.weld, outlines.crease_angle.to_bits());
        let cached = self.statics.lock().unwrap_or_else(|e| e.into_inner()).get(&key).cloned();
        let statics = match cached {
            Some(s) => s,
            None => {
                let fe = crate::parallel::install(|| index.feature_edges(outlines.crease_angle))?;
                let s = Arc::new(Outline::statics(&fe));
                self.statics.lock().unwrap_or_else(|e| e.into_inner()).insert(key, s.clone());
                s
            }
        };
        let all = if outlines.styles[crate::edges::outlines::LineKind::Silhouette as usize].is_some() {
            let sil = crate::parallel::install(|| index.silhouette(view))?;
            statics.with_silhouettes(&sil)
        } else {
            (*statics).clone()
        };
        let (edges, kinds) =
            all.edges.iter().zip(&all.kinds).filter(|(_, k)| outlines.styles[**k as usize].is_some()).unzip();
        Ok(Outline { edges, kinds })
    }

    /// Positions the edges index (stored coordinates; welded indices name the same points).
    pub fn positions(&self) -> &[[f64; 3]] {
        &self.host.positions
    }
}

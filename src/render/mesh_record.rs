//! A mesh a renderer holds: its device buffers, its geometry on the host, and what effects
//! derive from it once and keep with it (the outline analysis, per crease angle), so that each
//! view only does its own part.

use std::any::{Any, TypeId};
use std::collections::HashMap;
use std::sync::{Arc, Mutex};

use super::gpu_mesh::{GpuMesh, HostMesh};

pub struct MeshRecord {
    pub gpu: GpuMesh,
    pub host: HostMesh,
    /// A point cloud's splats (`render::splats`): inked in image space, never by its edges.
    pub splats: bool,
    derived: Mutex<HashMap<TypeId, Arc<dyn Any + Send + Sync>>>,
}

impl MeshRecord {
    pub fn new(gpu: GpuMesh, host: HostMesh) -> Self {
        MeshRecord { gpu, host, splats: false, derived: Mutex::new(HashMap::new()) }
    }

    /// The record, marked as a point cloud's splats where `splats`.
    pub fn marked_splats(mut self, splats: bool) -> Self {
        self.splats = splats;
        self
    }

    /// The value of type `T` kept with this mesh, made by `make` the first time it is asked
    /// for. `make` must be cheap (build expensive parts lazily inside `T`): it runs under a lock.
    pub fn derived<T: Any + Send + Sync>(&self, make: impl FnOnce() -> T) -> Arc<T> {
        let mut map = self.derived.lock().unwrap_or_else(|e| e.into_inner());
        let entry = map.entry(TypeId::of::<T>()).or_insert_with(|| Arc::new(make()));
        entry.clone().downcast::<T>().expect("stored under its own type")
    }
}

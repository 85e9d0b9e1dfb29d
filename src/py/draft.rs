//! `Renderer._draft`: the draft of a scene for a WebGL2 page (`render::draft`).

use pyo3::prelude::*;
use pyo3::types::PyBytes;

use super::render::{mesh_specs, without_gil, PyRenderer};
use super::settings::PyRenderOptions;
use crate::error::Error;

#[pymethods]
impl PyRenderer {
    /// items: [(mesh id, Material or None, 4x4 transform or None)] as `render` takes them, seen
    /// from the options' camera: (the draft as JSON, the bytes its spans point into).
    fn _draft<'py>(
        &self,
        py: Python<'py>,
        items: &Bound<'py, PyAny>,
        options: &PyRenderOptions,
    ) -> PyResult<(String, Bound<'py, PyBytes>)> {
        let o = &options.inner;
        let scene = self.inner.check(o.scene(&mesh_specs(items)?)?, o.frame)?;
        let inner = &self.inner;
        let (draft, blob): (String, Vec<u8>) = without_gil(py, || {
            let (draft, blob) = inner.draft(&scene)?;
            let json = serde_json::to_string(&draft)
                .map_err(|e| Error::Internal(format!("a draft as JSON: {e}")))?;
            Ok((json, blob))
        })?;
        Ok((draft, PyBytes::new(py, &blob)))
    }
}

//! `Renderer._draft`: the draft of a scene for a WebGL2 page (`render::draft`).

use pyo3::prelude::*;
use pyo3::types::PyBytes;

use super::render::{line_specs, mesh_specs, without_gil, PyRenderer};
use super::settings::PyRenderOptions;
use crate::error::Error;

#[pymethods]
impl PyRenderer {
    /// items: [(mesh id, Material or None, 4x4 transform or None)] as `render` takes them, seen
    /// from the options' camera, with the line sets `lines` as `render` takes them: (the draft
    /// as JSON, the bytes its spans point into).
    #[pyo3(signature = (items, options, lines = None))]
    fn _draft<'py>(
        &self,
        py: Python<'py>,
        items: &Bound<'py, PyAny>,
        options: &PyRenderOptions,
        lines: Option<&Bound<'py, PyAny>>,
    ) -> PyResult<(String, Bound<'py, PyBytes>)> {
        let o = &options.inner;
        let sets = lines.map(line_specs).transpose()?.unwrap_or_default();
        let scene = self.inner.check(o.scene_with_lines(&mesh_specs(items)?, sets)?, o.frame)?;
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

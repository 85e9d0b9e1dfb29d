//! PyO3 glue: NumPy in and out, argument checks, GIL release, error mapping.

mod albedo;
mod args;
mod convert;
mod draft;
mod edges;
mod errors;
mod mesh_input;
mod points;
mod render;
mod runtime;
mod settings;
mod shapes;
mod smooth;
mod strokes;

use pyo3::prelude::*;

/// Everything `toonmesh._core` holds.
pub fn register(m: &Bound<'_, PyModule>) -> PyResult<()> {
    errors::register(m)?;
    settings::register(m)?;
    let functions = [
        wrap_pyfunction!(edges::_feature_edges, m)?,
        wrap_pyfunction!(edges::_curvature, m)?,
        wrap_pyfunction!(edges::_view_lines, m)?,
        wrap_pyfunction!(edges::_chains, m)?,
        wrap_pyfunction!(edges::_intersections, m)?,
        wrap_pyfunction!(edges::_intersection_lines, m)?,
        wrap_pyfunction!(edges::_sobel, m)?,
        wrap_pyfunction!(edges::_paper_edges, m)?,
        wrap_pyfunction!(edges::_vertex_count, m)?,
        wrap_pyfunction!(runtime::set_num_threads, m)?,
        wrap_pyfunction!(runtime::get_num_threads, m)?,
        wrap_pyfunction!(shapes::icosphere, m)?,
        wrap_pyfunction!(shapes::grid, m)?,
        wrap_pyfunction!(smooth::_smooth, m)?,
        wrap_pyfunction!(smooth::_smoothing_description, m)?,
        wrap_pyfunction!(strokes::_pen_strokes, m)?,
        wrap_pyfunction!(strokes::_plotter_order, m)?,
        wrap_pyfunction!(strokes::_svg_document, m)?,
        wrap_pyfunction!(points::_point_normals, m)?,
        wrap_pyfunction!(render::_shadow_truth, m)?,
        wrap_pyfunction!(albedo::_srgb_from_linear, m)?,
        wrap_pyfunction!(render::_normal_mode, m)?,
        wrap_pyfunction!(render::_up_axis, m)?,
        wrap_pyfunction!(render::_transform, m)?,
        wrap_pyfunction!(render::gpu_info, m)?,
        wrap_pyfunction!(render::encode_png_rgba, m)?,
        wrap_pyfunction!(render::decode_png, m)?,
        wrap_pyfunction!(settings::_restore, m)?,
        wrap_pyfunction!(settings::kang_table, m)?,
    ];
    for f in functions {
        m.add_function(f)?;
    }
    m.add_class::<edges::PyEdgeIndex>()?;
    m.add_class::<render::PyRenderer>()?;
    m.add("__version__", env!("CARGO_PKG_VERSION"))?;
    Ok(())
}

//! Python bindings for `crate::render::effects::outlines::pen`: the strokes of a line drawing as
//! a pen draws them, called by `toonmesh/rendering/_strokes.py`.

use pyo3::prelude::*;
use pyo3::types::PyList;

use super::args::{self, items};
use super::convert::{array_values, rows, ToPython, FLOATS};
use super::runtime::detached;
use crate::error::{as_many, Error, Result};
use crate::render::effects::outlines::pen::svg::{self, Group, Ink, Stroke};
use crate::render::effects::outlines::pen::{self, plotter_order as order};

/// (K, 2) finite pixel coordinates.
fn point_array(arg: &str, obj: &Bound<'_, PyAny>) -> Result<Vec<[f64; 2]>> {
    let p = rows(&array_values(arg, obj, &["float64"], (&[None, Some(2)], "(K, 2)"))?.0);
    pen::check_points(arg, &p).map(|()| p)
}

/// (K,) finite widths in pixels, float32 or float64.
fn width_array(arg: &str, obj: &Bound<'_, PyAny>, n: usize) -> Result<Vec<f64>> {
    let w = array_values(arg, obj, FLOATS, (&[None], "(K,)"))?.0;
    pen::check_widths(arg, &w, n).map(|()| w)
}

/// Line `i` of the lines `arg` and its widths (None: not given), the `i`th of `widths_arg`.
fn stroke(
    (arg, widths_arg, i): (&str, &str, usize),
    line: &Bound<'_, PyAny>,
    widths: Option<&Bound<'_, PyAny>>,
) -> Result<(Vec<[f64; 2]>, Option<Vec<f64>>)> {
    let points = point_array(&format!("{arg}[{i}]"), line)?;
    let widths = widths.map(|w| width_array(&format!("{widths_arg}[{i}]"), w, points.len())).transpose()?;
    Ok((points, widths))
}

/// Each of `lines` as the SVG draws it (`pen::drawn`): the points drawn and which of the line's
/// points they are. `widths[i]` None simplifies line i by its points alone.
#[pyfunction]
pub(super) fn _pen_strokes<'py>(
    py: Python<'py>,
    lines: &Bound<'py, PyAny>,
    widths: &Bound<'py, PyAny>,
    smooth: &Bound<'py, PyAny>,
    simplify: &Bound<'py, PyAny>,
) -> PyResult<Bound<'py, PyList>> {
    let (line_items, width_items) = (items("lines", lines, "a list")?, items("widths", widths, "a list")?);
    as_many("widths", width_items.len(), ("one entry per line", line_items.len()))?;
    let strokes = line_items
        .iter()
        .zip(&width_items)
        .enumerate()
        .map(|(i, (l, w))| stroke(("lines", "widths", i), l, Some(w).filter(|w| !w.is_none())))
        .collect::<Result<Vec<_>>>()?;
    let (smooth, simplify) = (args::number("smooth", smooth)?, args::number("simplify", simplify)?);
    let drawn = detached(py, || pen::drawn_all(&strokes, smooth, simplify))?;
    let out = drawn.into_iter().map(|(p, kept)| (p, kept.into_iter().map(|i| i as i64).collect::<Vec<_>>()));
    PyList::new(py, out.map(|d| d.to_python(py)).collect::<PyResult<Vec<_>>>()?)
}

/// `pen::plotter_order::plotter_order` of the strokes with first points `starts` and last
/// points `ends` ((N, 2) each): the strokes' indices in drawing order, and whether each is drawn
/// from its last point.
#[pyfunction]
pub(super) fn _plotter_order<'py>(
    py: Python<'py>,
    starts: &Bound<'py, PyAny>,
    ends: &Bound<'py, PyAny>,
) -> PyResult<Bound<'py, PyAny>> {
    let (starts, ends) = (point_array("starts", starts)?, point_array("ends", ends)?);
    as_many("ends", ends.len(), ("as many as starts", starts.len()))?;
    let drawn = detached(py, || Ok(order::plotter_order(&starts, &ends)))?;
    let (index, reversed): (Vec<i64>, Vec<bool>) = drawn.into_iter().map(|(i, r)| (i as i64, r)).unzip();
    (index, reversed).to_python(py)
}

/// One group of `svg_document`: (id, colour, width in pixels or None for filled outlines,
/// (dash, gap) or None, lines, widths per line or None).
fn group(arg: &str, obj: &Bound<'_, PyAny>) -> Result<Group> {
    let fields = items(arg, obj, "a list")?;
    let [id, color, width, dashes, lines, line_widths] = fields.as_slice() else {
        return Err(Error::invalid(arg, format!("expected 6 fields, got {}", fields.len())));
    };
    let field = |name: &str| format!("{arg}.{name}");
    let ink = if width.is_none() {
        Ink::Filled
    } else {
        let width = args::number(&field("width"), width)?;
        let dashes = args::optional(&field("dashes"), Some(dashes), args::numbers)?
            .map(|d| <[f64; 2]>::try_from(d.as_slice()))
            .transpose()
            .map_err(|_| Error::invalid(field("dashes"), "expected (dash, gap)"))?;
        Ink::Lines { width, dashes }
    };
    let lines = items(&field("lines"), lines, "a list")?;
    let line_widths =
        if line_widths.is_none() { None } else { Some(items(&field("widths"), line_widths, "a list")?) };
    match &line_widths {
        None if matches!(ink, Ink::Filled) => {
            return Err(Error::invalid(field("widths"), "filled outlines need one widths array per line"))
        }
        None => {}
        Some(w) => as_many(&field("widths"), w.len(), ("one widths array per line", lines.len()))?,
    }
    let strokes = lines
        .iter()
        .enumerate()
        .map(|(i, l)| {
            let (points, widths) =
                stroke((&field("lines"), &field("widths"), i), l, line_widths.as_ref().map(|w| &w[i]))?;
            Ok(Stroke { points, widths: widths.unwrap_or_default() })
        })
        .collect::<Result<Vec<_>>>()?;
    Ok(Group { id: args::text(&field("id"), id)?, color: args::rgb(&field("color"), color)?, ink, strokes })
}

/// `pen::svg::document`: the SVG text of a `width` x `height` drawing of `groups`.
#[pyfunction]
pub(super) fn _svg_document(
    py: Python<'_>,
    width: &Bound<'_, PyAny>,
    height: &Bound<'_, PyAny>,
    groups: &Bound<'_, PyAny>,
) -> PyResult<String> {
    let size = |name: &str, obj| -> Result<u32> {
        let v = args::integer(name, obj)?;
        u32::try_from(v).map_err(|_| Error::invalid(name, format!("must be in [0, 2**32), got {v}")))
    };
    let groups = items("groups", groups, "a list")?
        .iter()
        .enumerate()
        .map(|(i, g)| group(&format!("groups[{i}]"), g))
        .collect::<Result<Vec<_>>>()?;
    let (width, height) = (size("width", width)?, size("height", height)?);
    detached(py, || Ok(svg::document(width, height, &groups)))
}

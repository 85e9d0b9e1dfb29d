"""Mesh-space outlines seen by a camera, as SVG line art or NPZ arrays (``toonmesh edges``).

The lines are the renderer's own ``lines`` output (silhouettes of the view, boundaries, creases,
non-manifold edges, with hidden lines removed against its depth buffer), so they fall exactly
where a render with that camera draws the mesh. Hidden lines are those of the same render with
hidden-line removal turned off, less the visible ones.
"""

from __future__ import annotations

from typing import Any, Dict, List, Optional

import numpy as np

from toonmesh import edges
from toonmesh.rendering import _strokes
from toonmesh._core import Outlines
from toonmesh.rendering._render import render

#: Depth offset (in pixel footprints) that lets every line through: no hidden-line removal.
_SHOW_ALL = 1e30
#: Hidden lines in the SVG: grey, dashes of 4 pixels with gaps of 3.
_HIDDEN_COLOR = "#9a9a9a"
_HIDDEN_DASHES = (4.0, 3.0)


def view_lines(
    vertices: np.ndarray,
    faces: np.ndarray,
    camera: Any,
    outlines: Outlines,
    *,
    width: int,
    height: int,
    hidden: bool = False,
    backend: Optional[str] = None,
    up: Optional[str] = None,
) -> Dict[str, Any]:
    """The visible (and, with ``hidden``, every) polyline of one view that ``outlines`` (mesh
    lines) draws, and the mesh's feature edges at its crease angle; see :func:`write_npz` for
    the arrays. ``up``: the scene's up axis (None: y), which a fitted ``camera`` keeps up."""
    kw = dict(camera=camera, width=width, height=height, outputs=("lines",), backend=backend, up=up)
    seen = render(vertices, faces, outlines=outlines, **kw)
    everything = None
    if hidden:
        everything = render(vertices, faces, outlines=outlines.replace(depth_offset=_SHOW_ALL), **kw)
    features = edges.feature_edges(vertices, faces, outlines.crease_angle, weld=outlines.weld)
    return {"seen": seen, "everything": everything, "features": features}


def _length(lines: List[np.ndarray]) -> float:
    return float(sum(np.linalg.norm(np.diff(p, axis=0), axis=1).sum() for p in lines))


def summary(lines: Dict[str, Any]) -> str:
    """Counts of polylines per kind, and how much of the drawing is hidden."""
    seen = lines["seen"]
    kinds = seen.line_kinds or []
    counts = ", ".join(f"{kinds.count(k):,} {k}" for k in sorted(set(kinds))) or "no lines"
    text = f"{len(kinds):,} visible polylines ({counts})"
    if lines["everything"] is not None:
        total = _length(lines["everything"].lines)
        text += f"; {100 * (1 - _length(seen.lines) / total) if total else 0:.0f}% of the line length is hidden"
    return text


def write_svg(path: str, lines: Dict[str, Any], **svg_options: Any) -> None:
    """Writes the visible lines as SVG (the render's :meth:`RenderResult.svg` with
    ``svg_options``, its defaults where left out); with hidden lines, those go underneath,
    dashed and grey."""
    seen, everything = lines["seen"], lines["everything"]
    groups = seen.svg_groups(**svg_options)
    if everything is not None:
        groups.insert(0, ("hidden", _HIDDEN_COLOR, 1.0, _HIDDEN_DASHES, [(p, None) for p in everything.lines]))
    svg = _strokes.svg_document(seen.width, seen.height, groups)
    with open(path, "w", encoding="utf-8") as f:
        f.write(svg)


def write_npz(path: str, lines: Dict[str, Any]) -> None:
    """Writes the drawing as arrays: ``points`` (P, 2) float64 pixel coordinates of every visible
    polyline, one after another, with ``starts`` (L + 1,) int64 where each begins,
    ``kinds`` (L,) its kind and ``widths`` (P,) float32 the ink's width at each point (pixels); the mesh's feature edges (``boundary``, ``crease``,
    ``crease_angles``, ``crease_convex``, ``nonmanifold``); and ``view_matrix``,
    ``projection``, ``width``, ``height`` of the camera."""
    seen, fe = lines["seen"], lines["features"]
    polylines = seen.lines or []
    starts = np.concatenate([[0], np.cumsum([len(p) for p in polylines])]).astype(np.int64)
    np.savez_compressed(
        path,
        points=np.concatenate(polylines) if polylines else np.zeros((0, 2)),
        starts=starts,
        kinds=np.array(seen.line_kinds or [], dtype=str),
        widths=np.concatenate(seen.line_widths) if polylines else np.zeros(0, np.float32),
        boundary=fe.boundary,
        crease=fe.crease,
        crease_angles=fe.crease_angles,
        crease_convex=fe.crease_convex,
        nonmanifold=fe.nonmanifold,
        view_matrix=seen.view_matrix,
        projection=seen.projection,
        width=np.int64(seen.width),
        height=np.int64(seen.height),
    )

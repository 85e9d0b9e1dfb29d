"""Mesh-space outlines seen by a camera, as SVG line art or NPZ arrays (``toonmesh edges``).

The lines are the renderer's own ``lines`` output (silhouettes of the view, boundaries, creases,
non-manifold edges, with the lines behind surfaces found exactly), so they fall exactly where a
render with that camera draws the mesh; with ``Outlines(hidden=True)`` the hidden lines come
as the kind ``hidden``, in their own dashed style.
"""

from __future__ import annotations

from typing import Any, Dict, List, Optional

import numpy as np

from toonmesh import edges
from toonmesh.rendering import _strokes
from toonmesh._core import Outlines
from toonmesh.rendering._render import render


def view_lines(
    vertices: np.ndarray,
    faces: np.ndarray,
    camera: Any,
    outlines: Outlines,
    *,
    width: int,
    height: int,
    backend: Optional[str] = None,
    up: Optional[str] = None,
) -> Dict[str, Any]:
    """The polylines of one view that ``outlines`` (mesh lines) draws (the visible ones, and
    the hidden ones where it asks for them), and the mesh's feature edges at its crease angle;
    see :func:`write_npz` for the arrays. ``up``: the scene's up axis (None: y), which a fitted
    ``camera`` keeps up."""
    kw = dict(camera=camera, width=width, height=height, outputs=("lines",), backend=backend, up=up)
    seen = render(vertices, faces, outlines=outlines, **kw)
    features = edges.feature_edges(vertices, faces, outlines.crease_angle, weld=outlines.weld)
    return {"seen": seen, "features": features}


def _length(lines: List[np.ndarray]) -> float:
    return float(sum(np.linalg.norm(np.diff(p, axis=0), axis=1).sum() for p in lines))


def summary(lines: Dict[str, Any]) -> str:
    """Counts of polylines per kind, and how much of the drawing is hidden."""
    seen = lines["seen"]
    kinds = seen.line_kinds or []
    visible = [k for k in kinds if k != "hidden"]
    counts = ", ".join(f"{visible.count(k):,} {k}" for k in sorted(set(visible))) or "no lines"
    text = f"{len(visible):,} visible polylines ({counts})"
    if seen.outlines is not None and seen.outlines.hidden:
        polylines = seen.lines or []
        hidden = _length([p for p, k in zip(polylines, kinds) if k == "hidden"])
        total = _length(polylines)
        text += f"; {100 * hidden / total if total else 0:.0f}% of the line length is hidden"
    return text


def write_svg(path: str, lines: Dict[str, Any], **svg_options: Any) -> None:
    """Writes the lines as SVG (the render's :meth:`RenderResult.svg` with ``svg_options``, its
    defaults where left out): hidden lines, where drawn, go underneath in their dashed style."""
    lines["seen"].save_svg(path, **svg_options)


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

"""Mesh-space outlines seen by a camera: the edges, where they land in the image, and which ones
the surface hides; written as SVG line art or as NPZ arrays (``toonmesh edges``).

The camera is resolved by the renderer itself (a depth-only render at the drawing's size), so the
lines fall exactly where a render with that camera draws the mesh, and that depth buffer decides
which lines are hidden.
"""

from __future__ import annotations

from typing import Any, Dict, Optional

import numpy as np

#: Line kinds, in the order an edge is assigned to one (an edge of several kinds is drawn once).
KINDS = ("silhouette", "boundary", "nonmanifold", "crease")

_STROKES = {"silhouette": "#000000", "boundary": "#1f4e9c", "nonmanifold": "#c0392b", "crease": "#444444"}


def view_lines(
    vertices: np.ndarray,
    faces: np.ndarray,
    camera: Any,
    *,
    width: int,
    height: int,
    crease_angle: float = 30.0,
    weld: bool = False,
    backend: Optional[str] = None,
) -> Dict[str, Any]:
    """Outline edges of one view with their image positions and visibility.

    Returns a dict of arrays: the feature edges (``boundary``, ``crease``, ``crease_angles``,
    ``crease_convex``, ``nonmanifold``; (K, 2) int64 vertex pairs), ``silhouette`` for this
    camera, and for their union ``edges`` (K, 2), ``kind`` (K,) int8 (index into ``kinds``),
    ``segments`` (K, 2, 3) float64 end points, ``points`` (K, 2, 2) float64 end points in
    pixels (x right, y down, origin at the top-left corner), ``visible`` (K,) bool (the segment's
    midpoint is not behind the surface); and ``view_matrix``, ``projection``, ``width``,
    ``height``.
    """
    import toonmesh as tm

    index = tm.edges.EdgeIndex(vertices, faces, crease_angle=crease_angle, weld=weld)
    shot = tm.render(vertices, faces, camera=camera, width=width, height=height, outputs=("depth",), backend=backend)
    view, proj = np.asarray(shot.view_matrix), np.asarray(shot.projection)
    orthographic = proj[3, 3] == 1.0
    rotation = view[:3, :3]
    if orthographic:
        silhouette = index.silhouette(direction=-rotation[2])  # the camera looks down its -z
    else:
        silhouette = index.silhouette(eye=-rotation.T @ view[:3, 3])
    features = index.features
    parts = {"silhouette": silhouette, "boundary": features.boundary, "nonmanifold": features.nonmanifold,
             "crease": features.crease}
    edges, kind = _classified(parts, index.n_vertices)
    segments = index.segments(edges)
    points, depth = _project(segments.reshape(-1, 3), view, proj, width, height)
    mid_points, mid_depth = _project(segments.mean(axis=1), view, proj, width, height)
    visible = _visible(mid_points, mid_depth, np.asarray(shot.depth), shot.far - shot.near)
    return {
        "boundary": features.boundary, "crease": features.crease, "crease_angles": features.crease_angles,
        "crease_convex": features.crease_convex, "nonmanifold": features.nonmanifold, "silhouette": silhouette,
        "edges": edges, "kind": kind, "kinds": np.array(KINDS), "segments": segments,
        "points": points.reshape(-1, 2, 2), "visible": visible,
        "view_matrix": view, "projection": proj, "width": np.int64(width), "height": np.int64(height),
    }


def _classified(parts: Dict[str, np.ndarray], n_vertices: int) -> Any:
    """The union of the edge arrays, each edge once with the first kind (in KINDS order) it has."""
    n = max(n_vertices, 1)
    keys, kinds = [], []
    for code, name in enumerate(KINDS):
        e = np.asarray(parts[name], dtype=np.int64).reshape(-1, 2)
        keys.append(e.min(axis=1) * n + e.max(axis=1))
        kinds.append(np.full(len(e), code, dtype=np.int8))
    k, c = np.concatenate(keys), np.concatenate(kinds)
    order = np.lexsort((c, k))  # by edge, then by kind: the first of each run is the kind kept
    k, c = k[order], c[order]
    first = np.concatenate(([True], k[1:] != k[:-1])) if len(k) else np.zeros(0, dtype=bool)
    k, c = k[first], c[first]
    return np.stack([k // n, k % n], axis=1), c


def _project(points: np.ndarray, view: np.ndarray, proj: np.ndarray, width: int, height: int) -> Any:
    """Pixel positions (x right, y down) and linear view depth of world points."""
    p = np.concatenate([points, np.ones((len(points), 1))], axis=1)
    eye_space = p @ view.T
    clip = eye_space @ proj.T
    ndc = clip[:, :2] / clip[:, 3:4]
    pixels = np.stack([(ndc[:, 0] + 1.0) * 0.5 * width, (1.0 - ndc[:, 1]) * 0.5 * height], axis=1)
    return pixels, -eye_space[:, 2]


def _visible(points: np.ndarray, depth: np.ndarray, depth_buffer: np.ndarray, depth_range: float) -> np.ndarray:
    """A point is visible when it lies in the image and is not behind the surface: its depth is
    at most the deepest of the 3x3 pixels around it (so lines on the rim, next to the background,
    stay), plus a small tolerance for lines lying on the surface."""
    h, w = depth_buffer.shape
    padded = np.pad(depth_buffer.astype(np.float64), 1, constant_values=np.inf)
    deepest = np.max([padded[dy : dy + h, dx : dx + w] for dy in range(3) for dx in range(3)], axis=0)
    x, y = np.floor(points[:, 0]).astype(np.int64), np.floor(points[:, 1]).astype(np.int64)
    inside = (x >= 0) & (x < w) & (y >= 0) & (y < h)
    behind = np.ones(len(points), dtype=np.float64) * np.inf
    behind[inside] = deepest[y[inside], x[inside]]
    return inside & (depth <= behind + 2e-3 * depth_range)


def write_svg(path: str, lines: Dict[str, Any], *, keep_hidden: bool = False, stroke_width: float = 1.5) -> int:
    """Writes the visible lines (and, with ``keep_hidden``, the hidden ones dashed) as an SVG
    drawing of the render's size, one group per kind. Returns the number of lines drawn."""
    w, h = int(lines["width"]), int(lines["height"])
    pts, kind, visible = lines["points"], lines["kind"], lines["visible"]
    out = [
        f'<svg xmlns="http://www.w3.org/2000/svg" width="{w}" height="{h}" viewBox="0 0 {w} {h}">',
        '<rect width="100%" height="100%" fill="#ffffff"/>',
    ]
    drawn = 0

    def group(name: str, mask: np.ndarray, style: str) -> None:
        nonlocal drawn
        if not mask.any():
            return
        out.append(f'<g id="{name}" {style} stroke-width="{stroke_width:g}" stroke-linecap="round" fill="none">')
        out.extend(
            f'<line x1="{a[0]:.2f}" y1="{a[1]:.2f}" x2="{b[0]:.2f}" y2="{b[1]:.2f}"/>' for a, b in pts[mask]
        )
        out.append("</g>")
        drawn += int(mask.sum())

    if keep_hidden:
        group("hidden", ~visible, 'stroke="#9a9a9a" stroke-dasharray="4 3"')
    for code, name in enumerate(KINDS):
        group(name, visible & (kind == code), f'stroke="{_STROKES[name]}"')
    out.append("</svg>\n")
    with open(path, "w") as f:
        f.write("\n".join(out))
    return drawn


def write_npz(path: str, lines: Dict[str, Any]) -> None:
    """Writes every array of :func:`view_lines` to an NPZ file."""
    np.savez_compressed(path, **lines)

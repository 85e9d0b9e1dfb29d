"""Lines over time: how much of each line setting's drawing pops per 1-degree step of a bunny
turntable, beside its frame time.

The popping of a step is the share of ink pixels that have no ink within 2 px after exact
reprojection into the next frame through the depth buffer, counting only points the next frame
sees (:func:`toonmesh.testing.temporal_popping`); "appearing" is the same measure run backward
(lines that pop in). The turntable: the Stanford bunny at 512x512, the eye at 2.4 bounding radii
from the bounding box's centre, a 40-degree field of view, turning about the up axis (+y) in
1-degree steps (a whole turn; 15 steps with ``--quick``), all views in one
:meth:`toonmesh.Renderer.render_many`.

    python -m toonmesh.bench temporal [--quick] [--json FILE]
"""

from __future__ import annotations

import time
from typing import Any, Dict, List, Sequence

import numpy as np

import toonmesh as tm
import toonmesh.data
from toonmesh.bench._timing import table
from toonmesh.testing import temporal_popping

#: The line settings compared, as keywords of tm.Outlines.
SETTINGS: Dict[str, Dict[str, Any]] = {
    "mesh lines": {"kind": "mesh"},
    "mesh lines + suggestive": {"kind": "mesh", "suggestive": True},
    "image-space lines": {"kind": "image"},
    "both": {"kind": "both"},
    "both + suggestive": {"kind": "both", "suggestive": True},
}
SIZE = 512
EYE_RADII = 2.4
FOV_Y = 40.0


def turntable(vertices: np.ndarray, steps: int, step_degrees: float = 1.0) -> List[tm.Camera]:
    """``steps + 1`` cameras turning about +y around the mesh's bounding-box centre, the eye at
    ``EYE_RADII`` bounding radii, ``step_degrees`` apart."""
    centre = 0.5 * (vertices.min(axis=0) + vertices.max(axis=0))
    radius = float(np.linalg.norm(vertices - centre, axis=1).max())
    cameras = []
    for k in range(steps + 1):
        a = np.radians(k * step_degrees)
        eye = centre + EYE_RADII * radius * np.array([np.sin(a), 0.0, np.cos(a)])
        cameras.append(tm.Camera.look_at(tuple(eye), target=tuple(centre), up=(0, 1, 0), fov_y=FOV_Y))
    return cameras


def popping_table(quick: bool) -> str:
    V, F = tm.data.bunny()
    steps = 15 if quick else 360
    cameras = turntable(V, steps)
    renderer = tm.Renderer()
    mesh = renderer.add_mesh(V, F)
    rows: List[Sequence[Any]] = []
    for label, keywords in SETTINGS.items():
        kw = dict(keywords)
        outlines = tm.Outlines(kw.pop("kind"), **kw)

        def draw() -> Any:
            return renderer.render_many(mesh, cameras, width=SIZE, height=SIZE, outlines=outlines,
                                        outputs=("outline", "depth"))

        draw()  # warm: the mesh's lines and curvature are built once per mesh
        t0 = time.perf_counter()
        stack = draw()
        frame = (time.perf_counter() - t0) / len(cameras)
        p = temporal_popping(stack)
        rows.append([label, f"{100 * p.share:.3f}%", f"{100 * p.appearing:.3f}%", f"{frame * 1e3:.1f} ms",
                     f"{p.counted.mean():.0f}"])
    return table(["lines", "popping per step", "appearing per step", "frame", "ink px"], rows,
                 f"Popping per 1-degree step ({steps} steps, bunny {SIZE}x{SIZE}, {renderer.info['backend']})")


def main(quick: bool = False, repeat: int = 3, extra: Sequence[str] = ()) -> None:
    print(popping_table(quick))


accuracy = main

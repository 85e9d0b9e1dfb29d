"""Lines over time: how much of each line setting's drawing pops per 1-degree step of a bunny
turntable, beside its frame time.

The popping of a step is the share of ink pixels that have no ink within 2 px after exact
reprojection into the next frame through the depth buffer, counting only points the next frame
sees (:func:`toonmesh.testing.temporal_popping`); "appearing" is the same measure run backward
(lines that pop in). The turntable: the Stanford bunny at 512x512, the eye at 2.4 bounding radii
from the bounding box's centre, a 40-degree field of view, turning about the up axis (+y) in
1-degree steps (a whole turn; 15 steps with ``--quick``), all views in one
:meth:`toonmesh.Renderer.render_many`.

Blender's Freestyle is the peer (:mod:`toonmesh.bench._freestyle`), when a ``blender`` executable
is on PATH ("Freestyle: not installed" otherwise): its smooth contours, and with suggestive
contours, on the same cameras, measured the same way, with its frame time and how well its
drawing agrees with toonmesh's (the share of its ink within 2 px of toonmesh's lines of the same
kinds, and the share of the model's outline it inks). A full run turns Freestyle through the
first ``FREESTYLE_STEPS`` steps only, with toonmesh's settings measured again on those steps
beside it.

    python -m toonmesh.bench temporal [--quick] [--json FILE]
"""

from __future__ import annotations

import time
from typing import Any, Dict, List, Sequence

import numpy as np

import toonmesh as tm
import toonmesh.data
from toonmesh.bench import _freestyle
from toonmesh.bench._timing import table
from toonmesh.testing import INK_COVERAGE, _popping_frame, temporal_popping
from toonmesh.testing._temporal import Frame

#: The line settings compared, as keywords of tm.Outlines.
SETTINGS: Dict[str, Dict[str, Any]] = {
    "mesh lines": {"kind": "mesh"},
    "mesh lines + suggestive": {"kind": "mesh", "suggestive": True},
    "mesh lines + suggestive, each view alone": {"kind": "mesh", "suggestive": True, "suggestive_coherence": False},
    "image-space lines": {"kind": "image"},
    "both": {"kind": "both"},
    "both + suggestive": {"kind": "both", "suggestive": True},
}
SIZE = 512
EYE_RADII = 2.4
FOV_Y = 40.0
#: Steps of the turntable that Blender's Freestyle draws in a full run (a frame takes it seconds).
FREESTYLE_STEPS = 90
HEADERS = ["lines", "popping per step", "appearing per step", "frame", "ink px",
           "camera agreement (ink / outline)"]


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
    blender = _freestyle.find_blender()
    # Freestyle takes seconds a frame: beside it, every drawing is measured on its shorter turn
    peer_steps = min(steps, FREESTYLE_STEPS)
    apart = blender is not None and peer_steps < steps
    beside = {setting for setting, _ in _freestyle.RUNS.values()}
    ours: Dict[str, List[Frame]] = {}  # toonmesh's frames of the settings beside Freestyle's
    rows: List[Sequence[Any]] = []
    peer_rows: List[Sequence[Any]] = []
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
        rows.append(_row(label, temporal_popping(stack), frame))
        head = [stack[i] for i in range(peer_steps + 1)]
        if apart:
            peer_rows.append(_row(label, temporal_popping(head), frame))
        if label in beside and blender is not None:
            ours[label] = [_popping_frame(i, r, INK_COVERAGE) for i, r in enumerate(head)]
        del stack, head
    freestyle = _freestyle.rows(blender, V, F, ours)
    title = f"Popping per 1-degree step ({{}} steps, bunny {SIZE}x{SIZE}, {renderer.info['backend']})"
    if not apart:
        return table(HEADERS, rows + freestyle, title.format(steps))
    return (table(HEADERS[:-1], [r[:-1] for r in rows], title.format(steps)) + "\n"
            + table(HEADERS, peer_rows + freestyle, "Beside Blender's Freestyle: " + title.format(peer_steps)))


def _row(label: str, p: Any, frame: float) -> List[Any]:
    return [label, f"{100 * p.share:.3f}%", f"{100 * p.appearing:.3f}%", f"{frame * 1e3:.1f} ms",
            f"{p.counted.mean():.0f}", ""]


def main(quick: bool = False, repeat: int = 3, extra: Sequence[str] = ()) -> None:
    print(popping_table(quick))


accuracy = main

"""The interactive viewer's frame time: an orbit step of the bunny at 512x512 with mesh outlines,
rendered and encoded through :class:`toonmesh.Viewer`'s own path (render, encode, hand to the
widget), and the frames per second that gives.

    python -m toonmesh.bench viewer [--quick] [--repeat N] [--json FILE]

Rows: ``orbit()`` from Python (the full-size frame, as PNG and as JPEG), and a frame drawn while
dragging (``drag_scale`` 0.5 of the size, JPEG). Each figure is the median over the frames (at
least 20, or 5 with ``--quick``) after a warm-up frame, on the adapter ``tm.gpu_info()`` names
(Mesa's lavapipe/llvmpipe where there is no GPU; ``TOONMESH_BACKEND`` picks the backend).
"""

from __future__ import annotations

import statistics
import time
from typing import Any, List, Sequence, Tuple

import toonmesh as tm
from toonmesh.bench._timing import table
from toonmesh.data import bunny

SIZE = 512


def _frames(viewer: Any, draft: bool, count: int) -> Tuple[float, float]:
    """Median seconds of a whole orbit frame and of its render alone."""
    walls: List[float] = []
    renders: List[float] = []
    for i in range(count + 1):
        viewer._move("orbit", 6.0, 0.0)
        t0 = time.perf_counter()
        result = viewer._show(draft=draft)
        if i:  # the first is a warm-up
            walls.append(time.perf_counter() - t0)
            renders.append(result.total_time)
    return statistics.median(walls), statistics.median(renders)


def main(quick: bool = False, repeat: int = 3, extra: Sequence[str] = ()) -> None:
    count = 5 if quick else max(20, repeat)
    V, F = bunny()
    info = tm.gpu_info()
    rows: List[Sequence[Any]] = []
    for label, image_format, draft in (
        ("orbit() full size", "png", False),
        ("orbit() full size", "jpeg", False),
        ("frame while dragging", "jpeg", True),
    ):
        viewer = tm.Viewer(V, F, outlines="mesh", width=SIZE, height=SIZE, image_format=image_format)
        try:
            frame, render = _frames(viewer, draft, count)
            assert viewer.frame is not None
            size = f"{viewer.frame.shape[1]}x{viewer.frame.shape[0]}"
        finally:
            viewer.close()
        rows.append((label, size, "jpeg" if draft else image_format, f"{render * 1e3:.1f} ms",
                     f"{(frame - render) * 1e3:.1f} ms", f"{frame * 1e3:.1f} ms", round(1.0 / frame, 1)))
    title = (f"Viewer frames: the bunny ({len(F):,} faces) with mesh outlines, on {info['name']} "
             f"({info['backend']}, {info['device_type']}); median of {count}")
    print(table(("frame", "size", "format", "render", "encode + send", "frame", "fps"), rows, title))


if __name__ == "__main__":
    main()

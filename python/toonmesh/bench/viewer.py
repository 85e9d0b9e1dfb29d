"""The interactive viewer's frame time: an orbit step of the bunny at 512x512 with mesh outlines,
rendered and encoded through :class:`toonmesh.Viewer`'s own path (render, encode, hand to the
widget), and the frames per second that gives.

    python -m toonmesh.bench viewer [--quick] [--repeat N] [--json FILE]

Rows: ``orbit()`` from Python (the full-size frame, as PNG and as JPEG), and a frame drawn while
dragging (``drag_scale`` 0.5 of the size, JPEG), taking turns frame by frame. Each figure is the
median over the frames (at least 20, or 5 with ``--quick``) after a warm-up round, on the adapter ``tm.gpu_info()`` names
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


KINDS = (
    ("orbit() full size", "png", False),
    ("orbit() full size", "jpeg", False),
    ("frame while dragging", "jpeg", True),
)


def _frame(viewer: Any, draft: bool) -> Tuple[float, float]:
    """Seconds of one orbit frame through the viewer's path, and of its render alone."""
    viewer._move("orbit", 6.0, 0.0)
    t0 = time.perf_counter()
    result = viewer._show(draft=draft)
    return time.perf_counter() - t0, result.total_time


def main(quick: bool = False, repeat: int = 3, extra: Sequence[str] = ()) -> None:
    count = 5 if quick else max(20, repeat)
    V, F = bunny()
    info = tm.gpu_info()
    viewers = [tm.Viewer(V, F, outlines="mesh", width=SIZE, height=SIZE, image_format=fmt) for _, fmt, _ in KINDS]
    times: List[List[Tuple[float, float]]] = [[] for _ in KINDS]
    try:
        for i in range(count + 1):  # the kinds take turns frame by frame, so load falls on each alike
            for k, (viewer, (_, _, draft)) in enumerate(zip(viewers, KINDS)):
                t = _frame(viewer, draft)
                if i:  # the first round warms up
                    times[k].append(t)
        rows: List[Sequence[Any]] = []
        for (label, fmt, draft), viewer, kind_times in zip(KINDS, viewers, times):
            frame = statistics.median(t[0] for t in kind_times)
            render = statistics.median(t[1] for t in kind_times)
            assert viewer.frame is not None
            size = f"{viewer.frame.shape[1]}x{viewer.frame.shape[0]}"
            rows.append((label, size, "jpeg" if draft else fmt, f"{render * 1e3:.1f} ms",
                         f"{(frame - render) * 1e3:.1f} ms", f"{frame * 1e3:.1f} ms", round(1.0 / frame, 1)))
    finally:
        for viewer in viewers:
            viewer.close()
    title = (f"Viewer frames: the bunny ({len(F):,} faces) with mesh outlines, on {info['name']} "
             f"({info['backend']}, {info['device_type']}); median of {count}")
    print(table(("frame", "size", "format", "render", "encode + send", "frame", "fps"), rows, title))


if __name__ == "__main__":
    main()

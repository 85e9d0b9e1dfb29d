"""Blender's Freestyle as the temporal benchmark's peer: its line drawing of the same turntable,
measured by the same :func:`toonmesh.testing.temporal_popping`.

When a ``blender`` executable is on PATH, the mesh is written as OBJ into a temporary folder and
Blender runs headless (``blender -b --factory-startup --python _freestyle_blender.py``) with the
turntable's cameras: Freestyle on with "smooth" contours (face smoothness on; silhouettes,
borders and creases; and again with suggestive contours, at Freestyle's default
``kr_derivative_epsilon``), lines only (the surface a holdout on a transparent film), at
toonmesh's default line width. Each frame's line alpha is the ink. Freestyle gives no depth
image of its own: the depth, view and projection are toonmesh's render of the same camera and
the same geometry, so only the ink differs between the two drawings.
"""

from __future__ import annotations

import json
import os
import shutil
import statistics
import subprocess
import tempfile
from typing import Any, Dict, List, Mapping, NamedTuple, Optional, Sequence, Tuple

import numpy as np

import toonmesh as tm
from toonmesh.testing import INK_COVERAGE, POPPING_PIXELS, TemporalPopping, _png, _temporal, temporal_popping
from toonmesh.testing._temporal import Frame

#: The Freestyle runs: label, the toonmesh line setting (of the temporal benchmark) drawing the same
#: kinds of line, and whether suggestive contours are drawn.
RUNS: Dict[str, Tuple[str, bool]] = {"Freestyle smooth": ("mesh lines", False),
                                     "Freestyle smooth + suggestive": ("mesh lines + suggestive", True)}
#: Render engines tried in turn (the first that runs headless draws every frame) and their
#: samples per pixel: enough to antialias the strokes as toonmesh's coverage is. Cycles first: it
#: needs no GL, and on the CPU it drew the bunny's frames in 2.1 s against EEVEE's 5.4 s on
#: software GL (the same strokes; Freestyle's own work is most of Cycles' frame).
ENGINES: Tuple[Tuple[str, int], ...] = (("CYCLES", 8), ("BLENDER_EEVEE", 8))
#: The clip range given to Blender, as multiples of toonmesh's near and far planes: wider, so
#: that Freestyle never clips a line that toonmesh draws.
CLIP_MARGIN = (0.5, 2.0)
_SCRIPT = os.path.join(os.path.dirname(os.path.abspath(__file__)), "_freestyle_blender.py")


class Drawing(NamedTuple):
    """Freestyle's frames of one run."""

    ink: List[np.ndarray]  # (H, W) float32 line alpha in [0, 1], one per camera
    seconds: List[float]  # each frame's render time in Blender (no startup, no mesh import)
    version: str  # Blender's version
    engine: str  # the render engine that drew the strokes


def find_blender() -> Optional[str]:
    """The ``blender`` executable on PATH, or None."""
    return shutil.which("blender")


def blender_camera(view: np.ndarray, projection: np.ndarray) -> Dict[str, Any]:
    """Blender's camera for toonmesh's ``view`` (4x4 world to view) and perspective
    ``projection`` (4x4, wgpu's clip z in [0, 1]): ``matrix`` (4x4 camera-to-world rows: a
    Blender camera looks down its local -z with +y up, as toonmesh's view space does), ``fov_y``
    (degrees, with the sensor fit vertical) and ``clip`` ([near, far] in world units, widened by
    :data:`CLIP_MARGIN`)."""
    view = np.asarray(view, dtype=np.float64)
    p = np.asarray(projection, dtype=np.float64)
    fov_y = float(np.degrees(2.0 * np.arctan(1.0 / p[1, 1])))
    # wgpu's right-handed perspective: p22 = f / (n - f), p23 = n f / (n - f)
    near, far = p[2, 3] / p[2, 2], p[2, 3] / (p[2, 2] + 1.0)
    return {"matrix": np.linalg.inv(view).tolist(), "fov_y": fov_y,
            "clip": [float(near * CLIP_MARGIN[0]), float(far * CLIP_MARGIN[1])]}


def write_obj(path: str, vertices: np.ndarray, faces: np.ndarray) -> None:
    """The mesh as a Wavefront OBJ file, its positions exact (17 significant digits)."""
    with open(path, "w") as f:
        f.writelines("v %.17g %.17g %.17g\n" % tuple(v) for v in np.asarray(vertices, dtype=np.float64))
        f.writelines("f %d %d %d\n" % tuple(t) for t in np.asarray(faces, dtype=np.int64) + 1)


def draw(blender: str, obj: str, frames: Sequence[Frame], suggestive: bool, width: float) -> Drawing:
    """Freestyle's lines of the mesh in ``obj`` from each frame's camera (toonmesh's frames, of
    one square size), ``width`` pixels wide. Raises RuntimeError with Blender's last words when
    no engine draws every frame."""
    size = frames[0].depth.shape[0]
    cameras = [blender_camera(f.view, f.projection) for f in frames]
    last = ""
    for engine, samples in ENGINES:
        with tempfile.TemporaryDirectory(prefix="toonmesh-freestyle-") as out:
            job = os.path.join(out, "job.json")
            with open(job, "w") as f:
                json.dump({"obj": obj, "out": out, "size": size, "cameras": cameras, "thickness": width,
                           "suggestive": suggestive, "engine": engine, "samples": samples}, f)
            run = subprocess.run([blender, "-b", "--factory-startup", "--python", _SCRIPT, "--", job],
                                 stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)
            report = os.path.join(out, "report.json")
            if run.returncode != 0 or not os.path.exists(report):
                last = " ".join(run.stdout.strip().splitlines()[-3:])[-300:]
                continue
            with open(report) as f:
                info = json.load(f)
            ink = []
            for i in range(len(frames)):
                with open(os.path.join(out, "frame_%04d.png" % i), "rb") as png:
                    ink.append(_png.decode(png.read(), "frame")[:, :, 3].astype(np.float32) / 255.0)
            return Drawing(ink, info["seconds"], info["version"], info["engine"])
    raise RuntimeError(f"Blender drew no frames: {last}")


def popping(drawing: Drawing, frames: Sequence[Frame]) -> TemporalPopping:
    """:func:`temporal_popping` of Freestyle's ink, with the depth and cameras of toonmesh's
    ``frames`` (the same cameras and geometry)."""
    return temporal_popping([(ink, f.depth, f.view, f.projection) for ink, f in zip(drawing.ink, frames)])


def agreement(drawing: Drawing, frames: Sequence[Frame]) -> Tuple[float, float]:
    """How well the cameras agree, over all frames: the share of Freestyle's ink within
    :data:`POPPING_PIXELS` of toonmesh's ink (``frames``' ink: the same kinds of line), and the
    share of the model's outline (the pixels of toonmesh's depth image on the edge of the covered
    region) with Freestyle ink within :data:`POPPING_PIXELS`."""
    disc = _temporal.disc_offsets(POPPING_PIXELS)
    cross = [(0, 1), (1, 0), (0, -1), (-1, 0)]
    on, ink_px, covered, outline_px = 0, 0, 0, 0
    for theirs, frame in zip(drawing.ink, frames):
        a, b = theirs >= INK_COVERAGE, frame.ink
        on += int((a & _temporal.spread(b, disc, np.logical_or, False)).sum())
        ink_px += int(a.sum())
        surface = np.isfinite(frame.depth)
        outline = surface & ~_temporal.spread(surface, cross, np.logical_and, True)
        covered += int((outline & _temporal.spread(a, disc, np.logical_or, False)).sum())
        outline_px += int(outline.sum())
    return on / max(ink_px, 1), covered / max(outline_px, 1)


def rows(blender: Optional[str], vertices: np.ndarray, faces: np.ndarray,
         ours: Mapping[str, Sequence[Frame]]) -> List[Sequence[Any]]:
    """The benchmark's rows for Freestyle: label, popping, appearing, frame time, mean ink
    pixels counted and camera agreement, each run measured on the cameras, depth and ink of
    ``ours[setting]`` (toonmesh's frames of the setting beside it, see :data:`RUNS`); one row
    saying so when ``blender`` is None (not installed) or a run fails."""
    if blender is None:
        return [["Freestyle: not installed", "", "", "", "", ""]]
    width = tm.LineStyle().width  # toonmesh's default line width, in pixels
    out: List[Sequence[Any]] = []
    with tempfile.TemporaryDirectory(prefix="toonmesh-freestyle-mesh-") as folder:
        obj = os.path.join(folder, "mesh.obj")
        write_obj(obj, vertices, faces)
        for label, (setting, suggestive) in RUNS.items():
            frames = ours[setting]
            try:
                drawing = draw(blender, obj, frames, suggestive, width)
            except RuntimeError as exc:
                out.append([f"{label}: {exc}", "", "", "", "", ""])
                continue
            p = popping(drawing, frames)
            on, outline = agreement(drawing, frames)
            engine = "EEVEE" if drawing.engine == "BLENDER_EEVEE" else drawing.engine.title()
            out.append([f"{label} (Blender {drawing.version}, {engine})", f"{100 * p.share:.3f}%",
                        f"{100 * p.appearing:.3f}%", f"{statistics.median(drawing.seconds) * 1e3:.0f} ms",
                        f"{p.counted.mean():.0f}", f"{100 * on:.1f}% / {100 * outline:.1f}%"])
    return out

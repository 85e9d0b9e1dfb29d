"""Line visibility and intersection lines in the render: what the exact rule (rays against the
scene's surfaces) costs against the depth rule (the depth image with a tolerance), what hidden
lines and intersection lines add to a frame, and what each rule gets right (ink that shows
through a thin sheet).

    python -m toonmesh.bench lines [--quick] [--accuracy] [--repeat N] [--json FILE]
"""

from __future__ import annotations

from typing import Any, Dict, List, Sequence, Tuple

import numpy as np

import toonmesh as tm
from toonmesh.bench._timing import median_time, table

Mesh = Tuple[np.ndarray, np.ndarray]

#: The rules and line sets the frame table compares, as keywords of Outlines("mesh", ...).
VARIANTS: Dict[str, Dict[str, Any]] = {
    "depth rule": {"visibility": "depth", "intersection": False},
    "exact": {"intersection": False},
    "exact + hidden": {"intersection": False, "hidden": True},
    "exact + intersections": {},
    "exact + both": {"hidden": True},
}


def slab(lo: Sequence[float], hi: Sequence[float]) -> Mesh:
    """A box from corner ``lo`` to corner ``hi``, faces wound outward (``toonmesh.shapes.box``)."""
    return tm.shapes.box(lo, hi)


def pipe(axis: int, radius: float = 1.0, half_length: float = 2.0, sections: int = 96) -> Mesh:
    """A closed cylinder about ``axis`` (0, 1 or 2: x, y or z) through the origin, capped."""
    a = np.linspace(0, 2 * np.pi, sections, endpoint=False)
    ring = np.c_[radius * np.cos(a), radius * np.sin(a)]
    V = np.vstack([np.c_[ring, np.full(sections, -half_length)], np.c_[ring, np.full(sections, half_length)],
                   [[0, 0, -half_length], [0, 0, half_length]]])
    i, j = np.arange(sections), (np.arange(sections) + 1) % sections
    n = 2 * sections
    F = np.vstack([np.c_[i, j, j + sections], np.c_[i, j + sections, i + sections],
                   np.c_[np.full(sections, n), j, i], np.c_[np.full(sections, n + 1), i + sections, j + sections]])
    return np.roll(V, axis + 1, axis=1), F  # the cylinder's z becomes the axis asked for


def sheet_over_beams(gaps: Sequence[float] = (0.001, 0.003, 0.005)) -> List[Mesh]:
    """A 2 m sheet, 5 mm thick with its top at y = 0, and a beam under it at each gap (metres)."""
    beams = [slab((-0.9 + 0.6 * i, -0.1 - g, -0.9), (-0.8 + 0.6 * i, -0.005 - g, 0.9)) for i, g in enumerate(gaps)]
    return [slab((-1, -0.005, -1), (1, 0.0, 1))] + beams


def scenes(quick: bool) -> Dict[str, Tuple[List[Any], Any]]:
    """Name -> (meshes as tm.Mesh, camera)."""
    level = 4 if quick else 7
    V, F = tm.shapes.icosphere(level)
    moved = np.eye(4)
    moved[0, 3] = 0.5
    corner = tm.Camera.fit((1.0, 0.6, 0.8))
    return {
        f"sphere ({len(F):,} faces)": ([tm.Mesh(V, F)], corner),
        f"two overlapping spheres (2 x {len(F):,})": ([tm.Mesh(V, F), tm.Mesh(V, F, transform=moved)], corner),
        "teapot": ([tm.Mesh(*tm.shapes.teapot())], corner),
        "crossing pipes (96 sections)": ([tm.Mesh(*pipe(0)), tm.Mesh(*pipe(1))],
                                         tm.Camera.look_at((4.0, 3.0, 6.0), (0, 0, 0), fov_y=40)),
        "sheet over three beams": ([tm.Mesh(*m, normals="flat") for m in sheet_over_beams()],
                                   tm.Camera.look_at((0.3, 3.0, 0.6), (0, 0, 0), fov_y=45)),
    }


def frame_table(quick: bool, repeat: int, size: int = 512) -> None:
    """Frame time of each scene under each rule and line set, and its ratio to the depth rule."""
    r = tm.Renderer()
    rows = []
    for name, (meshes, camera) in scenes(quick).items():
        placed = [tm.Mesh(r.add_mesh(m.vertices, m.faces, normals=m.normals), transform=m.transform) for m in meshes]
        times = {}
        for variant, kw in VARIANTS.items():
            o = tm.Outlines("mesh", **kw)
            times[variant] = median_time(
                lambda: r.render(placed, camera=camera, width=size, height=size, outlines=o), repeat)
        base = times["depth rule"]
        rows.append([name] + [f"{times[v] * 1e3:.1f} ms ({times[v] / base:.2f}x)" for v in VARIANTS])
    print(table(["scene"] + list(VARIANTS), rows,
                f"frame time at {size}x{size}, colour with mesh-space lines (ratio to the depth rule)"))


def accuracy(quick: bool = False, repeat: int = 3, extra: Sequence[str] = ()) -> None:
    """Ink that beams under a thin sheet add (pixels that the sheet alone does not ink), and how
    much of the sheet's own lines each rule keeps (their length against the exact rule's): the
    depth rule at several tolerances against the exact rule, with each one's frame time."""
    r = tm.Renderer()
    cam = tm.Camera.look_at((0.3, 3.0, 0.6), (0, 0, 0), fov_y=45)
    parts = [r.add_mesh(*m, normals="flat") for m in sheet_over_beams()]
    teapot = r.add_mesh(*tm.shapes.teapot())
    rows = []
    rules = [("depth", {"visibility": "depth", "depth_offset": d}) for d in (0.0, 0.25, 1.0, 4.0)]
    own = {}
    for label, kw in [("exact", {})] + rules:
        o = tm.Outlines("mesh", **kw)
        render = lambda meshes: r.render(meshes, camera=cam, width=400, height=300, outlines=o,  # noqa: E731
                                         outputs=("outline", "lines"))
        alone, under = render(parts[:1]), render(parts)
        shows = int(((alone.outline > 0.1) != (under.outline > 0.1)).sum())
        pot = r.render(teapot, camera=tm.Camera.fit((1.0, 0.6, 0.8)), width=400, height=300, outlines=o,
                       outputs=("lines",))
        own.setdefault("sheet", _length(alone.lines))
        own.setdefault("teapot", _length(pot.lines))
        seconds = median_time(lambda: render(parts), repeat)
        offset = f"{kw['depth_offset']:g}" if "depth_offset" in kw else "-"
        sheet = f"{100 * _length(alone.lines) / own['sheet']:.1f}%"
        pot_kept = f"{100 * _length(pot.lines) / own['teapot']:.1f}%"
        rows.append([label, offset, shows, sheet, pot_kept, f"{seconds * 1e3:.1f} ms"])
    print(table(["rule", "depth_offset (footprints)", "ink pixels through the sheet", "sheet alone: lines / exact's",
                 "teapot: lines / exact's", "frame"], rows,
                "beams 1, 3 and 5 mm under a 2 m sheet, 400x300: what shows through, and what each rule keeps"))


def _length(polylines: Any) -> float:
    return float(sum(np.linalg.norm(np.diff(p, axis=0), axis=1).sum() for p in polylines or []))


def main(quick: bool = False, repeat: int = 3, extra: Sequence[str] = ()) -> None:
    frame_table(quick, repeat)
    accuracy(quick, repeat)

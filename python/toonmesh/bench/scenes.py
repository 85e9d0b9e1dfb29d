"""Scenes of many instances: one geometry placed many times against the same triangles merged
into one mesh, drawn by the same renderer (the instances' geometry uploaded once).

    python -m toonmesh.bench scenes [--quick] [--repeat N] [--json FILE]

Rows: a frame from arrays (``toonmesh.render`` of the Mesh list: upload, draw, read back) and a
frame from meshes already on the device (``Renderer.render`` of handles: draw and read back);
ratio = instances' time / merged mesh's time (the target is within 1.5x).
"""

from __future__ import annotations

from typing import Any, Dict, List, Sequence, Tuple

import numpy as np

import toonmesh as tm
from toonmesh.bench._timing import median_time, table
from toonmesh.bench.effects import ring


def instances(count: int, faces: int) -> Tuple[Tuple[np.ndarray, np.ndarray], List[np.ndarray]]:
    """A torus of about ``faces`` triangles and ``count`` transforms placing it on a grid, each
    turned differently."""
    n = max(3, int(round(np.sqrt(faces / 2 * 2.5))))
    m = max(3, faces // (2 * n))
    mesh = ring(1.0, 0.35, n=n, m=m)
    side = int(np.ceil(np.sqrt(count)))
    transforms = []
    for i in range(count):
        a = 0.37 * i
        c, s = np.cos(a), np.sin(a)
        T = np.eye(4)
        T[:3, :3] = [[c, 0, s], [0, 1, 0], [-s, 0, c]]
        T[:3, 3] = [3.0 * (i % side), 0.0, 3.0 * (i // side)]
        transforms.append(T)
    return mesh, transforms


def merged(mesh: Tuple[np.ndarray, np.ndarray], transforms: Sequence[np.ndarray]) -> Tuple[np.ndarray, np.ndarray]:
    """The instances' triangles as one mesh (the same triangles, world coordinates)."""
    V, F = mesh
    Vs = [V @ T[:3, :3].T + T[:3, 3] for T in transforms]
    return np.concatenate(Vs), np.concatenate([F + k * len(V) for k in range(len(transforms))])


def rows(count: int, faces: int, size: int, repeat: int) -> List[Sequence[Any]]:
    mesh, transforms = instances(count, faces)
    whole = merged(mesh, transforms)
    camera = tm.Camera.fit((0.3, 1.0, 0.6))
    kw: Dict[str, Any] = dict(camera=camera, width=size, height=size, outlines=None)
    scene = [tm.Mesh(*mesh, transform=T) for T in transforms]
    uploads: List[int] = []
    renderer = tm.rendering._render.shared_renderer(None)
    real = renderer._add  # every upload goes through it

    def counting(*a: Any, **k: Any) -> Any:
        uploads.append(1)
        return real(*a, **k)

    renderer._add = counting  # type: ignore[method-assign]
    try:
        tm.render(scene, **kw)
        uploaded = len(uploads)
    finally:
        del renderer._add
    t_scene = median_time(lambda: tm.render(scene, **kw), repeat)
    t_whole = median_time(lambda: tm.render(*whole, **kw), repeat)
    handle = renderer.add_mesh(*mesh)
    whole_handle = renderer.add_mesh(*whole)
    try:
        placed = [tm.Mesh(handle, transform=T) for T in transforms]
        t_placed = median_time(lambda: renderer.render(placed, **kw), repeat)
        t_one = median_time(lambda: renderer.render(whole_handle, **kw), repeat)
    finally:
        renderer.remove_mesh(handle)
        renderer.remove_mesh(whole_handle)
    n_faces = len(whole[1])
    label = f"{count} x {len(mesh[1]):,} faces"
    return [
        [label, "from arrays", f"{uploaded} upload(s)", f"{t_scene * 1e3:.1f} ms", f"{t_whole * 1e3:.1f} ms",
         f"{t_scene / t_whole:.2f}x", f"{n_faces:,}"],
        [label, "on the device", "none", f"{t_placed * 1e3:.1f} ms", f"{t_one * 1e3:.1f} ms",
         f"{t_placed / t_one:.2f}x", f"{n_faces:,}"],
    ]


def main(quick: bool = False, repeat: int = 3, extra: Sequence[str] = ()) -> None:
    count, faces, size = (50, 500, 256) if quick else (500, 2000, 1024)
    print(table(("scene", "frame", "instances uploaded", "instances", "merged", "ratio", "faces"),
                rows(count, faces, size, repeat), f"Instances against one merged mesh ({size}x{size})"))

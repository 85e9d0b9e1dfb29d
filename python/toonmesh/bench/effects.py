"""Shadows, hatching, dithering, rim light, paper grain, colour (vertex and face colours,
textures) and glass: what each costs, and what the shadow map's size and filter buy in accuracy
(intersection over union of the shadowed pixels with a CPU ray cast).

    python -m toonmesh.bench effects [--quick] [--accuracy] [--repeat N] [--json FILE]
"""

from __future__ import annotations

from typing import Any, Dict, List, Sequence, Tuple

import numpy as np

import toonmesh as tm
from toonmesh import _core
from toonmesh.bench._timing import median_time, table

Mesh = Tuple[np.ndarray, np.ndarray]


def box(center: Sequence[float], half: float) -> Mesh:
    """A cube of half-size ``half`` at ``center``, faces wound outward (``toonmesh.shapes.box``)."""
    return tm.shapes.box(np.subtract(center, half), np.add(center, half))


def plane(half: float, y: float = 0.0) -> Mesh:
    """A square floor at height ``y``, facing up."""
    V = np.array([[-half, y, -half], [half, y, -half], [half, y, half], [-half, y, half]])
    return V, np.array([[0, 2, 1], [0, 3, 2]])


def ring(R: float, r: float, n: int = 48, m: int = 24, center: Sequence[float] = (0.0, 0.0, 0.0)) -> Mesh:
    """A torus around the y axis (tube radius ``r``), ``n`` x ``m`` quads."""
    u, v = np.meshgrid(np.linspace(0, 2 * np.pi, n, endpoint=False), np.linspace(0, 2 * np.pi, m, endpoint=False),
                       indexing="ij")
    V = np.stack([(R + r * np.cos(v)) * np.cos(u), r * np.sin(v), (R + r * np.cos(v)) * np.sin(u)], -1).reshape(-1, 3)
    i, j = np.meshgrid(np.arange(n), np.arange(m), indexing="ij")
    a, b = i * m + j, ((i + 1) % n) * m + j
    c, d = ((i + 1) % n) * m + (j + 1) % m, i * m + (j + 1) % m
    F = np.concatenate([np.stack([a, d, c], -1).reshape(-1, 3), np.stack([a, c, b], -1).reshape(-1, 3)])
    return V + np.asarray(center), F


def join(*parts: Mesh) -> Mesh:
    """Several meshes as one."""
    Vs, Fs, n = [], [], 0
    for V, F in parts:
        Vs.append(V)
        Fs.append(F + n)
        n += len(V)
    return np.vstack(Vs), np.vstack(Fs)


# Name -> (mesh, light direction, camera direction): the shadow scenes of the tests and tables.
SHADOW_SCENES: Dict[str, Tuple[Mesh, Tuple[float, float, float], Tuple[float, float, float]]] = {
    "box on a plane": (join(box((0.0, 0.5, 0.0), 0.5), plane(3.0)), (1.0, -2.0, 0.6), (0.2, 1.2, 1.5)),
    "torus over a plane": (join(ring(1.0, 0.35, center=(0.0, 0.8, 0.0)), plane(3.0)), (0.5, -2.0, 0.3),
                           (0.3, 1.5, 1.2)),
    "sphere on itself": (tm.shapes.icosphere(3), (1.0, -0.4, -0.8), (0.4, 0.3, 1.0)),
}


def shadow_against_truth(name: str, size: int, shadows: Any = True, backend: str = "vulkan",
                         renderer: "tm.Renderer | None" = None) -> Tuple[Any, np.ndarray]:
    """The render (colour and shadow output, flat normals) of a shadow scene, and the ray-cast
    truth of its shadow output."""
    (V, F), direction, eye = SHADOW_SCENES[name]
    r = renderer or tm.Renderer(backend=backend)
    res = r.render(tm.Mesh(V, F, normals="flat"), lights=[tm.Light.directional(direction, shadows=shadows)],
                   camera=tm.Camera.fit(eye), width=size, height=size, outputs=("color", "shadow"))
    toward = -np.asarray(direction, float) / np.linalg.norm(direction)
    truth = _core._shadow_truth((V, F), res.projection @ res.view_matrix, (size, size), toward)
    return res, truth


def iou(a: np.ndarray, b: np.ndarray) -> float:
    return float((a & b).sum() / max((a | b).sum(), 1))


def shimmer(space: str, pattern: str = "bayer4", size: int = 160, degrees: float = 1.0) -> float:
    """The share of surface points whose dither decision (whether dithering changed their band)
    changes between two frames of a turntable ``degrees`` apart, the light turning with the
    object. Each pixel of the second frame is followed back to its surface point in the first
    (through its depth), so a pattern that moves with the surface scores 0."""
    V, F = tm.shapes.icosphere(4, noise=0.02, seed=3)
    r = tm.Renderer()
    mesh = r.add_mesh(V, F)
    dithered = tm.Material.bands(dither=tm.Dither(pattern, space=space, scale=2.0))

    def frame(deg: float, material: Any) -> Any:
        a = np.radians(deg)
        rot = np.array([[np.cos(a), 0, np.sin(a), 0], [0, 1, 0, 0], [-np.sin(a), 0, np.cos(a), 0], [0, 0, 0, 1.0]])
        light = tm.Light.directional(tuple(rot[:3, :3] @ np.array([0.5, -0.6, -1.0])))
        return r.render(tm.Mesh(mesh, transform=rot, material=material), lights=[light],
                        camera=tm.Camera.fit((0.0, 0.0, 1.0)), width=size, height=size,
                        outputs=("color", "depth")), rot

    (a_plain, rot_a), (a_dith, _) = frame(0.0, tm.Material.bands()), frame(0.0, dithered)
    (b_plain, rot_b), (b_dith, _) = frame(degrees, tm.Material.bands()), frame(degrees, dithered)
    decide_a = (a_plain.color != a_dith.color).any(-1)
    decide_b = (b_plain.color != b_dith.color).any(-1)
    # pixels of b -> view space -> world -> the same surface point in a -> pixels of a
    ys, xs = np.nonzero(np.isfinite(b_plain.depth))
    z = b_plain.depth[ys, xs]
    P = b_plain.projection
    ndc = np.stack([(xs + 0.5) / size * 2 - 1, 1 - (ys + 0.5) / size * 2])
    view = np.stack([ndc[0] * z / P[0, 0], ndc[1] * z / P[1, 1], -z, np.ones_like(z)])
    world = np.linalg.inv(b_plain.view_matrix) @ view
    world_a = rot_a @ np.linalg.inv(rot_b) @ world
    clip = a_plain.projection @ a_plain.view_matrix @ world_a
    xa = np.floor((clip[0] / clip[3] * 0.5 + 0.5) * size).astype(int)
    ya = np.floor((0.5 - clip[1] / clip[3] * 0.5) * size).astype(int)
    ok = (xa >= 0) & (xa < size) & (ya >= 0) & (ya < size)
    ok[ok] &= np.isfinite(a_plain.depth[ya[ok], xa[ok]])
    return float((decide_b[ys[ok], xs[ok]] != decide_a[ya[ok], xa[ok]]).mean())


def _shadow_table(size: int, repeat: int) -> List[Sequence[Any]]:
    rows = []
    r = tm.Renderer()
    for map_size in (512, 1024, 2048, 4096):
        for flt in ("none", "pcf"):
            s = tm.Shadows(size=map_size, filter=flt)
            ious = [iou(*(m < 0.5 for m in (res.shadow, truth)))
                    for res, truth in (shadow_against_truth(n, size, s, renderer=r) for n in SHADOW_SCENES)]
            (V, F), direction, eye = SHADOW_SCENES["torus over a plane"]
            mesh = r.add_mesh(V, F)
            light = [tm.Light.directional(direction, shadows=s)]
            t = median_time(lambda: r.render(mesh, lights=light, camera=tm.Camera.fit(eye), width=size, height=size),
                            repeat)
            rows.append((map_size, flt, min(ious), float(np.mean(ious)), t * 1e3))
    return rows


def _cost_table(subdivisions: int, size: int, repeat: int) -> List[Sequence[Any]]:
    V, F = tm.shapes.icosphere(subdivisions, noise=0.01, seed=1)
    r = tm.Renderer()
    mesh = r.add_mesh(V, F)
    key = [tm.Light.directional((0.5, -0.6, -1.0))]
    casting = [tm.Light.directional((0.5, -0.6, -1.0), shadows=True)]
    cases: List[Tuple[Any, ...]] = [
        ("bands (reference)", tm.Material.bands(), key),
        ("+ shadows (2048, pcf)", tm.Material.bands(), casting),
        ("hatching (field)", tm.Material.hatching(), key),
        ("hatching (triplanar)", tm.Material.hatching(mode="triplanar"), key),
        ("dither bayer4, screen", tm.Material.bands(dither="bayer4"), key),
        ("dither bayer4, object", tm.Material.bands(dither=tm.Dither("bayer4", space="object")), key),
        ("hatching + dither + shadows", tm.Material.hatching(dither="bayer4"), casting),
        ("rim", tm.Material.bands(rim=tm.Rim()), key),
        ("rim, lit side, soft", tm.Material.bands(rim=tm.Rim(side="lit", softness=0.2)), key),
        ("paper (screen)", tm.Material.bands(), key, dict(paper=tm.Paper())),
        ("paper (surface)", tm.Material.bands(), key, dict(paper=tm.Paper(space="surface"))),
    ]
    times = {}
    # in turns, so that a slow spell of the machine does not land on one case
    for _ in range(max(1, repeat)):
        for name, material, lights, *more in cases:
            options = more[0] if more else {}
            t = median_time(lambda: r.render(mesh, material=material, lights=lights, width=size, height=size, **options),
                            1)
            times.setdefault(name, []).append(t)
    base = float(np.median(times[cases[0][0]]))
    return [(name, len(F), f"{size}x{size}", float(np.median(t)) * 1e3, float(np.median(t)) / base)
            for name, t in times.items()]


def sphere_uv(V: np.ndarray) -> np.ndarray:
    """Longitude and latitude of points around the origin, in [0, 1] (an equirectangular map)."""
    d = V / np.linalg.norm(V, axis=1, keepdims=True)
    return np.stack([np.arctan2(d[:, 2], d[:, 0]) / (2 * np.pi) + 0.5, np.arcsin(d[:, 1]) / np.pi + 0.5], -1)


def _colour_table(subdivisions: int, size: int, texture_size: int, repeat: int) -> List[Sequence[Any]]:
    """Frame times of a sphere without colour, with vertex or face colours, and textured."""
    V, F = tm.shapes.icosphere(subdivisions, noise=0.01, seed=1)
    rng = np.random.default_rng(0)
    y, x = np.mgrid[0:texture_size, 0:texture_size]
    texture = np.stack([(x * 7) % 256, (y * 5) % 256, ((x ^ y) * 3) % 256], -1).astype(np.uint8)
    uv = sphere_uv(V)
    r = tm.Renderer()
    cases = [
        ("untextured (reference)", r.add_mesh(V, F)),
        ("vertex colours", r.add_mesh(V, F, vertex_colors=rng.integers(0, 256, (len(V), 3)).astype(np.uint8))),
        ("face colours", r.add_mesh(V, F, face_colors=rng.integers(0, 256, (len(F), 3)).astype(np.uint8))),
        (f"textured {texture_size}^2, linear", r.add_mesh(V, F, uv=uv, texture=texture)),
        (f"textured {texture_size}^2, nearest", r.add_mesh(V, F, uv=uv, texture=texture, texture_filter="nearest")),
    ]
    times: Dict[str, List[float]] = {}
    for _ in range(max(1, repeat)):  # in turns, as in _cost_table
        for name, mesh in cases:
            t = median_time(lambda: r.render(mesh, width=size, height=size), 1)
            times.setdefault(name, []).append(t)
    base = float(np.median(times[cases[0][0]]))
    return [(name, len(F), f"{size}x{size}", float(np.median(t)) * 1e3, float(np.median(t)) / base)
            for name, t in times.items()]


def glass_scenes(teapot_subdivisions: int = 3) -> Dict[str, List[Tuple[Mesh, Any]]]:
    """Name -> meshes with their glass materials: three squares in a row (opaque red under green
    and blue of opacity 0.4 and 0.5), and a teapot inside a box of opacity 0.3 (two glass layers
    over most of the teapot, four beside it)."""
    def square(half: float, z: float) -> Mesh:
        V = np.array([[-half, -half, z], [half, -half, z], [half, half, z], [-half, half, z]])
        return V, np.array([[0, 1, 2], [0, 2, 3]])

    V, F = tm.shapes.teapot(teapot_subdivisions)
    V = (V - V.mean(axis=0)) / np.abs(V - V.mean(axis=0)).max()
    return {
        "3 squares": [(square(2.0, 0.0), tm.Material.lambert("#e62619")),
                      (square(0.6, 0.5), tm.Material.lambert("#19cc33", opacity=0.4)),
                      (square(0.4, 1.0), tm.Material.lambert("#1933e6", opacity=0.5))],
        "teapot in a glass box": [((V, F), tm.Material.bands()),
                                  (box((0.0, 0.0, 0.0), 1.3), tm.Material.bands("#a0c8ff", opacity=0.3))],
    }


def _glass_table(size: int, repeat: int, backends: Sequence[str] = ("vulkan", "gl")) -> List[Sequence[Any]]:
    """Frame times of each glass scene against the same scene all opaque, on each backend,
    the two in turns (medians of the runs)."""
    rows = []
    for backend in backends:
        r = tm.Renderer(backend=backend)
        for name, items in glass_scenes().items():
            glass = [tm.Mesh(V, F, material=m) for (V, F), m in items]
            opaque = [tm.Mesh(V, F, material=m.replace(opacity=1.0)) for (V, F), m in items]
            times: Dict[str, List[float]] = {}
            for _ in range(max(1, repeat)):
                for kind, meshes in (("opaque", opaque), ("glass", glass)):
                    t = median_time(lambda: r.render(meshes, width=size, height=size, outlines="mesh"), 1)
                    times.setdefault(kind, []).append(t)
            o, g = (float(np.median(times[k])) for k in ("opaque", "glass"))
            rows.append((backend, name, f"{size}x{size}", o * 1e3, g * 1e3, g / o))
    return rows


def accuracy(quick: bool = False, repeat: int = 3, extra: Sequence[str] = ()) -> None:
    size = 128 if quick else 256
    print(table(("shadow map", "filter", "IoU (worst scene)", "IoU (mean)", "frame ms (torus)"),
                _shadow_table(size, 1 if quick else repeat),
                f"Shadow map size and filter against a ray cast ({size}x{size}, three scenes)"))
    rows = [(space, pattern, shimmer(space, pattern, size=96 if quick else 160))
            for pattern in ("bayer4", "blue") for space in ("screen", "object")]
    print(table(("space", "pattern", "shimmer"), rows,
                "Dither shimmer: share of surface points whose decision changes, turntable 1 degree"))


def main(quick: bool = False, repeat: int = 3, extra: Sequence[str] = ()) -> None:
    accuracy(quick, repeat)
    sub, size = (4, 256) if quick else (8, 1024)
    print(table(("effect", "faces", "size", "frame ms", "x bands"), _cost_table(sub, size, repeat),
                "What each effect costs"))
    print(table(("mesh", "faces", "size", "frame ms", "x untextured"),
                _colour_table(sub, size, 256 if quick else 1024, repeat),
                "What colour costs (target: textured within 1.2x of untextured; medians of runs in turns)"))
    print(table(("backend", "scene", "size", "opaque ms", "glass ms", "x opaque"),
                _glass_table(256 if quick else 512, repeat),
                "What glass costs (4 layers, mesh outlines; the same scene all opaque; medians of runs in turns)"))

"""Rendering benchmark: toonmesh against moderngl, pyrender (OSMesa, EGL) and PyVista on the
same frame, side by side, and what toonmesh's own options cost.

The main table: the same mesh (``shapes.icosphere(8)``: 655,362 vertices, 1,310,720 faces),
camera (eye (0, 0, 3.2), 40 degrees vertical field of view) and frames (colour at 1024x1024 and
1920x1080; colour + depth at 1024x1024), the mesh uploaded once. toonmesh renders in this
process (thresholded Phong and Lambert, Vulkan and GL); each peer in a process of its own
(:mod:`toonmesh.bench._peers`). All renderers take turns frame by frame, so that a change in the
machine's load falls on each alike; each figure is the median of ``repeat`` frames after a
warm-up frame. A peer that is not installed, or cannot start here, is reported as such.

Then: one-shot ``tm.render`` (upload included) against a frame of a mesh already uploaded; the
upload of each normal mode (``"auto"`` splits vertices at creases); ``render_many`` of a turntable against as many ``render`` calls; what outlines add to a frame;
Kang, Kim and Yoon's scenes (their four small models with outlines, toon shading and shadows at
640x480, next to the paper's frames per second); the accuracy knobs and outline accuracy
(:func:`accuracy`); a point cloud's splats against a mesh of as many faces (``points``); and a
fresh process from import to the first PNG.

Options after the suite name: ``--size N`` (the square frame), ``--wide WxH``,
``--subdivisions S``, ``--skip-peers``, ``--only TABLE,...`` (frames, oneshot, normals, stream,
outlines, kang, points, accuracy, cold).
"""

from __future__ import annotations

import argparse
import os
import statistics
import subprocess
import sys
import tempfile
import time
from typing import Any, Callable, Dict, Iterator, List, Optional, Sequence, Tuple

import numpy as np

from toonmesh.bench import _peers
from toonmesh.bench._timing import median_time, ms, table

EYE = _peers.EYE
FOV_Y = _peers.FOV_Y
TABLES = ("frames", "oneshot", "normals", "stream", "outlines", "kang", "points", "accuracy", "cold")

# A frame kind: (label, outputs, width, height)
Frame = Tuple[str, str, int, int]


def _frames(size: int, wide: Tuple[int, int]) -> List[Frame]:
    w, h = wide
    return [
        (f"colour {size}x{size}", "color", size, size),
        (f"colour {w}x{h}", "color", w, h),
        (f"colour + depth {size}x{size}", "color+depth", size, size),
    ]


def _outputs(kind: str) -> Tuple[str, ...]:
    return ("color", "depth") if kind == "color+depth" else ("color",)


class _Toonmesh:
    """toonmesh as a contestant: one backend and material, the mesh uploaded once."""

    def __init__(self, renderer: Any, mesh: Any, material: Any, shading: str):
        import toonmesh as tm

        self.name = f"toonmesh {renderer.backend}"
        self.shading = shading
        self.msaa = "none (msaa=1)"
        self.info: Dict[str, Any] = {"renderer": renderer.info["name"].split(" (")[0]}
        self._render = renderer.render
        self._mesh = mesh
        self._material = material
        self._camera = tm.Camera.look_at(EYE, fov_y=FOV_Y)

    def frame(self, kind: str, width: int, height: int) -> float:
        t0 = time.perf_counter()
        self._render(self._mesh, camera=self._camera, material=self._material, width=width, height=height,
                     outputs=_outputs(kind))
        return time.perf_counter() - t0


class _Peer:
    """A peer as a contestant (its worker process), or its reason for not taking part."""

    SHADING = {"moderngl": "plain Lambert", "moderngl, culled": "plain Lambert, back faces culled", "pyrender OSMesa": "pyrender default (PBR)",
               "pyrender EGL": "pyrender default (PBR)", "PyVista": "VTK default (Phong)"}

    def __init__(self, name: str, subdivisions: int):
        self.name = name
        self.shading = self.SHADING[name]
        self._proc: Optional[_peers.PeerProcess] = None
        if not _peers.installed(name):
            self.info: Dict[str, Any] = {"error": "not installed"}
        else:
            self._proc = _peers.PeerProcess(name, subdivisions)
            self.info = self._proc.info
        self.msaa = self.info.get("msaa", "")

    def frame(self, kind: str, width: int, height: int) -> float:
        return self._proc.frame(kind, width, height) if self._proc is not None else float("nan")

    def close(self) -> None:
        if self._proc is not None:
            self._proc.close()


def _side_by_side(contestants: Sequence[Any], frames: Sequence[Frame], repeat: int) -> Dict[Tuple[str, str, str], float]:
    """Median seconds per (name, shading, frame label): the contestants take turns frame by
    frame (after one warm-up frame each, per frame kind, which also sizes their targets)."""
    times: Dict[Tuple[str, str, str], List[float]] = {}
    for label, kind, w, h in frames:
        for c in contestants:
            c.frame(kind, w, h)
        for _ in range(max(1, repeat)):
            for c in contestants:
                times.setdefault((c.name, c.shading, label), []).append(c.frame(kind, w, h))
    return {k: float(np.median(v)) for k, v in times.items()}


def _frame_tables(subdiv: int, frames: Sequence[Frame], repeat: int, skip_peers: bool) -> None:
    import toonmesh as tm

    V, F = tm.shapes.icosphere(subdiv)
    ours: List[_Toonmesh] = []
    missing: List[Tuple[str, str]] = []
    for backend in ("vulkan", "gl"):
        try:
            r = tm.Renderer(backend)
        except tm.GpuUnavailableError as e:
            missing.append((f"toonmesh {backend}", str(e).splitlines()[0][:80]))
            continue
        mesh = r.add_mesh(V, F)
        ours.append(_Toonmesh(r, mesh, tm.Material.thresholded_phong(), "thresholded Phong"))
        ours.append(_Toonmesh(r, mesh, tm.Material.lambert(), "Lambert"))
    peers = [] if skip_peers else [_Peer(name, subdiv) for name in _peers.PEERS]
    try:
        running = [p for p in peers if "error" not in p.info]
        medians = _side_by_side(ours + running, frames, repeat)
    finally:
        for p in peers:
            p.close()
    labels = [f[0] for f in frames]
    rows: List[Sequence[Any]] = []
    for c in ours + peers:
        cells = [ms(medians[c.name, c.shading, lab]) if (c.name, c.shading, lab) in medians and
                 np.isfinite(medians[c.name, c.shading, lab]) else c.info.get("error", "failed") for lab in labels]
        rows.append((c.name, c.info.get("renderer", ""), c.shading, c.msaa, *cells))
    rows += [(name, "", "", "", *[why] * len(labels)) for name, why in missing]
    n_v, n_f = len(V), len(F)
    print(table(["renderer", "device", "shading", "anti-aliasing", *labels], rows,
                title=f"Frames: icosphere({subdiv}) = {n_v:,} vertices / {n_f:,} faces, uploaded once; "
                      f"median of {repeat}, renderers in turns"))
    # toonmesh's speed against each peer's: the peer's median over toonmesh's, per frame kind
    ratio_rows = []
    for p in peers:
        for o in ours:
            cells = []
            for lab in labels:
                peer = medians.get((p.name, p.shading, lab), float("nan"))
                cells.append(f"{peer / medians[o.name, o.shading, lab]:.2f}x" if np.isfinite(peer) else p.info.get("error", "failed"))
            ratio_rows.append((p.name, f"{o.name}, {o.shading}", *cells))
    if ratio_rows:
        print(table(["peer", "toonmesh", *labels], ratio_rows,
                    title="toonmesh's speed-up over each peer (peer's median time / toonmesh's; above 1x toonmesh is faster)"))


def _renderers() -> Iterator[Tuple[str, Any]]:
    """(backend, Renderer) for each backend that opens on this machine."""
    import toonmesh as tm

    for backend in ("vulkan", "gl"):
        try:
            yield backend, tm.Renderer(backend)
        except tm.GpuUnavailableError:
            continue


def _oneshot(subdiv: int, size: int, repeat: int) -> None:
    """``tm.render(V, F)`` (upload, render, read back) against a frame of the mesh uploaded once,
    taken in turns."""
    import toonmesh as tm

    V, F = tm.shapes.icosphere(subdiv)
    cam = tm.Camera.look_at(EYE, fov_y=FOV_Y)
    mat = tm.Material.thresholded_phong()
    rows = []
    for backend, r in _renderers():
        kw = dict(camera=cam, material=mat, width=size, height=size)
        uploads, oneshots, steady = [], [], []
        tm.render(V, F, backend=backend, **kw)  # warm-up
        for _ in range(max(1, repeat)):
            t0 = time.perf_counter()
            mesh = r.add_mesh(V, F)
            uploads.append(time.perf_counter() - t0)
            t0 = time.perf_counter()
            r.render(mesh, **kw)
            steady.append(time.perf_counter() - t0)
            r.remove_mesh(mesh)
            t0 = time.perf_counter()
            tm.render(V, F, backend=backend, **kw)
            oneshots.append(time.perf_counter() - t0)
        o, s, u = (float(np.median(x)) for x in (oneshots, steady, uploads))
        rows.append((f"toonmesh {backend}", ms(u), ms(s), ms(o), f"{o / s:.2f}x"))
    print(table(["renderer", "upload (add_mesh)", "frame, mesh uploaded", "one-shot tm.render", "one-shot / frame"], rows,
                title=f"One-shot render of icosphere({subdiv}) ({20 * 4**subdiv:,} faces) at {size}x{size}, "
                      f"thresholded Phong, upload included; median of {repeat}"))


def _normal_uploads(subdiv: int, repeat: int) -> None:
    """``Renderer.add_mesh`` with each normal mode, taken in turns: ``"auto"`` on the smooth
    sphere splits no vertex, on the noisy one (nearly every edge a crease at 30 degrees) nearly
    every one."""
    import toonmesh as tm

    meshes = {"smooth": tm.shapes.icosphere(subdiv), "noisy": tm.shapes.icosphere(subdiv, noise=0.02, seed=1)}
    kinds = [("smooth", "smooth", "smooth"), ("flat", "smooth", "flat"), ("auto, nothing splits", "smooth", "auto"),
             ("auto, nearly all split", "noisy", "auto")]
    rows = []
    for backend, r in _renderers():
        times: Dict[str, List[float]] = {label: [] for label, _, _ in kinds}
        for k in range(max(1, repeat) + 1):  # the first round warms up
            for label, mesh, normals in kinds:
                t0 = time.perf_counter()
                r.remove_mesh(r.add_mesh(*meshes[mesh], normals=normals))
                if k:
                    times[label].append(time.perf_counter() - t0)
        rows.append((f"toonmesh {backend}", *(ms(float(np.median(times[label]))) for label, _, _ in kinds)))
    print(table(["renderer", *(f"normals={label}" for label, _, _ in kinds)], rows,
                title=f"Uploads of icosphere({subdiv}) ({20 * 4**subdiv:,} faces) by normal mode; median of {repeat}"))


def _stream(views: int, size: int, repeat: int) -> None:
    """``render_many`` of a turntable against as many ``render`` calls, in turns."""
    import toonmesh as tm
    from toonmesh.data import bunny

    V, F = bunny()
    cams = [tm.Camera.fit((np.sin(a), 0.3, np.cos(a))) for a in np.linspace(0, 2 * np.pi, views, endpoint=False)]
    rows = []
    for backend, r in _renderers():
        mesh = r.add_mesh(V, F)
        kw = dict(width=size, height=size)
        one = lambda: [r.render(mesh, camera=c, **kw) for c in cams]  # noqa: E731
        many = lambda: r.render_many(mesh, cams, **kw)  # noqa: E731
        one()
        many()
        t_one, t_many = [], []
        for _ in range(max(1, repeat)):
            t_one.append(median_time(one, repeat=1, warmup=0))
            t_many.append(median_time(many, repeat=1, warmup=0))
        a, b = float(np.median(t_one)), float(np.median(t_many))
        rows.append((f"toonmesh {backend}", f"{views / a:.1f}", f"{views / b:.1f}", f"{a / b:.2f}x"))
        r.remove_mesh(mesh)
    print(table(["renderer", f"{views} render calls (frames/s)", f"render_many of {views} views (frames/s)", "throughput ratio"],
                rows, title=f"Streams of views: the bunny ({len(F):,} faces) at {size}x{size}, a turntable; median of {repeat}"))


def _outline_cost(subdiv: int, size: int, repeat: int) -> None:
    """Outlines on the sphere (its lines are the rim), each variant in turns with the plain frame."""
    import toonmesh as tm

    V, F = tm.shapes.icosphere(subdiv)
    cam = tm.Camera.look_at(EYE, fov_y=FOV_Y)
    rows = []
    for backend, r in _renderers():
        mesh = r.add_mesh(V, F)
        kw = dict(camera=cam, width=size, height=size)
        for outlines in ("mesh", "image", "both"):
            with_, without = [], []
            r.render(mesh, outlines=outlines, **kw)
            for _ in range(max(1, repeat)):
                with_.append(median_time(lambda: r.render(mesh, outlines=outlines, **kw), repeat=1, warmup=0))
                without.append(median_time(lambda: r.render(mesh, **kw), repeat=1, warmup=0))
            t, t0 = float(np.median(with_)), float(np.median(without))
            rows.append((f"toonmesh {backend}", f"outlines={outlines!r}", ms(t0), ms(t), f"{(t - t0) * 1e3:+.1f} ms"))
        r.remove_mesh(mesh)
    print(table(["renderer", "outlines", "frame without", "frame with", "cost"], rows,
                title=f"What outlines cost: icosphere({subdiv}) at {size}x{size}, bands colour; median of {repeat}, in turns"))


def _line_steps(subdiv: int, size: int, repeat: int) -> None:
    """The frame's ``silhouettes`` step (finding a view's mesh lines) under each contour rule,
    on the sphere clean and with noise, median over views around it; the first frame with
    suggestive contours also measures the curvature, once per mesh."""
    import math

    import toonmesh as tm

    views = [tm.Camera.look_at((3 * math.cos(a), 3 * math.sin(a), 1.0), fov_y=FOV_Y)
             for a in np.linspace(0, 2 * math.pi, 7, endpoint=False)]
    settings = [("contours='faces' (Kang et al.)", dict(contours="faces")), ("contours='auto' (the default)", {}),
                ("auto + suggestive contours", dict(suggestive=True))]
    rows = []
    for noise in (0.0, 2e-4):
        V, F = tm.shapes.icosphere(subdiv, noise=noise, seed=1)
        r = tm.Renderer()
        mesh = r.add_mesh(V, F)
        base = None
        for name, kw in settings:
            outlines = tm.Outlines("mesh", **kw)
            first = r.render(mesh, camera=views[0], width=size, height=size, outlines=outlines).timings["silhouettes"]
            steps = [r.render(mesh, camera=c, width=size, height=size, outlines=outlines).timings["silhouettes"]
                     for _ in range(max(1, repeat)) for c in views]
            step = float(np.median(steps))
            base = base or step
            rows.append((f"icosphere({subdiv}, noise={noise:g}): {len(F):,} f", name, ms(first), ms(step), f"{step / base:.2f}x"))
        del r
    print(table(["mesh", "lines", "first frame's step", "step per view (median)", "against the face-edge rule"], rows,
                title=f"Finding a view's mesh lines (the frame's 'silhouettes' step) at {size}x{size}, {len(views)} views"))


# Kang, Kim and Yoon (2001): frames per second of their software renderer on a Pentium III, as
# ranges over their models: outlines only, outlines + toon shading, + shadows.
KANG_PAPER_FPS = ("about 80", "60-69", "45-50")


def sphere_cloud(n: int, seed: int = 0) -> np.ndarray:
    """``n`` points drawn uniformly on the unit sphere."""
    v = np.random.default_rng(seed).normal(size=(n, 3))
    return v / np.linalg.norm(v, axis=1, keepdims=True)


def uv_sphere(faces: int) -> Tuple[np.ndarray, np.ndarray]:
    """A unit sphere of about ``faces`` triangles (a latitude-longitude grid, poles included)."""
    m = max(2, int(round(np.sqrt(faces / 4))))  # m rings of 2m quads: 4 m^2 triangles
    theta, phi = np.meshgrid(np.linspace(0, np.pi, m + 1), np.linspace(0, 2 * np.pi, 2 * m, endpoint=False),
                             indexing="ij")
    V = np.stack([np.sin(theta) * np.cos(phi), np.cos(theta), np.sin(theta) * np.sin(phi)], -1).reshape(-1, 3)
    i, j = np.meshgrid(np.arange(m), np.arange(2 * m), indexing="ij")
    a, b = i * 2 * m + j, i * 2 * m + (j + 1) % (2 * m)
    c, d = a + 2 * m, b + 2 * m
    F = np.concatenate([np.stack([a, c, d], -1).reshape(-1, 3), np.stack([a, d, b], -1).reshape(-1, 3)])
    return V, F


def points_cost(n: int, size: int, repeat: int, backends: Optional[Sequence[str]] = None) -> List[Sequence[Any]]:
    """Frames of ``n`` points on a sphere (splats, normals estimated at upload) against a sphere
    mesh of ``n`` faces, both uploaded once, in turns; rows (backend, upload of the points,
    upload of the mesh, frame of the points, frame of the mesh, ratio)."""
    import toonmesh as tm

    cloud = tm.Points(sphere_cloud(n))
    V, F = uv_sphere(n)
    kw = dict(width=size, height=size, camera=tm.Camera.fit((0.3, 0.4, 1.0)))
    rows = []
    for backend, r in _renderers():
        if backends is not None and backend not in backends:
            continue
        t0 = time.perf_counter()
        splats = r.add_points(cloud)
        up_points = time.perf_counter() - t0
        t0 = time.perf_counter()
        mesh = r.add_mesh(V, F)
        up_mesh = time.perf_counter() - t0
        t_points, t_mesh = [], []
        for k in range(max(1, repeat) + 1):  # the first round warms up
            for handle, times in ((splats, t_points), (mesh, t_mesh)):
                t0 = time.perf_counter()
                r.render(handle, **kw)
                if k:
                    times.append(time.perf_counter() - t0)
        p, m = float(np.median(t_points)), float(np.median(t_mesh))
        rows.append((f"toonmesh {backend}", ms(up_points), ms(up_mesh), ms(p), ms(m), f"{p / m:.2f}x"))
        r.remove_mesh(splats)
        r.remove_mesh(mesh)
    return rows


def _points(n: int, size: int, repeat: int) -> None:
    print(table(["renderer", "upload: points (normals, splats)", "upload: mesh", "frame: points", "frame: mesh",
                 "points / mesh"], points_cost(n, size, repeat),
                title=f"Point clouds: {n:,} points on a sphere as splats against a sphere mesh of {n:,} faces at "
                      f"{size}x{size}, each uploaded once; median of {repeat} frames in turns"))


def _kang_models() -> List[Tuple[str, Any, int, float]]:
    """(name, (V, F), the paper's face count, crease angle in degrees)."""
    from toonmesh import shapes

    return [
        ("donut", shapes.torus(), 450, 40.0),
        ("chess piece", shapes.pawn(), 480, 50.0),
        ("teapot", shapes.teapot(), 1024, 60.0),
        ("sphere", shapes.uv_sphere(), 264, 40.0),
    ]


def kang_scene(V: np.ndarray, F: np.ndarray) -> Tuple[Tuple[np.ndarray, np.ndarray], np.ndarray, float]:
    """A model on a floor: the floor quad (V, F) under the model, and the model's bounding
    sphere (centre, radius), for cameras that frame the model."""
    lo, hi = V.min(axis=0), V.max(axis=0)
    centre = (lo + hi) / 2
    radius = float(np.linalg.norm(hi - lo) / 2)
    half = 2.5 * radius
    floor_v = np.array([[-half, 0, -half], [half, 0, -half], [half, 0, half], [-half, 0, half]]) + [centre[0], lo[1], centre[2]]
    floor_f = np.array([[0, 2, 1], [0, 3, 2]])
    return (floor_v, floor_f), centre, radius


KANG_LIGHT = (1.0, -1.2, -0.3)  # the direction the light travels: the shadow falls beside the model
KANG_SMALL_MAP = 512  # a shadow map nearer the paper's frame than the default 2048 x 2048


def _kang(width: int, height: int, views: int, repeat: int) -> None:
    """Each model with a floor, in three stages like the paper's table, as frames per second
    over a turntable of ``views`` (``render_many``), median of ``repeat`` turns."""
    import toonmesh as tm

    rows = []
    for backend, r in _renderers():
        for name, (V, F), paper_faces, crease in _kang_models():
            (floor_v, floor_f), centre, radius = kang_scene(V, F)
            scene = [tm.Mesh(r.add_mesh(V, F), material=tm.Material.lut(tm.kang_table(), "#4a90d9")),
                     tm.Mesh(r.add_mesh(floor_v, floor_f), material=tm.Material.lut(tm.kang_table(), "#d8d0c0"))]
            distance = radius / np.sin(np.radians(20.0)) * 1.1
            cams = [tm.Camera.look_at(centre + distance * np.array([np.sin(a), 0.6, np.cos(a)]) / np.sqrt(1.36),
                                      target=centre, fov_y=40.0) for a in np.linspace(0, 2 * np.pi, views, endpoint=False)]
            ink = tm.Outlines("mesh", crease_angle=crease)
            plain = tm.Light.directional(KANG_LIGHT)
            shadowed = tm.Light.directional(KANG_LIGHT, shadows=True)
            small_map = tm.Light.directional(KANG_LIGHT, shadows=tm.Shadows(size=KANG_SMALL_MAP))
            stages = [
                dict(outputs="outline", outlines=ink, lights=[plain]),
                dict(outputs="color", outlines=ink, lights=[plain]),
                dict(outputs="color", outlines=ink, lights=[shadowed]),
                dict(outputs="color", outlines=ink, lights=[small_map]),
            ]
            fps: List[List[float]] = [[] for _ in stages]
            for kw in stages:
                r.render_many(scene, cams[:2], width=width, height=height, **kw)  # warm-up
            for _ in range(max(1, repeat)):
                for k, kw in enumerate(stages):
                    t0 = time.perf_counter()
                    r.render_many(scene, cams, width=width, height=height, **kw)
                    fps[k].append(views / (time.perf_counter() - t0))
            for item in scene:
                r.remove_mesh(item.handle)
            rows.append((name, f"{len(F):,} ({paper_faces:,})", f"toonmesh {backend}",
                         *[f"{statistics.median(f):.0f} fps" for f in fps]))
    rows.append(("the paper's four models", "264-1,024", "Kang et al. 2001, Pentium III",
                 *[f"{x} fps" for x in KANG_PAPER_FPS], f"{KANG_PAPER_FPS[-1]} fps"))
    map_size = tm.Shadows().size
    print(table(["model", "faces (paper)", "renderer", "outlines only", "+ toon (lookup table)",
                 f"+ shadows ({map_size}x{map_size} map, the default)", f"+ shadows ({KANG_SMALL_MAP}x{KANG_SMALL_MAP} map)"], rows,
                title=f"Kang, Kim and Yoon's scenes at {width}x{height}: each model on a floor, mesh outlines, "
                      f"toon shading through the paper's table, shadow map; a turntable of {views} views "
                      f"(render_many), median of {repeat}"))


def _knobs(size: int, repeat: int) -> List[Sequence[Any]]:
    import toonmesh as tm
    from toonmesh.data import bunny

    V, F = bunny()
    r = tm.Renderer()
    mesh = r.add_mesh(V, F)
    kw = dict(width=size, height=size, material=tm.Material.bands())
    reference = r.render(mesh, supersample=4, **kw).color.astype(np.float64)
    rows = []
    knobs = (dict(band_antialias=False), dict(), dict(msaa=4), dict(supersample=2), dict(supersample=3),
             dict(msaa=4, supersample=2), dict(supersample=4))
    for knob in knobs:
        t = median_time(lambda: r.render(mesh, **kw, **knob), repeat=repeat)
        img = r.render(mesh, **kw, **knob).color.astype(np.float64)
        diff = np.abs(img - reference)[..., :3]
        name = ", ".join(f"{k}={v}" for k, v in knob.items()) or "band_antialias=True (the default)"
        rows.append((name, t, float(diff.mean()), float((diff.max(axis=-1) > 8).mean() * 100)))
    return rows


def stroke_stats(lines: Sequence[np.ndarray]) -> Tuple[int, float, float, float]:
    """Strokes, the share of them under 5 px (%), their median length (px) and how much they
    turn per 100 px of line (radians): how clean a line drawing is."""
    lengths = np.array([np.linalg.norm(np.diff(l, axis=0), axis=1).sum() for l in lines])
    turn = 0.0
    for l in lines:
        d = np.diff(l, axis=0)
        d = d[np.linalg.norm(d, axis=1) > 1e-9]
        if len(d) > 1:
            a = np.diff(np.arctan2(d[:, 1], d[:, 0]))
            turn += float(np.abs((a + np.pi) % (2 * np.pi) - np.pi).sum())
    if not len(lengths):
        return 0, 0.0, 0.0, 0.0
    return len(lines), float((lengths < 5).mean() * 100), float(np.median(lengths)), 100 * turn / max(lengths.sum(), 1e-9)


def _line_settings(size: int, repeat: int) -> List[Sequence[Any]]:
    """The raw bunny's silhouette strokes under each line setting, and the frame's time: what
    each costs and how clean the strokes come out (after the SVG's quarter-pixel simplification)."""
    import toonmesh as tm
    from toonmesh.rendering import _strokes
    from toonmesh.data import bunny

    V, F = bunny()
    r = tm.Renderer()
    mesh = r.add_mesh(V, F)
    settings = [
        ("contours='faces' (Kang et al.)", dict(contours="faces")),
        ("contours='auto' (the default: smooth between creases)", dict()),
        ("+ suggestive contours", dict(suggestive=True)),
        ("+ taper=20, width_by_depth", dict(taper=20.0, width_by_depth=True)),
    ]
    rows = []
    for name, kw in settings:
        outlines = tm.Outlines("mesh", **kw)
        args = dict(outlines=outlines, width=size, height=size, outputs=("color", "lines"))
        t = median_time(lambda: r.render(mesh, **args), repeat=repeat)
        res = r.render(mesh, **args)
        sil = [_strokes.simplified(l, _strokes.SIMPLIFY) for l, k in zip(res.lines, res.line_kinds) if k == "silhouette"]
        n, short, median, turn = stroke_stats(sil)
        rows.append((name, f"{t * 1e3:.1f} ms", n, f"{short:.0f}%", f"{median:.1f} px", f"{turn:.1f}"))
    return rows


def _stroke_smoothing(size: int, repeat: int) -> List[Sequence[Any]]:
    """The raw bunny's silhouette strokes (default outlines) under each ``smooth`` radius of
    :meth:`RenderResult.strokes`, after the SVG's quarter-pixel simplification: how much they
    turn per 100 px, the farthest any point moved (at most the radius), and the time it took."""
    import toonmesh as tm
    from toonmesh.rendering import _strokes
    from toonmesh.data import bunny

    V, F = bunny()
    rows = []
    for rule in ("faces", "auto"):
        res = tm.render(V, F, outlines=tm.Outlines("mesh", contours=rule), width=size, height=size, outputs=("lines",))
        for radius in (0.0, 0.5, 1.0, 2.0, 4.0):
            t = median_time(lambda: res.strokes(smooth=radius, simplify=_strokes.SIMPLIFY), repeat=repeat)
            moved = 0.0
            for line, k in zip(res.lines, res.line_kinds):
                if k == "silhouette":
                    moved = max(moved, float(np.hypot(*(_strokes.smoothed(line, radius) - line).T).max()))
            sil = [p for p, _, k in res.strokes(smooth=radius, simplify=_strokes.SIMPLIFY) if k == "silhouette"]
            n, _, _, turn = stroke_stats(sil)
            points = sum(len(p) for p in sil)
            rows.append((f"contours={rule!r}, smooth={radius:g}", f"{turn:.1f}", f"{moved:.2f} px", points,
                         f"{t * 1e3:.1f} ms"))
    return rows


def _pen_strokes(size: int, n_random: int, repeat: int) -> List[Sequence[Any]]:
    """What the SVG and the pen plotter's order cost: the bunny's strokes (default outlines with
    suggestive contours) as SVG, drawn in order, for a plotter and as filled outlines, and the
    plotter's order of ``n_random`` random short strokes (greedy nearest neighbour, about
    n log n)."""
    import toonmesh as tm
    from toonmesh.rendering import _strokes
    from toonmesh.data import bunny

    V, F = bunny()
    res = tm.render(V, F, outlines=tm.Outlines("mesh", suggestive=True), width=size, height=size, outputs=("lines",))
    label = f"the bunny at {size}x{size}: {len(res.lines or []):,} strokes"
    rows: List[Sequence[Any]] = []
    for call, kw in (("svg()", {}), ("svg(order='plotter')", dict(order="plotter")),
                     ("svg(widths='point')", dict(widths="point")), ("svg(smooth=2)", dict(smooth=2.0))):
        rows.append((label, call, ms(median_time(lambda: res.svg(**kw), repeat=repeat))))
    rng = np.random.default_rng(0)
    starts = rng.uniform(0, 1000, (n_random, 2))
    lines = [np.stack([s, s + rng.normal(0, 10, 2)]) for s in starts]
    t = median_time(lambda: _strokes.plotter_order(lines), repeat=repeat)
    rows.append((f"{n_random:,} random strokes in 1000x1000 px", "plotter_order", ms(t)))
    return rows


def _near(mask: np.ndarray) -> np.ndarray:
    """Pixels within one pixel (3x3) of a set pixel."""
    p = np.pad(mask, 1)
    h, w = mask.shape
    return np.any([p[dy : dy + h, dx : dx + w] for dy in range(3) for dx in range(3)], axis=0)


def _outline_accuracy(sizes: Sequence[int], repeat: int) -> List[Sequence[Any]]:
    """Mesh-space against image-space outlines, each against the exact visible silhouettes (and
    boundaries) of the bunny rasterised at 4x, pooled to the size: precision and recall of
    outline pixels with a one-pixel tolerance, and each frame's time against the plain frame."""
    import toonmesh as tm
    from toonmesh.data import bunny

    V, F = bunny()
    r = tm.Renderer()
    mesh = r.add_mesh(V, F)
    cam = tm.Camera.fit((0.35, 0.3, 1.0))
    rims = dict(crease=False, nonmanifold=False)
    variants = [
        ("mesh-space, width 1.5", tm.Outlines("mesh", **rims), {}),
        ("mesh-space, width 1", tm.Outlines("mesh", width=1.0, **rims), {}),
        ("mesh-space, width 3", tm.Outlines("mesh", width=3.0, **rims), {}),
        ("mesh-space, width 1.5, msaa 4", tm.Outlines("mesh", **rims), dict(msaa=4)),
        ("image-space (detect_edges defaults)", tm.Outlines("image"), {}),
        ("image-space, depth only", tm.Outlines("image", normal_threshold=1e9), {}),
    ]
    rows = []
    for size in sizes:
        kw = dict(camera=cam, width=size, height=size)
        exact = r.render(mesh, camera=cam, width=4 * size, height=4 * size, outputs="outline",
                         outlines=tm.Outlines("mesh", width=1.0, **rims)).outline > 0.5
        truth = exact.reshape(size, 4, size, 4).any(axis=(1, 3))
        for label, outlines, knob in variants:
            # the frame with and without outlines in turns, so that a change in the machine's
            # load falls on both
            with_, without = [], []
            for _ in range(max(1, repeat)):
                with_.append(median_time(lambda: r.render(mesh, outlines=outlines, **kw, **knob), repeat=1))
                without.append(median_time(lambda: r.render(mesh, **kw, **knob), repeat=1))
            t, t0 = float(np.median(with_)), float(np.median(without))
            found = r.render(mesh, outputs="outline", outlines=outlines, **kw, **knob).outline > 0.5
            precision = float((found & _near(truth)).sum() / max(found.sum(), 1))
            recall = float((truth & _near(found)).sum() / max(truth.sum(), 1))
            rows.append((f"{size}x{size}", label, f"{t * 1e3:.1f} ms", f"{(t - t0) * 1e3:+.1f} ms", precision, recall))
    return rows


def _cold_start(size: int) -> Dict[str, float]:
    with tempfile.TemporaryDirectory() as d:
        png = os.path.join(d, "bunny.png")
        code = (
            "import time; t0 = time.perf_counter()\n"
            "import toonmesh as tm\nfrom toonmesh.data import bunny\n"
            f"V, F = bunny(); tm.render(V, F, width={size}, height={size}).save({png!r})\n"
            "print(time.perf_counter() - t0)\n"
        )
        t0 = time.perf_counter()
        out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, timeout=300)
        total = time.perf_counter() - t0
        inside = float(out.stdout.strip().splitlines()[-1]) if out.returncode == 0 else float("nan")
        return {"import to PNG": inside, "process start to exit": total}


def _options(quick: bool, extra: Sequence[str]) -> argparse.Namespace:
    parser = argparse.ArgumentParser(prog="python -m toonmesh.bench render")
    parser.add_argument("--size", type=int, default=256 if quick else 1024, help="the square frame's side")
    parser.add_argument("--wide", type=_size, default=(320, 180) if quick else (1920, 1080), metavar="WxH",
                        help="the wide frame")
    parser.add_argument("--subdivisions", type=int, default=5 if quick else 8)
    parser.add_argument("--skip-peers", action="store_true")
    parser.add_argument("--only", type=_tables, default=TABLES, metavar="TABLE,...",
                        help=f"run only these tables: {', '.join(TABLES)}")
    return parser.parse_args(list(extra))


def _size(text: str) -> Tuple[int, int]:
    try:
        w, h = (int(x) for x in text.lower().split("x"))
    except ValueError:
        raise argparse.ArgumentTypeError(f"expected WxH, got {text!r}") from None
    if w < 1 or h < 1:
        raise argparse.ArgumentTypeError(f"expected WxH of at least 1x1, got {text!r}")
    return w, h


def _tables(text: str) -> Tuple[str, ...]:
    names = tuple(t.strip() for t in text.split(",") if t.strip())
    unknown = [n for n in names if n not in TABLES]
    if unknown or not names:
        raise argparse.ArgumentTypeError(f"expected some of {', '.join(TABLES)}, got {text!r}")
    return names


def accuracy(quick: bool = False, repeat: int = 3, extra: Sequence[str] = ()) -> None:
    """The tables of error against time: each accuracy knob (MSAA, supersampling) on the bunny,
    the line settings (how clean the silhouette strokes come out), and outlines against the
    exact ones at several sizes. They use sizes of their own (smaller
    with ``quick``); the options in ``extra`` are checked but set the main table only."""
    _options(quick, extra)
    knob_size = 128 if quick else 512
    print(table(
        ["accuracy knob", "time", "mean abs difference (0-255)", "% pixels off by > 8"],
        [(k, f"{t * 1e3:.1f} ms", d, f"{p:.2f}") for k, t, d, p in _knobs(knob_size, repeat)],
        title=f"Accuracy knobs: the bunny at {knob_size}x{knob_size}, toon bands, against 4x supersampling",
    ))
    line_size = 200 if quick else 600
    print(table(
        ["line setting", "frame", "silhouette strokes", "under 5 px", "median", "turning per 100 px (rad)"],
        _line_settings(line_size, repeat),
        title=f"Line settings: the raw bunny at {line_size}x{line_size}, mesh lines",
    ))
    print(table(
        ["stroke smoothing", "turning per 100 px (rad)", "farthest point moved", "points", "time (all strokes)"],
        _stroke_smoothing(line_size, repeat),
        title=f"Stroke smoothing (RenderResult.strokes(smooth=...)): the raw bunny's silhouette strokes at "
              f"{line_size}x{line_size}, simplified to a quarter pixel",
    ))
    print(table(["strokes", "call", "time"], _pen_strokes(256 if quick else 1024, 2_000 if quick else 20_000, repeat),
                title="Pen strokes: the SVG's text and the plotter's order"))
    sizes = (128, 256) if quick else (256, 512, 1024, 2048)
    print(table(
        ["size", "outlines", "frame", "cost over the same frame without", "precision", "recall"],
        _outline_accuracy(sizes, repeat),
        title="Outlines: the bunny's silhouettes and boundaries against the exact ones rasterised at 4x "
              "(outline pixels, one-pixel tolerance)",
    ))


def main(quick: bool = False, repeat: int = 3, extra: Sequence[str] = ()) -> None:
    args = _options(quick, extra)
    size, subdiv, only = args.size, args.subdivisions, args.only
    if "frames" in only:
        _frame_tables(subdiv, _frames(size, args.wide), repeat, args.skip_peers)
    if "oneshot" in only:
        _oneshot(subdiv, size, repeat)
    if "normals" in only:
        _normal_uploads(subdiv, repeat)
    if "stream" in only:
        _stream(10 if quick else 100, 128 if quick else 512, repeat)
    if "outlines" in only:
        _outline_cost(subdiv, size, repeat)
        _line_steps(subdiv, size, repeat)
    if "kang" in only:
        _kang(320 if quick else 640, 240 if quick else 480, 6 if quick else 30, repeat)
    if "points" in only:
        _points(20_000 if quick else 1_000_000, 128 if quick else 512, repeat)
    if "accuracy" in only:
        accuracy(quick, repeat, extra)
    if "cold" in only:
        cold = _cold_start(512)
        print(table(["cold start (fresh process, bunny 512x512 to PNG)", "seconds"], [(k, v) for k, v in cold.items()]))

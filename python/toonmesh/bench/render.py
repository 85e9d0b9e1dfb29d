"""Rendering benchmark: toonmesh against pyrender (EGL, OSMesa) and PyVista, side by side.

Same mesh (``toonmesh._core.icosphere(8, 0.02, 1)``: 655,362 vertices, 1,310,720 faces), same
camera, same size (1024 x 1024), steady state (mesh on the device, one warm-up frame, median of
``repeat``). Each peer runs in its own process (a GL platform is chosen at import), so one run
of ``python -m toonmesh.bench render`` fills the whole table. Also: the cost of each accuracy
knob (MSAA, supersampling), outlines against exact silhouettes at several sizes (what accuracy
costs), and a fresh process from import to the first PNG of the bunny.

Options after the suite name: ``--size N``, ``--subdivisions S``, ``--skip-peers``.
"""

from __future__ import annotations

import argparse
import json
import os
import subprocess
import sys
import tempfile
import time
from typing import Any, Dict, List, Optional, Sequence

import numpy as np

from toonmesh.bench._timing import median_time, table

EYE = (0.0, 0.0, 3.2)
FOV_Y = 40.0

_PEER_SETUP = """
import json, os, sys, time, statistics
import numpy as np
from toonmesh import _core
size, subdiv, repeat = int(sys.argv[1]), int(sys.argv[2]), int(sys.argv[3])
V, F = _core.icosphere(subdiv, 0.02, 1)
def median(fn):
    fn()
    ts = []
    for _ in range(max(1, repeat)):
        t = time.perf_counter(); fn(); ts.append(time.perf_counter() - t)
    return statistics.median(ts)
"""

_PYRENDER = _PEER_SETUP + """
import trimesh, pyrender
mesh = pyrender.Mesh.from_trimesh(trimesh.Trimesh(V, F, process=False), smooth=True)
scene = pyrender.Scene(ambient_light=[0.1, 0.1, 0.1])
scene.add(mesh)
pose = np.eye(4); pose[:3, 3] = %(eye)r
scene.add(pyrender.PerspectiveCamera(yfov=np.radians(%(fov)r), aspectRatio=1.0), pose=pose)
scene.add(pyrender.DirectionalLight(intensity=3.0), pose=pose)
r = pyrender.OffscreenRenderer(size, size)
color_depth = median(lambda: r.render(scene))
print(json.dumps({"color+depth": color_depth}))
""" % {"eye": EYE, "fov": FOV_Y}

_PYVISTA = _PEER_SETUP + """
import pyvista as pv
faces = np.hstack([np.full((len(F), 1), 3), F]).ravel()
pl = pv.Plotter(off_screen=True, window_size=(size, size))
pl.add_mesh(pv.PolyData(V, faces), smooth_shading=True, color="orange")
pl.camera.position = %(eye)r; pl.camera.focal_point = (0, 0, 0); pl.camera.up = (0, 1, 0)
pl.camera.view_angle = %(fov)r
def color():
    pl.render(); pl.screenshot(return_img=True)
def color_depth():
    pl.render(); pl.screenshot(return_img=True); pl.get_image_depth()
print(json.dumps({"color": median(color), "color+depth": median(color_depth)}))
""" % {"eye": EYE, "fov": FOV_Y}


def _peer(name: str, code: str, env_extra: Dict[str, str], size: int, subdiv: int, repeat: int) -> Dict[str, Any]:
    env = dict(os.environ, **env_extra)
    try:
        out = subprocess.run(
            [sys.executable, "-c", code, str(size), str(subdiv), str(repeat)],
            env=env, capture_output=True, text=True, timeout=1800,
        )
    except subprocess.TimeoutExpired:
        return {"error": "timed out"}
    lines = [line for line in out.stdout.splitlines() if line.startswith("{")]
    if out.returncode != 0 or not lines:
        last = (out.stderr.strip().splitlines() or ["failed"])[-1]
        return {"error": last[:70]}
    return json.loads(lines[-1])


def _toonmesh_times(size: int, subdiv: int, repeat: int) -> List[Sequence[Any]]:
    import toonmesh as tm
    from toonmesh import _core

    V, F = _core.icosphere(subdiv, 0.02, 1)
    rows = []
    cam = tm.Camera.look_at(EYE, fov_y=FOV_Y)
    for backend in ("vulkan", "gl"):
        try:
            r = tm.Renderer(backend)
        except tm.GpuUnavailableError as e:
            rows.append((f"toonmesh {backend}", "unavailable", str(e)[:60]))
            continue
        t0 = time.perf_counter()
        mesh = r.add_mesh(V, F)
        upload = time.perf_counter() - t0
        name = f"toonmesh {backend} ({r.info['name'].split(' (')[0]})"
        for label, outputs in (("bands colour", ("color",)), ("bands colour+depth", ("color", "depth"))):
            t = median_time(lambda: r.render(mesh, camera=cam, width=size, height=size, outputs=outputs), repeat=repeat)
            rows.append((name, label, t))
        # Outlines on the same sphere without noise: its lines are the rim. (On the noisy
        # sphere nearly every edge is a crease at 30 degrees, so mesh-space lines draw about two
        # million strips: see the README.)
        smooth = r.add_mesh(*_core.icosphere(subdiv, 0.0, 1))
        for label, outlines in (("smooth sphere: bands colour", None), ("  + mesh outlines", "mesh"),
                                ("  + image outlines", "image"), ("  + both outlines", "both")):
            t = median_time(lambda: r.render(smooth, camera=cam, width=size, height=size, outlines=outlines), repeat=repeat)
            rows.append((name, label, t))
        r.remove_mesh(smooth)
        rows.append((f"toonmesh {backend}", "upload (once)", upload))
        # What each normal mode costs to upload: "auto" on the smooth sphere splits nothing, on
        # the noisy one (nearly every edge a crease at 30 degrees) nearly every vertex.
        for label, mesh_args, normals in (("smooth", (subdiv, 0.0, 1), "smooth"), ("flat", (subdiv, 0.0, 1), "flat"),
                                          ("auto, smooth sphere", (subdiv, 0.0, 1), "auto"),
                                          ("auto, noisy sphere", (subdiv, 0.02, 1), "auto")):
            V2, F2 = _core.icosphere(*mesh_args)
            t = median_time(lambda: r.remove_mesh(r.add_mesh(V2, F2, normals=normals)), repeat=repeat)
            rows.append((f"toonmesh {backend}", f"upload, normals={label}", t))
        r.remove_mesh(mesh)
    return rows


def _knobs(size: int, repeat: int) -> List[Sequence[Any]]:
    import toonmesh as tm
    from toonmesh.data import bunny

    V, F = bunny()
    r = tm.Renderer()
    mesh = r.add_mesh(V, F)
    kw = dict(width=size, height=size, material=tm.Material.bands())
    reference = r.render(mesh, supersample=4, **kw).color.astype(np.float64)
    rows = []
    for knob in (dict(), dict(msaa=4), dict(supersample=2), dict(supersample=3), dict(msaa=4, supersample=2), dict(supersample=4)):
        t = median_time(lambda: r.render(mesh, **kw, **knob), repeat=repeat)
        img = r.render(mesh, **kw, **knob).color.astype(np.float64)
        diff = np.abs(img - reference)[..., :3]
        name = ", ".join(f"{k}={v}" for k, v in knob.items()) or "msaa=1, supersample=1"
        rows.append((name, t, float(diff.mean()), float((diff.max(axis=-1) > 8).mean() * 100)))
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
            rows.append((f"{size}x{size}", label, f"{t * 1e3:.1f} ms", f"+{(t - t0) * 1e3:.1f} ms", precision, recall))
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
    parser.add_argument("--size", type=int, default=256 if quick else 1024)
    parser.add_argument("--subdivisions", type=int, default=5 if quick else 8)
    parser.add_argument("--skip-peers", action="store_true")
    return parser.parse_args(list(extra))


def accuracy(quick: bool = False, repeat: int = 3, extra: Sequence[str] = ()) -> None:
    """The tables of error against time: each accuracy knob (MSAA, supersampling) on the bunny,
    and outlines against the exact ones at several sizes. They use sizes of their own (smaller
    with ``quick``); the options in ``extra`` are checked but set the main table only."""
    _options(quick, extra)
    knob_size = 128 if quick else 512
    print(table(
        ["accuracy knob", "time", "mean abs difference (0-255)", "% pixels off by > 8"],
        [(k, f"{t * 1e3:.1f} ms", d, f"{p:.2f}") for k, t, d, p in _knobs(knob_size, repeat)],
        title=f"Accuracy knobs: the bunny at {knob_size}x{knob_size}, toon bands, against 4x supersampling",
    ))
    sizes = (128, 256) if quick else (256, 512, 1024, 2048)
    print(table(
        ["size", "outlines", "frame", "cost over the same frame without", "precision", "recall"],
        _outline_accuracy(sizes, repeat),
        title="Outlines: the bunny's silhouettes and boundaries against the exact ones rasterised at 4x "
              "(outline pixels, one-pixel tolerance)",
    ))


def main(quick: bool = False, repeat: int = 3, extra: Sequence[str] = ()) -> None:
    args = _options(quick, extra)
    size, subdiv = args.size, args.subdivisions
    n_v, n_f = 10 * 4**subdiv + 2, 20 * 4**subdiv
    print(f"# Rendering: icosphere({subdiv}) = {n_v:,} vertices / {n_f:,} faces, {size}x{size}, median of {repeat}")
    rows: List[Sequence[Any]] = list(_toonmesh_times(size, subdiv, repeat))
    peers: Dict[str, Dict[str, Any]] = {}
    if not args.skip_peers:
        peers["pyrender EGL"] = _peer("pyrender EGL", _PYRENDER, {"PYOPENGL_PLATFORM": "egl"}, size, subdiv, repeat)
        peers["pyrender OSMesa"] = _peer("pyrender OSMesa", _PYRENDER, {"PYOPENGL_PLATFORM": "osmesa"}, size, subdiv, repeat)
        peers["PyVista"] = _peer("PyVista", _PYVISTA, {}, size, subdiv, repeat)
    for name, res in peers.items():
        if "error" in res:
            rows.append((name, "unavailable", res["error"]))
        else:
            for what, t in res.items():
                rows.append((name, f"plain {what}", t))
    base = next((p["color+depth"] for k, p in peers.items() if k == "pyrender EGL" and "color+depth" in p), None)
    out_rows = []
    for row in rows:
        t = row[2]
        ratio = f"{base / t:.1f}x" if base and isinstance(t, float) and "upload" not in row[1] else ""
        out_rows.append((row[0], row[1], f"{t * 1e3:.1f} ms" if isinstance(t, float) else t, ratio))
    print(table(["renderer", "frame", "median time", "speed-up vs pyrender EGL colour+depth"], out_rows))
    accuracy(quick, repeat, extra)
    cold = _cold_start(512)
    print(table(["cold start (fresh process, bunny 512x512 to PNG)", "seconds"], [(k, v) for k, v in cold.items()]))

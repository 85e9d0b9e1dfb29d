"""Render many mesh files, and many views of each, in this process or on a Dask cluster.

Each mesh is one task: it is read, uploaded once, and rendered from every view by the worker's
own :class:`toonmesh.Renderer` (one per worker process and backend, kept between tasks), then
its images are written to ``out_dir`` (a folder every worker can reach). The result is a list of
dicts, one per image written, in the order of ``paths`` and views; ``pandas.DataFrame(rows)``
turns it into a table.

Needs ``pip install 'toonmesh[batch]'`` (``dask[distributed]`` and trimesh) for
:func:`render_files`; :func:`render_file` needs trimesh only.

Examples:
    >>> from toonmesh.batch import render_files
    >>> rows = render_files(["a.obj", "b.ply"], "frames/", views=8, width=512, height=512)
    >>> # on a cluster: render_files(..., client=Client("tcp://scheduler:8786"))
"""

from __future__ import annotations

import copy
import os
import socket
import time
from typing import Any, Callable, Dict, List, Optional, Sequence, Tuple

import numpy as np

from toonmesh import _core, smooth
from toonmesh.files._write import check_distinct_names, image_suffix, save_result, view_paths
from toonmesh.files._load import load, under_own_colours
from toonmesh.rendering._render import (RenderOptions, after_smoothing, draw, place_meshes, remove_meshes, shared_renderer,
                                        split_lines)
from toonmesh.scene._scene import Mesh, Normals, normal_mode
from toonmesh.scene._points import Points
from toonmesh.rendering._views import check_views, turntable

__all__ = ["render_file", "render_files"]

#: ``smooth_method`` "paper": the renderer's own smoothing at upload (each vertex to its
#: neighbours' mean, as in :func:`toonmesh.render`), not a :mod:`toonmesh.smooth` method.
AT_UPLOAD = "paper"
#: Every ``smooth_method``: the renderer's own, then the core's smoothing methods.
SMOOTH_METHODS = (AT_UPLOAD,) + tuple(_core.SMOOTH_METHODS)


def _smoothed(V: np.ndarray, F: np.ndarray, method: str, iterations: int) -> np.ndarray:
    if method not in SMOOTH_METHODS:
        raise ValueError(f"smooth_method: expected one of {', '.join(map(repr, SMOOTH_METHODS))}, got {method!r}")
    return getattr(smooth, method)(V, F, iterations=iterations)  # type: ignore[no-any-return]


def _prepared(meshes: List[Any], normals: Normals, method: str, iterations: int) -> List[Any]:
    """The file's meshes in ``normals`` (None: their own, else the default), smoothed by
    ``method`` (once per geometry: its instances share the smoothed arrays, and so one upload).
    "paper" is left to the upload. Its points and lines are kept as read."""
    smoothed: Dict[Tuple[int, int], np.ndarray] = {}
    out = []
    for m in meshes:
        if not isinstance(m, Mesh):  # points and lines: drawn as read
            out.append(m)
            continue
        m = copy.copy(m)
        assert m.vertices is not None and m.faces is not None  # read from a file: arrays, not a MeshHandle
        if normals is not None:
            m.normals = normal_mode(normals, len(m.vertices))
        if iterations and method != AT_UPLOAD:
            key = (id(m.vertices), id(m.faces))
            if key not in smoothed:
                smoothed[key] = _smoothed(m.vertices, m.faces, method, iterations)
            m.vertices = smoothed[key]
            m.normals = after_smoothing(m.normals, True, f"smooth_method={method!r}")
        out.append(m)
    return out


def render_views(
    mesh_path: str,
    files: Sequence[str],
    *,
    backend: Optional[str] = None,
    smooth_iterations: int = 0,
    smooth_method: str = AT_UPLOAD,
    normals: Normals = None,
    own_colors_material: Any = None,
    save: Callable[[Any, str], None] = save_result,
    **render_options: Any,
) -> List[Dict[str, Any]]:
    """Renders one mesh file into ``files``, one view each (a turntable about the scene's up
    axis when there are several files, unless ``camera`` is given with one file).
    ``render_options``: the keywords of :class:`toonmesh.RenderOptions` (``up``: the file's up
    axis, by default its format's convention). ``normals``: as :func:`toonmesh.render` takes
    them (None: the file's own where it has them, else the default). ``own_colors_material``:
    the material of the meshes that carry their own colours or texture (default: the render's
    ``material``; the command line gives the style in white, so that a file's colours show as
    they are). ``save(result, path)`` writes each view (default: the file, by its suffix; the
    command line's video keeps the colour instead). Returns one dict per file: see
    :func:`render_files`."""
    t0 = time.perf_counter()
    if "camera" in render_options and len(files) != 1:
        raise ValueError("camera: give either a camera or several views, not both")
    cameras = [render_options.pop("camera")] if "camera" in render_options else turntable(len(files))
    options = RenderOptions(**render_options)  # checked once, before the mesh is read
    renderer = shared_renderer(backend)
    meshes = load(mesh_path)
    if own_colors_material is not None:
        meshes = under_own_colours(meshes, own_colors_material)
    meshes, lines = split_lines(_prepared(meshes, normals, smooth_method, smooth_iterations))
    at_upload = smooth_iterations if smooth_method == AT_UPLOAD or not smooth_iterations else 0
    scene, uploaded = place_meshes(renderer, meshes, at_upload)
    n_vertices = sum(p.handle.n_vertices for p in scene)
    n_faces = sum(p.handle.n_faces for p, m in zip(scene, meshes) if not isinstance(m, Points))  # placed in order
    n_points = sum(len(m) for m in meshes if isinstance(m, Points))
    n_segments = sum(len(l) for l in lines)
    load_s = time.perf_counter() - t0
    worker = f"{socket.gethostname()}:{os.getpid()}"
    rows = []
    try:
        for k, (camera, path) in enumerate(zip(cameras, files)):
            t1 = time.perf_counter()
            result = draw(renderer, scene, options.replace(camera=camera), lines)
            t2 = time.perf_counter()
            save(result, path)
            rows.append({
                "mesh": mesh_path, "view": k, "path": path, "vertices": n_vertices, "faces": n_faces,
                "points": n_points, "segments": n_segments,
                "up": result.up, "load_s": load_s if k == 0 else 0.0, "render_s": t2 - t1,
                "write_s": time.perf_counter() - t2, "worker": worker,
            })
    finally:
        remove_meshes(renderer, uploaded)
    return rows


def render_file(mesh_path: str, out_dir: str, *, views: int = 1, **options: Any) -> List[Dict[str, Any]]:
    """Renders one mesh file in this process into ``out_dir``.

    Args:
        mesh_path: the mesh file.
        out_dir: the folder the images are written to.
        views: as in :func:`render_files`.
        **options: as in :func:`render_files`.

    Returns:
        One dict per image written, as :func:`render_files` gives them.
    """
    outputs = options.get("outputs", ("color",))
    outputs = [outputs] if isinstance(outputs, str) else list(outputs)
    os.makedirs(out_dir, exist_ok=True)
    files = view_paths(mesh_path, out_dir, check_views(views), image_suffix(outputs))
    return render_views(mesh_path, files, **options)


def render_files(
    paths: Sequence[str], out_dir: str, *, views: int = 1, client: Any = None, **options: Any
) -> List[Dict[str, Any]]:
    """Renders every mesh file in ``paths`` from ``views`` views on a Dask cluster.

    Args:
        paths: mesh files (OBJ, PLY, STL, OFF, GLB, ... as :func:`toonmesh.load` reads them), readable by the
            workers. File name stems must differ: images are named after them.
        out_dir: folder for the images, created if needed, writable by the workers. One view
            gives ``STEM.png``; several give ``STEM-000.png``, ``STEM-001.png``, ... (``.npz``
            with every output array when ``outputs`` asks for ``normal`` or ``depth``).
        views: views per mesh: a turntable of fit cameras about the up axis, the first one the
            fitted camera's three-quarter view (see ``toonmesh render --up``).
        client: a ``dask.distributed.Client``; None starts a local cluster (one worker process
            per core, one thread each) for this call and closes it afterwards.
        **options: for every mesh, as :func:`render_views` takes them: ``backend`` as in
            :class:`toonmesh.Renderer`;
            ``smooth_iterations`` and ``smooth_method``, smoothing before rendering (``"paper"``,
            the default, is the renderer's own, each vertex to its neighbours' mean, as in
            :func:`toonmesh.render`; or a :mod:`toonmesh.smooth` method by name, with that
            many iterations and its defaults: :data:`SMOOTH_METHODS` lists them all); ``normals``, as in
            :func:`toonmesh.render` (None: each file's own, else the default); and the keywords of
            :class:`toonmesh.RenderOptions` for every view (``width``, ``height``, ``material``,
            ``lights``, ``outputs``, ``up``, the files' up axis: "x", "y" or "z", by default each
            format's convention; ``camera`` only with one view), which pickle, so they travel to
            the workers.

    Returns:
        A list of dicts, one per image, in the order of ``paths`` and then views: ``mesh``,
        ``view`` (0-based), ``path`` (the file written), ``vertices``, ``faces`` (summed over
        the scene's placed meshes, as drawn), ``points`` and ``segments`` (of its point clouds
        and lines), ``up`` (the up axis the view used), ``load_s``
        (reading, smoothing and uploading the mesh; on the first view's row), ``render_s``,
        ``write_s`` (seconds) and ``worker`` (host:pid). ``pandas.DataFrame(rows)`` makes it a
        table.

    Raises:
        ImportError: dask.distributed is not installed.
        Exception: the first task's error (a missing or unreadable file, a bad option), as it
            was raised.
    """
    try:
        from dask.distributed import Client, LocalCluster
    except ImportError:
        raise ImportError("render_files needs dask.distributed: pip install 'toonmesh[batch]'") from None
    paths = [os.fspath(p) for p in paths]
    check_distinct_names(paths)
    n_views = check_views(views)
    os.makedirs(out_dir, exist_ok=True)
    own = None
    if client is None:
        cluster = LocalCluster(n_workers=os.cpu_count() or 1, threads_per_worker=1, processes=True,
                               dashboard_address=None)
        own = client = Client(cluster)
    try:
        futures = client.map(render_file, paths, out_dir=out_dir, views=n_views, pure=False, **options)
        results = client.gather(futures)
    finally:
        if own is not None:
            cluster = own.cluster
            own.close()
            cluster.close()
    return [row for rows in results for row in rows]

"""Outline benchmarks: toonmesh.edges side by side with trimesh, scikit-image and OpenCV.

``python -m toonmesh.bench edges [--quick] [--repeat N]``. Peers that are not installed are
left out of the tables.
"""

from __future__ import annotations

import math
import os
from typing import Any, List, Optional, Sequence

import numpy as np

from toonmesh import _core
from toonmesh import edges as te
from toonmesh.bench._timing import median_time, ms, table


def _optional(name: str) -> Any:
    try:
        return __import__(name)
    except ImportError:
        return None


def _ratio(peer: Optional[float], ours: float) -> str:
    return "-" if peer is None else f"{peer / ours:.1f}x"


def mesh_rows(subdivisions: int, noise: float, repeat: int, with_index: bool = True) -> List[Sequence[Any]]:
    """Feature edges (and, with ``with_index``, EdgeIndex) on a noisy icosphere. The noise is
    relative to the unit radius; at subdivision 8 an edge is about 0.005 long, so 2e-4 gives a
    smooth sphere without creases and 2e-3 a rough one where a third of the edges are creases."""
    V, F = _core.icosphere(subdivisions, noise, 1)
    n_crease = len(te.feature_edges(V, F, crease_angle=30.0).crease)
    label = f"icosphere({subdivisions}, noise={noise:g}): {len(V):,} v / {len(F):,} f, {n_crease:,} creases"
    trimesh = _optional("trimesh")
    rows: List[Sequence[Any]] = []

    ours_fe = median_time(lambda: te.feature_edges(V, F, crease_angle=30.0), repeat)
    peer_fe = None
    peer_boundary = None
    if trimesh is not None:
        theta = math.radians(30.0)

        def trimesh_creases() -> Any:
            m = trimesh.Trimesh(V, F, process=False)
            return m.face_adjacency_edges[m.face_adjacency_angles > theta]

        def trimesh_boundary() -> Any:
            m = trimesh.Trimesh(V, F, process=False)
            return m.edges_sorted[trimesh.grouping.group_rows(m.edges_sorted, require_count=1)]

        peer_fe = median_time(trimesh_creases, repeat)
        peer_boundary = median_time(trimesh_boundary, repeat)
    rows.append([label, "feature_edges (boundary + crease + non-manifold)", ms(ours_fe), "-" if peer_fe is None else ms(peer_fe), _ratio(peer_fe, ours_fe)])
    if peer_fe is not None and peer_boundary is not None:
        both = peer_fe + peer_boundary
        rows.append([label, "  vs trimesh creases + boundaries (two routes)", ms(ours_fe), ms(both), _ratio(both, ours_fe)])
    if not with_index:
        return rows

    build = median_time(lambda: te.EdgeIndex(V, F), max(1, repeat - 1))
    rows.append([label, "EdgeIndex build (once per mesh)", ms(build), "-", "-"])
    index = te.EdgeIndex(V, F)
    eyes = [(3 * math.cos(t), 3 * math.sin(t), 1.0) for t in np.linspace(0, 2 * math.pi, 12, endpoint=False)]
    per_view = median_time(lambda: [index.silhouette(eye=e) for e in eyes], repeat) / len(eyes)
    numpy_view = None
    if trimesh is not None:
        # The vectorised NumPy way with trimesh's face pairs prepared in advance: a fair baseline
        # for the per-view part alone.
        m = trimesh.Trimesh(V, F, process=False)
        normals, points = index.face_normals, V[F[:, 0]]
        pairs, pair_edges = m.face_adjacency, m.face_adjacency_edges

        def numpy_silhouette() -> Any:
            front = np.einsum("ij,ij->i", normals, points - np.asarray(eyes[0])) < 0
            return pair_edges[front[pairs[:, 0]] != front[pairs[:, 1]]]

        numpy_view = median_time(numpy_silhouette, repeat)
    rows.append(
        [
            label,
            "EdgeIndex.silhouette per view (perspective) vs prepared NumPy",
            ms(per_view),
            "-" if numpy_view is None else ms(numpy_view),
            _ratio(numpy_view, per_view),
        ]
    )
    ortho = median_time(lambda: index.silhouette(direction=(0.3, -1.0, 0.2)), repeat)
    rows.append([label, "EdgeIndex.silhouette per view (orthographic)", ms(ortho), "-", "-"])
    # the lines through the faces, against the face-edge silhouette of the same views
    contours = median_time(lambda: [index.contours(eye=e) for e in eyes], repeat) / len(eyes)
    rows.append([label, "EdgeIndex.contours per view, vs its silhouette", ms(contours), ms(per_view), _ratio(per_view, contours)])
    index.suggestive_contours(eye=eyes[0])  # the curvature, once per mesh
    suggestive = median_time(lambda: [index.suggestive_contours(eye=e) for e in eyes], repeat) / len(eyes)
    rows.append([label, "EdgeIndex.suggestive_contours per view, vs its silhouette", ms(suggestive), ms(per_view),
                 _ratio(per_view, suggestive)])
    return rows


def sobel_rows(size: int, repeat: int) -> List[Sequence[Any]]:
    img = np.random.default_rng(0).random((size, size)).astype(np.float32)
    label = f"{size}x{size} float32"
    rows: List[Sequence[Any]] = []
    ours = median_time(lambda: te.sobel(img), repeat)
    skimage = _optional("skimage")
    if skimage is not None:
        from skimage import filters

        sk = median_time(lambda: filters.sobel(img), repeat)
        rows.append([label, "sobel vs skimage.filters.sobel", ms(ours), ms(sk), _ratio(sk, ours)])
    cv2 = _optional("cv2")
    if cv2 is not None:
        inv_sqrt2 = np.float32(1 / math.sqrt(2))

        def cv2_skimage_equivalent() -> Any:
            gx = cv2.Sobel(img, cv2.CV_32F, 1, 0, ksize=3, scale=0.25, borderType=cv2.BORDER_REFLECT)
            gy = cv2.Sobel(img, cv2.CV_32F, 0, 1, ksize=3, scale=0.25, borderType=cv2.BORDER_REFLECT)
            return cv2.magnitude(gx, gy) * inv_sqrt2

        cv = median_time(cv2_skimage_equivalent, repeat)
        rows.append([label, "sobel vs cv2 (scale=0.25, REFLECT, magnitude/sqrt2)", ms(ours), ms(cv), _ratio(cv, ours)])
        ours_cv = median_time(lambda: te.sobel(img, convention="opencv"), repeat)

        def cv2_plain() -> Any:
            return cv2.magnitude(cv2.Sobel(img, cv2.CV_32F, 1, 0, ksize=3), cv2.Sobel(img, cv2.CV_32F, 0, 1, ksize=3))

        cvp = median_time(cv2_plain, repeat)
        rows.append([label, "sobel(convention='opencv') vs cv2 defaults", ms(ours_cv), ms(cvp), _ratio(cvp, ours_cv)])
    ours_h = median_time(lambda: te.sobel_h(img), repeat)
    if skimage is not None:
        from skimage import filters

        skh = median_time(lambda: filters.sobel_h(img), repeat)
        rows.append([label, "sobel_h vs skimage.filters.sobel_h", ms(ours_h), ms(skh), _ratio(skh, ours_h)])
    return rows


def _ellipsoid(subdivisions: int) -> Any:
    """An ellipsoid (1, 0.7, 0.5) from an icosphere, with its exact mean curvature per vertex."""
    V, F = _core.icosphere(subdivisions, 0.0, 0)
    a, b, c = 1.0, 0.7, 0.5
    V = V * [a, b, c]
    x, y, z = V.T
    q = x**2 / a**4 + y**2 / b**4 + z**2 / c**4
    mean = -(x**2 + y**2 + z**2 - a**2 - b**2 - c**2) / (2 * (a * b * c) ** 2 * q**1.5)
    return V, F, mean


def curvature_rows(subdivisions: int, repeat: int) -> List[Sequence[Any]]:
    """Principal curvature on an ellipsoid: time and median relative error of the mean
    curvature against its closed form, beside libigl's and pymeshlab's estimators."""
    V, F, exact = _ellipsoid(subdivisions)
    label = f"ellipsoid: {len(V):,} v / {len(F):,} f"

    def err(mean: np.ndarray) -> str:
        return f"{np.median(np.abs(mean - exact) / np.abs(exact)):.3%}"

    ours = median_time(lambda: te.curvature(V, F), repeat)
    rows: List[Sequence[Any]] = [[label, "toonmesh curvature (per-face fit, Rusinkiewicz)", ms(ours), err(te.curvature(V, F).mean), "1.0x"]]
    igl = _optional("igl")
    if igl is not None:
        def igl_mean() -> np.ndarray:
            _, _, k1, k2, _ = igl.principal_curvature(V, F, radius=2)
            return 0.5 * (k1 + k2)

        t = median_time(igl_mean, repeat)
        rows.append([label, "libigl principal_curvature (radius 2)", ms(t), err(igl_mean()), _ratio(t, ours)])
    pymeshlab = _optional("pymeshlab")
    if pymeshlab is not None:
        for method, name in [(0, "Taubin"), (3, "pseudo-inverse quadric fit")]:
            def meshlab_mean() -> np.ndarray:
                ms_ = pymeshlab.MeshSet()
                ms_.add_mesh(pymeshlab.Mesh(V, F))
                ms_.compute_curvature_principal_directions_per_vertex(method=method, curvcolormethod=0)
                return ms_.current_mesh().vertex_scalar_array()

            t = median_time(meshlab_mean, repeat)
            rows.append([label, f"pymeshlab principal directions ({name})", ms(t), err(meshlab_mean()), _ratio(t, ours)])
    return rows


def smoothing_rows(subdivisions: int, noise: float, repeat: int) -> List[Sequence[Any]]:
    """What curvature smoothing costs and buys on a noisy ellipsoid: time, the median error of
    the mean curvature against the clean ellipsoid's closed form, and the share of vertices the
    estimate calls saddles (k1 k2 < 0; the ellipsoid has none, and each draws suggestive
    contours)."""
    V, F, exact = _ellipsoid(subdivisions)
    noisy, _ = _core.icosphere(subdivisions, noise, 1)
    noisy = noisy * [1.0, 0.7, 0.5]
    edge = float(np.linalg.norm(V[F] - V[np.roll(F, 1, axis=1)], axis=2).mean())
    label = f"ellipsoid: {len(V):,} v, noise {noise / edge:.2f} mean edges"
    rows: List[Sequence[Any]] = []
    for smoothing in (0.0, 1.0, 2.0, 3.0):
        t = median_time(lambda: te.curvature(noisy, F, smoothing=smoothing), repeat)
        c = te.curvature(noisy, F, smoothing=smoothing)
        error = np.median(np.abs(c.mean - exact) / np.abs(exact))
        rows.append([label, f"smoothing={smoothing:g}", ms(t), f"{error:.1%}", f"{(c.k1 * c.k2 < 0).mean():.1%}"])
    return rows


def intersection_rows(brute_sizes: Sequence[int], size: int, repeat: int) -> List[Sequence[Any]]:
    """Intersection lines of two unit icospheres half a radius apart: the hierarchy (built on
    every call, as ``edges.intersections`` does) against the all-pairs reference on the sizes
    where that runs, then the hierarchy alone at ``size``. Time per million triangles of both
    meshes together."""
    rows: List[Sequence[Any]] = []
    for subdivisions in list(brute_sizes) + [size]:
        a = _core.icosphere(subdivisions, 0.0, 0)
        b = (a[0] + [0.5, 0.0, 0.0], a[1])
        triangles = 2 * len(a[1])
        ours = median_time(lambda: te.intersections([a, b]), repeat)
        label = f"2 x icosphere({subdivisions}): {triangles:,} triangles, {len(te.intersections([a, b])):,} segments"
        per_million = f"{ours / triangles * 1e9:.1f} ms"
        if subdivisions in brute_sizes:
            from toonmesh.edges import _mesh_list

            peer = median_time(lambda: _core._intersections(_mesh_list([a, b]), False, True), max(1, repeat - 2))
            rows.append([label, per_million, ms(ours), ms(peer), _ratio(peer, ours)])
        else:
            rows.append([label, per_million, ms(ours), "-", "-"])
    return rows


def main(quick: bool = False, repeat: int = 3, extra: Sequence[str] = ()) -> None:
    """Prints the outline benchmark tables (Markdown). ``quick`` uses a small mesh and image."""
    subdivisions = 5 if quick else 8
    size = 1024 if quick else 4096
    repeat = 1 if quick else repeat
    load = f", load average {os.getloadavg()[0]:.1f} on {os.cpu_count()} cores" if hasattr(os, "getloadavg") else ""
    print(f"toonmesh {_core.__version__}, {_core.get_num_threads()} threads; median of {repeat} runs{load}")
    rows = mesh_rows(subdivisions, 0.0002, repeat) + mesh_rows(subdivisions, 0.002, repeat, with_index=False)
    print(table(["case", "call", "toonmesh", "peer", "speed-up"], rows, title="Mesh-space outlines"))
    print(table(["case", "call", "toonmesh", "peer", "speed-up"], sobel_rows(size, repeat), title="Sobel"))
    crossing = intersection_rows((2, 3) if quick else (2, 3, 4), 5 if quick else 7, repeat)
    print(table(["case", "per million triangles", "intersections", "all pairs (reference)", "speed-up"], crossing,
                title="Intersection lines: bounding-volume hierarchy against every pair of triangles"))
    curv = curvature_rows(4 if quick else 8, repeat)
    print(table(["case", "estimator", "time", "mean curvature error (median)", "toonmesh's speed-up"], curv, title="Principal curvature"))
    smooth = smoothing_rows(4 if quick else 7, 0.003 if quick else 0.002, repeat)
    print(table(["case", "curvature(smoothing=...)", "time", "mean curvature error (median)", "saddle vertices"], smooth,
                title="What curvature smoothing costs: a noisy ellipsoid (smoothing in mean edge lengths)"))

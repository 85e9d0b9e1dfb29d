"""Testing helpers for code that uses toonmesh: compare meshes, renders and line drawings within
tolerances that make sense for each, and cross-check toonmesh against the libraries it
reproduces (trimesh, pymeshlab, libigl, scikit-image) on your own meshes.

- :func:`assert_mesh_close` / :func:`mesh_difference`: vertex positions, relative to the
  bounding-box diagonal, and the faces (topology);
- :func:`assert_images_close` / :func:`image_difference`: colour images (a render, or an
  array), by the share of pixels that differ by more than a few 8-bit levels;
- :func:`assert_drawings_close` / :func:`drawing_difference`: line drawings (a render's
  lines, its SVG) as geometry, within a pixel tolerance, so float noise in an SVG never fails;
- :func:`smoothing_vs_trimesh`, :func:`smoothing_vs_pymeshlab`, :func:`curvature_vs_libigl`,
  :func:`sobel_vs_skimage`: run toonmesh and the peer on the same input and measure how far
  apart they are. A peer that is not installed skips the test under pytest (or raises
  :class:`PeerMissingError` outside it) and fails loudly where ``CI=true``
  (:func:`need_peer`);
- :func:`temporal_popping`: how much of a sequence's line drawing pops from frame to frame
  (ink that vanishes from where its surface went), for turntables and fly-bys;
- :class:`Snapshot`: a reference image or drawing kept beside a test, what the ``toon_snapshot``
  fixture of toonmesh's pytest plugin (:mod:`toonmesh.pytest_plugin`) gives a test.

The default tolerances (:data:`IMAGE_LEVELS`, :data:`IMAGE_SHARE`, :data:`LINE_PIXELS`,
:data:`LINE_SHARE`) pass between toonmesh's Vulkan and GL backends for the same scene; see
docs/testing.md for what was measured. Nothing here modifies its arguments.
"""

from __future__ import annotations

import importlib
import math
import os
import re
from collections import Counter
from pathlib import Path
from types import ModuleType
from typing import Any, Dict, List, NamedTuple, Optional, Sequence, Tuple, Union

import numpy as np

from toonmesh import edges, smooth
from toonmesh.rendering import _strokes
from toonmesh.testing import _drawings, _png, _temporal
from toonmesh.arguments._checks import number
from toonmesh.rendering._results import RenderResult

__all__ = [
    "IMAGE_LEVELS",
    "IMAGE_SHARE",
    "INK_COVERAGE",
    "LINE_PIXELS",
    "LINE_SHARE",
    "MESH_RTOL",
    "POPPING_PIXELS",
    "CurvatureAgreement",
    "DrawingDifference",
    "ImageDifference",
    "MeshDifference",
    "PeerMissingError",
    "Snapshot",
    "SobelDifference",
    "TemporalPopping",
    "assert_drawings_close",
    "assert_images_close",
    "assert_mesh_close",
    "curvature_vs_libigl",
    "drawing_difference",
    "image_difference",
    "mesh_difference",
    "need_peer",
    "smoothing_vs_pymeshlab",
    "smoothing_vs_trimesh",
    "sobel_vs_skimage",
    "temporal_popping",
]

#: A pixel differs when one of its channels differs by more than this many 8-bit levels (of
#: 255): about 3%, above the rounding and interpolation noise between devices.
IMAGE_LEVELS = 8
#: Images are close when at most this share of their pixels differ (0.1%).
IMAGE_SHARE = 0.001
#: A point of a line drawing differs when it lies farther than this many pixels from the other
#: drawing's lines of the same kind.
LINE_PIXELS = 1.0
#: Drawings are close when at most this share of their line length differs (0.5%).
LINE_SHARE = 0.005
#: Meshes are close when no vertex is farther than this share of the expected mesh's
#: bounding-box diagonal from where the expected mesh has it.
MESH_RTOL = 1e-6


# ------------------------------------------------------------------------------------------------
# Peers


class PeerMissingError(ImportError):
    """A peer library a comparison needs is not installed (raised outside pytest, and under
    pytest where ``CI=true``)."""


def need_peer(module: str, purpose: str = "") -> ModuleType:
    """Imports the peer library ``module`` (say ``"trimesh"``) for a comparison.

    When it is not installed: under pytest the test is skipped, with the reason; where the
    environment variable ``CI`` is ``true`` (any case) the run must have every peer, so
    :class:`PeerMissingError` is raised instead (the test fails); outside pytest,
    :class:`PeerMissingError` (an ``ImportError``) says what to install.

    Args:
        module: the module's import name (``"igl"`` for libigl, ``"skimage"`` for
            scikit-image).
        purpose: what it is needed for, added to the reason (default: nothing).

    Returns:
        The imported module.
    """
    if not isinstance(module, str):
        raise TypeError(f"module: expected a module name (str), got {type(module).__name__}")
    if not isinstance(purpose, str):
        raise TypeError(f"purpose: expected a str, got {type(purpose).__name__}")
    try:
        return importlib.import_module(module)
    except ImportError as exc:
        reason = f"{module} is not installed" + (f" ({purpose})" if purpose else "")
        if os.environ.get("CI", "").lower() == "true":
            raise PeerMissingError(f"{reason}; CI=true, where every peer must be installed "
                                   f"(pip install 'toonmesh[test]')") from exc
        if "PYTEST_CURRENT_TEST" in os.environ or "PYTEST_VERSION" in os.environ:
            import pytest

            pytest.skip(reason, allow_module_level=True)
        raise PeerMissingError(f"{reason}: install it to run this comparison") from exc


# ------------------------------------------------------------------------------------------------
# Meshes


class MeshDifference(NamedTuple):
    """How far apart two meshes' vertices are (:func:`mesh_difference`).

    Attributes:
        relative: the largest distance divided by the expected mesh's bounding-box diagonal.
        largest: the largest distance between a vertex and its counterpart, in the mesh's
            units.
        vertex: the index of that vertex.
        diagonal: the bounding-box diagonal of the expected mesh (mesh units).
        distances: (N,) float64, every vertex's distance to its counterpart (mesh units).
    """

    relative: float
    largest: float
    vertex: int
    diagonal: float
    distances: np.ndarray


def _real_array(name: str, value: Any, what: str) -> np.ndarray:
    if isinstance(value, (str, bytes)) or value is None:
        raise TypeError(f"{name}: expected {what}, got {type(value).__name__}")
    try:
        arr = np.asarray(value)
    except (ValueError, TypeError) as exc:  # ragged lists
        raise TypeError(f"{name}: cannot be read as an array ({exc})") from None
    if arr.dtype.kind not in "fiu":
        raise TypeError(f"{name}: expected {what} of real numbers, got dtype {arr.dtype}")
    return arr


def _mesh(name: str, value: Any) -> Tuple[np.ndarray, Optional[np.ndarray]]:
    """(V (N, 3) float64, F (M, 3) int64 or None) of a mesh argument: a ``(vertices, faces)``
    pair, an object with ``vertices`` and ``faces`` (a ``trimesh.Trimesh``), or positions."""
    faces: Any = None
    if hasattr(value, "vertices") and hasattr(value, "faces"):
        value, faces = value.vertices, value.faces
    elif isinstance(value, (tuple, list)) and len(value) == 2 and np.ndim(value[0]) == 2:
        value, faces = value
    V = _real_array(name, value, "an (N, 3) array of positions or a (vertices, faces) pair")
    if V.ndim != 2 or V.shape[1] != 3 or len(V) == 0:
        raise ValueError(f"{name}: positions must be an (N, 3) array with N >= 1, got shape {V.shape}")
    V = V.astype(np.float64)
    bad = ~np.isfinite(V).all(axis=1)
    if bad.any():
        i = int(np.argmax(bad))
        raise ValueError(f"{name}: positions must be finite; vertex {i} is {tuple(V[i].tolist())}")
    if faces is None:
        return V, None
    F = _real_array(f"{name}", faces, "an (M, 3) array of faces")
    if F.dtype.kind == "f":
        raise TypeError(f"{name}: faces must be integers, got dtype {F.dtype}")
    if F.ndim != 2 or F.shape[1] != 3:
        raise ValueError(f"{name}: faces must be an (M, 3) array, got shape {F.shape}")
    if F.size and (F.min() < 0 or F.max() >= len(V)):
        raise IndexError(f"{name}: face index {int(F.min() if F.min() < 0 else F.max())} outside [0, {len(V)})")
    return V, F.astype(np.int64)


def _norms(x: np.ndarray) -> np.ndarray:
    """Lengths of the rows of x, without overflow or underflow at any scale."""
    scale = float(np.abs(x).max(initial=0.0))
    if scale == 0.0 or not np.isfinite(scale):
        scale = 1.0
    return np.asarray(np.linalg.norm(x / scale, axis=-1) * scale, dtype=np.float64)


def _diagonal(V: np.ndarray) -> float:
    return float(_norms(V.max(axis=0) - V.min(axis=0)))


def _differences(V: np.ndarray, W: np.ndarray) -> MeshDifference:
    distances = _norms(V - W)
    vertex = int(np.argmax(distances))
    largest = float(distances[vertex])
    diagonal = _diagonal(W) or _diagonal(V)
    relative = largest / diagonal if diagonal > 0 else (0.0 if largest == 0 else math.inf)
    return MeshDifference(relative, largest, vertex, diagonal, distances)


def mesh_difference(actual: Any, expected: Any) -> MeshDifference:
    """How far each vertex of ``actual`` is from the same vertex of ``expected``.

    Args:
        actual: a mesh: a ``(vertices, faces)`` pair, an object with ``vertices`` and
            ``faces`` (a ``trimesh.Trimesh``), or just the (N, 3) positions; positions of any
            real dtype (compared in float64), finite. Faces are not looked at here
            (:func:`assert_mesh_close` checks them).
        expected: a mesh as ``actual``, with the same number of vertices.

    Returns:
        :class:`MeshDifference`: distances in the mesh's units, and the largest relative to the
        expected mesh's bounding-box diagonal (so the same for the mesh at any scale).

    Raises:
        TypeError: an argument that is not a mesh, naming it.
        ValueError: likewise, or vertex counts that differ (naming both).
        IndexError: likewise.
    """
    __tracebackhide__ = True  # pytest shows the caller's line
    V, _ = _mesh("actual", actual)
    W, _ = _mesh("expected", expected)
    if len(V) != len(W):
        raise ValueError(f"actual, expected: {len(V)} vertices against {len(W)}: positions compare vertex by vertex")
    return _differences(V, W)


def _rotated(F: np.ndarray) -> np.ndarray:
    """Each face turned to its lexicographically smallest rotation (its orientation kept)."""
    best = F
    for k in (1, 2):
        cand = np.roll(F, -k, axis=1)
        less = (cand[:, 0] < best[:, 0]) | (
            (cand[:, 0] == best[:, 0]) & ((cand[:, 1] < best[:, 1]) | ((cand[:, 1] == best[:, 1]) & (cand[:, 2] < best[:, 2])))
        )
        best = np.where(less[:, None], cand, best)
    return best


def _face_problem(Fa: np.ndarray, Fe: np.ndarray) -> Optional[str]:
    """What differs between two meshes' faces as triangles in any row order and rotation
    (None when nothing does)."""
    if len(Fa) != len(Fe):
        return f"actual has {len(Fa)} faces, expected {len(Fe)}"
    ra, re_ = _rotated(Fa), _rotated(Fe)
    if np.array_equal(ra[np.lexsort(ra.T[::-1])], re_[np.lexsort(re_.T[::-1])]):
        return None
    theirs = Counter(map(tuple, re_.tolist()))
    missing = []
    for i, face in enumerate(map(tuple, ra.tolist())):
        if theirs[face] > 0:
            theirs[face] -= 1
        else:
            missing.append(i)
    first = missing[0]
    flipped = tuple(_rotated(Fa[first:first + 1, ::-1])[0].tolist()) in set(map(tuple, re_.tolist()))
    return (f"{len(missing)} of the {len(Fa)} faces of actual are not faces of expected (as triangles, in any "
            f"order and rotation); the first: face {first} {tuple(Fa[first].tolist())}"
            + (", which expected has the other way round (flipped)" if flipped else ""))


def assert_mesh_close(
    actual: Any,
    expected: Any,
    *,
    rtol: float = MESH_RTOL,
    atol: float = 0.0,
    check_faces: bool = True,
) -> MeshDifference:
    """Asserts that two meshes are the same within a tolerance relative to their size.

    Every vertex of ``actual`` must lie within ``atol + rtol * diagonal`` of the same vertex of
    ``expected`` (``diagonal``: the expected mesh's bounding-box diagonal, so the default works
    at any scale); both must have as many vertices and, where both have faces and
    ``check_faces``, the same faces: the same triangles with the same orientation, in any
    order of the rows and any rotation of a face's corners.

    Args:
        actual: a ``(vertices, faces)`` pair, an object with ``vertices`` and ``faces`` (a
            ``trimesh.Trimesh``), or (N, 3) positions alone; positions of any real dtype,
            finite; faces (M, 3) integer indices.
        expected: a mesh as ``actual``.
        rtol: float >= 0, default :data:`MESH_RTOL` (1e-6): the tolerance as a share of the
            expected mesh's bounding-box diagonal.
        atol: float >= 0, default 0: an absolute tolerance added, in the mesh's units.
        check_faces: bool, default True: compare the faces where both meshes have them.

    Returns:
        :class:`MeshDifference` of the two (when they are close).

    Raises:
        AssertionError: they differ; the message names the worst vertex, its distance (mesh
            units and relative to the diagonal), both positions, and how many vertices are
            beyond the tolerance, or the first face that differs.
        TypeError, ValueError, IndexError: a bad argument, naming it.
    """
    __tracebackhide__ = True  # pytest shows the caller's line
    rtol = number("rtol", rtol, 0.0)
    atol = number("atol", atol, 0.0)
    if not isinstance(check_faces, (bool, np.bool_)):
        raise TypeError(f"check_faces: expected True or False, got {type(check_faces).__name__}")
    V, Fa = _mesh("actual", actual)
    W, Fe = _mesh("expected", expected)
    if len(V) != len(W):
        raise AssertionError(f"meshes differ: actual has {len(V)} vertices, expected {len(W)}")
    if check_faces and Fa is not None and Fe is not None:
        problem = _face_problem(Fa, Fe)
        if problem:
            raise AssertionError(f"meshes differ: {problem}")
    d = _differences(V, W)
    limit = atol + rtol * d.diagonal
    if d.largest > limit:
        i = d.vertex
        beyond = int((d.distances > limit).sum())
        raise AssertionError(
            f"meshes differ: vertex {i} is {d.relative:.3g} of the bounding-box diagonal ({d.largest:.6g} in the "
            f"mesh's units) from where expected has it; tolerance {limit:.3g} (rtol {rtol:g} of the diagonal "
            f"{d.diagonal:.6g}, atol {atol:g}); actual {tuple(np.round(V[i], 9).tolist())}, expected "
            f"{tuple(np.round(W[i], 9).tolist())}; {beyond} of {len(V)} vertices are beyond the tolerance"
        )
    return d


# ------------------------------------------------------------------------------------------------
# Images


class ImageDifference(NamedTuple):
    """How two images differ (:func:`image_difference`), in 8-bit levels (0 to 255).

    Attributes:
        share: the share of pixels (0 to 1) whose largest channel difference exceeds ``levels``.
        largest: the largest difference of any channel of any pixel (levels).
        at: ``(x, y)`` of a pixel with that difference (x right, y down from the top left).
        differing: how many pixels exceed ``levels``.
        levels: the tolerance per pixel the share was counted with.
    """

    share: float
    largest: int
    at: Tuple[int, int]
    differing: int
    levels: int


def _image(name: str, value: Any) -> np.ndarray:
    """An image argument as (H, W, C) uint8."""
    if isinstance(value, RenderResult):
        if value.color is None:
            raise ValueError(f"{name}: the render has no colour image (render with outputs=('color', ...))")
        value = value.color
    if isinstance(value, (str, bytes, int, float)) or value is None:
        raise TypeError(f"{name}: expected a RenderResult or an image array, got {type(value).__name__}")
    try:
        arr = np.asarray(value)
    except (ValueError, TypeError) as exc:
        raise TypeError(f"{name}: cannot be read as an image array ({exc})") from None
    if arr.dtype.kind not in "biuf":
        raise TypeError(f"{name}: expected an image of uint8 levels or floats in [0, 1], got dtype {arr.dtype}")
    if arr.ndim == 2:
        arr = arr[:, :, None]
    if arr.ndim != 3 or not 1 <= arr.shape[2] <= 4 or arr.shape[0] == 0 or arr.shape[1] == 0:
        raise ValueError(f"{name}: an image is (H, W) or (H, W, C) with C in 1..4 channels, got shape {np.shape(value)}")
    if arr.dtype.kind == "b":
        return arr.astype(np.uint8) * np.uint8(255)
    if arr.dtype.kind == "f":
        if not np.isfinite(arr).all() or arr.min() < 0 or arr.max() > 1:
            raise ValueError(f"{name}: a float image must hold finite values in [0, 1] (scale other buffers first)")
        return np.round(arr.astype(np.float64) * 255.0).astype(np.uint8)
    if arr.dtype != np.uint8 and (arr.min() < 0 or arr.max() > 255):
        raise ValueError(f"{name}: an integer image must hold 8-bit levels in [0, 255]")
    return arr.astype(np.uint8)


def _levels(name: str, value: Any) -> int:
    if isinstance(value, (bool, np.bool_)) or not isinstance(value, (int, np.integer)):
        raise TypeError(f"{name}: expected an int number of 8-bit levels, got {type(value).__name__}")
    if not 0 <= int(value) <= 255:
        raise ValueError(f"{name}: must be in [0, 255] 8-bit levels, got {value}")
    return int(value)


def _image_pair(actual: Any, expected: Any) -> Tuple[np.ndarray, np.ndarray]:
    a, e = _image("actual", actual), _image("expected", expected)
    if a.shape[:2] != e.shape[:2]:
        raise AssertionError(f"images differ in size: actual {a.shape[1]}x{a.shape[0]}, expected {e.shape[1]}x{e.shape[0]}")
    if a.shape[2] != e.shape[2]:
        raise AssertionError(f"images differ in channels: actual has {a.shape[2]}, expected {e.shape[2]}")
    return a, e


def _compare_images(a: np.ndarray, e: np.ndarray, levels: int) -> Tuple[ImageDifference, np.ndarray]:
    diff = np.abs(a.astype(np.int16) - e.astype(np.int16)).max(axis=2)
    y, x = np.unravel_index(int(np.argmax(diff)), diff.shape)
    count = int((diff > levels).sum())
    return ImageDifference(count / diff.size, int(diff[y, x]), (int(x), int(y)), count, levels), diff


def image_difference(actual: Any, expected: Any, *, levels: int = IMAGE_LEVELS) -> ImageDifference:
    """How two images of the same size differ, in 8-bit levels.

    Args:
        actual: a :class:`toonmesh.RenderResult` (its ``color``, sRGB) or an image array:
            (H, W) or (H, W, C) with C in 1..4 channels, of uint8 levels, other integers in
            [0, 255], bools (0 or 255) or floats in [0, 1] (255 levels, rounded).
        expected: an image as ``actual``, of the same size.
        levels: int in [0, 255], default :data:`IMAGE_LEVELS` (8): a pixel counts as
            differing when one of its channels differs by more.

    Returns:
        :class:`ImageDifference`.

    Raises:
        AssertionError: the images differ in size or channel count (no pixel compares).
        TypeError, ValueError: a bad argument, naming it.
    """
    __tracebackhide__ = True  # pytest shows the caller's line
    levels = _levels("levels", levels)
    a, e = _image_pair(actual, expected)
    return _compare_images(a, e, levels)[0]


def _share(name: str, value: Any) -> float:
    return number(name, value, 0.0, 1.0)


def assert_images_close(
    actual: Any, expected: Any, *, levels: int = IMAGE_LEVELS, share: float = IMAGE_SHARE
) -> ImageDifference:
    """Asserts that two images are the same but for a few pixels: at most ``share`` of the
    pixels may differ by more than ``levels`` 8-bit levels in a channel.

    The defaults (8 levels, 0.1% of the pixels) pass between toonmesh's Vulkan and GL backends
    rendering the same scene (docs/testing.md has the measurements); ``levels=0, share=0``
    asks for the same bits.

    Args:
        actual: as in :func:`image_difference` (a render or an image array).
        expected: as in :func:`image_difference`.
        levels: int in [0, 255], default :data:`IMAGE_LEVELS`.
        share: float in [0, 1], default :data:`IMAGE_SHARE` (0.001).

    Returns:
        :class:`ImageDifference` of the two (when they are close).

    Raises:
        AssertionError: they differ: how many pixels and what share differ by more than
            ``levels``, the largest difference and where.
        TypeError, ValueError: a bad argument, naming it.
    """
    __tracebackhide__ = True  # pytest shows the caller's line
    levels = _levels("levels", levels)
    share = _share("share", share)
    d = image_difference(actual, expected, levels=levels)
    if d.share > share:
        raise AssertionError(f"images differ: {_image_summary(d)} (allowed: {share:.3%})")
    return d


def _image_summary(d: ImageDifference) -> str:
    return (f"{d.share:.3%} of the pixels ({d.differing}) differ by more than {d.levels} levels; the largest "
            f"difference is {d.largest} levels, at x={d.at[0]}, y={d.at[1]}")


def _difference_image(a: np.ndarray, e: np.ndarray, diff: np.ndarray, levels: int) -> np.ndarray:
    """An RGBA picture of where two images differ: the expected image faded to light grey,
    pixels within the tolerance but not equal in yellow, those beyond it in red."""
    rgb = e[:, :, :3] if e.shape[2] >= 3 else np.repeat(e[:, :, :1], 3, axis=2)
    grey = rgb.astype(np.float64).mean(axis=2)
    if e.shape[2] in (2, 4):  # on white where transparent
        alpha = e[:, :, -1].astype(np.float64) / 255.0
        grey = grey * alpha + 255.0 * (1.0 - alpha)
    faded = (255.0 - (255.0 - grey) * 0.25).astype(np.uint8)
    out = np.stack([faded, faded, faded, np.full_like(faded, 255)], axis=2)
    out[(diff > 0) & (diff <= levels)] = (255, 200, 0, 255)
    out[diff > levels] = (255, 0, 0, 255)
    return out


# ------------------------------------------------------------------------------------------------
# Line drawings


class DrawingDifference(NamedTuple):
    """How two line drawings differ as geometry (:func:`drawing_difference`).

    Attributes:
        share: the share of the two drawings' line length (0 to 1) that lies farther than
            ``pixels`` from the other drawing's lines of the same kind.
        largest: the largest such distance between lines of a kind both drawings have, in
            pixels (to within 1/8 pixel).
        at: ``(x, y)`` pixel coordinates of the point at that distance ((0, 0) when no
            point is farther than 0).
        kind: the kind (SVG group id) of the line it is on.
        styles: how the kinds' styles (stroke colour and width, fill) differ, one sentence each.
        only: the kinds of line only one drawing has, one sentence each (their whole length
            counts in ``share``).
        pixels: the tolerance the share was counted with.
    """

    share: float
    largest: float
    at: Tuple[float, float]
    kind: str
    styles: List[str]
    only: List[str]
    pixels: float


def _svg_text(name: str, value: Any) -> str:
    """The SVG document of a drawing argument."""
    if isinstance(value, RenderResult):
        if value.lines is None:
            raise ValueError(f"{name}: the render has no lines (render with outputs=(..., 'lines') and outlines)")
        return value.svg()
    if isinstance(value, str):
        if not value.lstrip().startswith("<"):
            raise ValueError(f"{name}: a string that is not an SVG document")
        return value
    if isinstance(value, (list, tuple)):
        lines = []
        for i, line in enumerate(value):
            p = _real_array(f"{name}[{i}]", line, "a (K, 2) array of pixel coordinates")
            if p.ndim != 2 or p.shape[1] != 2 or len(p) == 0:
                raise ValueError(f"{name}[{i}]: a line is a (K, 2) array of pixel coordinates with K >= 1, got shape {p.shape}")
            if not np.isfinite(p).all():
                raise ValueError(f"{name}[{i}]: pixel coordinates must be finite")
            lines.append(p.astype(np.float64))
        top = max((float(p.max()) for p in lines), default=0.0)
        size = int(math.ceil(max(top, 0.0))) + 1
        group: Any = ("lines", "#000000", 1.0, None, [(p, None) for p in lines])  # widths: None, one per kind
        return _strokes.svg_document(size, size, [group])
    raise TypeError(f"{name}: expected a RenderResult with lines, an SVG document (str) or a list of (K, 2) "
                    f"arrays, got {type(value).__name__}")


def _drawing(name: str, value: Any) -> _drawings.Drawing:
    return _drawings.parse_svg(_svg_text(name, value), name)


def _pixels(name: str, value: Any) -> float:
    return number(name, value, 0.0, 1e6)


def _compare_drawings(a: _drawings.Drawing, e: _drawings.Drawing, pixels: float) -> Tuple[DrawingDifference, np.ndarray]:
    c = _drawings.compare(a, e, pixels)
    return DrawingDifference(c.share, c.largest, c.at, c.kind, c.styles, c.only, pixels), c.differing


def drawing_difference(actual: Any, expected: Any, *, pixels: float = LINE_PIXELS) -> DrawingDifference:
    """How two line drawings differ as geometry: each stroke's distance to the other drawing's
    strokes of the same kind, in pixels, so that the numbers' float noise, how the lines are
    split into strokes and in which order they are drawn do not count.

    Args:
        actual: a :class:`toonmesh.RenderResult` rendered with the ``lines`` output (its
            :meth:`~toonmesh.RenderResult.svg`), an SVG document (str: polylines, polygons,
            lines and paths, one group per kind), or a list of (K, 2) arrays of pixel
            coordinates (one kind).
        expected: a drawing as ``actual``.
        pixels: float in [0, 1e6], default :data:`LINE_PIXELS` (1.0): a point counts as
            differing when it lies farther than this from the other drawing.

    Returns:
        :class:`DrawingDifference`.

    Raises:
        TypeError, ValueError: a bad argument, naming it.
    """
    __tracebackhide__ = True  # pytest shows the caller's line
    pixels = _pixels("pixels", pixels)
    return _compare_drawings(_drawing("actual", actual), _drawing("expected", expected), pixels)[0]


def assert_drawings_close(
    actual: Any, expected: Any, *, pixels: float = LINE_PIXELS, share: float = LINE_SHARE
) -> DrawingDifference:
    """Asserts that two line drawings are the same as geometry: at most ``share`` of their line
    length may lie farther than ``pixels`` from the other's lines of the same kind, and each
    kind's style (colour, width) must be the same.

    Args:
        actual: as in :func:`drawing_difference`.
        expected: as in :func:`drawing_difference`.
        pixels: float in [0, 1e6], default :data:`LINE_PIXELS` (1.0 pixel).
        share: float in [0, 1], default :data:`LINE_SHARE` (0.005).

    Returns:
        :class:`DrawingDifference` of the two (when they are close).

    Raises:
        AssertionError: they differ: the share of line length and the largest distance, and
            where, or the style that changed.
        TypeError, ValueError: a bad argument, naming it.
    """
    __tracebackhide__ = True  # pytest shows the caller's line
    pixels = _pixels("pixels", pixels)
    share = _share("share", share)
    d = drawing_difference(actual, expected, pixels=pixels)
    problem = _drawing_problem(d, share)
    if problem:
        raise AssertionError(f"drawings differ: {problem}")
    return d


def _drawing_problem(d: DrawingDifference, share: float) -> str:
    if d.styles:
        return "; ".join(d.styles)
    if d.share > share:
        return (f"{d.share:.3%} of the line length lies farther than {d.pixels:g} px from the other drawing (allowed: "
                f"{share:.3%}); the largest distance is {d.largest:.3g} px, at x={d.at[0]:.1f}, y={d.at[1]:.1f} on the "
                f"{d.kind or 'ungrouped'} lines" + "".join(f"; {s}" for s in d.only))
    return ""


def _difference_svg(actual: _drawings.Drawing, expected: _drawings.Drawing, differing: np.ndarray) -> str:
    """An SVG of two drawings over each other: the reference in light grey, the actual drawing
    in blue, and the points farther than the tolerance from the other as red dots."""
    def polylines(d: _drawings.Drawing) -> List[Tuple[np.ndarray, None]]:
        return [(s, None) for g in d.groups.values() for s in g.strokes]

    w = int(math.ceil(max(actual.width, expected.width, 1.0)))
    h = int(math.ceil(max(actual.height, expected.height, 1.0)))
    dots = [(np.vstack([p, p]), None) for p in differing[:: max(1, len(differing) // 5000)]]
    groups: List[Any] = [  # centre lines: no widths per point
        ("expected", "#b4b4b4", 2.0, None, polylines(expected)),
        ("actual", "#2060d0", 1.0, None, polylines(actual)),
        ("differing", "#ff0000", 2.5, None, dots),
    ]
    return _strokes.svg_document(w, h, groups)


# ------------------------------------------------------------------------------------------------
# Snapshots


_SAFE = re.compile(r"[^A-Za-z0-9_.\-\[\]=+,]")


def _stem(name: str) -> str:
    """A test's name as a file name: characters other than letters, digits and ``_.-[]=+,``
    become ``_``; at most 150 characters."""
    return _SAFE.sub("_", name)[:150] or "_"


class Snapshot:
    """References kept beside a test, compared with what the test makes now: what the
    ``toon_snapshot`` fixture gives a test (see :mod:`toonmesh.pytest_plugin` and
    docs/testing.md).

    ``snapshot(value)`` compares ``value`` with the reference ``<directory>/<test name>.png``
    (an image) or ``.svg`` (a line drawing); a second call in the same test uses
    ``<test name>-2``, and so on, unless given a ``name``. When they differ beyond the
    tolerances it writes ``<stem>.actual.png`` and ``<stem>.diff.png`` (or ``.svg``) beside the
    reference and raises AssertionError naming the reference, the share that differs and the
    largest difference; when they match it removes such files left by an earlier failure.
    With ``update`` a missing or differing reference is written instead and the call passes (a
    reference that still matches is left as it is, so its bytes do not churn).

    Args:
        directory: the folder of the references (str or os.PathLike; made when first needed).
        test_name: the stem of the references' file names (the test's name, its parameters
            included); characters other than letters, digits and ``_.-[]=+,`` become ``_``.
        update: bool, default False: write missing and differing references.
        written: a list the paths of written references are appended to (default: none), for
            a report at the end of the run.
    """

    def __init__(self, directory: Union[str, "os.PathLike[str]"], test_name: str, *, update: bool = False,
                 written: Optional[List[Path]] = None):
        if not isinstance(directory, (str, os.PathLike)):
            raise TypeError(f"directory: expected a folder path, got {type(directory).__name__}")
        if not isinstance(test_name, str):
            raise TypeError(f"test_name: expected a str, got {type(test_name).__name__}")
        if not test_name:
            raise ValueError("test_name: must not be empty")
        if not isinstance(update, (bool, np.bool_)):
            raise TypeError(f"update: expected True or False, got {type(update).__name__}")
        if written is not None and not isinstance(written, list):
            raise TypeError(f"written: expected a list or None, got {type(written).__name__}")
        self.directory = Path(directory)
        self.test_name = test_name
        self.update = bool(update)
        self.written = written if written is not None else []
        self._calls = 0

    def __call__(
        self,
        value: Any,
        name: Optional[str] = None,
        *,
        kind: str = "auto",
        levels: int = IMAGE_LEVELS,
        pixels: float = LINE_PIXELS,
        share: Optional[float] = None,
    ) -> Path:
        """Compares ``value`` with its reference (see the class); returns the reference's path.

        Args:
            value: an image (a :class:`toonmesh.RenderResult` with a colour image, or an image
                array as :func:`image_difference` takes) or a line drawing (a render's lines,
                an SVG document, a list of (K, 2) pixel coordinate arrays).
            name: the reference's file stem instead of the test's name (say to share one
                reference between the backends a test is parametrized over). Default None.
            kind: "auto" (default: a render's colour image when it has one, else its lines; an
                SVG document or a list of lines is a drawing; an array an image), "image" or
                "drawing" (a render's lines even when it has a colour image).
            levels: int in [0, 255], default :data:`IMAGE_LEVELS`: images, per pixel.
            pixels: float in [0, 1e6], default :data:`LINE_PIXELS`: drawings, per point.
            share: float in [0, 1] or None (default: :data:`IMAGE_SHARE` for an image,
                :data:`LINE_SHARE` for a drawing): the share of pixels, or of line length,
                that may differ.
        """
        __tracebackhide__ = True
        if not isinstance(kind, str):
            raise TypeError(f"kind: expected 'auto', 'image' or 'drawing', got {type(kind).__name__}")
        if kind not in ("auto", "image", "drawing"):
            raise ValueError(f"kind: must be 'auto', 'image' or 'drawing', got {kind!r:.40}")
        if name is not None and not isinstance(name, str):
            raise TypeError(f"name: expected a str or None, got {type(name).__name__}")
        if name == "":
            raise ValueError("name: must not be empty")
        levels = _levels("levels", levels)
        pixels = _pixels("pixels", pixels)
        if share is not None:
            share = _share("share", share)
        if kind == "auto":
            drawing = isinstance(value, (str, list, tuple)) or (
                isinstance(value, RenderResult) and value.color is None and value.lines is not None)
            kind = "drawing" if drawing else "image"
        self._calls += 1
        stem = _stem(name) if name is not None else _stem(self.test_name + ("" if self._calls == 1 else f"-{self._calls}"))
        if kind == "image":
            return self._image(value, stem, levels, IMAGE_SHARE if share is None else share)
        return self._drawing(value, stem, pixels, LINE_SHARE if share is None else share)

    def _paths(self, stem: str, ext: str) -> Tuple[Path, Path, Path]:
        d = self.directory
        return d / f"{stem}{ext}", d / f"{stem}.actual{ext}", d / f"{stem}.diff{ext}"

    def _write(self, path: Path, data: bytes) -> None:
        path.parent.mkdir(parents=True, exist_ok=True)
        path.write_bytes(data)

    def _passed(self, reference: Path, actual: Path, diff: Path, data: Optional[bytes]) -> Path:
        """Clears what an earlier failure left; with ``data``, writes the reference."""
        for stale in (actual, diff):
            if stale.exists():
                stale.unlink()
        if data is not None:
            self._write(reference, data)
            self.written.append(reference)
        return reference

    def _missing(self, reference: Path, actual: Path, data: bytes) -> None:
        __tracebackhide__ = True
        self._write(actual, data)
        raise AssertionError(f"no reference {reference}: run pytest --toon-update to write it (what it would hold: {actual})")

    def _image(self, value: Any, stem: str, levels: int, share: float) -> Path:
        __tracebackhide__ = True
        image = _image("value", value)
        reference, actual, diff = self._paths(stem, ".png")
        data = _png.encode(image)
        if not reference.exists():
            if self.update:
                return self._passed(reference, actual, diff, data)
            self._missing(reference, actual, data)
        expected = _png.decode(reference.read_bytes(), str(reference))
        if expected.shape != image.shape:
            problem = (f"the image is {image.shape[1]}x{image.shape[0]} with {image.shape[2]} channels, the reference "
                       f"{expected.shape[1]}x{expected.shape[0]} with {expected.shape[2]}")
            picture = None
        else:
            d, per_pixel = _compare_images(image, expected, levels)
            if d.share <= share:
                return self._passed(reference, actual, diff, None)
            problem = f"{_image_summary(d)} (allowed: {share:.3%})"
            picture = _difference_image(image, expected, per_pixel, levels)
        if self.update:
            return self._passed(reference, actual, diff, data)
        self._write(actual, data)
        written = f"wrote {actual}"
        if picture is not None:
            self._write(diff, _png.encode(picture))
            written += f" and {diff.name} (red: beyond the tolerance, yellow: within it)"
        raise AssertionError(f"{reference} differs: {problem}; {written}. If the change is meant: pytest --toon-update")

    def _drawing(self, value: Any, stem: str, pixels: float, share: float) -> Path:
        __tracebackhide__ = True
        text = _svg_text("value", value)
        drawing = _drawings.parse_svg(text, "value")
        reference, actual, diff = self._paths(stem, ".svg")
        data = text.encode("utf-8")
        if not reference.exists():
            if self.update:
                return self._passed(reference, actual, diff, data)
            self._missing(reference, actual, data)
        expected = _drawings.parse_svg(reference.read_text(encoding="utf-8"), str(reference))
        d, differing = _compare_drawings(drawing, expected, pixels)
        problem = _drawing_problem(d, share)
        if not problem:
            return self._passed(reference, actual, diff, None)
        if self.update:
            return self._passed(reference, actual, diff, data)
        self._write(actual, data)
        self._write(diff, _difference_svg(drawing, expected, differing).encode("utf-8"))
        raise AssertionError(f"{reference} differs: {problem}; wrote {actual} and {diff.name} (grey: the reference, "
                             f"blue: now, red: farther than {pixels:g} px). If the change is meant: pytest --toon-update")


# ------------------------------------------------------------------------------------------------
# Cross-checks against the peers


_SMOOTHING = ("laplacian", "taubin", "hc", "implicit")


def _method(method: Any, valid: Tuple[str, ...], peer: str) -> str:
    if not isinstance(method, str):
        raise TypeError(f"method: expected one of {', '.join(map(repr, valid))}, got {type(method).__name__}")
    if method not in valid:
        if method in _SMOOTHING:
            raise ValueError(f"method: {peer} has no {method} smoothing to compare with (it has {', '.join(valid)})")
        raise ValueError(f"method: must be one of {', '.join(map(repr, valid))}, got {method!r:.40}")
    return method


def _ours(method: str, vertices: Any, faces: Any, preset: str, options: Dict[str, Any]) -> Tuple[np.ndarray, np.ndarray, np.ndarray]:
    """toonmesh's result under the peer's preset (which checks every option, naming it), and
    the input as float64 positions and int64 faces for the peer."""
    if "preset" in options:
        raise TypeError(f"preset: the comparison sets preset={preset!r} itself")
    if options.get("weld"):
        raise ValueError("weld: the peer smooths the mesh as given; weld it first and compare the welded mesh")
    ours = getattr(smooth, method)(vertices, faces, preset=preset, **options)
    V, F = (vertices.vertices, vertices.faces) if faces is None else (vertices, faces)
    return np.asarray(ours), np.array(V, dtype=np.float64), np.array(F, dtype=np.int64)


def _pinned_indices(pinned: Any, n: int) -> np.ndarray:
    p = np.asarray(pinned)
    return np.nonzero(p)[0] if p.dtype == bool else p.astype(np.int64).ravel()


def smoothing_vs_trimesh(vertices: Any, faces: Any = None, method: str = "laplacian", **options: Any) -> MeshDifference:
    """Smooths a mesh with toonmesh (``preset="trimesh"``) and with trimesh, and measures how
    far apart the results are.

    ``method`` and trimesh's filter: "laplacian" (``filter_laplacian``), "implicit"
    (``filter_laplacian(implicit_time_integration=True)``, ``step`` as its ``lamb``), "taubin"
    (``filter_taubin``, ``mu`` as ``-nu``) and "hc" (``filter_humphrey``). ``options`` are the
    toonmesh function's keywords (``iterations``, ``lamb``, ``mu``, ``alpha``, ``beta``,
    ``step``, ``weights`` "uniform" or "distance", ``pinned``, ``volume_constraint``; ``tol``
    and ``max_iter`` are toonmesh's alone), each given to trimesh as its counterpart; one left
    out takes both libraries' default, which the preset makes the same. trimesh raises on a
    mesh whose unreferenced vertices come after the largest face index.

    Args:
        vertices: (N, 3) float32 or float64 positions, or a ``trimesh.Trimesh`` (then leave
            ``faces`` out); never modified.
        faces: (M, 3) integer vertex indices.
        method: "laplacian" (default), "implicit", "taubin" or "hc".
        **options: as above; checked by toonmesh, which names a bad one.

    Returns:
        :class:`MeshDifference` of toonmesh's result against trimesh's, relative to the
        trimesh result's bounding-box diagonal; agreeing libraries give about 1e-12 (float64).

    Raises:
        TypeError, ValueError, IndexError: a bad argument, naming it (before trimesh is
            needed).
        PeerMissingError: trimesh is not installed, outside pytest or where ``CI=true``
            (under pytest otherwise the test is skipped).
    """
    method = _method(method, _SMOOTHING, "trimesh")
    ours, V, F = _ours(method, vertices, faces, "trimesh", options)
    trimesh = need_peer("trimesh", "toonmesh.testing.smoothing_vs_trimesh")
    mesh = trimesh.Trimesh(V, F, process=False)
    kw: Dict[str, Any] = {}
    weights, pinned = options.get("weights"), options.get("pinned")
    if weights is not None or pinned is not None:
        op: Dict[str, Any] = {"equal_weight": str(weights).lower() != "distance"}
        if pinned is not None:
            op["pinned_vertices"] = _pinned_indices(pinned, len(V))
        kw["laplacian_operator"] = trimesh.smoothing.laplacian_calculation(mesh, **op)
    given = {k: v for k, v in options.items() if v is not None}
    names = {"iterations": "iterations", "lamb": "lamb", "alpha": "alpha", "beta": "beta",
             "volume_constraint": "volume_constraint", "step": "lamb"}
    kw.update({names[k]: v for k, v in given.items() if k in names})
    if "mu" in given:
        kw["nu"] = -given["mu"]
    if method in ("laplacian", "implicit"):
        trimesh.smoothing.filter_laplacian(mesh, implicit_time_integration=method == "implicit", **kw)
    elif method == "taubin":
        trimesh.smoothing.filter_taubin(mesh, **kw)
    else:
        trimesh.smoothing.filter_humphrey(mesh, **kw)
    return _differences(ours.astype(np.float64), np.asarray(mesh.vertices, np.float64))


def smoothing_vs_pymeshlab(vertices: Any, faces: Any = None, method: str = "laplacian", **options: Any) -> MeshDifference:
    """Smooths a mesh with toonmesh (``preset="pymeshlab"``) and with pymeshlab, and measures
    how far apart the results are.

    ``method`` and pymeshlab's filter: "laplacian" (``apply_coord_laplacian_smoothing``:
    ``iterations`` as ``stepsmoothnum``, ``weights`` "cotangent" or "uniform" as
    ``cotangentweight``, ``boundary`` "slide" or "free" as ``boundary``), "taubin"
    (``apply_coord_taubin_smoothing``: ``lamb``, ``mu``, ``iterations``) and "hc"
    (``apply_coord_hc_laplacian_smoothing``, called ``iterations`` times). An option left out
    takes both libraries' default, which the preset makes the same. pymeshlab's filters have
    no pinned vertices, so ``pinned`` is refused.

    Args:
        vertices: (N, 3) float32 or float64 positions, or a ``trimesh.Trimesh`` (then leave
            ``faces`` out); never modified.
        faces: (M, 3) integer vertex indices.
        method: "laplacian" (default), "taubin" or "hc".
        **options: the toonmesh function's keywords, as above; checked by toonmesh, which
            names a bad one.

    Returns:
        :class:`MeshDifference` of toonmesh's result against pymeshlab's, relative to the
        pymeshlab result's bounding-box diagonal; agreeing libraries give about 1e-12.

    Raises:
        TypeError, ValueError, IndexError: a bad argument, naming it (before pymeshlab is
            needed).
        PeerMissingError: pymeshlab is not installed, outside pytest or where ``CI=true``.
    """
    method = _method(method, ("laplacian", "taubin", "hc"), "pymeshlab")
    if options.get("pinned") is not None:
        raise ValueError("pinned: pymeshlab's smoothing filters have no pinned vertices")
    ours, V, F = _ours(method, vertices, faces, "pymeshlab", options)
    pymeshlab = need_peer("pymeshlab", "toonmesh.testing.smoothing_vs_pymeshlab")
    ms = pymeshlab.MeshSet()
    ms.add_mesh(pymeshlab.Mesh(V, F))
    given = {k: v for k, v in options.items() if v is not None}
    if method == "laplacian":
        kw: Dict[str, Any] = {}
        if "iterations" in given:
            kw["stepsmoothnum"] = given["iterations"]
        if "weights" in given:
            kw["cotangentweight"] = given["weights"].lower() == "cotangent"
        if "boundary" in given:
            kw["boundary"] = given["boundary"].lower() == "slide"
        ms.apply_coord_laplacian_smoothing(**kw)
    elif method == "taubin":
        names = {"lamb": "lambda_", "mu": "mu", "iterations": "stepsmoothnum"}
        ms.apply_coord_taubin_smoothing(**{names[k]: v for k, v in given.items() if k in names})
    else:
        for _ in range(int(given.get("iterations", 1))):
            ms.apply_coord_hc_laplacian_smoothing()
    return _differences(ours.astype(np.float64), np.asarray(ms.current_mesh().vertex_matrix(), np.float64))


class CurvatureAgreement(NamedTuple):
    """How toonmesh's curvature agrees with a peer's (:func:`curvature_vs_libigl`); all three
    are 1 for the same numbers. Unitless.

    Attributes:
        mean_correlation: Pearson correlation of the two mean curvatures over the vertices.
        k1_correlation: the same for the larger principal curvature.
        sign_agreement: the share of the vertices where the peer's mean curvature is clearly
            non-zero (its magnitude above the median) on which the two signs agree.
    """

    mean_correlation: float
    k1_correlation: float
    sign_agreement: float


def curvature_vs_libigl(
    vertices: Any, faces: Any = None, *, radius: int = 2, smoothing: float = 0.0
) -> CurvatureAgreement:
    """Principal curvatures from :func:`toonmesh.edges.curvature` and from libigl's
    ``principal_curvature`` (quadric fitting over a ``radius``-ring) on the same mesh, compared
    (the two estimators differ, so agreement is a correlation, not equality: on scanned meshes
    such as the bunny both correlations are above 0.9 and the signs agree on 95%).

    Args:
        vertices: (N, 3) float32 or float64 positions, or a ``trimesh.Trimesh`` (then leave
            ``faces`` out); never modified.
        faces: (M, 3) integer vertex indices.
        radius: int in [1, 10], default 2: libigl's neighbourhood, in rings.
        smoothing: float >= 0, default 0: toonmesh's ``smoothing`` (mean edge lengths).

    Returns:
        :class:`CurvatureAgreement` (a correlation is nan where either curvature is constant,
        as on a sphere).

    Raises:
        TypeError, ValueError, IndexError: a bad argument, naming it (before libigl is needed).
        PeerMissingError: libigl (``igl``) is not installed, outside pytest or where ``CI=true``.
    """
    if isinstance(radius, (bool, np.bool_)) or not isinstance(radius, (int, np.integer)):
        raise TypeError(f"radius: expected an int number of rings, got {type(radius).__name__}")
    if not 1 <= int(radius) <= 10:
        raise ValueError(f"radius: must be in [1, 10] rings, got {radius}")
    c = edges.curvature(vertices, faces, smoothing=smoothing)
    V, F = (vertices.vertices, vertices.faces) if faces is None else (vertices, faces)
    igl = need_peer("igl", "toonmesh.testing.curvature_vs_libigl")
    _, _, kmax, kmin, _ = igl.principal_curvature(np.array(V, np.float64), np.array(F, np.int64), radius=int(radius))
    k1, k2 = np.maximum(kmax, kmin), np.minimum(kmax, kmin)
    mean = 0.5 * (k1 + k2)
    with np.errstate(invalid="ignore", divide="ignore"):
        mean_corr = float(np.corrcoef(c.mean, mean)[0, 1])
        k1_corr = float(np.corrcoef(c.k1, k1)[0, 1])
    clear = np.abs(mean) > np.percentile(np.abs(mean), 50)
    signs = float(np.mean(np.sign(c.mean[clear]) == np.sign(mean[clear]))) if clear.any() else 1.0
    return CurvatureAgreement(mean_corr, k1_corr, signs)


class SobelDifference(NamedTuple):
    """toonmesh's Sobel filter against scikit-image's (:func:`sobel_vs_skimage`).

    Attributes:
        largest: the largest absolute difference of any pixel, in the image's units (a unit
            step gives 0.7071 in both); non-finite values count as the same where both have
            the same, as inf where only one has one.
        dtype: the dtype of toonmesh's result.
        peer_dtype: the dtype of scikit-image's (the same: toonmesh follows its rules).
    """

    largest: float
    dtype: np.dtype
    peer_dtype: np.dtype


def sobel_vs_skimage(image: Any, mask: Any = None, *, which: str = "sobel") -> SobelDifference:
    """A Sobel filter from :mod:`toonmesh.edges` and from ``skimage.filters`` on the same image,
    compared. A multi-channel image is filtered channel by channel in toonmesh; it is compared
    with scikit-image's filter of each channel.

    Args:
        image: (H, W) or (H, W, C) image of a real or bool dtype (as
            :func:`toonmesh.edges.sobel` takes); never modified.
        mask: (H, W) bool array or None (default): where the gradient is computed, as
            scikit-image's ``mask``.
        which: "sobel" (default: the magnitude), "sobel_h" or "sobel_v".

    Returns:
        :class:`SobelDifference`: about 1e-7 for float32 images, 1e-16 for float64.

    Raises:
        AssertionError: the two results differ in shape (nothing to compare).
        TypeError, ValueError: a bad argument, naming it (before scikit-image is needed).
        PeerMissingError: scikit-image is not installed, outside pytest or where ``CI=true``.
    """
    valid = ("sobel", "sobel_h", "sobel_v")
    if not isinstance(which, str):
        raise TypeError(f"which: expected one of {', '.join(map(repr, valid))}, got {type(which).__name__}")
    if which not in valid:
        raise ValueError(f"which: must be one of {', '.join(map(repr, valid))}, got {which!r:.40}")
    ours = getattr(edges, which)(image, mask)
    need_peer("skimage", "toonmesh.testing.sobel_vs_skimage")
    from skimage import filters

    img = np.asarray(image)
    peer = getattr(filters, which)
    if img.ndim == 3:
        theirs = np.stack([peer(img[..., c], mask=mask) for c in range(img.shape[2])], axis=-1)
    else:
        theirs = peer(img, mask=mask)
    if ours.shape != theirs.shape:
        raise AssertionError(f"toonmesh's {which} is {ours.shape}, scikit-image's {theirs.shape}")
    a, b = ours.astype(np.float64), theirs.astype(np.float64)
    with np.errstate(invalid="ignore"):
        diff = np.abs(a - b)
    diff[(a == b) | (np.isnan(a) & np.isnan(b))] = 0.0  # the same inf or nan passed through
    diff[np.isnan(diff)] = np.inf
    return SobelDifference(float(np.max(diff, initial=0.0)), ours.dtype, theirs.dtype)


# ------------------------------------------------------------------------------------------------
# Lines over time

#: Ink within this many pixels of where a surface point went counts as the same ink
#: (:func:`temporal_popping`).
POPPING_PIXELS = 2.0
#: A pixel is ink where its outline coverage is at least this (:func:`temporal_popping`).
INK_COVERAGE = 0.5


class TemporalPopping(NamedTuple):
    """How much ink pops from frame to frame of a sequence (:func:`temporal_popping`).

    Attributes:
        share: popped ink pixels over counted ink pixels, all steps together (a fraction: 0.001
            is 0.1% per step).
        steps: (K - 1,) float64, each step's share (nan where the step counted no ink).
        counted: (K - 1,) int64, each step's ink pixels whose surface point the next frame sees.
        popped: (K - 1,) int64, those of them with no ink within ``pixels`` of where the point
            went.
        appearing: the same measure run backward (ink of each next frame with no ink near where
            its point was in the frame before): lines that pop in rather than out.
        where: K - 1 arrays, each (popped, 2) int64: the (row, column) of every popped ink pixel
            of a step, in the frame it leaves (to see where a drawing pops).
    """

    share: float
    steps: np.ndarray
    counted: np.ndarray
    popped: np.ndarray
    appearing: float
    where: List[np.ndarray]


def _popping_frame(i: int, frame: Any, ink: float) -> _temporal.Frame:
    where = f"frames[{i}]"
    if isinstance(frame, RenderResult):
        for name in ("outline", "depth"):
            if getattr(frame, name) is None:
                raise ValueError(f"{where}: has no {name!r} image; render with outputs including "
                                 "'outline' and 'depth'")
        coverage, depth, view, projection = frame.outline, frame.depth, frame.view_matrix, frame.projection
    elif isinstance(frame, (tuple, list)) and len(frame) == 4:
        coverage, depth, view, projection = frame
    else:
        raise TypeError(f"{where}: expected a toonmesh.RenderResult or a tuple (ink, depth, view_matrix, "
                        f"projection), got {type(frame).__name__}")
    coverage = np.asarray(coverage)
    depth = np.asarray(depth, dtype=np.float64)
    view = np.asarray(view, dtype=np.float64)
    projection = np.asarray(projection, dtype=np.float64)
    if coverage.ndim != 2 or depth.shape != coverage.shape:
        raise ValueError(f"{where}: ink and depth must be (H, W) images of one shape, got "
                         f"{coverage.shape} and {depth.shape}")
    for name, m in (("view_matrix", view), ("projection", projection)):
        if m.shape != (4, 4) or not np.isfinite(m).all():
            raise ValueError(f"{where}: {name} must be a finite 4x4 matrix, got shape {m.shape}")
        if not np.isfinite(np.linalg.cond(m)) or np.linalg.cond(m) > 1e12:
            raise ValueError(f"{where}: {name} must be invertible (a camera's matrix)")
    if np.isnan(depth).any():
        raise ValueError(f"{where}: depth has NaN (inf marks where no surface is)")
    ink_mask = coverage if coverage.dtype == bool else coverage.astype(np.float64) >= ink
    return _temporal.Frame(ink_mask, depth, view, projection)


def temporal_popping(frames: Any, *, pixels: float = POPPING_PIXELS, ink: float = INK_COVERAGE,
                     depth_tolerance: float = 0.01) -> TemporalPopping:
    """How much of a sequence's ink pops: the share of ink pixels that have no ink within
    ``pixels`` after exact reprojection into the next frame through the depth buffer.

    Each ink pixel of frame k is taken back to the surface point it was drawn on (its depth
    and frame k's camera), carried into frame k + 1's image by that frame's camera, and pops
    when frame k + 1 has no ink within ``pixels`` of where it lands. Only points that frame
    k + 1 sees are counted (in the image and not behind a nearer surface, within
    ``depth_tolerance``), so a line that turns behind the model has not popped; ink over the
    background (just outside a silhouette) takes the depth of the nearest surface within
    ``pixels``. The scene must hold still while the camera moves (a turntable, a fly-by).

    Args:
        frames: a sequence of K >= 2 frames in order: :class:`toonmesh.RenderResult` (a
            :class:`toonmesh.RenderStack` from ``render_many(..., outputs=("outline",
            "depth"))``, with its outline coverage as the ink), or tuples ``(ink, depth,
            view_matrix, projection)`` from another renderer: ink an (H, W) bool mask or
            coverage in [0, 1], depth (H, W) linear view depth in world units (inf where no
            surface is), the 4x4 world-to-view matrix (right-handed, looking down -z) and the
            4x4 projection to clip space with z in [0, 1]. Never modified.
        pixels: the distance, in pixels, within which ink counts as the same (default
            :data:`POPPING_PIXELS`, 2).
        ink: the coverage at and above which a pixel is ink (default :data:`INK_COVERAGE`, 0.5).
        depth_tolerance: how much farther than the surface a point may be and still be seen,
            relative to its depth (default 0.01).

    Returns:
        :class:`TemporalPopping` (``share`` is the figure: a fraction, per step).

    Raises:
        TypeError, ValueError: a bad argument, naming it (``frames[i]`` for one frame).
    """
    if isinstance(frames, (str, bytes)) or not isinstance(frames, Sequence):
        raise TypeError(f"frames: expected a sequence of frames, got {type(frames).__name__}")
    if len(frames) < 2:
        raise ValueError(f"frames: need at least 2 frames to compare, got {len(frames)}")
    pixels = number("pixels", pixels, 0.0, 64.0)
    ink = number("ink", ink, 0.0, 1.0, open_lo=True)
    depth_tolerance = number("depth_tolerance", depth_tolerance, 0.0, 1.0)
    seq = [_popping_frame(i, f, ink) for i, f in enumerate(frames)]
    forward = [_temporal.step(a, b, pixels, depth_tolerance) for a, b in zip(seq[:-1], seq[1:])]
    backward = [_temporal.step(b, a, pixels, depth_tolerance) for a, b in zip(seq[:-1], seq[1:])]
    counted = np.array([s.counted for s in forward], dtype=np.int64)
    popped = np.array([s.popped for s in forward], dtype=np.int64)
    with np.errstate(invalid="ignore", divide="ignore"):
        steps = np.where(counted > 0, popped / np.maximum(counted, 1), np.nan)

    def share(c: int, p: int) -> float:
        return p / c if c > 0 else 0.0

    return TemporalPopping(share(int(counted.sum()), int(popped.sum())), steps, counted, popped,
                           share(sum(s.counted for s in backward), sum(s.popped for s in backward)),
                           [s.where for s in forward])

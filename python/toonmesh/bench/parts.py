"""Noisy CAD parts for the feature-preserving smoothers' tests and benchmark, made in code.

Every part is a subdivided cube (a grid of ``n x n`` squares per side, two triangles each,
welded: ``12 n^2`` faces) mapped so that its creases stay on grid lines, hence sharp in the
clean mesh:

``box``
    The cube itself: twelve 90-degree creases and eight corners.
``fandisk``
    A house-like part: the top bent into a gable roof (a 143-degree ridge and 126-degree eaves
    next to 90-degree creases), creases of several angles as on the fandisk model.
``cylinder``
    A cylinder with flat caps (the cube's cross-section mapped onto a disc): a smoothly curved
    wall meeting two flat caps at circular 90-degree creases.

The harder parts (``HARD_PARTS``), with features that are small, weak or curved:

``grooved-sphere``
    A sphere (the cube projected onto it) cut by three V-grooves along its great circles
    ``x = 0``, ``y = 0`` and ``z = 0``, each ``2 GROOVE_WIDTH`` wide and ``GROOVE_DEPTH`` deep
    (of the radius): curved surfaces meeting at creases of about 45 degrees (the rims) and 100
    (the bottoms), three grid squares apart.
``dodecagon``
    A twelve-sided prism (the cube's cross-section mapped onto a regular dodecagon): flat sides
    meeting at weak 30-degree creases, which impulsive noise imitates, and 90-degree creases at
    the caps. Its grid has a multiple of 6 squares per side, so that the sides' creases lie on
    grid lines.

Noise is along the clean vertex normals, in units of the clean mesh's mean edge length:
``gaussian`` moves every vertex by ``level`` times a standard normal; ``impulsive`` moves a
random tenth of the vertices by ``level`` times a standard normal (and the rest not at all).
"""

from __future__ import annotations

from typing import Tuple

import numpy as np
import numpy.typing as npt

Mesh = Tuple[npt.NDArray[np.float64], npt.NDArray[np.int64]]

PARTS = ("box", "fandisk", "cylinder")
HARD_PARTS = ("grooved-sphere", "dodecagon")
#: The grooves' half-width, in the cube's coordinates (the sphere's radius is 1): three grid
#: squares at 20,000 faces.
GROOVE_WIDTH = 0.15
#: The grooves' depth, as a fraction of the radius.
GROOVE_DEPTH = 0.15
NOISES = ("gaussian", "impulsive")
IMPULSIVE_FRACTION = 0.1


def cube(n: int) -> Mesh:
    """The cube [-1, 1]^3 with ``n x n`` squares per side, welded, outward-oriented."""
    t = np.linspace(-1.0, 1.0, n + 1)
    u, v = np.meshgrid(t, t, indexing="ij")
    u, v = u.ravel(), v.ravel()
    one = np.ones_like(u)
    idx = np.arange((n + 1) ** 2).reshape(n + 1, n + 1)
    a, b, c, d = idx[:-1, :-1].ravel(), idx[1:, :-1].ravel(), idx[1:, 1:].ravel(), idx[:-1, 1:].ravel()
    quads = np.stack([np.stack([a, b, c], 1), np.stack([a, c, d], 1)], 1).reshape(-1, 3)
    verts, faces = [], []
    for axis in range(3):
        for sign in (-1.0, 1.0):
            p = np.empty((u.size, 3))
            p[:, axis] = sign * one
            p[:, (axis + 1) % 3] = u
            p[:, (axis + 2) % 3] = v
            f = quads if sign > 0 else quads[:, ::-1]
            faces.append(f + sum(len(x) for x in verts))
            verts.append(p)
    V = np.concatenate(verts)
    F = np.concatenate(faces)
    key = np.round(V * n).astype(np.int64)
    _, first, inverse = np.unique(key, axis=0, return_index=True, return_inverse=True)
    return V[first], inverse.ravel()[F].astype(np.int64)


def part(name: str, faces: int = 20000) -> Mesh:
    """The clean part ``name`` (one of PARTS or HARD_PARTS) with about ``faces`` faces (12 n^2
    for even n; n a multiple of 6 for the dodecagon). Lengths are in units of the part's size:
    every part fits in [-1.5, 1.5]^3."""
    step = 6 if name == "dodecagon" else 2
    n = max(step, int(round(np.sqrt(faces / 12.0) / step)) * step)
    V, F = cube(n)
    x, y, z = V[:, 0].copy(), V[:, 1].copy(), V[:, 2].copy()
    if name == "box":
        pass
    elif name == "fandisk":
        # Scaling the top half by a tent in x keeps every side planar and bends the top.
        top = z > 0
        z[top] = z[top] * (1.0 + 0.75 * (1.0 - np.abs(x[top])))
        y = 0.6 * y
    elif name == "cylinder":
        # The square's elliptical-grid map onto the disc sends its boundary onto the circle.
        x, y = x * np.sqrt(1.0 - y * y / 2.0), y * np.sqrt(1.0 - x * x / 2.0)
        z = 1.2 * z
    elif name == "grooved-sphere":
        # The radius is a tent in each cube coordinate, kinked on grid lines: sharp V-grooves.
        r = 1.0 - GROOVE_DEPTH * sum(np.maximum(0.0, 1.0 - np.abs(c) / GROOVE_WIDTH) for c in (x, y, z))
        scale = r / np.sqrt(x * x + y * y + z * z)
        x, y, z = x * scale, y * scale, z * scale
    elif name == "dodecagon":
        # Concentric squares onto concentric dodecagons: a third of each square side per side.
        s = np.maximum(np.abs(x), np.abs(y))
        safe = np.where(s > 0, s, 1.0)
        square_angle = np.arctan2(y, x)
        # Position along the square's boundary, in quarter turns from the corner at -45 degrees.
        bx, by = x / safe, y / safe
        side = np.floor(((square_angle + np.pi / 4) % (2 * np.pi)) / (np.pi / 2))
        along = np.choose(side.astype(int) % 4, [by, -bx, -by, bx])
        angle = -np.pi / 4 + side * np.pi / 2 + (along + 1.0) * np.pi / 4
        k = np.floor((angle + np.pi / 4) / (np.pi / 6) + 1e-9)
        a0 = -np.pi / 4 + k * np.pi / 6
        t = (angle - a0) / (np.pi / 6)
        p0 = np.stack([np.cos(a0), np.sin(a0)])
        p1 = np.stack([np.cos(a0 + np.pi / 6), np.sin(a0 + np.pi / 6)])
        q = (1 - t) * p0 + t * p1
        x, y = np.where(s > 0, s * q[0], 0.0), np.where(s > 0, s * q[1], 0.0)
        z = 1.2 * z
    else:
        raise ValueError(f"part: unknown part '{name}', expected one of {PARTS + HARD_PARTS}")
    return np.stack([x, y, z], 1), F


def face_normals(V: npt.NDArray[np.floating], F: npt.NDArray[np.integer]) -> npt.NDArray[np.float64]:
    V = np.asarray(V, np.float64)
    n = np.cross(V[F[:, 1]] - V[F[:, 0]], V[F[:, 2]] - V[F[:, 0]])
    return n / np.maximum(np.linalg.norm(n, axis=1, keepdims=True), 1e-300)


def mean_edge_length(V: npt.NDArray[np.floating], F: npt.NDArray[np.integer]) -> float:
    e = np.concatenate([V[F[:, 1]] - V[F[:, 0]], V[F[:, 2]] - V[F[:, 1]], V[F[:, 0]] - V[F[:, 2]]])
    return float(np.linalg.norm(e, axis=1).mean())


def noisy(V: npt.NDArray[np.float64], F: npt.NDArray[np.int64], level: float, kind: str = "gaussian",
          seed: int = 0) -> npt.NDArray[np.float64]:
    """``V`` with noise of ``level`` mean edge lengths along the vertex normals (see above)."""
    if kind not in NOISES:
        raise ValueError(f"kind: unknown noise '{kind}', expected one of {NOISES}")
    rng = np.random.default_rng(seed)
    fn = np.cross(V[F[:, 1]] - V[F[:, 0]], V[F[:, 2]] - V[F[:, 0]])
    vn = np.zeros_like(V)
    for k in range(3):
        np.add.at(vn, F[:, k], fn)
    vn /= np.maximum(np.linalg.norm(vn, axis=1, keepdims=True), 1e-300)
    amount = level * mean_edge_length(V, F) * rng.standard_normal(len(V))
    if kind == "impulsive":
        amount *= rng.random(len(V)) < IMPULSIVE_FRACTION
    return V + amount[:, None] * vn


def normal_error(V: npt.NDArray[np.floating], F: npt.NDArray[np.integer], clean: npt.NDArray[np.floating]) -> float:
    """Mean angle, in degrees, between the face normals of ``V`` and of ``clean``."""
    d = np.einsum("ij,ij->i", face_normals(V, F), face_normals(clean, F))
    return float(np.degrees(np.arccos(np.clip(d, -1.0, 1.0))).mean())

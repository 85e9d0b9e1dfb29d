"""The Utah teapot: Martin Newell's 32 bicubic Bezier patches (1975, public domain),
tessellated into a welded, outward-oriented triangle mesh (see :func:`toonmesh.shapes.teapot`)."""

from __future__ import annotations

import re
from pathlib import Path
from typing import Tuple

import numpy as np
import numpy.typing as npt

#: Newell's data: the control points, then the patches.
_DATA = Path(__file__).resolve().parents[1] / "data" / "teapot.txt"


def _data() -> Tuple[npt.NDArray[np.float64], npt.NDArray[np.int64]]:
    """The control points (x y z, z up) and each patch's 4 x 4 of them, as ``data/teapot.txt``
    lists them."""
    text = "\n".join(line for line in _DATA.read_text().splitlines() if not line.startswith("#"))
    _, points, patches = re.split(r"^(?:points|patches)$", text, flags=re.MULTILINE)
    return (
        np.array(points.replace(",", " ").split(), dtype=np.float64).reshape(-1, 3),
        np.array(patches.split(), dtype=np.int64).reshape(-1, 4, 4),
    )


def teapot_mesh(subdivisions: int) -> Tuple[npt.NDArray[np.float64], npt.NDArray[np.int64]]:
    """Each patch cut into ``subdivisions`` x ``subdivisions`` quads, two triangles each, its
    corners on the surface; points shared by patches welded; the triangles that collapse to a
    point (where a patch meets the lid's knob or the bottom's centre) left out."""
    points, patches = _data()
    points = points[:, [0, 2, 1]] * np.array([1.0, 1.0, -1.0])  # z up to y up (a rotation)
    n = subdivisions
    t = np.linspace(0.0, 1.0, n + 1)
    bernstein = np.stack([(1 - t) ** 3, 3 * t * (1 - t) ** 2, 3 * t**2 * (1 - t), t**3], axis=1)
    surface = np.einsum("ui,vj,pijc->puvc", bernstein, bernstein, points[patches])  # (32, n+1, n+1, 3)
    k, m = np.meshgrid(np.arange(n), np.arange(n), indexing="ij")
    a, b = k * (n + 1) + m, (k + 1) * (n + 1) + m
    quads = np.stack([a, a + 1, b + 1, b], axis=-1).reshape(-1, 4)  # counter-clockwise seen from outside
    quads = (quads[None] + (np.arange(len(patches)) * (n + 1) ** 2)[:, None, None]).reshape(-1, 4)
    faces = np.concatenate([quads[:, [0, 1, 2]], quads[:, [0, 2, 3]]])
    # Neighbouring patches evaluate their shared border from the same control points, so its
    # points agree to rounding: weld them on a 1e-9 grid.
    welded, index = np.unique(np.round(surface.reshape(-1, 3), 9), axis=0, return_inverse=True)
    faces = index.reshape(-1)[faces]
    keep = (faces[:, 0] != faces[:, 1]) & (faces[:, 1] != faces[:, 2]) & (faces[:, 2] != faces[:, 0])
    return welded + 0.0, faces[keep].astype(np.int64)

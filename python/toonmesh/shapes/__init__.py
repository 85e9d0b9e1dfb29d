"""Procedural test meshes, made in code so nothing large has to be stored.

Besides the icosphere and the grid, the test models of Kang, Kim and Yoon (2001), with their
face counts: :func:`torus` (the donut, 450 faces), :func:`pawn` (the chess piece, 480),
:func:`teapot` (Newell's teapot, 992 of its 1024 triangles; the rest are points) and
:func:`uv_sphere` (264), :func:`lathe`, which turns any profile into a surface of revolution, and
:func:`box`, an axis-aligned box between two corners.
Every model is closed and outward-oriented unless its docstring says otherwise, with y up.
"""

from __future__ import annotations

from typing import Tuple

import numpy as np
import numpy.typing as npt

from toonmesh import _core
from toonmesh.arguments._checks import integer, number
from toonmesh.shapes._teapot import teapot_mesh

__all__ = ["icosphere", "grid", "torus", "lathe", "pawn", "uv_sphere", "teapot", "box"]

Mesh = Tuple[npt.NDArray[np.float64], npt.NDArray[np.int64]]


def icosphere(subdivisions: int = 3, noise: float = 0.0, seed: int = 0) -> Mesh:
    """A unit icosphere, optionally with seeded radial noise.

    Args:
        subdivisions: int in [0, 10], default 3. Rounds of 1-to-4 triangle splitting: 10 * 4**s
            + 2 vertices (s=5: 10,242; s=7: 163,842; s=8: 655,362) and 20 * 4**s faces.
        noise: float >= 0, default 0.0. Each vertex's radius is multiplied by ``1 + noise * u``,
            u uniform in [-1, 1).
        seed: int, default 0. Seed of the noise; the same seed gives the same mesh on every
            platform.

    Returns:
        (V, F): (N, 3) float64 positions and (M, 3) int64 faces, outward-oriented, closed.

    Raises:
        TypeError: a non-integer ``subdivisions`` or ``seed`` or a non-number ``noise`` (bools
            and strings are refused).
        ValueError: values out of range (a seed is in [0, 2**64)).
    """
    return _core.icosphere(subdivisions, noise, seed)


def grid(n: int = 32, noise: float = 0.0, seed: int = 0) -> Mesh:
    """An open, flat ``n`` x ``n`` vertex grid on [0, 1]^2 with seeded noise in z.

    Args:
        n: int in [2, 4096], default 32. Vertices per side: n*n vertices and 2*(n-1)**2 faces.
        noise: float >= 0, default 0.0. z of each vertex is ``noise * u``, u uniform in [-1, 1).
        seed: int, default 0.

    Returns:
        (V, F): (N, 3) float64 positions and (M, 3) int64 faces.

    Raises:
        TypeError: as :func:`icosphere`.
        ValueError: as :func:`icosphere`.
    """
    return _core.grid(n, noise, seed)


def torus(major: float = 1.0, minor: float = 0.4, segments: int = 15, tube_segments: int = 15) -> Mesh:
    """A torus (a donut) about the y axis, centred on the origin: closed, outward-oriented.

    Args:
        major: float > 0, default 1.0. Distance from the axis to the centre of the tube.
        minor: float in (0, major), default 0.4. Radius of the tube.
        segments: int in [3, 4096], default 15. Steps around the axis.
        tube_segments: int in [3, 4096], default 15. Steps around the tube: ``segments *
            tube_segments`` vertices and ``2 * segments * tube_segments`` faces (the defaults
            give Kang et al.'s donut: 450).

    Returns:
        (V, F): (N, 3) float64 positions and (M, 3) int64 faces.

    Raises:
        TypeError: a non-number radius or a non-integer count.
        ValueError: values out of range.
    """
    R = number("major", major, 0.0, open_lo=True)
    r = number("minor", minor, 0.0, open_lo=True)
    if r >= R:
        raise ValueError(f"major, minor: the tube's radius (minor, {r:g}) must be smaller than major ({R:g})")
    n = integer("segments", segments, 3, 4096)
    m = integer("tube_segments", tube_segments, 3, 4096)
    u = np.linspace(0.0, 2 * np.pi, n, endpoint=False)[:, None]
    v = np.linspace(0.0, 2 * np.pi, m, endpoint=False)[None, :]
    ring = R + r * np.cos(v)
    V = np.stack(np.broadcast_arrays(ring * np.cos(u), r * np.sin(v), -ring * np.sin(u)), axis=-1).reshape(-1, 3)
    i, j = np.meshgrid(np.arange(n), np.arange(m), indexing="ij")
    a, b = i * m + j, (i + 1) % n * m + j  # b: the next step around the axis
    c, d = (i + 1) % n * m + (j + 1) % m, i * m + (j + 1) % m
    F = np.concatenate([np.stack([a, b, c], -1).reshape(-1, 3), np.stack([a, c, d], -1).reshape(-1, 3)])
    return V, F.astype(np.int64)


def lathe(profile: npt.ArrayLike, segments: int = 24) -> Mesh:
    """A surface of revolution: ``profile`` turned about the y axis.

    Args:
        profile: (K, 2) array-like of float, K >= 2. (radius, height) points, in order along the
            surface. A point at radius 0 is a pole (one vertex), allowed only at either end, where
            it closes the surface; an end at a radius above 0 is left open (a boundary). Run the
            profile upward along the outside (from the bottom pole to the top one, say) for
            outward-facing triangles; the reverse order gives inward-facing ones.
        segments: int in [3, 4096], default 24. Steps around the axis.

    Returns:
        (V, F): (N, 3) float64 positions and (M, 3) int64 faces: ``segments`` vertices per point
        of the profile (one at a pole); ``2 * segments`` faces per step of the profile, ``segments``
        for a step that ends at a pole. Closed when both ends are poles.

    Raises:
        TypeError: ``profile`` is not numbers or ``segments`` not an int.
        ValueError: a profile of the wrong shape, with non-finite or negative radii, a pole
            inside it, or two equal points in a row, or ``segments`` out of range.
    """
    try:
        P = np.asarray(profile)
    except Exception as exc:  # ragged lists and other non-arrays
        raise TypeError(f"profile: expected a (K, 2) array of numbers ({exc})") from None
    if P.dtype.kind not in "iuf":
        raise TypeError(f"profile: expected a (K, 2) array of numbers, got dtype {P.dtype}")
    P = P.astype(np.float64)
    if P.ndim != 2 or P.shape[1] != 2 or len(P) < 2:
        raise ValueError(f"profile: expected a (K, 2) array of (radius, height) with K >= 2, got shape {P.shape}")
    if not np.isfinite(P).all():
        raise ValueError("profile: must be finite numbers")
    if (P[:, 0] < 0).any():
        raise ValueError("profile: radii must be >= 0")
    if (P[1:-1, 0] == 0).any():
        raise ValueError("profile: only the first and last points may be at radius 0 (poles)")
    if (np.diff(P, axis=0) == 0).all(axis=1).any():
        raise ValueError("profile: two points in a row are equal")
    if len(P) == 2 and (P[:, 0] == 0).all():
        raise ValueError("profile: a profile of two poles is a line, not a surface")
    n = integer("segments", segments, 3, 4096)
    angle = np.linspace(0.0, 2 * np.pi, n, endpoint=False)
    cos, sin = np.cos(angle), np.sin(angle)
    pole = P[:, 0] == 0
    # vertex indices of each profile point: one at a pole, n on a ring
    start = np.concatenate([[0], np.cumsum(np.where(pole, 1, n))])
    V = np.concatenate(
        [[(0.0, h, 0.0)] if p else np.stack([r * cos, np.full(n, h), -r * sin], axis=-1) for (r, h), p in zip(P, pole)]
    )
    k = np.arange(n)
    faces = []
    for i in range(len(P) - 1):
        lo = start[i] if pole[i] else start[i] + k  # this ring, and the next one up the profile
        lo_next = start[i] if pole[i] else start[i] + (k + 1) % n
        hi = start[i + 1] if pole[i + 1] else start[i + 1] + k
        hi_next = start[i + 1] if pole[i + 1] else start[i + 1] + (k + 1) % n
        if not pole[i]:
            faces.append(np.stack(np.broadcast_arrays(lo, lo_next, hi_next), axis=-1))
        if not pole[i + 1]:
            faces.append(np.stack(np.broadcast_arrays(lo, hi_next, hi), axis=-1))
    return V, np.concatenate(faces).astype(np.int64)


# Kang et al.'s chess piece: (radius, height) from the base's centre to the top of the head.
_PAWN_PROFILE = [(0.0, 0.0), (0.5, 0.0), (0.5, 0.08), (0.38, 0.14), (0.22, 0.3), (0.15, 0.55), (0.28, 0.62),
                 (0.15, 0.68), (0.2, 0.8), (0.22, 0.92), (0.12, 1.04), (0.0, 1.08)]


def pawn(segments: int = 24) -> Mesh:
    """A chess pawn (base, collar and head) made with :func:`lathe`: closed, outward-oriented,
    standing on y = 0, 1.08 high, base radius 0.5.

    Args:
        segments: int in [3, 4096], default 24. Steps around the axis: ``20 * segments`` faces
            (the default gives Kang et al.'s chess piece: 480) and ``10 * segments + 2`` vertices.

    Returns:
        (V, F): (N, 3) float64 positions and (M, 3) int64 faces.
    """
    return lathe(_PAWN_PROFILE, integer("segments", segments, 3, 4096))


def uv_sphere(segments: int = 12, rings: int = 12) -> Mesh:
    """A unit sphere of latitude and longitude lines (poles on the y axis): closed,
    outward-oriented. The icosphere (:func:`icosphere`) has more even triangles; this is the
    sphere of many older papers.

    Args:
        segments: int in [3, 4096], default 12. Steps of longitude.
        rings: int in [2, 4096], default 12. Bands of latitude from pole to pole: ``2 * segments
            * (rings - 1)`` faces (the defaults give Kang et al.'s sphere: 264) and ``segments *
            (rings - 1) + 2`` vertices.

    Returns:
        (V, F): (N, 3) float64 positions and (M, 3) int64 faces.
    """
    n = integer("segments", segments, 3, 4096)
    rings = integer("rings", rings, 2, 4096)
    t = np.linspace(-np.pi / 2, np.pi / 2, rings + 1)
    profile = np.stack([np.cos(t), np.sin(t)], axis=-1)
    profile[[0, -1], 0] = 0.0  # exact poles
    return lathe(profile, n)


def teapot(subdivisions: int = 4) -> Mesh:
    """The Utah teapot, from Martin Newell's 32 bicubic Bezier patches (public domain).

    Each patch is cut into ``subdivisions`` x ``subdivisions`` quads of two triangles, the
    points the patches share are welded, and the triangles that collapse to a point at the
    lid's knob and the bottom's centre are left out: ``64 n**2 - 8 n`` faces (n = 4, the
    default: 992 of the 1024 triangles of Kang et al.'s teapot). y is up, the base on y = 0,
    the lid's knob at y = 3.15, the spout toward +x.

    As in Newell's data the surface is not closed: the lid and the rim it rests on are open
    circles, the spout is open at both ends, and the handle and spout pass into the body
    without being joined to it. Each part is consistently oriented, facing outward; no edge
    has more than two faces.

    Args:
        subdivisions: int in [2, 64], default 4. (At 1 the handle and spout would fold onto
            themselves.)

    Returns:
        (V, F): (N, 3) float64 positions and (M, 3) int64 faces.
    """
    return teapot_mesh(integer("subdivisions", subdivisions, 2, 64))


# the box's 12 triangles over its corners, numbered x-major (corner k = (x, y, z) bits of k: 4 2 1)
_BOX_FACES = [[0, 1, 3], [0, 3, 2], [4, 6, 7], [4, 7, 5], [0, 4, 5], [0, 5, 1],
              [2, 3, 7], [2, 7, 6], [0, 2, 6], [0, 6, 4], [1, 5, 7], [1, 7, 3]]


def box(lo: npt.ArrayLike = (-0.5, -0.5, -0.5), hi: npt.ArrayLike = (0.5, 0.5, 0.5)) -> Mesh:
    """An axis-aligned box from corner ``lo`` to corner ``hi``: closed, outward-oriented.

    Args:
        lo: 3 numbers (x, y, z), default (-0.5, -0.5, -0.5). The smallest corner.
        hi: 3 numbers (x, y, z), default (0.5, 0.5, 0.5). The largest corner: it must exceed
            ``lo`` on every axis.

    Returns:
        (V, F): (8, 3) float64 corners (corner k has x from ``hi`` when bit 4 of k is set, y bit
        2, z bit 1) and (12, 3) int64 faces, two per side.

    Raises:
        TypeError: a corner that is not 3 numbers.
        ValueError: a corner that is not finite, or a ``hi`` not above ``lo`` on an axis.
    """
    corners = []
    for name, value in (("lo", lo), ("hi", hi)):
        try:
            c = np.asarray(value)
        except Exception as exc:  # ragged lists and other non-arrays
            raise TypeError(f"{name}: expected 3 numbers (x, y, z) ({exc})") from None
        if c.dtype.kind not in "iuf" or c.shape != (3,):
            raise TypeError(f"{name}: expected 3 numbers (x, y, z), got {value!r}")
        if not np.isfinite(c).all():
            raise ValueError(f"{name}: must be finite, got {value!r}")
        corners.append(c.astype(np.float64))
    a, b = corners
    if not (b > a).all():
        raise ValueError(f"hi: must exceed lo on every axis, got lo={lo!r}, hi={hi!r}")
    V = np.array([[x, y, z] for x in (a[0], b[0]) for y in (a[1], b[1]) for z in (a[2], b[2])])
    return V, np.array(_BOX_FACES, dtype=np.int64)

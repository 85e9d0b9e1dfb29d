"""Procedural test meshes, made in code so nothing large has to be stored."""

from __future__ import annotations

from typing import Tuple

import numpy as np
import numpy.typing as npt

from toonmesh import _core

__all__ = ["icosphere", "grid"]

Mesh = Tuple[npt.NDArray[np.float64], npt.NDArray[np.int64]]


def icosphere(subdivisions: int = 3, noise: float = 0.0, seed: int = 0) -> Mesh:
    """A unit icosphere, optionally with seeded radial noise.

    Parameters
    ----------
    subdivisions : int in [0, 10], default 3
        Rounds of 1-to-4 triangle splitting: 10 * 4**s + 2 vertices (s=5: 10,242; s=7: 163,842;
        s=8: 655,362) and 20 * 4**s faces.
    noise : float >= 0, default 0.0
        Each vertex's radius is multiplied by ``1 + noise * u``, u uniform in [-1, 1).
    seed : int, default 0
        Seed of the noise; the same seed gives the same mesh on every platform.

    Returns
    -------
    (V, F): (N, 3) float64 positions and (M, 3) int64 faces, outward-oriented, closed.

    Raises
    ------
    TypeError for a non-integer ``subdivisions`` or ``seed`` or a non-number ``noise`` (bools
    and strings are refused); ValueError for values out of range (a seed is in [0, 2**64)).
    """
    return _core.icosphere(subdivisions, noise, seed)


def grid(n: int = 32, noise: float = 0.0, seed: int = 0) -> Mesh:
    """An open, flat ``n`` x ``n`` vertex grid on [0, 1]^2 with seeded noise in z.

    Parameters
    ----------
    n : int in [2, 4096], default 32
        Vertices per side: n*n vertices and 2*(n-1)**2 faces.
    noise : float >= 0, default 0.0
        z of each vertex is ``noise * u``, u uniform in [-1, 1).
    seed : int, default 0

    Returns
    -------
    (V, F): (N, 3) float64 positions and (M, 3) int64 faces.

    Raises
    ------
    TypeError, ValueError: as :func:`icosphere`.
    """
    return _core.grid(n, noise, seed)

"""Point clouds: what each point's neighbourhood says of the surface the cloud samples.

:class:`toonmesh.Points` places a cloud in a scene; the renderer draws it as splats, estimating
the normals it lacks with :func:`normals`.
"""

from __future__ import annotations

from typing import Any, Optional

import numpy as np

from toonmesh import _core


def normals(positions: Any, k: Optional[int] = None) -> np.ndarray:
    """Each point's unit normal, from its ``k`` nearest neighbours: the direction in which the
    point and its neighbours spread least (PCA of the neighbourhood), found with a k-d tree in
    parallel, the same bits for any thread count.

    Where a neighbourhood spans no plane the normal is still unit and finite: across the line
    for collinear points, the direction from the centroid (else +z) where every neighbour
    coincides with the point (duplicates, one point). A cloud of fewer than k + 1 points uses
    all its points.

    Args:
        positions: (N, 3) float32/float64, finite, N >= 1.
        k: neighbours per point, an int from 3 to 256; None (default): 12.

    Returns:
        (N, 3) unit normals in the positions' dtype, each turned away from the cloud's
        centroid (one consistent side on a closed scan; rendering shades both sides, so a
        normal pointing in draws the same).
    """
    if isinstance(positions, (list, tuple)):  # nested lists of numbers, as NumPy reads them
        positions = np.asarray(positions)
    return _core._point_normals(positions, k)  # type: ignore[no-any-return]


__all__ = ["normals"]

"""Where the command line and batch renders look from: an up axis and a turntable around it.

A mesh's up axis says which way its "front, slightly above" view lies. Seen with y up (most
exporters, and the renderer's default camera), the front faces +z; scans and CAD files often have
z up, and then the front faces -y (as in Blender). Each axis comes with a right-handed frame
(side, up, front), and the view direction is ``0.35 side + 0.3 up + front``: for y up that is
exactly :meth:`toonmesh.Camera.fit`'s default direction.
"""

from __future__ import annotations

import math
from typing import Any, Dict, List, Tuple

import numpy as np

from toonmesh._core import Camera

Vec3 = Tuple[float, float, float]

#: (side, up, front) unit vectors for each up axis; side x up = front (right-handed).
FRAMES: Dict[str, Tuple[Vec3, Vec3, Vec3]] = {
    "x": ((0.0, 0.0, 1.0), (1.0, 0.0, 0.0), (0.0, 1.0, 0.0)),
    "y": ((1.0, 0.0, 0.0), (0.0, 1.0, 0.0), (0.0, 0.0, 1.0)),
    "z": ((1.0, 0.0, 0.0), (0.0, 0.0, 1.0), (0.0, -1.0, 0.0)),
}

UP_AXES = tuple(FRAMES)


def _frame(up: str) -> Tuple[Vec3, Vec3, Vec3]:
    try:
        return FRAMES[up]
    except (KeyError, TypeError):
        raise ValueError(f"up: expected one of {', '.join(UP_AXES)}, got {up!r}") from None


def up_vector(up: str) -> Vec3:
    """The unit vector of axis ``up`` ("x", "y" or "z")."""
    return _frame(up)[1]


def view_direction(up: str, angle: float = 0.0) -> Vec3:
    """Scene -> eye direction of the front view, slightly above and to the side, turned by
    ``angle`` radians about the up axis (counter-clockwise seen from above)."""
    side, upv, front = _frame(up)
    c, s = math.cos(angle), math.sin(angle)
    # rotate the horizontal part (0.35 side + front) about up
    a, b = 0.35 * c + s, -0.35 * s + c
    return tuple(a * side[i] + 0.3 * upv[i] + b * front[i] for i in range(3))  # type: ignore[return-value]


def check_views(views: Any) -> int:
    """``views`` as an int, which must be >= 1."""
    if isinstance(views, bool) or not isinstance(views, (int, np.integer)) or views < 1:
        raise ValueError(f"views: expected an int >= 1, got {views!r}")
    return int(views)


def turntable(views: int, up: str = "y") -> List[Camera]:
    """``views`` fit cameras evenly spaced around the up axis, the first one the front view."""
    views = check_views(views)
    upv = up_vector(up)
    return [Camera.fit(view_direction(up, 2.0 * math.pi * k / views), up=upv) for k in range(views)]

"""The views of the command line and batch renders: a turntable of fitted cameras.

A fitted camera (:meth:`toonmesh.Camera.fit`) frames the scene from a three-quarter view about
its up axis (a file's convention, or the render's ``up``); a turntable turns that view about the
up axis in equal steps.
"""

from __future__ import annotations

from typing import Any, List

import numpy as np

from toonmesh._core import Camera


def check_views(views: Any) -> int:
    """``views`` as an int, which must be >= 1."""
    if isinstance(views, bool) or not isinstance(views, (int, np.integer)) or views < 1:
        raise ValueError(f"views: expected an int >= 1, got {views!r}")
    return int(views)


def turntable(views: int) -> List[Camera]:
    """``views`` fitted cameras evenly spaced around the up axis, the first the fitted camera's
    own three-quarter view."""
    views = check_views(views)
    return [Camera.fit(turn=360.0 * k / views) for k in range(views)]

"""Popping between the frames of a sequence: ink that vanishes from where the surface under it
went.

Each ink pixel of a frame is taken back to the surface point it was drawn on (through its depth
and the frame's camera), that point is carried into the next frame's image, and the pixel pops
when the next frame has no ink within ``radius`` pixels of where the point lands. Points that the
next frame does not see (occluded, or out of the image) are not counted: a line that goes behind
the model has not popped. Each ink pixel takes the depth of the nearest surface within
``radius`` pixels: ink drawn just outside a silhouette, over the background or over a farther
surface, belongs to the occluding surface.
"""

from __future__ import annotations

from typing import Any, List, NamedTuple, Sequence, Tuple

import numpy as np


class Frame(NamedTuple):
    """What the measure reads of one frame."""

    ink: np.ndarray  # (H, W) bool
    depth: np.ndarray  # (H, W) float64 linear view depth, inf where no surface is
    view: np.ndarray  # (4, 4) world -> view
    projection: np.ndarray  # (4, 4) view -> clip (wgpu's: z in [0, 1])


class Step(NamedTuple):
    """One step's count: ink pixels the next frame sees, and those of them with no ink near."""

    counted: int
    popped: int
    where: np.ndarray  # (popped, 2) int64: (row, column) of each popped ink pixel


def disc_offsets(radius: float) -> List[Tuple[int, int]]:
    """The integer offsets (dy, dx) within ``radius`` pixels of the centre."""
    r = int(np.floor(radius))
    return [(dy, dx) for dy in range(-r, r + 1) for dx in range(-r, r + 1) if dy * dy + dx * dx <= radius * radius]


def spread(image: np.ndarray, offsets: Sequence[Tuple[int, int]], reduce: Any, empty: Any) -> np.ndarray:
    """``reduce`` (np.maximum, np.minimum, np.logical_or) of ``image`` over each pixel's
    ``offsets``; pixels off the image count as ``empty``."""
    h, w = image.shape
    pad = max(max(abs(dy), abs(dx)) for dy, dx in offsets)
    padded = np.full((h + 2 * pad, w + 2 * pad), empty, dtype=image.dtype)
    padded[pad:pad + h, pad:pad + w] = image
    out: np.ndarray = np.full_like(image, empty)
    for dy, dx in offsets:
        out = reduce(out, padded[pad + dy:pad + dy + h, pad + dx:pad + dx + w])
    return out


def surface_points(frame: Frame, ys: np.ndarray, xs: np.ndarray, depth: np.ndarray) -> np.ndarray:
    """(N, 3) world points seen at pixels (ys, xs) at linear view depths ``depth``: the pixel
    centre's ray through the inverse projection (perspective or orthographic alike) cut where
    view-space z = -depth."""
    h, w = frame.depth.shape
    ndc = np.stack([2.0 * (xs + 0.5) / w - 1.0, 1.0 - 2.0 * (ys + 0.5) / h], axis=1)
    inverse = np.linalg.inv(frame.projection)

    def at(z: float) -> np.ndarray:
        clip = np.concatenate([ndc, np.full((len(ndc), 1), z), np.ones((len(ndc), 1))], axis=1)
        v = clip @ inverse.T
        return np.asarray(v[:, :3] / v[:, 3:4])

    a, b = at(0.25), at(0.75)
    t = (-depth - a[:, 2]) / (b[:, 2] - a[:, 2])
    view = a + t[:, None] * (b - a)
    world = np.concatenate([view, np.ones((len(view), 1))], axis=1) @ np.linalg.inv(frame.view).T
    return np.asarray(world[:, :3])


def step(a: Frame, b: Frame, radius: float, depth_tolerance: float) -> Step:
    """How much of ``a``'s ink pops going to ``b``."""
    offsets = disc_offsets(radius)
    # a line is drawn on the nearest surface around it: ink just outside a silhouette, over the
    # background or over a farther surface, belongs to the occluding surface
    near_depth = spread(a.depth, offsets, np.minimum, np.inf)
    ys, xs = np.nonzero(a.ink & np.isfinite(near_depth))
    if len(ys) == 0:
        return Step(0, 0, np.zeros((0, 2), np.int64))
    world = surface_points(a, ys, xs, near_depth[ys, xs])
    view = np.concatenate([world, np.ones((len(world), 1))], axis=1) @ b.view.T
    clip = view @ b.projection.T
    h, w = b.depth.shape
    ahead = clip[:, 3] > 0
    ndc = clip[:, :2] / np.where(ahead, clip[:, 3], 1.0)[:, None]
    px = np.rint((ndc[:, 0] + 1.0) * 0.5 * w - 0.5).astype(np.int64)
    py = np.rint((1.0 - ndc[:, 1]) * 0.5 * h - 0.5).astype(np.int64)
    inside = ahead & (px >= 0) & (px < w) & (py >= 0) & (py < h)
    px, py, seen_depth = px[inside], py[inside], -view[inside, 2]
    ys, xs = ys[inside], xs[inside]
    # seen in b: no nearer than the farthest surface b shows within the radius (a silhouette
    # point may fall just beside its surface), within the tolerance
    b_depth = np.where(np.isfinite(b.depth), b.depth, -np.inf)
    farthest = spread(b_depth, offsets, np.maximum, -np.inf)[py, px]
    seen = seen_depth <= farthest * (1.0 + depth_tolerance)
    near_ink = spread(b.ink, offsets, np.logical_or, False)[py, px]
    popped = seen & ~near_ink
    return Step(int(seen.sum()), int(popped.sum()), np.stack([ys[popped], xs[popped]], axis=1).astype(np.int64))

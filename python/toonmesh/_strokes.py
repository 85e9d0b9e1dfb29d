"""Strokes of a line drawing as a pen would draw them: optionally smoothed along their length
(Gaussian, in pixels), simplified in pixels (Douglas-Peucker) and ordered to keep the pen's
travel between strokes short (greedy nearest neighbour, either end first, as vpype's
``linesort`` does); strokes whose width varies along them drawn as filled outlines. Used by
:meth:`RenderResult.strokes` and :meth:`RenderResult.svg`."""

from __future__ import annotations

import math
from typing import Callable, List, Optional, Tuple

import numpy as np

ORDERS = ("drawing", "plotter")
#: How the SVG draws widths: "auto" (per point where the outlines taper or scale width by
#: depth, else per kind), "kind" (centre lines at each kind's width, for a pen plotter) or
#: "point" (filled outlines of each stroke's width at each point).
WIDTHS = ("auto", "kind", "point")

#: Default tolerance of the SVG's strokes, in pixels: a quarter pixel keeps the drawing the same
#: to the eye.
SIMPLIFY = 0.25
#: Default smoothing of the strokes, in pixels: none, the points as the renderer found them.
SMOOTH = 0.0
#: Longest smoothing radius, in pixels.
MAX_SMOOTH = 4096.0
#: Spacing of the samples that integrate a stroke over the smoothing window, in pixels.
SMOOTH_STEP = 0.25


def check_pixels(name: str, value: float, most: float = math.inf) -> None:
    """Refuses a length in pixels that is not a finite number in [0, most]."""
    if isinstance(value, (bool, np.bool_)) or not isinstance(value, (int, float, np.integer, np.floating)):
        raise TypeError(f"{name}: expected a number of pixels, got {type(value).__name__}")
    try:
        value = float(value)
    except OverflowError:
        raise ValueError(f"{name}: must be a finite number of pixels, got an int too large for a float") from None
    if not (math.isfinite(value) and 0 <= value <= most):
        bound = ">= 0" if most == math.inf else f"in [0, {most:g}]"
        raise ValueError(f"{name}: must be a finite number of pixels {bound}, got {value}")


def check(order: str, simplify: float, smooth: float = SMOOTH, widths: str = "auto") -> None:
    """Refuses an unknown order or way of drawing widths, a tolerance that is not a finite
    number >= 0, or a smoothing radius outside [0, MAX_SMOOTH] pixels."""
    for name, value, names in (("order", order, ORDERS), ("widths", widths, WIDTHS)):
        if not isinstance(value, str):
            raise TypeError(f"{name}: expected one of {', '.join(map(repr, names))}, got {type(value).__name__}")
        if value not in names:
            raise ValueError(f"{name}: must be one of {', '.join(map(repr, names))}, got {value!r:.40}")
    check_pixels("simplify", simplify)
    check_pixels("smooth", smooth, MAX_SMOOTH)


def smoothed(points: np.ndarray, radius: float) -> np.ndarray:
    """The polyline, each point moved to the Gaussian-weighted mean of the polyline within
    ``radius`` pixels of it along its length (sigma a third of the radius; the polyline is
    integrated, not just its points, so unevenly spaced points weigh by the length they stand
    for). Near the ends of an open polyline the window shrinks to the distance to the end, so
    the ends stay where they are; a closed one (first point equal to the last) wraps around and
    stays closed. No point moves more than ``radius`` pixels: every point averaged lies within
    that distance along the polyline, so within it in a straight line. 0 returns the points."""
    n = len(points)
    if radius <= 0 or n < 3:
        return points
    s = np.concatenate([[0.0], np.cumsum(np.hypot(*np.diff(points, axis=0).T))])
    total = s[-1]
    if not total > 0:
        return points
    closed = bool(np.array_equal(points[0], points[-1]))
    reach = min(radius, total / 2) if closed else radius
    h = np.full(n, reach) if closed else np.minimum(reach, np.minimum(s, total - s))
    k = int(min(max(math.ceil(2 * reach / SMOOTH_STEP), 8), 1024)) | 1
    unit = np.linspace(-1.0, 1.0, k)
    weights = np.exp(-0.5 * (3.0 * unit) ** 2)
    weights /= weights.sum()
    u = s[:, None] + h[:, None] * unit
    if closed:
        at = [np.interp(u, s[:-1], points[:-1, c], period=total) for c in (0, 1)]
    else:
        at = [np.interp(u, s, points[:, c]) for c in (0, 1)]
    out = np.stack([a @ weights for a in at], axis=1)
    if closed:
        out[-1] = out[0]
    else:
        out[[0, -1]] = points[[0, -1]]
    return out


def simplified(points: np.ndarray, tolerance: float) -> np.ndarray:
    """The polyline's points that stay within ``tolerance`` pixels of it (Douglas-Peucker); the
    ends are always kept. ``tolerance`` 0 keeps every point."""
    return points[kept(points, tolerance)]


def kept(points: np.ndarray, tolerance: float, widths: Optional[np.ndarray] = None) -> np.ndarray:
    """Indices of the points :func:`simplified` keeps. With ``widths`` (pixels per point) that
    vary, half the width is a third coordinate, so that the edges of the ink too stay within
    ``tolerance`` pixels of where they were (a taper keeps the points that shape it)."""
    n = len(points)
    if tolerance <= 0 or n < 3:
        return np.arange(n)
    if widths is not None and np.ptp(widths) > 0:
        return _douglas_peucker(np.column_stack([points, 0.5 * np.asarray(widths, float)]), tolerance, _distance_3d)
    return _douglas_peucker(points, tolerance, _distance_2d)


def _distance_2d(rel: np.ndarray, seg: np.ndarray) -> np.ndarray:
    """Distances of the points `rel` from the line through 0 along `seg` (from 0 if seg is 0)."""
    length = np.hypot(*seg)
    if length > 0:
        return np.abs(seg[0] * rel[:, 1] - seg[1] * rel[:, 0]) / length
    return np.hypot(rel[:, 0], rel[:, 1])


def _distance_3d(rel: np.ndarray, seg: np.ndarray) -> np.ndarray:
    length = float(np.linalg.norm(seg))
    if length > 0:
        return np.linalg.norm(np.cross(rel, seg), axis=1) / length
    return np.linalg.norm(rel, axis=1)


def _douglas_peucker(points: np.ndarray, tolerance: float, distance: Callable[..., np.ndarray]) -> np.ndarray:
    n = len(points)
    keep = np.zeros(n, bool)
    keep[[0, n - 1]] = True
    stack = [(0, n - 1)]
    while stack:
        a, b = stack.pop()
        if b - a < 2:
            continue
        dist = distance(points[a + 1 : b] - points[a], points[b] - points[a])
        k = int(np.argmax(dist))
        if dist[k] > tolerance:
            mid = a + 1 + k
            keep[mid] = True
            stack += [(a, mid), (mid, b)]
    return np.flatnonzero(keep)


def outline_path(points: np.ndarray, widths: np.ndarray) -> str:
    """SVG path data of the ink of a stroke whose width (pixels, per point) varies along it, the
    shape the line pass inks: each segment a band whose half width goes linearly from one end's
    to the other's, closed by half discs at both ends (so segments join round and the stroke
    ends round). Every piece winds the same way, so under the nonzero fill rule they are one
    shape where they overlap."""
    r = 0.5 * np.asarray(widths, float)
    parts = []
    if len(points) == 1:
        (x, y), q = points[0], r[0]
        return f"M{x - q:.2f},{y:.2f}A{q:.2f},{q:.2f} 0 0 1 {x + q:.2f},{y:.2f}A{q:.2f},{q:.2f} 0 0 1 {x - q:.2f},{y:.2f}Z"
    for (a, b), (ra, rb) in zip(zip(points[:-1], points[1:]), zip(r[:-1], r[1:])):
        d = b - a
        length = math.hypot(d[0], d[1])
        if length == 0:
            q = max(ra, rb)
            parts.append(
                f"M{a[0] - q:.2f},{a[1]:.2f}A{q:.2f},{q:.2f} 0 0 1 {a[0] + q:.2f},{a[1]:.2f}"
                f"A{q:.2f},{q:.2f} 0 0 1 {a[0] - q:.2f},{a[1]:.2f}Z"
            )
            continue
        nx, ny = -d[1] / length, d[0] / length
        parts.append(
            f"M{a[0] + nx * ra:.2f},{a[1] + ny * ra:.2f}"
            f"A{ra:.2f},{ra:.2f} 0 0 1 {a[0] - nx * ra:.2f},{a[1] - ny * ra:.2f}"
            f"L{b[0] - nx * rb:.2f},{b[1] - ny * rb:.2f}"
            f"A{rb:.2f},{rb:.2f} 0 0 1 {b[0] + nx * rb:.2f},{b[1] + ny * rb:.2f}Z"
        )
    return "".join(parts)


def plotter_order(lines: List[np.ndarray]) -> List[Tuple[int, bool]]:
    """The lines in the order a pen draws them with little travel: from the origin, each time
    the undrawn line with the nearest end, drawn from that end. Returns (index, reversed)."""
    if not lines:
        return []
    starts = np.array([l[0] for l in lines], float)
    ends = np.array([l[-1] for l in lines], float)
    todo = np.ones(len(lines), bool)
    pen = np.zeros(2)
    out: List[Tuple[int, bool]] = []
    for _ in range(len(lines)):
        ds = np.where(todo, np.hypot(*(starts - pen).T), np.inf)
        de = np.where(todo, np.hypot(*(ends - pen).T), np.inf)
        i, j = int(np.argmin(ds)), int(np.argmin(de))
        flip = de[j] < ds[i]
        k = j if flip else i
        todo[k] = False
        out.append((k, bool(flip)))
        pen = starts[k] if flip else ends[k]
    return out


def pen_travel(lines: List[np.ndarray]) -> float:
    """Pixels the pen travels up, from the origin, between the lines in the given order."""
    pen = np.zeros(2)
    total = 0.0
    for l in lines:
        total += float(np.hypot(*(l[0] - pen)))
        pen = l[-1]
    return total

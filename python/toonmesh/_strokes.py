"""Strokes of a line drawing as a pen would draw them: simplified in pixels (Douglas-Peucker)
and ordered to keep the pen's travel between strokes short (greedy nearest neighbour, either
end first, as vpype's ``linesort`` does). Used by :meth:`RenderResult.svg`."""

from __future__ import annotations

import math
from typing import List, Tuple

import numpy as np

ORDERS = ("drawing", "plotter")

#: Default tolerance of the SVG's strokes, in pixels: a quarter pixel keeps the drawing the same
#: to the eye.
SIMPLIFY = 0.25


def check(order: str, simplify: float) -> None:
    """Refuses an unknown order or a tolerance that is not a finite number >= 0."""
    if not isinstance(order, str) or order not in ORDERS:
        raise ValueError(f"order: must be 'drawing' or 'plotter', got {order!r:.40}")
    if isinstance(simplify, bool) or not isinstance(simplify, (int, float, np.integer, np.floating)):
        raise TypeError(f"simplify: expected a number of pixels, got {type(simplify).__name__}")
    if not (math.isfinite(simplify) and simplify >= 0):
        raise ValueError(f"simplify: must be a finite number of pixels >= 0, got {simplify}")


def simplified(points: np.ndarray, tolerance: float) -> np.ndarray:
    """The polyline's points that stay within ``tolerance`` pixels of it (Douglas-Peucker); the
    ends are always kept. ``tolerance`` 0 keeps every point."""
    n = len(points)
    if tolerance <= 0 or n < 3:
        return points
    keep = np.zeros(n, bool)
    keep[[0, n - 1]] = True
    stack = [(0, n - 1)]
    while stack:
        a, b = stack.pop()
        if b - a < 2:
            continue
        seg = points[b] - points[a]
        rel = points[a + 1 : b] - points[a]
        length = np.hypot(*seg)
        if length > 0:
            dist = np.abs(seg[0] * rel[:, 1] - seg[1] * rel[:, 0]) / length
        else:
            dist = np.hypot(rel[:, 0], rel[:, 1])
        k = int(np.argmax(dist))
        if dist[k] > tolerance:
            mid = a + 1 + k
            keep[mid] = True
            stack += [(a, mid), (mid, b)]
    return points[keep]


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

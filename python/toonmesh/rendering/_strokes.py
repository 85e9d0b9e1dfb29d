"""Strokes of a line drawing as a pen would draw them: optionally smoothed along their length
(Gaussian, in pixels), simplified in pixels (Douglas-Peucker) and ordered to keep the pen's
travel between strokes short (greedy nearest neighbour, either end first, as vpype's
``linesort`` does); strokes whose width varies along them drawn as filled outlines. Used by
:meth:`RenderResult.strokes` and :meth:`RenderResult.svg`; the geometry and the SVG text are
the Rust core's (``pen``), these are its Python faces and the checks of the user's options."""

from __future__ import annotations

import math
from typing import Any, List, Optional, Sequence, Tuple

import numpy as np

from toonmesh import _core

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
    return drawn([points], [None], radius, 0.0)[0][0]


def simplified(points: np.ndarray, tolerance: float) -> np.ndarray:
    """The polyline's points that stay within ``tolerance`` pixels of it (Douglas-Peucker); the
    ends are always kept. ``tolerance`` 0 keeps every point."""
    return drawn([points], [None], 0.0, tolerance)[0][0]


def kept(points: np.ndarray, tolerance: float, widths: Optional[np.ndarray] = None) -> np.ndarray:
    """Indices of the points :func:`simplified` keeps. With ``widths`` (pixels per point) that
    vary, half the width is a third coordinate, so that the edges of the ink too stay within
    ``tolerance`` pixels of where they were (a taper keeps the points that shape it)."""
    return drawn([points], [widths], 0.0, tolerance)[0][1]


def drawn(
    lines: Sequence[np.ndarray], widths: Sequence[Optional[np.ndarray]], smooth: float, simplify: float
) -> List[Tuple[np.ndarray, np.ndarray]]:
    """Each of ``lines`` smoothed over ``smooth`` pixels (:func:`smoothed`), then simplified to
    ``simplify`` pixels (:func:`kept`, by its ``widths`` where they are given, by its points
    where they are None): ``(points, kept)``, the points drawn and their indices in the line."""
    points = [np.asarray(l, float) for l in lines]
    return _core._pen_strokes(points, [None if w is None else np.asarray(w, float) for w in widths], smooth, simplify)


def plotter_order(lines: List[np.ndarray]) -> List[Tuple[int, bool]]:
    """The lines in the order a pen draws them with little travel: from the origin, each time
    the undrawn line with the nearest end, drawn from that end (ties: a first point before a
    last one, a lower index before a higher one). Returns (index, reversed)."""
    starts = np.array([l[0] for l in lines], float).reshape(-1, 2)
    ends = np.array([l[-1] for l in lines], float).reshape(-1, 2)
    index, backwards = _core._plotter_order(starts, ends)
    return list(zip(index.tolist(), backwards.tolist()))


def in_order(strokes: List[Tuple[np.ndarray, np.ndarray]], order: str) -> List[Tuple[np.ndarray, np.ndarray]]:
    """``(points, widths)`` strokes as ``order`` draws them: as they are ("drawing"), or in
    :func:`plotter_order`, each drawn from its nearer end ("plotter")."""
    if order != "plotter":
        return strokes
    flips = plotter_order([p for p, _ in strokes])
    return [(strokes[i][0][::-1], strokes[i][1][::-1]) if flip else strokes[i] for i, flip in flips]


#: One group of :func:`svg_document`: its id, colour, the width its centre lines are stroked at
#: (None: filled outlines of each point's width), (dash, gap) or None, and its strokes as
#: ``(points, widths)``.
SvgGroup = Tuple[str, Any, Optional[float], Optional[Tuple[float, float]], List[Tuple[np.ndarray, np.ndarray]]]


def svg_document(width: int, height: int, groups: Sequence[SvgGroup]) -> str:
    """The SVG document of a ``width`` x ``height`` pixel drawing made of ``groups``, drawn in
    order: each stroke a ``<polyline>`` stroked at its group's width, or a filled ``<path>``
    outlining its ink (each segment a band from one end's width to the other's, closed by half
    discs, all winding the same way so that the nonzero fill rule makes them one shape)."""
    rows = []
    for gid, color, line_width, dashes, strokes in groups:
        lines = [np.asarray(p, float) for p, _ in strokes]
        widths = None if line_width is not None else [w for _, w in strokes]
        rows.append((gid, color, line_width, dashes, lines, widths))
    return _core._svg_document(width, height, rows)


def pen_travel(lines: List[np.ndarray]) -> float:
    """Pixels the pen travels up, from the origin, between the lines in the given order."""
    pen = np.zeros(2)
    total = 0.0
    for l in lines:
        total += float(np.hypot(*(l[0] - pen)))
        pen = l[-1]
    return total

"""Line drawings as geometry, for :mod:`toonmesh.testing`: an SVG document read back into its
strokes (one group per line kind), and two drawings compared by how far each stroke lies from
the other drawing's strokes of the same kind, in pixels, so that float noise in the numbers of
an SVG never counts as a change.

Each stroke is sampled along its length (every quarter pixel at most); a sample's distance to
the other drawing is its distance to the nearest of that drawing's samples of the same kind, so
distances are exact to within an eighth of a pixel. The nearest sample is found on a grid of
cells, widened fourfold for the samples that find nothing near, so two drawings of a thousand
strokes compare in well under a second.
"""

from __future__ import annotations

import re
import xml.etree.ElementTree as ET
from typing import Dict, List, NamedTuple, Optional, Tuple

import numpy as np

#: The longest step between two samples of a stroke, in pixels.
SPACING = 0.25


class Group(NamedTuple):
    """One kind of line in a drawing: its style (stroke colour and width, fill) as the SVG
    writes it, and its strokes, (K, 2) float64 arrays of pixel coordinates."""

    style: Tuple[Optional[str], Optional[str], Optional[str]]
    strokes: List[np.ndarray]


class Drawing(NamedTuple):
    """A line drawing: its size in pixels and its groups by id (the line kind)."""

    width: float
    height: float
    groups: Dict[str, Group]


def _local(tag: str) -> str:
    return tag.rsplit("}", 1)[-1]


_NUMBER = re.compile(r"[-+]?(?:\d+\.?\d*|\.\d+)(?:[eE][-+]?\d+)?")
_COMMAND = re.compile(r"([MmLlHhVvZzAaCcQqSsTt])([^MmLlHhVvZzAaCcQqSsTt]*)")
#: Numbers each path command takes, and where its end point is among them.
_ARITY = {"M": 2, "L": 2, "T": 2, "H": 1, "V": 1, "A": 7, "C": 6, "Q": 4, "S": 4, "Z": 0}


def _numbers(text: str) -> List[float]:
    return [float(x) for x in _NUMBER.findall(text)]


def _points(text: str) -> np.ndarray:
    values = _numbers(text)
    return np.asarray(values[: len(values) // 2 * 2], np.float64).reshape(-1, 2)


def path_strokes(d: str) -> List[np.ndarray]:
    """The outlines of an SVG path's ``d`` as polylines through its commands' end points (arcs
    and curves are taken by their end points: the filled outlines toonmesh writes join short
    segments with half-disc arcs, which this keeps within their width)."""
    strokes: List[List[Tuple[float, float]]] = []
    x = y = 0.0
    start = (0.0, 0.0)
    for command, args in _COMMAND.findall(d):
        upper = command.upper()
        values = _numbers(args)
        n = _ARITY[upper]
        if upper == "Z":
            if strokes and strokes[-1]:
                strokes[-1].append(start)
            x, y = start
            continue
        for i in range(0, max(len(values) - n + 1, 0), max(n, 1)):
            v = values[i:i + n]
            relative = command.islower()
            if upper == "H":
                x = v[0] + (x if relative else 0.0)
            elif upper == "V":
                y = v[0] + (y if relative else 0.0)
            else:
                ex, ey = v[-2], v[-1]
                x, y = (x + ex, y + ey) if relative else (ex, ey)
            if upper == "M" and i == 0:
                strokes.append([(x, y)])
                start = (x, y)
            else:
                if not strokes:
                    strokes.append([start])
                strokes[-1].append((x, y))
    return [np.asarray(s, np.float64) for s in strokes if s]


def parse_svg(text: str, name: str = "drawing") -> Drawing:
    """The strokes of an SVG document: ``<polyline>``, ``<polygon>``, ``<line>`` and ``<path>``
    elements, grouped by the id of the innermost ``<g>`` around them ("" for none). Raises
    ValueError naming ``name`` when the text is not an SVG document."""
    try:
        root = ET.fromstring(text)
    except ET.ParseError as exc:
        raise ValueError(f"{name}: not an SVG document ({exc})") from None
    if _local(root.tag) != "svg":
        raise ValueError(f"{name}: not an SVG document (its root element is <{_local(root.tag)}>)")
    box = _numbers(root.get("viewBox", ""))
    width = float(box[2]) if len(box) == 4 else float((_numbers(root.get("width", "0")) or [0.0])[0])
    height = float(box[3]) if len(box) == 4 else float((_numbers(root.get("height", "0")) or [0.0])[0])
    groups: Dict[str, Group] = {}

    def walk(node: ET.Element, gid: str, style: Tuple[Optional[str], Optional[str], Optional[str]]) -> None:
        for child in node:
            tag = _local(child.tag)
            if tag == "g":
                inner = (child.get("stroke", style[0]), child.get("stroke-width", style[1]), child.get("fill", style[2]))
                walk(child, child.get("id", gid), inner)
                continue
            if tag in ("polyline", "polygon"):
                strokes = [_points(child.get("points", ""))]
                if tag == "polygon" and len(strokes[0]):
                    strokes = [np.vstack([strokes[0], strokes[0][:1]])]
            elif tag == "line":
                v = [float(child.get(k, "0")) for k in ("x1", "y1", "x2", "y2")]
                strokes = [np.asarray(v, np.float64).reshape(2, 2)]
            elif tag == "path":
                strokes = path_strokes(child.get("d", ""))
            else:
                continue
            group = groups.setdefault(gid, Group(style, []))
            group.strokes.extend(s for s in strokes if len(s))

    walk(root, "", (root.get("stroke"), root.get("stroke-width"), root.get("fill")))
    return Drawing(width, height, groups)


def samples(strokes: List[np.ndarray], spacing: float = SPACING) -> Tuple[np.ndarray, np.ndarray]:
    """Points along ``strokes`` at most ``spacing`` pixels apart, and the length of line each
    stands for (a lone point stands for ``spacing``)."""
    points, weights = [], []
    for s in strokes:
        s = np.asarray(s, np.float64)
        if len(s) == 1:
            points.append(s)
            weights.append(np.array([spacing]))
            continue
        seg = np.diff(s, axis=0)
        length = np.hypot(seg[:, 0], seg[:, 1])
        n = np.maximum(np.ceil(length / spacing).astype(np.int64), 1)
        which = np.repeat(np.arange(len(seg)), n)
        t = (np.arange(n.sum()) - np.repeat(np.cumsum(n) - n, n)) / np.repeat(n, n)
        points.append(np.vstack([s[which] + seg[which] * t[:, None], s[-1:]]))
        weights.append(np.append(np.repeat(length / n, n), 0.0))
    if not points:
        return np.zeros((0, 2)), np.zeros(0)
    return np.vstack(points), np.concatenate(weights)


def nearest(a: np.ndarray, b: np.ndarray, cell: float = 1.0) -> np.ndarray:
    """Distance from each point of ``a`` to the nearest point of ``b`` (inf when ``b`` is
    empty), on grids of ``cell`` pixels and coarser."""
    out = np.full(len(a), np.inf)
    if len(b) == 0 or len(a) == 0:
        return out
    todo = np.arange(len(a))
    extent = float(np.ptp(np.vstack([a, b]), axis=0).max()) + 1.0
    while len(todo):
        found = _within_cell(a[todo], b, cell)
        out[todo] = np.minimum(out[todo], found)
        # exact where below the cell: the nearest point is then in the 3x3 block around it
        todo = todo[~(found < cell)] if cell <= extent else todo[:0]
        cell *= 4.0
    return out


def _within_cell(a: np.ndarray, b: np.ndarray, cell: float) -> np.ndarray:
    """Distance to the nearest point of ``b`` in the 3x3 block of cells around each point of
    ``a`` (inf where there is none)."""
    origin = np.minimum(a.min(axis=0), b.min(axis=0)) - cell
    kb = np.floor((b - origin) / cell).astype(np.int64)
    nx = int(max(kb[:, 0].max(), np.floor((a[:, 0].max() - origin[0]) / cell))) + 3
    keys = kb[:, 1] * nx + kb[:, 0]
    order = np.argsort(keys, kind="stable")
    keys, bs = keys[order], b[order]
    best = np.full(len(a), np.inf)
    for lo in range(0, len(a), 65536):
        pa = a[lo:lo + 65536]
        ka = np.floor((pa - origin) / cell).astype(np.int64)
        chunk = best[lo:lo + 65536]
        for dx in (-1, 0, 1):
            for dy in (-1, 0, 1):
                key = (ka[:, 1] + dy) * nx + ka[:, 0] + dx
                first = np.searchsorted(keys, key, "left")
                count = np.searchsorted(keys, key, "right") - first
                has = count > 0
                if not has.any():
                    continue
                c = count[has]
                offsets = np.arange(c.sum()) - np.repeat(np.cumsum(c) - c, c)
                idx_b = np.repeat(first[has], c) + offsets
                d = np.hypot(*(np.repeat(pa[has], c, axis=0) - bs[idx_b]).T)
                starts = np.cumsum(c) - c
                chunk[has] = np.minimum(chunk[has], np.minimum.reduceat(d, starts))
    return best


#: Stroke widths closer than this (pixels) are the same width.
WIDTH_TOLERANCE = 0.01


def _same_style(a: Tuple[Optional[str], Optional[str], Optional[str]],
                b: Tuple[Optional[str], Optional[str], Optional[str]]) -> bool:
    """The same colours (in any case) and stroke widths within WIDTH_TOLERANCE pixels."""
    def width(w: Optional[str]) -> Optional[float]:
        found = _numbers(w or "")
        return found[0] if found else None

    wa, wb = width(a[1]), width(b[1])
    same_width = (wa is None and wb is None) or (wa is not None and wb is not None and abs(wa - wb) <= WIDTH_TOLERANCE)
    return same_width and (a[0] or "").lower() == (b[0] or "").lower() and (a[2] or "").lower() == (b[2] or "").lower()


class Comparison(NamedTuple):
    """Two drawings compared: the share of their line length farther than the tolerance from
    the other, the largest distance (pixels) between lines of a kind both have, where it is,
    the differing points of each, how styles differ and which kinds one drawing lacks."""

    share: float
    largest: float
    at: Tuple[float, float]
    kind: str
    differing: np.ndarray
    styles: List[str]
    only: List[str]


def compare(actual: Drawing, expected: Drawing, pixels: float) -> Comparison:
    """Each drawing's strokes against the other's of the same kind (see the module)."""
    total = differing_length = 0.0
    largest, at, worst_kind = 0.0, (0.0, 0.0), ""
    differing = []
    styles, only = [], []
    for kind in sorted(set(actual.groups) | set(expected.groups)):
        a, e = actual.groups.get(kind), expected.groups.get(kind)
        if a is None or e is None:
            only.append(f"the {kind or 'ungrouped'} lines are only in {'the reference' if a is None else 'actual'}")
        if a is not None and e is not None and not _same_style(a.style, e.style):
            styles.append(f"the {kind or 'ungrouped'} lines' style (stroke, stroke-width, fill) is {a.style}, "
                          f"in the reference {e.style}")
        pa, wa = samples(a.strokes if a else [])
        pe, we = samples(e.strokes if e else [])
        for p, w, other in ((pa, wa, pe), (pe, we, pa)):
            d = nearest(p, other, max(pixels, 1.0))
            far = d > pixels
            total += float(w.sum())
            differing_length += float(w[far].sum())
            differing.append(p[far])
            if a is not None and e is not None and len(d) and d.max() > largest:
                i = int(np.argmax(d))
                largest, at, worst_kind = float(d[i]), (float(p[i, 0]), float(p[i, 1])), kind
    share = differing_length / total if total > 0 else 0.0
    points = np.vstack(differing) if differing else np.zeros((0, 2))
    return Comparison(share, largest, at, worst_kind, points, styles, only)

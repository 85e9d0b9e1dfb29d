"""Noisy CAD parts held out from tuning, meshed unlike :mod:`toonmesh.bench.parts`' grids.

:mod:`toonmesh.bench.parts` maps one regular grid (a subdivided cube) onto every part, so every
vertex has six neighbours and every crease runs along grid lines between equal triangles. Real
CAD meshes are irregular: a tessellator samples each edge at its own rate, joins rows of unequal
counts, fans flat sides from one vertex and leaves long thin triangles along creases. These
parts are made that way, in code (NumPy only, deterministic):

Each part is swept: a closed cross-section (a loop of segments whose ends are the creases along
the sweep) is sampled row by row at a sweep position and a scale, and consecutive rows are
joined by merging their samples in order along the loop (so no triangle crosses a corner, and
rows of different counts give vertices of every valence). Each row samples each segment at its
own jittered count (density varying by up to 2.5x from row to row and segment to segment); rows
sit at the profile's kinks (the creases across the sweep) and, between them, at jittered
spacings. The two ends are flat caps: concentric rings down to a small fan, or one fan from the
centre to the boundary (as a CAD tessellator meshes a flat face: long thin triangles).

``sharp-sphere``
    A sphere cut flat at ``z = +-0.7`` (rim creases of 46 degrees) with a V-groove around its
    equator (creases at the rims and the bottom), rings on the caps.
``twelve-prism``
    A twelve-sided prism: 30-degree creases between the sides, 90 degrees at the caps; the sides'
    rows three times sparser than their samples (triangles long and thin along the vertical
    creases), each cap one fan from its centre.
``chamfered-box``
    A box with its vertical edges chamfered and its top edges bevelled (creases of 45, 90 and
    about 34 degrees, corners where three meet), rings on the caps.
``fandisk-like``
    A tapered extrusion of a house-like profile whose roof dips in a concave arc (a curved
    surface meeting flat ones at creases of several angles, as on the fandisk model).

Noise is :func:`toonmesh.bench.parts.noisy`'s (along the vertex normals, in mean edge lengths).
"""

from __future__ import annotations

from typing import Callable, List, Sequence, Tuple

import numpy as np
import numpy.typing as npt

Mesh = Tuple[npt.NDArray[np.float64], npt.NDArray[np.int64]]
#: A segment of a cross-section: parameters in [0, 1] -> (n, 2) points at scale 1.
Segment = Callable[[npt.NDArray[np.float64]], npt.NDArray[np.float64]]
#: A piece of a profile: parameters in [0, 1] -> (scale, sweep position), each (n,).
Piece = Callable[[npt.NDArray[np.float64]], Tuple[npt.NDArray[np.float64], npt.NDArray[np.float64]]]

HELD_OUT = ("sharp-sphere", "twelve-prism", "chamfered-box", "fandisk-like")
#: How much a row's or a segment's sampling density varies (a factor drawn in this range).
DENSITY_SPREAD = (0.65, 1.6)
#: How far a sample moves from its even spacing, in spacings.
JITTER = 0.35


def _line(p: Sequence[float], q: Sequence[float]) -> Segment:
    a, b = np.asarray(p, float), np.asarray(q, float)
    return lambda t: a + t[:, None] * (b - a)


def _arc(centre: Sequence[float], radius: float, start: float, end: float) -> Segment:
    c = np.asarray(centre, float)
    return lambda t: c + radius * np.stack([np.cos(start + t * (end - start)), np.sin(start + t * (end - start))], 1)


def _polygon(points: Sequence[Sequence[float]]) -> List[Segment]:
    return [_line(points[k], points[(k + 1) % len(points)]) for k in range(len(points))]


def _length(f: Callable[[npt.NDArray[np.float64]], npt.NDArray[np.float64]]) -> float:
    p = f(np.linspace(0.0, 1.0, 65))
    return float(np.linalg.norm(np.diff(p, axis=0), axis=1).sum())


def _spacing(n: int, rng: np.random.Generator) -> npt.NDArray[np.float64]:
    """``n`` parameters in [0, 1): 0 first, the others jittered about even spacing, increasing."""
    t = (np.arange(n) + rng.uniform(-JITTER, JITTER, n)) / n
    t[0] = 0.0
    return np.sort(t)


def _strip(ua: npt.NDArray[np.float64], ia: npt.NDArray[np.int64], ub: npt.NDArray[np.float64],
           ib: npt.NDArray[np.int64], end: float) -> List[Tuple[int, int, int]]:
    """Triangles joining two closed rows (loop parameters ``ua``, ``ub`` increasing from 0 to
    below ``end``; vertex indices ``ia``, ``ib``) by merging them in order: each triangle has
    one row's edge and the other row's vertex, and no triangle crosses a parameter both rows
    hold (a corner). Oriented so that row a -> row b is 'up' with the loop counter-clockwise."""
    ua, ub = np.append(ua, end), np.append(ub, end)
    ia, ib = np.append(ia, ia[0]), np.append(ib, ib[0])
    na, nb = len(ua) - 1, len(ub) - 1
    out = []
    i = j = 0
    while i < na or j < nb:
        if j == nb or (i < na and ua[i + 1] <= ub[j + 1]):
            out.append((ia[i], ia[i + 1], ib[j]))
            i += 1
        else:
            out.append((ia[i], ib[j + 1], ib[j]))
            j += 1
    return out


class _Builder:
    """Vertices and faces of a swept part, in the sweep's frame (loop x, loop y, sweep)."""

    def __init__(self, loop: List[Segment], density: float, rng: np.random.Generator):
        self.loop, self.density, self.rng = loop, density, rng
        self.lengths = [_length(s) for s in loop]
        # The loop's largest distance from its centre (the origin), for the caps' rings.
        self.radius = max(float(np.linalg.norm(s(np.linspace(0.0, 1.0, 65)), axis=1).max()) for s in loop)
        # At least three samples per row, so that no row closes on itself.
        self.least = -(-3 // len(loop))
        self.verts: List[npt.NDArray[np.float64]] = []
        self.faces: List[Tuple[int, int, int]] = []
        self.count = 0

    def _add(self, p: npt.NDArray[np.float64]) -> npt.NDArray[np.int64]:
        self.verts.append(p)
        idx = np.arange(self.count, self.count + len(p))
        self.count += len(p)
        return idx

    def row(self, scale: float, w: float, density: float) -> Tuple[npt.NDArray[np.float64], npt.NDArray[np.int64]]:
        """One loop at ``scale`` and sweep position ``w``: every segment starts at a sample."""
        us, pts = [], []
        for k, (seg, length) in enumerate(zip(self.loop, self.lengths)):
            n = max(self.least, int(round(scale * length * density * self.rng.uniform(*DENSITY_SPREAD))))
            t = _spacing(n, self.rng)
            us.append(k + t)
            pts.append(seg(t) * scale)
        p = np.concatenate(pts)
        return np.concatenate(us), self._add(np.column_stack([p, np.full(len(p), w)]))

    def side(self, profile: List[Piece], row_density: float) -> List[Tuple[npt.NDArray[np.float64], npt.NDArray[np.int64], float, float]]:
        """Rows along the profile's pieces (one at each kink), joined; returns every row."""
        rows = []
        for k, piece in enumerate(profile):
            m = max(1, int(round(_length(lambda t: np.column_stack(piece(t))) * row_density
                                 * self.rng.uniform(*DENSITY_SPREAD))))
            t = (np.arange(m) + np.r_[0.0, self.rng.uniform(-JITTER, JITTER, m - 1)]) / m
            if k == len(profile) - 1:
                t = np.append(t, 1.0)
            scale, w = piece(t)
            for s, z in zip(scale, w):
                u, idx = self.row(float(s), float(z), self.density * self.rng.uniform(*DENSITY_SPREAD))
                if rows:
                    self.faces += _strip(rows[-1][0], rows[-1][1], u, idx, len(self.loop))
                rows.append((u, idx, float(s), float(z)))
        return rows

    def cap(self, u: npt.NDArray[np.float64], idx: npt.NDArray[np.int64], scale: float, w: float, top: bool,
            rings: bool) -> None:
        """A flat cap inside the row (``u``, ``idx``): concentric rings and a small fan at the
        centre, or one fan from the centre (``rings`` False)."""
        new: List[Tuple[int, int, int]] = []
        if rings:
            steps = max(1, int(round(scale * self.radius * self.density)))
            for j in range(1, steps):
                inner = scale * (1.0 - (j + self.rng.uniform(-0.3, 0.3)) / steps)
                u2, idx2 = self.row(inner, w, self.density)
                new += _strip(u, idx, u2, idx2, len(self.loop))
                u, idx = u2, idx2
        centre = int(self._add(np.array([[0.0, 0.0, w]]))[0])
        new += [(centre, int(a), int(b)) for a, b in zip(idx, np.roll(idx, -1))]
        self.faces += new if top else [(a, c, b) for a, b, c in new]

    def mesh(self) -> Mesh:
        return np.concatenate(self.verts), np.asarray(self.faces, np.int64)


def _sphere_profile() -> List[Piece]:
    cut, rim, depth = 0.7, 0.12, 0.1  # flat cuts at z = +-cut, groove half-width and depth
    angle = np.arcsin(cut)

    def arc(a0: float, a1: float) -> Piece:
        return lambda t: (np.cos(a0 + t * (a1 - a0)), np.sin(a0 + t * (a1 - a0)))

    r_rim = np.sqrt(1.0 - rim * rim)

    def wall(z0: float, r0: float, z1: float, r1: float) -> Piece:
        return lambda t: (r0 + t * (r1 - r0), z0 + t * (z1 - z0))

    return [arc(-angle, -np.arcsin(rim)), wall(-rim, r_rim, 0.0, 1.0 - depth), wall(0.0, 1.0 - depth, rim, r_rim),
            arc(np.arcsin(rim), angle)]


def _build(name: str, density: float, seed: int) -> Mesh:
    rng = np.random.default_rng(seed)
    rings = True
    if name == "sharp-sphere":
        loop, profile, row_factor = [_arc((0.0, 0.0), 1.0, 0.0, 2 * np.pi)], _sphere_profile(), 1.0
    elif name == "twelve-prism":
        corners = [(np.cos(a), np.sin(a)) for a in np.arange(12) * np.pi / 6]
        loop, row_factor, rings = _polygon(corners), 1.0 / 3.0, False
        profile = [lambda t: (np.ones_like(t), -1.2 + 2.4 * t)]
    elif name == "chamfered-box":
        c = 0.3
        loop = _polygon([(-1 + c, -1), (1 - c, -1), (1, -1 + c), (1, 1 - c), (1 - c, 1), (-1 + c, 1), (-1, 1 - c),
                         (-1, -1 + c)])
        profile = [lambda t: (np.ones_like(t), -1.0 + 1.7 * t), lambda t: (1.0 - 0.2 * t, 0.7 + 0.3 * t)]
        row_factor = 1.0
    elif name == "fandisk-like":
        # Star-shaped about the origin, so that the caps' rings (scaled copies) nest.
        loop = [_line((-1.0, -0.6), (1.0, -0.6)), _line((1.0, -0.6), (1.0, 0.2)), _line((1.0, 0.2), (0.35, 0.6)),
                _arc((0.0, 1.1), np.hypot(0.35, 0.5), -np.arctan2(0.5, 0.35), -np.pi + np.arctan2(0.5, 0.35)),
                _line((-0.35, 0.6), (-1.0, 0.2)), _line((-1.0, 0.2), (-1.0, -0.6))]
        profile, row_factor = [lambda t: (1.0 - 0.15 * t, -1.0 + 2.0 * t)], 1.0
    else:
        raise ValueError(f"part: unknown held-out part '{name}', expected one of {HELD_OUT}")
    b = _Builder(loop, density, rng)
    rows = b.side(profile, density * row_factor)
    for (u, idx, scale, w), top in ((rows[0], False), (rows[-1], True)):
        b.cap(u, idx, scale, w, top, rings)
    V, F = b.mesh()
    if name == "fandisk-like":  # the sweep along y: (x, z, y) keeps the orientation with a sign
        V = np.column_stack([V[:, 0], -V[:, 2], V[:, 1]])
    return V, F


def part(name: str, faces: int = 20000, seed: int = 0) -> Mesh:
    """The clean held-out part ``name`` (one of HELD_OUT) with about ``faces`` faces (within
    20%), its triangulation drawn from ``seed``. Every part fits in [-1.5, 1.5]^3, outward-
    oriented, closed and manifold."""
    density = 20.0
    V, F = _build(name, density, seed)
    for _ in range(2):  # faces grow as density squared
        density *= np.sqrt(faces / len(F))
        V, F = _build(name, density, seed)
    return V, F

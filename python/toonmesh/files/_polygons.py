"""Polygons of more than three corners, triangulated as the file means them.

trimesh splits every polygon into a fan about its first corner, which is right for a convex
polygon only: the fan of a concave one covers area outside it (an L-shaped or star-shaped face
fills its notches). Here a polygon whose fan is wrong is split by ear clipping in the plane that
fits it best (Newell's normal), so that its triangles cover it once; one whose fan is right (no
fan triangle turned over: a convex polygon, or one seen from its first corner) keeps it.
"""

from __future__ import annotations

import re
from typing import Any, List, Optional, Sequence, Tuple

import numpy as np

#: A fan triangle counts as turned over when its area along the polygon's normal is below minus
#: this share of the fan's.
FAN_TOLERANCE = 1e-9
#: A polygon whose corners lie further from their plane than this share of its size is not flat:
#: it keeps trimesh's fan (no split of it is the right one).
FLAT = 0.01


def plane_coordinates(points: np.ndarray) -> np.ndarray:
    """(n, 2) coordinates of (n, 3) corners in the plane Newell's normal gives, turned so that
    the polygon winds counter-clockwise in them."""
    p = np.asarray(points, dtype=np.float64)
    nxt = np.roll(p, -1, axis=0)
    normal = np.array([np.sum((p[:, 1] - nxt[:, 1]) * (p[:, 2] + nxt[:, 2])),
                       np.sum((p[:, 2] - nxt[:, 2]) * (p[:, 0] + nxt[:, 0])),
                       np.sum((p[:, 0] - nxt[:, 0]) * (p[:, 1] + nxt[:, 1]))])
    length = np.linalg.norm(normal)
    if not length > 0:
        return p[:, :2] * 0
    normal /= length
    helper = np.eye(3)[int(np.argmin(np.abs(normal)))]
    u = np.cross(normal, helper)
    u /= np.linalg.norm(u)
    v = np.cross(normal, u)
    return np.stack([p @ u, p @ v], axis=1)  # counter-clockwise about the normal


def _cross(o: np.ndarray, a: np.ndarray, b: np.ndarray) -> float:
    return float((a[0] - o[0]) * (b[1] - o[1]) - (a[1] - o[1]) * (b[0] - o[0]))


def ear_clip(xy: np.ndarray, keep_straight: bool = False) -> Optional[List[List[int]]]:
    """Triangles (corner indices, counter-clockwise) of a simple polygon given counter-clockwise
    by ear clipping; None where no ear is found (a polygon crossing itself). A straight corner
    left over is dropped, or kept as a triangle without area where ``keep_straight`` (so that
    an n-corner polygon gives n - 2 triangles)."""
    left = list(range(len(xy)))
    out: List[List[int]] = []
    guard = 0
    while len(left) > 3:
        n = len(left)
        for k in range(n):
            i, j, m = left[k - 1], left[k], left[(k + 1) % n]
            if _cross(xy[i], xy[j], xy[m]) <= 0:
                continue  # a reflex (or straight) corner is no ear
            inside = False
            for q in left:
                if q in (i, j, m):
                    continue
                p = xy[q]
                if _cross(xy[i], xy[j], p) >= 0 and _cross(xy[j], xy[m], p) >= 0 and _cross(xy[m], xy[i], p) >= 0:
                    inside = True
                    break
            if not inside:
                out.append([i, j, m])
                del left[k]
                break
        else:
            guard += 1
            if guard > 1:
                return None
            # only straight corners left as candidates: drop one that adds no area
            straight = [k for k in range(n) if abs(_cross(xy[left[k - 1]], xy[left[k]], xy[left[(k + 1) % n]])) == 0]
            if not straight:
                return None
            k = straight[0]
            if keep_straight:
                out.append([left[k - 1], left[k], left[(k + 1) % n]])
            del left[k]
            continue
        guard = 0
    out.append(left)
    return out


def triangles(points: np.ndarray, keep_straight: bool = False) -> List[List[int]]:
    """Triangles (corner indices) of a polygon of (n, 3) corners: its fan where that is right,
    else ear clipping (the fan again for a polygon crossing itself); ``keep_straight``: see
    :func:`ear_clip`."""
    n = len(points)
    fan = [[0, i, i + 1] for i in range(1, n - 1)]
    if n <= 3:
        return fan
    if fans_are_right(np.asarray(points, dtype=np.float64)[None])[0]:
        return fan
    clipped = ear_clip(plane_coordinates(points), keep_straight)
    return fan if clipped is None else clipped


def fans_are_right(points: np.ndarray) -> np.ndarray:
    """Whether the fan about the first corner covers each polygon once (none of its triangles
    turned over), or the polygon is not flat (see :data:`FLAT`), for many polygons of n corners
    at once ((k, n, 3) corners): (k,) bool."""
    p = np.asarray(points, dtype=np.float64)
    nxt = np.roll(p, -1, axis=1)
    normal = np.stack([np.sum((p[..., 1] - nxt[..., 1]) * (p[..., 2] + nxt[..., 2]), axis=1),
                       np.sum((p[..., 2] - nxt[..., 2]) * (p[..., 0] + nxt[..., 0]), axis=1),
                       np.sum((p[..., 0] - nxt[..., 0]) * (p[..., 1] + nxt[..., 1]), axis=1)], axis=1)
    a = p[:, :1]
    # each fan triangle's area along the polygon's normal: all of one sign, and the fan covers
    # each point inside once (its winding number); one turned over covers what is outside
    areas = np.einsum("kij,kj->ki", np.cross(p[:, 1:-1] - a, p[:, 2:] - a), normal)
    scale = np.maximum(np.abs(areas).sum(axis=1), 1e-300)
    # a polygon far from flat has no one right split: trimesh's fan is kept, as it was read
    unit = normal / np.maximum(np.linalg.norm(normal, axis=1, keepdims=True), 1e-300)
    height = np.ptp(np.einsum("kij,kj->ki", p, unit), axis=1)
    size = np.linalg.norm(np.ptp(p, axis=1), axis=1)
    bent = height > FLAT * size
    return np.all(areas >= -FAN_TOLERANCE * scale[:, None], axis=1) | bent


def split_obj(data: bytes) -> bytes:
    """An OBJ's text with each polygon whose fan is wrong (a concave one) written as the
    triangles ear clipping gives, one ``f`` line each, its corners' words as written; other
    lines as they are. Position indices are positive (after
    :func:`toonmesh.files._checks.obj_for_trimesh` where they were not)."""
    lines = data.split(b"\n")
    positions: List[List[float]] = []
    polygons: dict = {}  # corner count -> [(line, words, position indices)]
    for number, raw in enumerate(lines):
        words = (raw.split(b"#", 1)[0] if b"#" in raw else raw).split()
        if not words:
            continue
        if words[0] == b"v":
            positions.append([float(w) for w in words[1:4]])
        elif words[0] == b"f" and len(words) > 4:
            index = [int(w.split(b"/", 1)[0]) - 1 for w in words[1:]]
            polygons.setdefault(len(index), []).append((number, words[1:], index))
    V = np.asarray(positions, dtype=np.float64).reshape(-1, 3)
    replaced = {}
    for n, faces in polygons.items():
        corners = V[np.asarray([f[2] for f in faces], dtype=np.int64)]
        for k in np.flatnonzero(~fans_are_right(corners)):
            number, words, _ = faces[k]
            replaced[number] = b"\n".join(b"f " + b" ".join(words[i] for i in t) for t in triangles(corners[k]))
    if not replaced:
        return data
    return b"\n".join(replaced.get(i, raw) for i, raw in enumerate(lines))


def fan_layout(polygons: Sequence[Any]) -> Tuple[np.ndarray, List[np.ndarray]]:
    """The triangles ``trimesh.geometry.triangulate_quads`` makes of polygons given as corner
    index lists (the triangles, the quads' first halves, their second halves, then each larger
    polygon's fan), and each polygon's rows among them."""
    lengths = np.fromiter((len(p) for p in polygons), dtype=np.int64, count=len(polygons))
    rows: List[np.ndarray] = [np.empty(0, np.int64)] * len(polygons)
    fans: List[np.ndarray] = [np.empty((0, 3), np.int64)]
    at = 0
    tri = np.flatnonzero(lengths == 3).tolist()
    if len(tri):
        fans.append(np.asarray([polygons[k] for k in tri], dtype=np.int64).reshape(-1, 3))
        for r, k in enumerate(tri):
            rows[k] = np.array([r])
        at = len(tri)
    quad = np.flatnonzero(lengths == 4).tolist()
    if len(quad):
        q = np.asarray([polygons[k] for k in quad], dtype=np.int64).reshape(-1, 4)
        fans += [q[:, [0, 1, 2]], q[:, [2, 3, 0]]]
        for r, k in enumerate(quad):
            rows[k] = np.array([at + r, at + len(quad) + r])
        at += 2 * len(quad)
    for k in np.flatnonzero(lengths > 4).tolist():
        p = np.asarray(polygons[k], dtype=np.int64)
        n = len(p)
        rows[k], at = np.arange(at, at + n - 2), at + n - 2
        fans.append(np.stack([np.full(n - 2, p[0]), p[1:-1], p[2:]], axis=1))
    return np.concatenate(fans), rows


def split_fans(vertices: np.ndarray, faces: np.ndarray, polygons: Sequence[Any]) -> Optional[np.ndarray]:
    """trimesh's triangles of a PLY's polygons (``faces``, laid out as :func:`fan_layout` says)
    with each polygon whose fan is wrong (a concave one) split by ear clipping into the same
    rows, so that face colours stay with their faces; None where nothing changes, or where
    ``faces`` are not laid out so (then they are left as trimesh read them)."""
    lengths = np.fromiter((len(p) for p in polygons), dtype=np.int64, count=len(polygons))
    if not len(lengths) or lengths.max() <= 3 or lengths.min() < 3:
        return None
    fans, rows = fan_layout(polygons)
    if not np.array_equal(fans, np.asarray(faces)):
        return None  # not the layout above: left as read
    return split(np.asarray(vertices, dtype=np.float64), fans, rows, polygons, lengths)


def split(V: np.ndarray, fans: np.ndarray, rows: List[np.ndarray], polygons: Sequence[Any],
          lengths: np.ndarray) -> Optional[np.ndarray]:
    """``fans`` (laid out as :func:`fan_layout` says, each polygon's triangles in its ``rows``)
    with each polygon whose fan is wrong split by ear clipping in the same rows; None where
    none is (or a polygon names a vertex outside ``V``, (N, 3) positions). ``lengths``: each
    polygon's corner count."""
    out = None
    for n in np.unique(lengths[lengths > 3]):
        which = np.flatnonzero(lengths == n).tolist()
        index = np.asarray([polygons[k] for k in which], dtype=np.int64).reshape(len(which), n)
        if index.max() >= len(V) or index.min() < 0:
            return None  # said by the reader
        for w in np.flatnonzero(~fans_are_right(V[index])):
            split = triangles(V[index[w]], keep_straight=True)
            if len(split) != n - 2:
                continue
            if out is None:
                out = fans.copy()
            out[rows[which[w]]] = index[w][np.asarray(split)]
    return out


def off_mesh(text: str) -> Optional[Tuple[np.ndarray, np.ndarray]]:
    """(V (N, 3) float64, F (M, 3) int64) of an OFF file (its text, comments stripped), read as
    trimesh reads it (each vertex line's first 3 numbers; each face line's corners), its
    polygons as trimesh lays out their fans (:func:`fan_layout`), a concave one's by ear
    clipping; None where the file is malformed or has no faces (trimesh then reads it and says
    what is wrong). trimesh itself fails on a file that mixes polygons of more than four
    corners with others."""
    try:
        _, _, raw = re.split("(COFF|OFF)", text, maxsplit=1)
        lines = [line.strip() for line in raw.splitlines()]
        lines = [line for line in lines if line]
        counts = lines[0].split()
        v, f = int(counts[0]), int(counts[1])
        V = np.array([line.split()[:3] for line in lines[1 : v + 1]], dtype=np.float64).reshape(v, 3)
        words = [line.split() for line in lines[v + 1 : v + f + 1]]
        if not words:
            return None
        if all(len(w) == 4 and w[0] == "3" for w in words):  # triangles: one array at once
            F = np.array([w[1:] for w in words], dtype=np.int64).reshape(-1, 3)
        else:
            polygons = [[int(w) for w in line[1 : int(line[0]) + 1]] for line in words]
            lengths = np.array([len(p) for p in polygons])
            if lengths.min() < 3:
                return None
            F, rows = fan_layout(polygons)
            clipped = split(V, F, rows, polygons, lengths) if len(F) and F.max() < v else None
            F = F if clipped is None else clipped
    except (ValueError, IndexError, OverflowError):
        return None
    if F.min() < 0 or F.max() >= v:
        return None  # trimesh says so
    return V, F

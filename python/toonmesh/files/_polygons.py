"""Polygons of more than three corners, triangulated as the file means them.

trimesh splits every polygon into a fan about its first corner, which is right for a convex
polygon only: the fan of a concave one covers area outside it (an L-shaped or star-shaped face
fills its notches). Here a polygon whose fan is wrong is split by ear clipping in the plane that
fits it best (Newell's normal), so that its triangles cover it once; one whose fan is right (no
fan triangle turned over: a convex polygon, or one seen from its first corner) keeps it.
"""

from __future__ import annotations

from typing import List, Optional

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


def ear_clip(xy: np.ndarray) -> Optional[List[List[int]]]:
    """Triangles (corner indices, counter-clockwise) of a simple polygon given counter-clockwise
    by ear clipping; None where no ear is found (a polygon crossing itself)."""
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
            del left[straight[0]]
            continue
        guard = 0
    out.append(left)
    return out


def triangles(points: np.ndarray) -> List[List[int]]:
    """Triangles (corner indices) of a polygon of (n, 3) corners: its fan where that is right,
    else ear clipping (the fan again for a polygon crossing itself)."""
    n = len(points)
    fan = [[0, i, i + 1] for i in range(1, n - 1)]
    if n <= 3:
        return fan
    if fans_are_right(np.asarray(points, dtype=np.float64)[None])[0]:
        return fan
    clipped = ear_clip(plane_coordinates(points))
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

"""Helpers shared by the edge tests: peer imports, mesh loading, and the brute-force oracles."""

from pathlib import Path

import numpy as np
import pytest

MESHES = Path(__file__).parent / "data" / "meshes"


from conftest import need  # noqa: E402  (skips on a user machine without the peer, fails in CI)


def load(name):
    trimesh = need("trimesh")
    return trimesh.load(MESHES / name, process=False, force="mesh")


def rotation(seed):
    q = np.random.default_rng(seed).normal(size=4)
    a, b, c, d = q / np.linalg.norm(q)
    return np.array(
        [
            [a * a + b * b - c * c - d * d, 2 * (b * c - a * d), 2 * (b * d + a * c)],
            [2 * (b * c + a * d), a * a - b * b + c * c - d * d, 2 * (c * d - a * b)],
            [2 * (b * d - a * c), 2 * (c * d + a * b), a * a - b * b - c * c + d * d],
        ]
    )


def rows(a):
    """A set of edge tuples, smaller index first."""
    a = np.sort(np.asarray(a).reshape(-1, 2), axis=1)
    return set(map(tuple, a.tolist()))


def normals_and_degenerate(V, F):
    """Oracle face normals (float64) and the degenerate rule of toonmesh.edges."""
    V = V.astype(np.float64)
    p0, p1, p2 = V[F[:, 0]], V[F[:, 1]], V[F[:, 2]]
    n = np.cross(p1 - p0, p2 - p0)
    length = np.linalg.norm(n, axis=1)
    longest = np.max([((p1 - p0) ** 2).sum(1), ((p2 - p0) ** 2).sum(1), ((p2 - p1) ** 2).sum(1)], axis=0)
    repeated = (F[:, 0] == F[:, 1]) | (F[:, 1] == F[:, 2]) | (F[:, 0] == F[:, 2])
    degenerate = repeated | ~(length > 1e-12 * longest)
    unit = np.where(degenerate[:, None], 0.0, n / np.where(length > 0, length, 1.0)[:, None])
    return unit, degenerate


def is_sorted_unique(e):
    e = np.asarray(e)
    if len(e) == 0:
        return True
    assert e.dtype == np.int64 and e.ndim == 2 and e.shape[1] == 2
    assert np.all(e[:, 0] < e[:, 1])
    key = e[:, 0].astype(np.int64) * (e.max() + 1) + e[:, 1]
    return bool(np.all(np.diff(key) > 0))


EPS = 1e-9  # edges with a face within EPS * (|eye| + |vertices|) of edge-on are not compared


def oracle(V, F, eye=None, direction=None):
    """(silhouette edges, edges too close to edge-on to judge) by brute force."""
    V = np.asarray(V, dtype=np.float64)
    n, degenerate = normals_and_degenerate(V, F)
    scale = np.abs(V).max() + (np.abs(eye).max() if eye is not None else 1.0)
    if eye is not None:
        s = np.einsum("ij,ij->i", n, V[F[:, 0]] - np.asarray(eye, dtype=np.float64))
    else:
        d = np.asarray(direction, dtype=np.float64)
        s = n @ (d / np.linalg.norm(d))
        scale = 1.0
    front = (s < 0) & ~degenerate
    back = (s >= 0) & ~degenerate
    close = np.abs(s) <= EPS * scale
    fe = np.sort(np.stack([F, np.roll(F, -1, axis=1)], axis=2).reshape(-1, 2), axis=1)
    face_of = np.repeat(np.arange(len(F)), 3)
    keep = fe[:, 0] != fe[:, 1]
    fe, face_of = fe[keep], face_of[keep]
    uniq, inv, counts = np.unique(fe, axis=0, return_inverse=True, return_counts=True)
    inv = inv.ravel()
    n_front = np.bincount(inv, weights=front[face_of], minlength=len(uniq))
    n_back = np.bincount(inv, weights=back[face_of], minlength=len(uniq))
    n_degen = np.bincount(inv, weights=degenerate[face_of], minlength=len(uniq))
    n_close = np.bincount(inv, weights=close[face_of], minlength=len(uniq))
    # a manifold edge next to a degenerate face (or a face used twice) is never a silhouette
    same_face = np.zeros(len(uniq), dtype=bool)
    two = np.flatnonzero(counts == 2)
    order = np.argsort(inv, kind="stable")
    firsts = np.searchsorted(inv[order], two)
    same_face[two] = face_of[order][firsts] == face_of[order][firsts + 1]
    manifold_ok = (counts == 2) & (n_degen == 0) & ~same_face
    sil = ((counts >= 3) | manifold_ok) & (n_front > 0) & (n_back > 0)
    return rows(uniq[sil]), rows(uniq[n_close > 0])


def random_views(rng, V, k):
    centre = V.mean(axis=0)
    radius = np.abs(V - centre).max()
    for _ in range(k):
        u = rng.normal(size=3)
        u /= np.linalg.norm(u)
        yield dict(eye=tuple(centre + u * radius * rng.uniform(1.5, 6.0)))
        yield dict(direction=tuple(rng.normal(size=3)))

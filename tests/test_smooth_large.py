"""Meshes large enough to take the paths small ones never reach: the spatial reordering of
scattered meshes (over 32,768 vertices) and the closed-fan shortcut of the adjacency build,
checked against a plain NumPy neighbour mean."""

from __future__ import annotations

import numpy as np
import pytest

import toonmesh as tm
from toonmesh import _core

from conftest import rel_err


def neighbour_mean(V: np.ndarray, F: np.ndarray) -> np.ndarray:
    """The mean of each vertex's distinct neighbours (itself where it has none)."""
    e = np.concatenate([F[:, [0, 1]], F[:, [1, 2]], F[:, [2, 0]]])
    e = e[e[:, 0] != e[:, 1]]
    e = np.unique(np.sort(e, axis=1), axis=0)
    both = np.concatenate([e, e[:, ::-1]])
    total = np.zeros_like(V)
    np.add.at(total, both[:, 0], V[both[:, 1]])
    count = np.bincount(both[:, 0], minlength=len(V)).astype(np.float64)
    out = V.copy()
    has = count > 0
    out[has] = total[has] / count[has, None]
    return out


def shuffled(V: np.ndarray, F: np.ndarray, seed: int):
    rng = np.random.default_rng(seed)
    perm = rng.permutation(len(V))  # new index -> old index
    inverse = np.argsort(perm)
    return V[perm], inverse[F][rng.permutation(len(F))], perm


@pytest.mark.parametrize("method", ["laplacian", "taubin", "hc"])
def test_a_shuffled_mesh_smooths_to_the_same_positions(method):
    V, F = _core.icosphere(6, 0.02, 3)  # 40,962 vertices: above the reordering threshold
    Vs, Fs, perm = shuffled(V, F, 1)
    smooth = getattr(tm.smooth, method)
    ours = smooth(V, F, iterations=5)
    theirs = smooth(Vs, Fs, iterations=5)
    assert rel_err(theirs, ours[perm], V) < 1e-12


def test_closed_and_messy_fans_both_give_the_neighbour_mean():
    V, F = _core.icosphere(6, 0.02, 4)
    # Open a hole, repeat a face, reverse one and add a degenerate one: their vertices take
    # the general path, every other vertex the closed-fan shortcut.
    F = np.concatenate([F[10:], F[20:21], F[30:31, ::-1], [[F[40, 0], F[40, 0], F[40, 1]]]])
    got = tm.smooth.laplacian(V, F, iterations=1, lamb=1.0, boundary="free")
    assert rel_err(got, neighbour_mean(V, F), V) < 1e-13
    Vs, Fs, perm = shuffled(V, F, 2)
    got = tm.smooth.laplacian(Vs, Fs, iterations=1, lamb=1.0, boundary="free")
    assert rel_err(got, neighbour_mean(Vs, Fs), V) < 1e-13


def test_a_closed_mesh_matches_trimesh_through_the_plain_mean():
    from conftest import need

    trimesh = need("trimesh")
    V, F = _core.icosphere(6, 0.02, 5)
    m = trimesh.Trimesh(V.copy(), F.copy(), process=False)
    trimesh.smoothing.filter_laplacian(m, iterations=4, volume_constraint=False)
    ours = tm.smooth.laplacian(V, F, iterations=4, preset="trimesh", volume_constraint=False)
    assert rel_err(ours, m.vertices, V) < 1e-12


@pytest.mark.parametrize("method", ["laplacian", "taubin", "hc"])
def test_closed_mesh_shortcuts_give_the_bits_of_the_general_path(method):
    # One stray open triangle makes the mesh not closed, so every vertex takes the general
    # adjacency and cotangent code; the sphere's own vertices must not notice.
    V, F = _core.icosphere(4, 0.03, 5)
    n = len(V)
    stray_V = np.vstack([V, [[3.0, 0, 0], [3.0, 1, 0], [3.0, 0, 1]]])
    stray_F = np.vstack([F, [[n, n + 1, n + 2]]])
    for weights in ("uniform", "cotangent", "distance"):
        fn = getattr(tm.smooth, method)
        closed = fn(V, F, weights=weights, iterations=5)
        general = fn(stray_V, stray_F, weights=weights, iterations=5)
        assert np.array_equal(closed, general[:n]), weights

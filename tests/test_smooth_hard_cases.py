"""Hard cases: degenerate and non-manifold input stays finite and sensible."""

from __future__ import annotations

import numpy as np
import pytest

import toonmesh as tm
from toonmesh import _core

METHODS = {
    "laplacian": lambda V, F, **kw: tm.smooth.laplacian(V, F, **kw),
    "laplacian-cot": lambda V, F, **kw: tm.smooth.laplacian(V, F, weights="cotangent", **kw),
    "laplacian-dist": lambda V, F, **kw: tm.smooth.laplacian(V, F, weights="distance", **kw),
    "taubin": lambda V, F, **kw: tm.smooth.taubin(V, F, **kw),
    "hc": lambda V, F, **kw: tm.smooth.hc(V, F, **kw),
    "implicit": lambda V, F, **kw: tm.smooth.implicit(V, F, **kw),
    "implicit-cot": lambda V, F, **kw: tm.smooth.implicit(V, F, weights="cotangent", **kw),
}


def _in_bounds(out, V, slack=1e-9):
    d = np.linalg.norm(V.max(0) - V.min(0))
    return bool((out >= V.min(0) - slack * d).all() and (out <= V.max(0) + slack * d).all())


def _sphere():
    return _core.icosphere(2, 0.05, 3)


def _with_zero_area_and_needle():
    V, F = _core.grid(8, 0.02, 4)
    n = len(V)
    a, b = F[10, 0], F[10, 1]
    extra = np.array([(V[a] + V[b]) / 2, V[a] + (V[b] - V[a]) * 1e-12 + [0, 0, 1e-13]])
    V = np.vstack([V, extra])
    F = np.vstack([F, [[a, b, n], [a, b, n + 1]]])  # zero-area and needle faces on edge a-b
    return V, F


def _repeated_index_duplicate_flipped():
    V, F = _sphere()
    F = np.vstack([F, [[F[0, 0], F[0, 0], F[0, 1]]], F[:5], F[5:9, ::-1]])
    return V, F


def _nonmanifold_fin():
    V, F = _core.grid(6, 0.0, 0)
    a, b = 7, 8  # an interior edge gets a third face: a fin sticking up
    V = np.vstack([V, (V[a] + V[b]) / 2 + [0, 0, 0.3]])
    F = np.vstack([F, [[a, b, len(V) - 1]]])
    return V, F


def _unreferenced_first_and_last():
    V, F = _sphere()
    V = np.vstack([[[9.0, 9.0, 9.0]], V, [[-9.0, 4.0, 2.0]]])
    return V, F + 1


def _fan(valence=1000):
    t = np.linspace(0, 2 * np.pi, valence, endpoint=False)
    rim = np.c_[np.cos(t), np.sin(t), 0.05 * np.sin(7 * t)]
    V = np.vstack([[0.0, 0.0, 0.3], rim])
    F = np.array([[0, 1 + i, 1 + (i + 1) % valence] for i in range(valence)])
    return V, F


HARD = {
    "zero-area-and-needle": _with_zero_area_and_needle,
    "repeated-duplicate-flipped": _repeated_index_duplicate_flipped,
    "nonmanifold-fin": _nonmanifold_fin,
    "unreferenced-first-last": _unreferenced_first_and_last,
    "fan-1000": _fan,
    "single-triangle": lambda: (np.array([[0.0, 0, 0], [1, 0, 0], [0, 1, 0]]), np.array([[0, 1, 2]])),
}


@pytest.mark.parametrize("case", sorted(HARD))
@pytest.mark.parametrize("method", sorted(METHODS))
@pytest.mark.parametrize("boundary", ["fixed", "free"])
def test_hard_cases_stay_finite_and_bounded(case, method, boundary):
    V, F = HARD[case]()
    out = METHODS[method](V, F, iterations=20, boundary=boundary)
    assert out.shape == V.shape and out.dtype == V.dtype
    assert np.isfinite(out).all()
    if not method.startswith(("taubin", "hc")):  # Taubin/HC inflate on purpose
        assert _in_bounds(out, V)


def test_unreferenced_vertices_stay_put():
    V, F = _unreferenced_first_and_last()
    for fn in METHODS.values():
        out = fn(V, F, iterations=5)
        assert np.array_equal(out[[0, -1]], V[[0, -1]])


def test_fixed_boundary_does_not_move_and_slide_stays_on_the_boundary():
    V, F = _core.grid(10, 0.05, 1)
    on_edge = (V[:, 0] == 0) | (V[:, 0] == 1) | (V[:, 1] == 0) | (V[:, 1] == 1)
    fixed = tm.smooth.laplacian(V, F, iterations=10, boundary="fixed")
    assert np.array_equal(fixed[on_edge], V[on_edge])
    assert not np.array_equal(fixed[~on_edge], V[~on_edge])
    # Sliding: a boundary vertex averages its boundary neighbours only, so moving interior
    # vertices changes nothing on the boundary, and a side's middle moves along that side.
    slid = tm.smooth.laplacian(V, F, iterations=1, boundary="slide")
    W = V.copy()
    W[~on_edge] += 5.0
    assert np.array_equal(tm.smooth.laplacian(W, F, iterations=1, boundary="slide")[on_edge], slid[on_edge])
    side = (V[:, 0] == 0) & (V[:, 1] > 0.2) & (V[:, 1] < 0.8)
    assert np.array_equal(slid[side, 0], V[side, 0])
    free = tm.smooth.laplacian(V, F, iterations=1, boundary="free")
    assert (free[side, 0] > 0).all()


def test_pinned_vertices_do_not_move():
    V, F = _sphere()
    mask = np.zeros(len(V), bool)
    mask[::7] = True
    for fn in METHODS.values():
        out = fn(V, F, iterations=5, pinned=mask)
        assert np.array_equal(out[mask], V[mask])


@pytest.mark.parametrize("method", sorted(METHODS))
@pytest.mark.parametrize("dtype", [np.float32, np.float64])
def test_offset_and_scale_commute_with_smoothing(method, dtype):
    """Translating by 1e6 or scaling by 1e-6 gives the transformed result, within the
    precision the dtype has at that magnitude."""
    V, F = _core.icosphere(3, 0.05, 5)
    base = METHODS[method](V.astype(dtype), F, iterations=5).astype(np.float64)
    eps = np.finfo(dtype).eps
    off = np.array([1e6, -1e6, 1e6])
    shifted = METHODS[method]((V + off).astype(dtype), F, iterations=5).astype(np.float64) - off
    # Rounding the input to the dtype at magnitude 1e6 alone moves points by ~1e6 eps.
    assert np.abs(shifted - base).max() <= 200 * eps * 1e6
    scaled = METHODS[method]((V * 1e-6).astype(dtype), F, iterations=5).astype(np.float64) / 1e-6
    assert np.abs(scaled - base).max() <= 200 * eps


def test_thousand_cotangent_iterations_stay_finite_and_inside():
    V, F = _core.icosphere(3, 0.1, 8)
    for boundary in ("fixed", "free"):
        out = tm.smooth.laplacian(V, F, iterations=1000, weights="cotangent", boundary=boundary)
        assert np.isfinite(out).all() and _in_bounds(out, V)
    Vh, Fh = _with_zero_area_and_needle()
    out = tm.smooth.laplacian(Vh, Fh, iterations=1000, weights="cotangent", boundary="free")
    assert np.isfinite(out).all() and _in_bounds(out, Vh)


def test_float32_input_gives_float32_and_close_to_float64():
    V, F = _core.icosphere(3, 0.05, 2)
    for fn in METHODS.values():
        a = fn(V.astype(np.float32), F, iterations=10)
        b = fn(V, F, iterations=10)
        assert a.dtype == np.float32
        assert np.abs(a - b).max() <= 1e-5


def test_huge_step_implicit_is_stable():
    V, F = _core.icosphere(3, 0.05, 9)
    out = tm.smooth.implicit(V, F, step=1e4, boundary="free")
    assert np.isfinite(out).all() and _in_bounds(out, V)
    # A huge step contracts a closed mesh toward its centroid.
    assert np.ptp(out, axis=0).max() < 0.1 * np.ptp(V, axis=0).max()


def test_implicit_reports_non_convergence():
    V, F = _core.icosphere(3, 0.05, 9)
    with pytest.raises(tm.ConvergenceError, match="max_iter"):
        tm.smooth.implicit(V, F, step=1e6, max_iter=2, tol=1e-14)

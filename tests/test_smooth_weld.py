"""Seam-safe smoothing: with weld=True, a mesh split along seams smooths exactly as its welded
version does, every copy of a point gets the same result, and seams are not boundaries."""

from __future__ import annotations

import numpy as np
import pytest

import toonmesh as tm
from toonmesh import _core

from conftest import diagonal, load_mesh, rel_err

SMOOTH = tm.smooth

# Every method with every weight type, and each preset that has the method.
CASES = [
    ("laplacian", {"weights": w}) for w in ("uniform", "cotangent", "distance")
] + [
    ("taubin", {"weights": w}) for w in ("uniform", "cotangent", "distance")
] + [
    ("hc", {"weights": w}) for w in ("uniform", "cotangent", "distance")
] + [
    ("implicit", {"weights": w, "step": 2.0}) for w in ("uniform", "cotangent", "distance")
] + [
    ("laplacian", {"preset": "trimesh"}),
    ("laplacian", {"preset": "trimesh", "weights": "distance"}),
    ("laplacian", {"preset": "pymeshlab"}),
    ("laplacian", {"preset": "pymeshlab", "weights": "uniform", "boundary": "free"}),
    ("laplacian", {"preset": "paper"}),
    ("taubin", {"preset": "trimesh"}),
    ("taubin", {"preset": "pymeshlab"}),
    ("hc", {"preset": "trimesh"}),
    ("hc", {"preset": "pymeshlab", "iterations": 3}),
    ("implicit", {"preset": "trimesh", "iterations": 2}),
]
IDS = [f"{m}-" + "-".join(f"{k}={v}" for k, v in kw.items()) for m, kw in CASES]


def split_along(V, F, inside):
    """Cuts the mesh along the loop of edges between the faces where `inside` is true and the
    rest: the vertices on that loop are copied (the copies appended after every original
    vertex) and the inside faces use the copies. Returns the split mesh and, per vertex, the
    index of the vertex it copies."""
    V, F = np.asarray(V), np.asarray(F)
    on_inside = np.zeros(len(V), bool)
    on_outside = np.zeros(len(V), bool)
    on_inside[F[inside].ravel()] = True
    on_outside[F[~inside].ravel()] = True
    seam = np.flatnonzero(on_inside & on_outside)
    assert len(seam) >= 3
    copy_of = np.arange(len(V))
    copy_of = np.concatenate([copy_of, seam])
    renumber = np.arange(len(V))
    renumber[seam] = len(V) + np.arange(len(seam))
    F2 = F.copy()
    F2[inside] = renumber[F[inside]]
    return V[copy_of], F2, copy_of


def sphere_split_along_a_loop():
    V, F = _core.icosphere(3, 0.03, 7)
    cap = V[F].mean(axis=1)[:, 2] > 0.35  # a spherical cap: its rim is a closed loop
    return V, F, *split_along(V, F, cap)


def grid_split_along_a_loop():
    V, F = _core.grid(14, 0.02, 3)
    c = V[F].mean(axis=1)
    disc = np.hypot(c[:, 0] - 0.5, c[:, 1] - 0.5) < 0.25  # an island in the middle
    return V, F, *split_along(V, F, disc)


def run(method, V, F, **kw):
    return getattr(SMOOTH, method)(V, F, **kw)


@pytest.mark.parametrize("method,kw", CASES, ids=IDS)
@pytest.mark.parametrize("mesh", [sphere_split_along_a_loop, grid_split_along_a_loop])
def test_a_split_mesh_smooths_to_the_bits_of_its_welded_version(mesh, method, kw):
    V, F, V2, F2, copy_of = mesh()
    welded = run(method, V, F, **kw)
    split = run(method, V2, F2, weld=True, **kw)
    assert split.shape == V2.shape and split.dtype == V2.dtype
    # The copies come after the vertices they copy, so the welded mesh is the original one,
    # vertex for vertex, and the same arithmetic gives the same bits.
    assert np.array_equal(split, welded[copy_of])
    assert not np.array_equal(split, V2)  # it did smooth


@pytest.mark.parametrize("boundary", ["fixed", "free", "slide"])
def test_without_weld_the_seam_tears_or_stays_and_with_weld_it_does_neither(boundary):
    V, F, V2, F2, copy_of = grid_split_along_a_loop()
    seam = np.flatnonzero(copy_of != np.arange(len(copy_of)))
    torn = SMOOTH.laplacian(V2, F2, boundary=boundary)
    gap = np.abs(torn[seam] - torn[copy_of[seam]]).max() / diagonal(V)
    healed = SMOOTH.laplacian(V2, F2, boundary=boundary, weld=True)
    if boundary == "fixed":
        # a seam counts as a boundary: both sides stay where they were
        assert np.array_equal(torn[seam], V2[seam]) and gap == 0
    elif boundary == "free":
        assert gap > 1e-3  # the two sides of the seam move apart
    else:
        # both sides slide along the seam as if it were a boundary
        assert rel_err(torn[seam], healed[seam], V) > 1e-3
    assert np.array_equal(healed[seam], healed[copy_of[seam]])
    assert not np.array_equal(healed[seam], V2[seam])  # a seam is not a boundary
    assert np.array_equal(healed, SMOOTH.laplacian(V, F, boundary=boundary)[copy_of])


@pytest.mark.parametrize("method,kw", CASES[:12], ids=IDS[:12])
def test_a_triangle_soup_smooths_like_the_indexed_mesh(method, kw):
    V, F = _core.icosphere(2, 0.03, 5)
    soup_V, soup_F = V[F].reshape(-1, 3), np.arange(3 * len(F)).reshape(-1, 3)  # an STL
    out = run(method, soup_V, soup_F, weld=True, **kw)
    assert out.shape == soup_V.shape
    # The welded soup numbers its vertices by first use; in that order it is the same bits ...
    first = np.unique(F.ravel(), return_index=True)[1]
    order = F.ravel()[np.sort(first)]  # original vertex of each welded vertex
    renumber = np.empty(len(V), np.int64)
    renumber[order] = np.arange(len(V))
    same_order = run(method, V[order], renumber[F], **kw)
    assert np.array_equal(out, same_order[renumber[F].ravel()])
    # ... and in the original numbering, the same to rounding.
    assert rel_err(out, run(method, V, F, **kw)[F.ravel()], V) < 1e-12
    # Without welding every face is its own island and every vertex on a (fixed) boundary.
    assert np.array_equal(run(method, soup_V, soup_F, **kw), soup_V)


def test_float32_and_pinned_copies():
    V, F, V2, F2, copy_of = sphere_split_along_a_loop()
    V32, V2_32 = V.astype(np.float32), V2.astype(np.float32)
    out = SMOOTH.taubin(V2_32, F2, weld=True)
    assert out.dtype == np.float32
    assert np.array_equal(out, SMOOTH.taubin(V32, F)[copy_of])
    # Pinning one copy pins its position, so all its copies stay.
    seam_copy = len(V)  # the first copy
    pinned = SMOOTH.laplacian(V2, F2, weld=True, pinned=[seam_copy])
    original = copy_of[seam_copy]
    assert np.array_equal(pinned[[seam_copy, original]], V2[[seam_copy, original]])
    assert np.array_equal(pinned, SMOOTH.laplacian(V, F, pinned=[original])[copy_of])


def test_a_mesh_without_copies_is_unchanged_by_weld():
    V, F = _core.icosphere(3, 0.03, 2)
    for w in ("uniform", "cotangent"):
        assert np.array_equal(SMOOTH.laplacian(V, F, weights=w, weld=True), SMOOTH.laplacian(V, F, weights=w))


def test_uv_seams_of_a_textured_mesh_stay_closed():
    V, F = load_mesh("spot")  # split at its UV seams
    _, first, inverse = np.unique(V, axis=0, return_index=True, return_inverse=True)
    inverse = inverse.ravel()
    rep = first[inverse]  # the smallest index at each position
    assert (rep != np.arange(len(V))).sum() > 100
    for boundary in ("free", "fixed"):
        torn = SMOOTH.laplacian(V, F, iterations=20, boundary=boundary)
        out = SMOOTH.laplacian(V, F, iterations=20, boundary=boundary, weld=True)
        gap = np.linalg.norm(torn - torn[rep], axis=1).max() / diagonal(V)
        if boundary == "free":
            assert gap > 1e-3  # cracks open along the seams
        else:
            assert np.array_equal(torn[rep != np.arange(len(V))], V[rep != np.arange(len(V))])
        assert np.array_equal(out, out[rep])  # no cracks: every copy at the same place
        moved = np.linalg.norm(out - V, axis=1)
        assert moved[rep != np.arange(len(V))].min() > 0  # and the seams are smoothed too
        # the same as smoothing the welded mesh itself (representatives in index order)
        reps = np.unique(rep)
        index = np.searchsorted(reps, rep)
        welded = SMOOTH.laplacian(V[reps], index[F], iterations=20, boundary=boundary)
        assert np.array_equal(out, welded[index])


@pytest.mark.parametrize("bad", [1, 0, None, "yes", 1.0, np.int64(1), [True]])
def test_weld_must_be_a_bool(bad):
    V, F = _core.icosphere(1, 0.0, 0)
    for f in (SMOOTH.laplacian, SMOOTH.taubin, SMOOTH.hc, SMOOTH.implicit):
        with pytest.raises(TypeError, match="weld"):
            f(V, F, weld=bad)


def test_weld_accepts_numpy_bools():
    V, F, V2, F2, copy_of = sphere_split_along_a_loop()
    assert np.array_equal(SMOOTH.hc(V2, F2, weld=np.bool_(True)), SMOOTH.hc(V, F)[copy_of])
    assert np.array_equal(SMOOTH.hc(V2, F2, weld=np.bool_(False)), SMOOTH.hc(V2, F2))


def test_the_core_refuses_anything_but_a_bool_too():
    V, F = _core.icosphere(1, 0.0, 0)
    with pytest.raises(TypeError, match="weld"):
        _core._smooth("laplacian", (V, F), weld=1)

"""The feature-preserving smoothers (bilateral and guided normal filtering) keep the contract of
the other smoothers: new arrays in the input's dtype, weld, pinned vertices, hard cases finite,
errors that name the argument, the same bits for any thread count, the GIL released."""

from __future__ import annotations


import numpy as np
import pytest

import toonmesh as tm
from toonmesh import _core
from toonmesh.bench import parts

from conftest import ticks_during
from test_smooth_hard_cases import HARD

FILTERS = {"bilateral": tm.smooth.bilateral, "guided": tm.smooth.guided}


@pytest.fixture(scope="module")
def noisy_box():
    V, F = parts.part("box", 3000)
    return parts.noisy(V, F, 0.3, seed=2), F, V


@pytest.mark.parametrize("name", sorted(FILTERS))
def test_returns_a_new_array_of_the_input_dtype_and_leaves_the_input_alone(noisy_box, name):
    N, F, clean = noisy_box
    N0, F0 = N.copy(), F.copy()
    out = FILTERS[name](N, F)
    assert out.dtype == np.float64 and out.shape == N.shape
    assert np.array_equal(N, N0) and np.array_equal(F, F0)
    assert not np.shares_memory(out, N)
    assert parts.normal_error(out, F, clean) < 0.3 * parts.normal_error(N, F, clean)
    out32 = FILTERS[name](N.astype(np.float32), F.astype(np.int32))
    assert out32.dtype == np.float32
    scale = np.linalg.norm(N.max(0) - N.min(0))
    assert np.abs(out32 - out).max() < 1e-4 * scale


@pytest.mark.parametrize("name", sorted(FILTERS))
def test_scale_and_offset_commute(noisy_box, name):
    N, F, _ = noisy_box
    ref = FILTERS[name](N, F)
    for s, t in ((1e-6, 0.0), (1e6, 0.0), (1.0, 5.0), (2.0**-600, 0.0), (2.0**600, 0.0)):
        out = FILTERS[name](N * s + t, F)
        assert np.abs((out - t) / s - ref).max() < 1e-6 * np.abs(ref).max()


@pytest.mark.parametrize("name", sorted(FILTERS))
@pytest.mark.parametrize("part", parts.PARTS)
def test_rotation_commutes_on_the_parts(name, part):
    # Exact invariance needs no decision near a tie (a face's flip test, the guided filter's
    # choice of patch), which random soups do not give but a part's surface does.
    V, F = parts.part(part, 3000)
    N = parts.noisy(V, F, 0.4, seed=5)
    q, _ = np.linalg.qr(np.random.default_rng(6).standard_normal((3, 3)))
    out = FILTERS[name](N, F)
    rotated = FILTERS[name](N @ q.T + [3.0, -1.0, 2.0], F)
    assert np.abs((rotated - [3.0, -1.0, 2.0]) @ q - out).max() < 1e-9


@pytest.mark.parametrize("name", sorted(FILTERS))
def test_pinned_vertices_come_back_exactly(noisy_box, name):
    N, F, _ = noisy_box
    pinned = np.arange(0, len(N), 7)
    out = FILTERS[name](N, F, pinned=pinned)
    assert np.array_equal(out[pinned], N[pinned])
    others = np.setdiff1d(np.arange(len(N)), pinned)
    assert (np.abs(out[others] - N[others]).max(axis=1) > 0).mean() > 0.9


@pytest.mark.parametrize("name", sorted(FILTERS))
def test_a_split_mesh_with_weld_gives_the_welded_result(noisy_box, name):
    N, F, _ = noisy_box
    soup = N[F.ravel()]
    soup_faces = np.arange(len(soup)).reshape(-1, 3)
    welded = FILTERS[name](N, F)
    out = FILTERS[name](soup, soup_faces, weld=True)
    assert np.array_equal(out, welded[F.ravel()])
    # without weld every face is alone: each is already flat, so nothing moves
    alone = FILTERS[name](soup, soup_faces)
    assert np.abs(alone - soup).max() < 1e-9


@pytest.mark.parametrize("case", sorted(HARD))
@pytest.mark.parametrize("name", sorted(FILTERS))
def test_hard_cases_stay_finite_and_near(case, name):
    V, F = HARD[case]()
    out = FILTERS[name](V, F)
    assert np.isfinite(out).all()
    used = np.zeros(len(V), bool)
    used[F.ravel()] = True
    assert np.array_equal(out[~used], V[~used])
    d = np.linalg.norm(V.max(0) - V.min(0))
    assert np.abs(out - V).max() < 0.5 * d


@pytest.mark.parametrize("name", sorted(FILTERS))
def test_a_clean_part_stays_nearly_as_it_is(name):
    V, F = parts.part("fandisk", 3000)
    out = FILTERS[name](V, F)
    assert parts.normal_error(out, F, V) < 0.5


def test_heavy_noise_leaves_fewer_faces_turned_over_than_it_made():
    V, F = parts.part("fandisk", 3000)
    N = parts.noisy(V, F, 0.7, seed=3)
    clean = parts.face_normals(V, F)

    def turned(X):
        return int((np.einsum("ij,ij->i", parts.face_normals(X, F), clean) < 0).sum())

    for fn in FILTERS.values():
        assert turned(fn(N, F)) < min(turned(N), 0.01 * len(F))


@pytest.mark.parametrize(
    "kwargs, error, message",
    [
        (dict(iterations=-1), ValueError, r"iterations: must be in \[0, 1000000\], got -1"),
        (dict(iterations=2.5), TypeError, "iterations: expected an integer, got float"),
        (dict(vertex_iterations=10**7), ValueError, "vertex_iterations: must be in"),
        (dict(sigma_s=0.0), ValueError, "sigma_s: must be a finite number > 0, got 0"),
        (dict(sigma_r=float("nan")), ValueError, "sigma_r: must be a finite number > 0, got NaN"),
        (dict(sigma_r="0.3"), TypeError, "sigma_r: expected a number, got str"),
        (dict(weld=1), TypeError, r"weld: expected a bool \(True or False\)"),
        (dict(pinned=[10**9]), IndexError, "pinned"),
    ],
)
@pytest.mark.parametrize("name", sorted(FILTERS))
def test_bad_options_name_the_argument(noisy_box, name, kwargs, error, message):
    N, F, _ = noisy_box
    with pytest.raises(error, match=message):
        FILTERS[name](N, F, **kwargs)


def test_bad_mesh_input_names_the_argument():
    with pytest.raises(ValueError, match="vertices: vertex 2 is not finite"):
        tm.smooth.guided(np.array([[0, 0, 0], [1, 0, 0], [0, np.nan, 0]]), np.array([[0, 1, 2]]))
    with pytest.raises(IndexError, match="faces: face 0 refers to vertex 3"):
        tm.smooth.bilateral(np.eye(3), np.array([[0, 1, 3]]))


def test_the_paper_preset_is_its_own_rule_with_a_fixed_range_width(noisy_box):
    N, F, clean = noisy_box
    paper = tm.smooth.guided(N, F, preset="paper")
    assert not np.array_equal(paper, tm.smooth.guided(N, F))
    assert np.array_equal(paper, tm.smooth.guided(N, F, preset="PAPER", sigma_r=0.35))
    assert not np.array_equal(paper, tm.smooth.guided(N, F, preset="paper", sigma_r=0.5))
    assert parts.normal_error(paper, F, clean) < 0.3 * parts.normal_error(N, F, clean)
    with pytest.raises(ValueError, match="preset: unknown value 'trimesh'; expected one of 'paper'"):
        tm.smooth.guided(N, F, preset="trimesh")
    with pytest.raises(TypeError, match="preset"):
        tm.smooth.bilateral(N, F, preset="paper")


def test_zero_vertex_iterations_returns_a_copy(noisy_box):
    N, F, _ = noisy_box
    out = tm.smooth.guided(N, F, vertex_iterations=0)
    assert np.array_equal(out, N) and not np.shares_memory(out, N)


def test_same_bits_for_any_thread_count():
    V, F = parts.part("cylinder", 20000)  # several chunks of work per pass
    N = parts.noisy(V, F, 0.4, seed=4)
    try:
        results = {}
        for n in (1, 2, 5):
            tm.set_num_threads(n)
            results[n] = [fn(N, F) for fn in FILTERS.values()]
        for n in (2, 5):
            for a, b in zip(results[1], results[n]):
                assert np.array_equal(a, b)
    finally:
        tm.set_num_threads(0)


def test_releases_the_gil():
    V, F = _core.icosphere(6, 0.05, 4)
    seconds, during = ticks_during(lambda: tm.smooth.guided(V, F, iterations=10))
    assert seconds > 0.02 and during >= 3

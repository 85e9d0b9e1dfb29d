"""The smoothing API as users meet it: input forms, errors, dtypes, threads, fork, GIL."""

from __future__ import annotations

import os
import sys
import time

import numpy as np
import pytest

import toonmesh as tm
from toonmesh import _core

from conftest import need, ticks_during


@pytest.fixture
def mesh():
    return _core.icosphere(3, 0.05, 1)


def test_any_memory_order_and_index_dtype(mesh):
    V, F = mesh
    ref = tm.smooth.laplacian(V, F)
    assert np.array_equal(tm.smooth.laplacian(np.asfortranarray(V), F), ref)
    Vs = np.zeros((len(V), 6))
    Vs[:, ::2] = V  # a strided view
    assert np.array_equal(tm.smooth.laplacian(Vs[:, ::2], F), ref)
    for dt in (np.int32, np.int64, np.uint32):
        assert np.array_equal(tm.smooth.laplacian(V, np.asfortranarray(F.astype(dt))), ref)
    assert np.array_equal(tm.smooth.laplacian(V.tolist(), F.tolist()), ref)


def test_inputs_are_never_modified(mesh):
    trimesh = need("trimesh")
    V, F = mesh
    V0, F0 = V.copy(), F.copy()
    for fn in (tm.smooth.laplacian, tm.smooth.taubin, tm.smooth.hc, tm.smooth.implicit):
        fn(V, F)
    assert np.array_equal(V, V0) and np.array_equal(F, F0)
    m = trimesh.Trimesh(V.copy(), F.copy(), process=False)
    out = tm.smooth.laplacian(m, preset="trimesh")
    assert np.array_equal(m.vertices, V0)
    ref = trimesh.Trimesh(V.copy(), F.copy(), process=False)
    trimesh.smoothing.filter_laplacian(ref)
    assert np.abs(out - ref.vertices).max() < 1e-12


@pytest.mark.parametrize(
    "vertices,faces,exc,match",
    [
        (np.zeros((4, 2)), np.array([[0, 1, 2]]), ValueError, r"vertices: expected shape \(N, 3\)"),
        (np.zeros((4, 3), np.int64), np.array([[0, 1, 2]]), TypeError, "vertices: dtype must be float32 or float64"),
        (np.array([[0, 0, 0], [1, 0, 0], [0, np.nan, 0]]), np.array([[0, 1, 2]]), ValueError, "vertices: vertex 2 is not finite"),
        (np.array([[0, 0, 0], [1, 0, 0], [0, np.inf, 0]]), np.array([[0, 1, 2]]), ValueError, "not finite"),
        (np.zeros((0, 3)), np.zeros((0, 3), np.int64), ValueError, "vertices: the mesh has no vertices"),
        (np.eye(3), np.zeros((0, 3), np.int64), ValueError, "faces: the mesh has no faces"),
        (np.eye(3), np.array([[0, 1, 3]]), IndexError, "faces: face 0 refers to vertex 3"),
        (np.eye(3), np.array([[0, -1, 2]]), IndexError, "faces: face 0 has a negative vertex index"),
        (np.eye(3), np.array([[0.0, 1, 2]]), TypeError, "faces: dtype must be int32, int64, uint32 or uint64"),
        (np.eye(3), np.array([[0, 1, 2, 0]]), ValueError, r"faces: expected shape \(M, 3\)"),
        (np.eye(3), None, TypeError, "faces: required"),
    ],
)
def test_bad_mesh_input_names_the_argument(vertices, faces, exc, match):
    with pytest.raises(exc, match=match):
        tm.smooth.laplacian(vertices, faces)


@pytest.mark.parametrize(
    "kwargs,match",
    [
        (dict(weights="cot"), "weights: unknown value 'cot'"),
        (dict(boundary="clamp"), "boundary: unknown value"),
        (dict(preset="blender"), "preset: unknown value"),
        (dict(iterations=-1), "iterations: must be in"),
        (dict(lamb=float("nan")), "lamb: must be a finite number"),
        (dict(lamb=1.5), "lamb: must be a finite number in"),
        (dict(weights="cotangent", preset="trimesh"), "weights: laplacian.preset='trimesh'. has no such weights"),
        (dict(boundary="fixed", preset="trimesh"), "boundary: .*has no boundary option"),
        (dict(lamb=0.5, preset="pymeshlab"), "lamb: .*has no step size"),
        (dict(volume_constraint=True, preset="paper"), "volume_constraint: .*has no volume constraint"),
        (dict(pinned=np.array([0, 10**6])), "pinned: vertex index 1000000 is outside"),
        (dict(pinned=np.zeros(3, bool)), "pinned: a boolean mask needs"),
    ],
)
def test_bad_options_name_the_argument(mesh, kwargs, match):
    V, F = mesh
    with pytest.raises((ValueError, IndexError), match=match):
        tm.smooth.laplacian(V, F, **kwargs)


def test_presets_that_do_not_exist_are_refused(mesh):
    V, F = mesh
    with pytest.raises(ValueError, match="preset: implicit.preset='pymeshlab'. does not exist"):
        tm.smooth.implicit(V, F, preset="pymeshlab")
    with pytest.raises(ValueError, match="preset: taubin.preset='paper'. does not exist"):
        tm.smooth.taubin(V, F, preset="paper")


def test_paper_preset_is_the_plain_neighbour_mean(mesh):
    V, F = mesh
    nbrs = [set() for _ in range(len(V))]
    for a, b, c in F:
        nbrs[a] |= {b, c}
        nbrs[b] |= {a, c}
        nbrs[c] |= {a, b}
    X = V.copy()
    for _ in range(3):
        X = np.array([X[sorted(n)].mean(axis=0) for n in nbrs])
    assert np.abs(tm.smooth.laplacian(V, F, iterations=3, preset="paper") - X).max() < 1e-14


def test_zero_iterations_returns_a_copy(mesh):
    V, F = mesh
    out = tm.smooth.laplacian(V, F, iterations=0)
    assert np.array_equal(out, V) and out is not V and not np.shares_memory(out, V)


def test_same_bits_for_any_thread_count():
    V, F = _core.icosphere(6, 0.05, 4)  # large enough to take the spatially reordered path
    calls = [
        lambda: tm.smooth.laplacian(V, F, weights="cotangent"),
        lambda: tm.smooth.hc(V, F),
        lambda: tm.smooth.implicit(V, F, step=5.0, weights="distance"),
        lambda: tm.smooth.laplacian(V.astype(np.float32), F, volume_constraint=True),
    ]
    before = tm.get_num_threads()
    try:
        results = {}
        for n in (1, 2, 3, 7):
            tm.set_num_threads(n)
            assert tm.get_num_threads() == n
            results[n] = [c() for c in calls]
        for n in (2, 3, 7):
            for a, b in zip(results[1], results[n]):
                assert np.array_equal(a, b)
    finally:
        tm.set_num_threads(0)
    assert tm.get_num_threads() == before


def test_an_absurd_thread_count_is_refused_and_changes_nothing():
    before = tm.get_num_threads()
    with pytest.raises(ValueError, match=r"n.*at most 1024 threads, got 1000000"):
        tm.set_num_threads(10**6)
    assert tm.get_num_threads() == before
    with pytest.raises(ValueError, match=r"n: must be >= 0"):
        tm.set_num_threads(-1)
    assert tm.get_num_threads() == before


@pytest.mark.skipif(not hasattr(os, "fork"), reason="needs os.fork")
def test_works_in_a_forked_child_after_the_pool_started(mesh):
    V, F = mesh
    ref = tm.smooth.laplacian(V, F)  # starts the thread pool in the parent
    r, w = os.pipe()
    pid = os.fork()
    if pid == 0:  # child: must not hang on the parent's (absent) worker threads
        try:
            ok = np.array_equal(tm.smooth.laplacian(V, F), ref)
            os.write(w, b"1" if ok else b"0")
        finally:
            os._exit(0)
    os.close(w)
    deadline = time.time() + 60
    while time.time() < deadline:
        done, _ = os.waitpid(pid, os.WNOHANG)
        if done:
            break
        time.sleep(0.05)
    else:
        os.kill(pid, 9)
        pytest.fail("smoothing hung in a forked child")
    assert os.read(r, 1) == b"1"


def test_releases_the_gil():
    V, F = _core.icosphere(6, 0.05, 4)
    seconds, during = ticks_during(lambda: tm.smooth.laplacian(V, F, iterations=30, weights="cotangent"))
    # With the GIL held the ticker could not run at all while smoothing.
    assert seconds > 0.02 and during >= 3


@pytest.mark.parametrize(
    "kwargs, error, message",
    [
        (dict(iterations=2.5), TypeError, "iterations: expected an integer, got float"),
        (dict(iterations=True), TypeError, "iterations: expected an integer, got bool"),
        (dict(lamb="0.5"), TypeError, "lamb: expected a number, got str"),
        (dict(weights=1), TypeError, "weights: expected a string, got int"),
        (dict(preset=("trimesh",)), TypeError, "preset: expected a string"),
        (dict(volume_constraint=1), TypeError, r"volume_constraint: expected a bool \(True or False\)"),
        (dict(pinned=3), TypeError, "pinned: expected vertex indices or an"),
        (dict(pinned=[[0, 1]]), TypeError, "pinned: expected vertex indices or an"),
    ],
)
def test_options_of_the_wrong_python_type_are_named(mesh, kwargs, error, message):
    V, F = mesh
    with pytest.raises(error, match=message):
        tm.smooth.laplacian(V, F, **kwargs)


def test_pinned_accepts_lists_tuples_and_empty_input(mesh):
    V, F = mesh
    as_array = tm.smooth.laplacian(V, F, pinned=np.array([0, 5]))
    assert np.array_equal(tm.smooth.laplacian(V, F, pinned=[0, 5]), as_array)
    mask = [i in (0, 5) for i in range(len(V))]
    assert np.array_equal(tm.smooth.laplacian(V, F, pinned=tuple(mask)), as_array)
    assert np.array_equal(as_array[[0, 5]], V[[0, 5]])
    free = tm.smooth.laplacian(V, F)
    assert np.array_equal(tm.smooth.laplacian(V, F, pinned=[]), free)
    assert np.array_equal(tm.smooth.laplacian(V, F, pinned=np.array([])), free)
    # NumPy scalars are fine where Python numbers are.
    assert np.array_equal(tm.smooth.laplacian(V, F, iterations=np.int64(3), lamb=np.float32(0.25)),
                          tm.smooth.laplacian(V, F, iterations=3, lamb=float(np.float32(0.25))))


def test_huge_unsigned_indices_are_reported_as_given(mesh):
    V, F = mesh
    Fu = F.astype(np.uint64)
    Fu[0, 0] = 2**63 + 5
    with pytest.raises(IndexError, match=r"faces: face 0 refers to vertex 9223372036854775813,"):
        tm.smooth.laplacian(V, Fu)
    with pytest.raises(IndexError, match=r"pinned: vertex index 18446744073709551615 is outside"):
        tm.smooth.laplacian(V, F, pinned=np.array([2**64 - 1], dtype=np.uint64))


def test_an_absurd_thread_count_in_the_environment_is_capped():
    import subprocess

    env = dict(os.environ, TOONMESH_NUM_THREADS="5000")
    out = subprocess.run([sys.executable, "-c", "import toonmesh; print(toonmesh.get_num_threads())"],
                         env=env, capture_output=True, text=True, check=True)
    assert out.stdout.strip() == "1024"

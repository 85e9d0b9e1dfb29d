"""Soak: many calls keep resident memory flat, and many threads at once give the sequential
results bit for bit. ``TOONMESH_LONG_TESTS=1`` runs ten times as many calls."""

from __future__ import annotations

import gc
import os
from concurrent.futures import ThreadPoolExecutor

import numpy as np
import pytest

import toonmesh as tm
from toonmesh import edges as te

from conftest import long_tests


def resident_bytes() -> int:
    with open("/proc/self/statm") as f:
        return int(f.read().split()[1]) * os.sysconf("SC_PAGE_SIZE")


def _small_calls():
    """Smoothing calls on small meshes (every method, both dtypes, and refused arguments), and
    the outline calls that go with them."""
    V, F = tm.shapes.icosphere(1, noise=0.1, seed=1)
    G, H = tm.shapes.grid(6, noise=0.1, seed=2)
    V32 = V.astype(np.float32)
    smoothing = [
        lambda: tm.smooth.laplacian(V, F),
        lambda: tm.smooth.laplacian(V32, F, weights="cotangent", iterations=3),
        lambda: tm.smooth.laplacian(G, H, weights="distance", boundary="slide", pinned=[0, 3]),
        lambda: tm.smooth.taubin(V, F, iterations=4),
        lambda: tm.smooth.hc(G, H, iterations=3),
        lambda: tm.smooth.implicit(V, F, step=2.0),
        lambda: tm.smooth.laplacian(V, F, preset="pymeshlab"),
        lambda: tm.smooth.laplacian(V * 1e300, F, weights="cotangent", iterations=2),
        lambda: tm.smooth.laplacian(V, F, lamb=float("nan")),  # refused
        lambda: tm.smooth.laplacian(V, F + 100),  # refused
    ]
    outlines = [
        lambda: te.feature_edges(V, F, crease_angle=10.0),
        lambda: te.silhouette(G, H, eye=(0.5, 0.5, 3.0)),
        lambda: te.sobel(G[:, :2].reshape(6, 12)),
    ]
    return smoothing, outlines


def _call(f):
    try:
        return f()
    except (ValueError, IndexError, TypeError):
        return None


@pytest.mark.skipif(not os.path.exists("/proc/self/statm"), reason="reads /proc/self/statm")
def test_resident_memory_stays_flat_over_many_smoothing_calls():
    smoothing, outlines = _small_calls()
    n = 100_000 if long_tests() else 10_000

    def run(count):
        for i in range(count):
            _call(smoothing[i % len(smoothing)])
            if i % 4 == 0:
                _call(outlines[(i // 4) % len(outlines)])

    run(1000)  # warm-up: the thread pool, NumPy's and the allocator's caches
    gc.collect()
    before = resident_bytes()
    run(n)
    gc.collect()
    after = resident_bytes()
    growth = (after - before) / before
    print(f"resident memory: {before / 2**20:.1f} MiB before, {after / 2**20:.1f} MiB after {n} calls")
    assert growth <= 0.05, f"grew {growth:.1%} ({(after - before) / 2**20:.1f} MiB) over {n} smoothing calls"


def _same(a, b):
    if isinstance(a, np.ndarray):
        return isinstance(b, np.ndarray) and a.dtype == b.dtype and np.array_equal(a, b)
    if isinstance(a, tuple):
        return all(_same(x, y) for x, y in zip(a, b))
    if hasattr(a, "__dataclass_fields__"):
        return all(_same(getattr(a, k), getattr(b, k)) for k in a.__dataclass_fields__)
    return a == b


def test_eight_threads_at_once_give_the_sequential_results_bit_for_bit():
    V, F = tm.shapes.icosphere(4, noise=0.05, seed=3)
    G, H = tm.shapes.grid(40, noise=0.05, seed=4)
    index = te.EdgeIndex(V, F, crease_angle=5.0)
    image = np.random.default_rng(5).random((300, 200)).astype(np.float32)
    tasks = [
        lambda: tm.smooth.laplacian(V, F, weights="cotangent"),
        lambda: tm.smooth.taubin(G, H, weights="distance", boundary="slide"),
        lambda: tm.smooth.hc(V.astype(np.float32), F),
        lambda: tm.smooth.implicit(V, F, step=3.0, volume_constraint=True),
        lambda: tm.smooth.laplacian(G, H, preset="trimesh"),
        lambda: te.feature_edges(V, F, crease_angle=5.0),
        lambda: te.silhouette(G, H, direction=(0.2, 0.1, -1.0)),
        lambda: index.outlines(eye=(0.5, 2.0, 3.0)),
        lambda: te.sobel(image),
    ]
    expected = [t() for t in tasks]
    rounds = 12 if long_tests() else 3
    with ThreadPoolExecutor(max_workers=8) as pool:
        futures = [(i, pool.submit(tasks[i])) for _ in range(rounds) for i in range(len(tasks))]
        for i, f in futures:
            assert _same(f.result(timeout=120), expected[i]), f"task {i} differs when run from 8 threads"

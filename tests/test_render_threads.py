"""Rendering: threads, repeated renders and memory."""

from __future__ import annotations

import threading

import numpy as np
import pytest

import toonmesh as tm
from toonmesh import _core

BACKENDS = ["vulkan", "gl"]


def _rss_bytes() -> int:
    with open("/proc/self/status") as f:
        for line in f:
            if line.startswith("VmRSS:"):
                return int(line.split()[1]) * 1024
    raise RuntimeError("no VmRSS")


@pytest.mark.parametrize("backend", BACKENDS)
def test_threads_give_the_same_images_as_one_after_another(backend):
    V, F = _core.icosphere(3, 0.03, 1)
    r = tm.Renderer(backend)
    mesh = r.add_mesh(V, F)
    views = [tm.Camera.fit((np.sin(a), 0.4, np.cos(a))) for a in np.linspace(0, 6, 8)]
    materials = [tm.Material.bands(), tm.Material.thresholded_phong(), tm.Material.lut(), tm.Material.phong()]
    jobs = [(v, materials[i % 4], (40 + i, 30 + 2 * i)) for i, v in enumerate(views)]

    def one(job):
        cam, mat, (w, h) = job
        return r.render(mesh, camera=cam, material=mat, width=w, height=h, outputs=("color", "depth")).color

    expected = [one(j) for j in jobs]
    results = [None] * (len(jobs) * 3)
    errors = []

    def worker(k):
        try:
            for i in range(k, len(results), 8):
                results[i] = one(jobs[i % len(jobs)])
        except Exception as e:  # pragma: no cover - reported below
            errors.append(e)

    threads = [threading.Thread(target=worker, args=(k,)) for k in range(8)]
    for t in threads:
        t.start()
    for t in threads:
        t.join()
    assert not errors
    for i, img in enumerate(results):
        assert np.array_equal(img, expected[i % len(jobs)])


def test_a_thousand_renders_keep_memory_flat():
    # every kind of frame: outputs, outlines, vector lines, antialiasing, shadows, hatching and
    # dithering, a stream of views
    V, F = _core.icosphere(2, 0.03, 0)
    r = tm.Renderer()
    mesh = r.add_mesh(V, F)
    kinds = [
        dict(),
        dict(outputs=("color", "normal", "depth")),
        dict(outlines="both", outputs=("color", "outline", "lines")),
        dict(msaa=4, supersample=2, outlines="mesh"),
        dict(lights=[tm.Light.directional((0.3, -1.0, -0.5), shadows=True)], outputs=("color", "shadow"),
             material=tm.Material.hatching(dither="bayer4")),
    ]

    def frames(n):
        for i in range(n):
            r.render(mesh, width=64, height=64, camera=tm.Camera.fit((1.0, 0.1 * (i % 7), 1.0)), **kinds[i % len(kinds)])
            if i % 100 == 0:
                r.render_many(mesh, [tm.Camera.fit((1.0, 0.1 * k, 1.0)) for k in range(4)], width=32, height=32)

    frames(200)
    before = _rss_bytes()
    frames(1000)
    grown = _rss_bytes() - before
    assert grown < 0.05 * before, f"RSS grew by {grown / 2**20:.1f} MiB ({grown / before:.1%}) over 1000 renders"


def test_transient_meshes_are_freed():
    V, F = _core.icosphere(3, 0.0, 0)
    r = tm.Renderer()
    for _ in range(20):
        r.render(tm.Mesh(V, F), width=16, height=16)
    assert r._engine.mesh_count == 0

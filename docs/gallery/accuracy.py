"""Accuracy against time, measured while the site is built.

Left: what smoothing buys for its time. A unit sphere of 10,242 vertices with 2% radial noise,
smoothed by each method for 1, 3, 10 and 30 iterations (implicit: that many steps of 1); the
error is the RMS error of the radius. Right: the renderer's accuracy knobs on the smoothed bunny
at 256x256 in toon bands, against the same frame supersampled 4 times: the mean difference of
the pixels (0-255) against the frame's time. Times are medians of 3 on the machine that built
this page; the tables of the [accuracy page](../accuracy.md) were measured the same way at
larger sizes (``python -m toonmesh.bench all --accuracy``). Needs matplotlib
(``pip install matplotlib``).
"""

import time

import matplotlib.pyplot as plt
import numpy as np

import toonmesh as tm
from toonmesh.data import bunny


def timed(f, repeat=3):
    """The result of f() and its median time in milliseconds."""
    times = []
    for _ in range(repeat):
        t0 = time.perf_counter()
        out = f()
        times.append(time.perf_counter() - t0)
    return out, 1e3 * float(np.median(times))


V, F = tm.shapes.icosphere(5, noise=0.02, seed=0)
methods = {
    "laplacian": lambda n: tm.smooth.laplacian(V, F, iterations=n),
    "cotangent": lambda n: tm.smooth.laplacian(V, F, iterations=n, weights="cotangent"),
    "taubin": lambda n: tm.smooth.taubin(V, F, iterations=n),
    "hc": lambda n: tm.smooth.hc(V, F, iterations=n),
    "implicit": lambda n: tm.smooth.implicit(V, F, step=1.0, iterations=n),
}
fig, (left, right) = plt.subplots(1, 2, figsize=(11, 4.2))
for name, smooth in methods.items():
    smooth(1)  # warm-up: the thread pool starts on first use
    points = []
    for n in (1, 3, 10, 30):
        X, ms = timed(lambda: smooth(n))
        points.append((ms, np.sqrt(np.mean((np.linalg.norm(X, axis=1) - 1) ** 2))))
    left.plot(*zip(*points), "o-", label=name)
left.axhline(
    np.sqrt(np.mean((np.linalg.norm(V, axis=1) - 1) ** 2)),
    color="gray",
    ls=":",
    label="input",
)
left.set(
    xscale="log",
    yscale="log",
    xlabel="time (ms)",
    ylabel="RMS error of the radius",
    title="smoothing: 1, 3, 10, 30 iterations",
)
left.legend(fontsize=8)

B, G = bunny()
B = tm.smooth.laplacian(B, G, iterations=5, preset="paper")
renderer = tm.Renderer()
mesh = renderer.add_mesh(B, G)
size = dict(width=256, height=256, material=tm.Material.bands("#f08a3c"))
reference = renderer.render(mesh, supersample=4, **size).color.astype(float)
knobs = {
    "band_antialias=False": dict(band_antialias=False),
    "default": {},
    "msaa=4": dict(msaa=4),
    "supersample=2": dict(supersample=2),
    "supersample=3": dict(supersample=3),
    "msaa=4, supersample=2": dict(msaa=4, supersample=2),
}
for name, knob in knobs.items():
    renderer.render(mesh, **size, **knob)  # warm-up: pipelines are made on first use
    r, ms = timed(lambda: renderer.render(mesh, **size, **knob))
    error = np.abs(r.color.astype(float) - reference).mean()
    right.plot(ms, error, "o")
    right.annotate(
        name, (ms, error), fontsize=8, xytext=(4, 4), textcoords="offset points"
    )
right.set(
    xlabel="frame time (ms)",
    ylabel="mean difference to 4x supersampling (0-255)",
    title="rendering: accuracy knobs, 256x256",
    yscale="log",
)
fig.tight_layout()
fig.savefig("accuracy.png", dpi=90)

"""Smoothing: every method on a noisy sphere and on the raw bunny.

Top: a unit sphere with 3% radial noise, then 10 iterations of each method with its defaults
(``implicit`` one step of 5); each panel gives the RMS error of the radius. Bottom: the raw
Stanford bunny scan and the same methods, toon-shaded, where the noise of the scan turns into
scattered band borders and smoothing makes the bands clean. The last panel is the papers'
pipeline: 5 iterations of the plain neighbour mean (``preset="paper"``).
"""

import numpy as np
from PIL import Image

import toonmesh as tm
from toonmesh.data import bunny
from toonmesh.figures import panels

SIZE = 200


sphere = tm.shapes.icosphere(4, noise=0.03, seed=0)
scan = bunny()
methods = {
    "input": lambda V, F: V,
    "laplacian": lambda V, F: tm.smooth.laplacian(V, F, iterations=10),
    "taubin": lambda V, F: tm.smooth.taubin(V, F, iterations=10),
    "hc": lambda V, F: tm.smooth.hc(V, F, iterations=10),
    "implicit": lambda V, F: tm.smooth.implicit(V, F, step=5.0),
    "paper preset, 5": lambda V, F: tm.smooth.laplacian(
        V, F, iterations=5, preset="paper"
    ),
}
images, labels = [], []
for (V, F), camera in (
    (sphere, tm.Camera.fit((0.5, 0.4, 1.0))),
    (scan, tm.Camera.fit((0.35, 0.3, 1.0))),
):
    for name, smooth in methods.items():
        X = smooth(V, F)
        r = tm.render(
            X,
            F,
            camera=camera,
            material=tm.Material.bands("#f08a3c"),
            outlines="mesh",
            width=SIZE,
            height=SIZE,
        )
        text = name
        if V is sphere[0]:
            text += f"  rms {np.sqrt(np.mean((np.linalg.norm(X, axis=1) - 1) ** 2)):.4f}"
        images.append(r.color)
        labels.append(text)
Image.fromarray(panels(images, labels, columns=len(methods))).save(
    "smoothing.png", optimize=True
)

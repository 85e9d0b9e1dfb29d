"""Smoothing: every method on a noisy sphere and on the raw bunny.

Top: a unit sphere with 3% radial noise, then 10 iterations of each method with its defaults
(``implicit`` one step of 5); each panel gives the RMS error of the radius. Bottom: the raw
Stanford bunny scan and the same methods, toon-shaded, where the noise of the scan turns into
scattered band borders and smoothing makes the bands clean. The last panel is the papers'
pipeline: 5 iterations of the plain neighbour mean (``preset="paper"``).
"""

import numpy as np
from PIL import Image, ImageDraw, ImageFont

import toonmesh as tm
from toonmesh.data import bunny

SIZE = 200


def label(image: np.ndarray, text: str) -> np.ndarray:
    """``image`` (H, W, 4) uint8 with ``text`` on a white box at its top left."""
    pil = Image.fromarray(image)
    draw = ImageDraw.Draw(pil)
    font = ImageFont.load_default(size=13)
    box = draw.textbbox((6, 4), text, font=font)
    draw.rectangle((box[0] - 3, box[1] - 2, box[2] + 3, box[3] + 2), fill="white")
    draw.text((6, 4), text, font=font, fill="black")
    return np.asarray(pil)


sphere = tm.shapes.icosphere(4, noise=0.03, seed=0)
scan = bunny()
methods = {
    "input": lambda V, F: V,
    "laplacian": lambda V, F: tm.smooth.laplacian(V, F, iterations=10),
    "taubin": lambda V, F: tm.smooth.taubin(V, F, iterations=10),
    "hc": lambda V, F: tm.smooth.hc(V, F, iterations=10),
    "implicit": lambda V, F: tm.smooth.implicit(V, F, step=5.0),
    "paper preset, 5": lambda V, F: tm.smooth.laplacian(V, F, iterations=5, preset="paper"),
}
rows = []
for (V, F), camera in ((sphere, tm.Camera.fit((0.5, 0.4, 1.0))), (scan, tm.Camera.fit((0.35, 0.3, 1.0)))):
    row = []
    for name, smooth in methods.items():
        X = smooth(V, F)
        r = tm.render(X, F, camera=camera, material=tm.Material.bands("#f08a3c"), outlines="mesh",
                      width=SIZE, height=SIZE)
        text = name
        if V is sphere[0]:
            text += f"  rms {np.sqrt(np.mean((np.linalg.norm(X, axis=1) - 1) ** 2)):.4f}"
        row.append(label(r.color, text))
    rows.append(np.concatenate(row, axis=1))
Image.fromarray(np.concatenate(rows, axis=0)).save("smoothing.png", optimize=True)

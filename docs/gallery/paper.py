"""Paper grain.

Paper grain on the smoothed bunny. Left to right: toon bands and ink
without paper; ``Paper()`` (the built-in grain, fixed to the screen); ``Paper(strength=0.9,
scale=2)`` under hatching, where the tooth breaks up strokes and lines as pencil on rough paper;
``Paper(space="surface")``, the grain fixed to the surface; and a user's grain image (a canvas
weave made here with NumPy).
"""

from pathlib import Path

import numpy as np
from PIL import Image

import toonmesh as tm
from toonmesh.data import bunny
from toonmesh.figures import panels

SIZE = 260
LABELS = [
    "no paper",
    "Paper()",
    "hatching, strength=0.9",
    'Paper(space="surface")',
    "Paper(canvas())",
]


def canvas(n: int = 32) -> np.ndarray:
    """A canvas weave: over-and-under threads, as an (n, n) grey image in [0, 1]."""
    t = np.linspace(0, 4 * np.pi, n, endpoint=False)
    warp, weft = np.meshgrid(np.sin(t) ** 2, np.cos(t) ** 2)
    return (
        0.5 * (warp + weft)
        + 0.15 * np.sign(np.sin(t))[None, :] * np.sign(np.sin(t))[:, None]
        + 0.15
    ).clip(0, 1)


def main() -> None:
    V, F = bunny()
    V = tm.smooth.laplacian(V, F, iterations=5, preset="paper")
    kw = dict(width=SIZE, height=SIZE, outlines="mesh", background="#f4efe4")
    bands = tm.Material.bands("#e08850")
    cells = [
        tm.render(V, F, material=bands, **kw).color,
        tm.render(V, F, material=bands, paper=tm.Paper(), **kw).color,
        tm.render(
            V,
            F,
            material=tm.Material.hatching(),
            paper=tm.Paper(strength=0.9, scale=2.0),
            **kw,
        ).color,
        tm.render(
            V,
            F,
            material=bands,
            paper=tm.Paper(space="surface", strength=0.8, scale=2.0),
            **kw,
        ).color,
        tm.render(
            V, F, material=bands, paper=tm.Paper(canvas(), strength=0.5, scale=1.0), **kw
        ).color,
    ]
    out = Path("paper.png")
    Image.fromarray(panels(cells, LABELS)).save(out, optimize=True)
    print("wrote", out)


if __name__ == "__main__":
    main()

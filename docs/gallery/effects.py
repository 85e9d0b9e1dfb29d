"""Toon looks: band borders, tones, hatching and shadows.

The toon finish, before (top: the papers' own settings) and after
(bottom: the defaults). Columns: the smoothed bunny in toon bands, the bunny cross-hatched, the
cow in bands, the cow cross-hatched, and a torus casting a shadow on a floor. Before: hard band borders
(``band_antialias=False``), the paper's band values (``Material.bands(preset="paper")``: the
darkest band and the shadow black, so ink vanishes over them) and triplanar hatching
(``mode="triplanar"``). After: band borders blended over a pixel, the darkest tone keeping 30%
of the colour, and hatching along the form (principal directions). No supersampling, so the
band borders show as the renderer draws them.
"""

from pathlib import Path

import numpy as np
from PIL import Image

import toonmesh as tm
from toonmesh.data import bunny, cow
from toonmesh.figures import panels

SIZE = 300


def torus_over_floor():
    """A torus 0.8 above a square floor 6 wide: the scene as one mesh."""
    V, F = tm.shapes.torus(1.0, 0.35, 48, 24)
    floor = np.array([[-3.0, 0, -3], [3, 0, -3], [3, 0, 3], [-3, 0, 3]])
    return np.vstack([V + (0, 0.8, 0), floor]), np.vstack(
        [F, np.array([[0, 2, 1], [0, 3, 2]]) + len(V)]
    )


def main() -> None:
    Vb, Fb = bunny()
    Vb = tm.smooth.laplacian(Vb, Fb, iterations=5, preset="paper")
    Vs, Fs = cow()
    (Vt, Ft), direction, eye = torus_over_floor(), (0.5, -2.0, 0.3), (0.3, 1.5, 1.2)
    light = [tm.Light.directional((0.6, -0.5, -1.0))]
    images, labels = [], []
    for before in (True, False):
        kw = dict(width=SIZE, height=SIZE, outlines="mesh", band_antialias=not before)
        bands = tm.Material.bands("#f08a3c", preset="paper" if before else None)
        hatching = tm.Material.hatching(mode="triplanar" if before else "field")
        side = dict(camera=tm.Camera.fit((0.9, 0.3, 1.0)), lights=light)
        cells = [
            tm.render(Vb, Fb, material=bands, lights=light, **kw).color,
            tm.render(Vb, Fb, material=hatching, lights=light, **kw).color,
            tm.render(
                Vs,
                Fs,
                material=tm.Material.bands("#d8c8f0", preset="paper" if before else None),
                **side,
                **kw,
            ).color,
            tm.render(Vs, Fs, material=hatching, **side, **kw).color,
            tm.render(
                Vt,
                Ft,
                material=tm.Material.bands("#e8a040", preset="paper" if before else None),
                lights=[tm.Light.directional(direction, shadows=True)],
                camera=tm.Camera.fit(eye),
                **kw,
            ).color,
        ]
        names = ["bands", "hatching", "bands", "hatching", "shadows"]
        when = "before" if before else "defaults"
        images += cells
        labels += [f"{when}: {name}" for name in names]
    out = Path("effects.png")
    Image.fromarray(panels(images, labels, columns=5)).save(out, optimize=True)
    print("wrote", out)


if __name__ == "__main__":
    main()

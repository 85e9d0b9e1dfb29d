"""Toon looks: band borders, tones, hatching and shadows.

The toon finish, before (top: the papers' own settings) and after
(bottom: the defaults). Columns: the smoothed bunny in toon bands, the bunny cross-hatched, spot
in bands, spot cross-hatched, and a torus casting a shadow on a floor. Before: hard band borders
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
from toonmesh.files._load import read_mesh
from toonmesh.bench.effects import SHADOW_SCENES
from toonmesh.data import bunny

ROOT = Path(__file__).resolve().parents[2]  # the repository: its test meshes
SIZE = 300


def main() -> None:
    Vb, Fb = bunny()
    Vb = tm.smooth.laplacian(Vb, Fb, iterations=5, preset="paper")
    Vs, Fs = read_mesh(str(ROOT / "tests" / "data" / "meshes" / "spot.obj"))
    (Vt, Ft), direction, eye = SHADOW_SCENES["torus over a plane"]
    light = [tm.Light.directional((0.6, -0.5, -1.0))]
    rows = []
    for before in (True, False):
        kw = dict(width=SIZE, height=SIZE, outlines="mesh", band_antialias=not before)
        bands = tm.Material.bands("#f08a3c", preset="paper" if before else None)
        hatching = tm.Material.hatching(mode="triplanar" if before else "field")
        spot = dict(camera=tm.Camera.fit((1.0, 0.35, 0.9)), lights=light)
        cells = [
            tm.render(Vb, Fb, material=bands, lights=light, **kw).color,
            tm.render(Vb, Fb, material=hatching, lights=light, **kw).color,
            tm.render(Vs, Fs, material=tm.Material.bands("#d8c8f0", preset="paper" if before else None), **spot, **kw).color,
            tm.render(Vs, Fs, material=hatching, **spot, **kw).color,
            tm.render(Vt, Ft, material=tm.Material.bands("#e8a040", preset="paper" if before else None),
                      lights=[tm.Light.directional(direction, shadows=True)], camera=tm.Camera.fit(eye), **kw).color,
        ]
        rows.append(np.concatenate(cells, axis=1))
    out = Path("effects.png")
    Image.fromarray(np.concatenate(rows, axis=0)).save(out, optimize=True)
    print("wrote", out)


if __name__ == "__main__":
    main()

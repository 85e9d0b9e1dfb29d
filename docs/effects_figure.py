"""Draws docs/effects.png: shadows, hatching and dithering. Left: a torus over a floor lit by a
shadow-casting light (Kang, Kim and Yoon's shadow z-buffer; the shadowed floor falls to the
lowest tone). Middle: the smoothed bunny cross-hatched (Borquez and Yepez), with mesh outlines.
Right: the same bunny dithered between its bands (Bayer 4x4 in screen space, 2-pixel cells).
Run from the repository root: ``python docs/effects_figure.py``.
"""

from pathlib import Path

import numpy as np
from PIL import Image

import toonmesh as tm
from toonmesh.bench.effects import SHADOW_SCENES
from toonmesh.data import bunny

ROOT = Path(__file__).resolve().parent.parent
SIZE = 360


def main() -> None:
    (V, F), direction, eye = SHADOW_SCENES["torus over a plane"]
    kw = dict(width=SIZE, height=SIZE, supersample=2)
    shadows = tm.render(V, F, lights=[tm.Light.directional(direction, shadows=True)],
                        material=tm.Material.lut(tm.kang_table(), color="#e8a040"), camera=tm.Camera.fit(eye),
                        outlines="mesh", **kw).color
    Vb, Fb = bunny()
    Vb = tm.smooth.laplacian(Vb, Fb, iterations=5, preset="paper")
    light = [tm.Light.directional((0.6, -0.5, -1.0))]
    hatched = tm.render(Vb, Fb, material=tm.Material.hatching(), lights=light, outlines="mesh", **kw).color
    dithered = tm.render(Vb, Fb, material=tm.Material.bands(dither=tm.Dither("bayer4", scale=2.0)), lights=light,
                         width=SIZE, height=SIZE).color
    row = np.concatenate([shadows, hatched, dithered], axis=1)
    out = ROOT / "docs" / "effects.png"
    Image.fromarray(row).save(out, optimize=True)
    print("wrote", out)


if __name__ == "__main__":
    main()

"""Rim light.

The rim light on the smoothed bunny in toon bands. Left to right: no rim;
``Rim()`` (white light added where n.v < 0.3); ``Rim(side="lit")`` under a light from the right;
``Rim("#5080ff", side="shadowed", blend="mix")``, a back light's glow painted on the dark side;
and a soft orange rim (``softness=0.3``, painted over) on a hatched bunny. On a dark background,
as rim light is usually shown.
"""

from pathlib import Path

from PIL import Image

import toonmesh as tm
from toonmesh.data import bunny
from toonmesh.figures import panels

SIZE = 260
LABELS = ["no rim", "Rim()", 'Rim(side="lit")', 'Rim(side="shadowed")', "hatching + Rim"]


def main() -> None:
    V, F = bunny()
    V = tm.smooth.laplacian(V, F, iterations=5, preset="paper")
    side = [tm.Light.directional((-1.0, -0.3, -0.4))]
    kw = dict(width=SIZE, height=SIZE, outlines="mesh", lights=side, background="#3a4050")
    colour = "#f08a3c"
    cells = [
        tm.render(V, F, material=tm.Material.bands(colour), **kw).color,
        tm.render(V, F, material=tm.Material.bands(colour, rim=tm.Rim()), **kw).color,
        tm.render(
            V,
            F,
            material=tm.Material.bands(
                colour, rim=tm.Rim(width=0.4, strength=0.8, side="lit")
            ),
            **kw,
        ).color,
        tm.render(
            V,
            F,
            material=tm.Material.bands(
                colour, rim=tm.Rim("#5080ff", width=0.4, side="shadowed", blend="mix")
            ),
            **kw,
        ).color,
        tm.render(
            V,
            F,
            material=tm.Material.hatching(
                rim=tm.Rim("#ff9020", width=0.5, softness=0.3, strength=1.0, blend="mix")
            ),
            **kw,
        ).color,
    ]
    out = Path("rim.png")
    Image.fromarray(panels(cells, LABELS)).save(out, optimize=True)
    print("wrote", out)


if __name__ == "__main__":
    main()

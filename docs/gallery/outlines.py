"""Ink outlines in the render.

Ink outlines in the render. Top row: the fandisk CAD part with
mesh-space lines (silhouettes, boundaries, creases as ridges and valleys: Kang, Kim and Yoon),
with image-space lines (between pixels whose normals turn or whose depths jump, the default
rule; no threshold to scale with the model), and the
line drawing alone (the ``outline`` output). Bottom row: the same for the smoothed bunny.
"""

import numpy as np
from PIL import Image

import toonmesh as tm
from toonmesh.data import bunny, fandisk
from toonmesh.figures import panels

SIZE = 360


def row(V, F, material, camera, crease_angle):
    """The model with mesh outlines, with image outlines, and its ink alone."""
    mesh = tm.Outlines(
        "mesh", crease_angle=crease_angle, ridge="#202060", valley="#a02020", width=1.8
    )
    image = tm.Outlines("image", width=1.8)
    kw = dict(material=material, camera=camera, width=SIZE, height=SIZE, supersample=2)
    a = tm.render(V, F, outlines=mesh, **kw).color
    b = tm.render(V, F, outlines=image, **kw).color
    ink = tm.render(
        V,
        F,
        outlines=tm.Outlines("both", crease_angle=crease_angle, width=1.8),
        outputs="outline",
        **kw,
    ).outline
    c = np.dstack(
        [
            np.repeat(((1 - ink) * 255).astype(np.uint8)[..., None], 3, axis=2),
            np.full(ink.shape, 255, np.uint8),
        ]
    )
    return [a, b, c]


def main() -> None:
    V1, F1 = fandisk()
    V2, F2 = bunny()
    V2 = tm.smooth.laplacian(V2, F2, iterations=5, preset="paper")
    top = row(V1, F1, tm.Material.bands("#8fb8de"), tm.Camera.fit((0.6, 0.5, 1.0)), 40.0)
    toon = tm.Material.thresholded_phong("#f08a3c", t_h=0.1, t_s=0.9)
    bottom = row(V2, F2, toon, tm.Camera.fit((0.35, 0.3, 1.0)), 60.0)
    labels = [
        'Outlines("mesh")',
        'Outlines("image")',
        'Outlines("both"): outputs="outline"',
    ] * 2
    Image.fromarray(panels(top + bottom, labels, columns=3)).save(
        "outlines.png", optimize=True
    )


if __name__ == "__main__":
    main()

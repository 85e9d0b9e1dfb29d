"""Normals: smooth, flat or auto.

The three normal modes (rows: ``"smooth"``, ``"flat"``, ``"auto"``) on
a box, a chess pawn (``shapes.pawn``), the fandisk CAD part and the bunny, with toon bands.
Smooth shading bends the bands across the box's edges and the pawn's rims, flat shading facets
the curved parts, and auto keeps both right; on the bunny auto is close to smooth.
"""

from PIL import Image

import toonmesh as tm
from toonmesh.data import bunny, fandisk
from toonmesh.figures import panels

SIZE = 220


def main() -> None:
    models = [
        (tm.shapes.box(), tm.Camera.fit((0.6, 0.5, 1.0)), "#8fb8de"),
        (tm.shapes.pawn(48), tm.Camera.fit((0.0, 0.35, 1.0)), "#e8c07a"),
        (fandisk(), tm.Camera.fit((0.6, 0.5, 1.0)), "#8fb8de"),
        (bunny(), tm.Camera.fit((0.35, 0.3, 1.0)), "#f08a3c"),
    ]
    images, labels = [], []
    for normals in ("smooth", "flat", "auto"):
        for (V, F), camera, colour in models:
            images.append(
                tm.render(
                    V,
                    F,
                    normals=normals,
                    camera=camera,
                    material=tm.Material.bands(colour),
                    width=SIZE,
                    height=SIZE,
                    supersample=2,
                ).color
            )
            labels.append(f'normals="{normals}"')
    Image.fromarray(panels(images, labels, columns=len(models))).save(
        "normals.png", optimize=True
    )


if __name__ == "__main__":
    main()

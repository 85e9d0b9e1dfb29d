"""CAD files by default: before and after.

Three CAD parts read from files the script writes: the fandisk (``toonmesh.data.fandisk``) and
a turned flange (``toonmesh.shapes.lathe``) as OBJ files without normals, y up, and a plate
with a round hole as an STL (z up, as CAD and 3D-printing tools write them). Top row, as the defaults drew them before: smooth normals across
every edge (star-shaped smears on the flat faces, bands bent over the edges) and a view from
(0.35, 0.3, 1) whatever the file's up axis (the STL from above). Bottom row, the defaults now:
normals split at the creases a drawing keeps (``normals="auto"``), and a three-quarter view
about the format's up axis that fills the frame. Needs trimesh to read and write the files
(``pip install 'toonmesh[io]'``).
"""

import numpy as np
import trimesh
from PIL import Image

import toonmesh as tm
from toonmesh.data import fandisk
from toonmesh.figures import panels

SIZE = 260
# a flange: (radius, height) up the outside, a bore of radius 0.25 through it
FLANGE = [
    (0.25, 0.0),
    (1.0, 0.0),
    (1.0, 0.2),
    (0.5, 0.2),
    (0.5, 0.9),
    (0.25, 0.9),
    (0.25, 0.0),
]


def plate_with_hole(segments: int = 48):
    """A square plate 2 wide and 0.4 thick with a round hole through it, z up."""
    a = np.linspace(0, 2 * np.pi, segments, endpoint=False)
    ring = np.c_[np.cos(a), np.sin(a)]
    square = ring / np.abs(ring).max(axis=1, keepdims=True)
    V = np.vstack(
        [np.c_[r, np.full(segments, z)] for z in (0.0, 0.4) for r in (square, 0.5 * ring)]
    )
    ob, ib, ot, it = (np.arange(segments) + k * segments for k in range(4))
    F = []
    for i in range(segments):
        j = (i + 1) % segments
        F += [
            [ot[i], it[i], it[j]],
            [ot[i], it[j], ot[j]],
            [ob[i], ib[j], ib[i]],
            [ob[i], ob[j], ib[j]],
        ]
        F += [
            [ob[i], ot[j], ot[i]],
            [ob[i], ob[j], ot[j]],
            [ib[i], it[i], it[j]],
            [ib[i], it[j], ib[j]],
        ]
    return V, np.array(F)


def main() -> None:
    trimesh.Trimesh(*fandisk(), process=False).export(
        "fandisk.obj", include_normals=False
    )
    trimesh.Trimesh(*tm.shapes.lathe(FLANGE, 64), process=False).export(
        "flange.obj", include_normals=False
    )
    trimesh.Trimesh(*plate_with_hole(), process=False).export("plate.stl")
    files = ["fandisk.obj", "flange.obj", "plate.stl"]
    look = dict(
        material=tm.Material.bands("#8fb8de"),
        outlines="mesh",
        width=SIZE,
        height=SIZE,
        supersample=2,
    )
    before = [
        tm.render(
            f, normals="smooth", camera=tm.Camera.fit((0.35, 0.3, 1.0)), up="y", **look
        ).color
        for f in files
    ]
    after = [tm.render(f, **look).color for f in files]
    labels = [f"before: {name}" for name in files] + [
        f"defaults: {name}" for name in files
    ]
    Image.fromarray(panels(before + after, labels, columns=3)).save(
        "cad_files.png", optimize=True
    )


if __name__ == "__main__":
    main()

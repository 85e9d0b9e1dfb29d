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
from PIL import Image, ImageDraw, ImageFont

import toonmesh as tm
from toonmesh.data import fandisk

SIZE = 260
# a flange: (radius, height) up the outside, a bore of radius 0.25 through it
FLANGE = [(0.25, 0.0), (1.0, 0.0), (1.0, 0.2), (0.5, 0.2), (0.5, 0.9), (0.25, 0.9), (0.25, 0.0)]


def label(image: np.ndarray, text: str) -> np.ndarray:
    """``image`` (H, W, 4) uint8 with ``text`` on a white box at its top left."""
    pil = Image.fromarray(image)
    draw = ImageDraw.Draw(pil)
    font = ImageFont.load_default(size=13)
    box = draw.textbbox((6, 4), text, font=font)
    draw.rectangle((box[0] - 3, box[1] - 2, box[2] + 3, box[3] + 2), fill="white")
    draw.text((6, 4), text, font=font, fill="black")
    return np.asarray(pil)


def plate_with_hole(segments: int = 48):
    """A square plate 2 wide and 0.4 thick with a round hole through it, z up."""
    a = np.linspace(0, 2 * np.pi, segments, endpoint=False)
    ring = np.c_[np.cos(a), np.sin(a)]
    square = ring / np.abs(ring).max(axis=1, keepdims=True)
    V = np.vstack([np.c_[r, np.full(segments, z)] for z in (0.0, 0.4) for r in (square, 0.5 * ring)])
    ob, ib, ot, it = (np.arange(segments) + k * segments for k in range(4))
    F = []
    for i in range(segments):
        j = (i + 1) % segments
        F += [[ot[i], it[i], it[j]], [ot[i], it[j], ot[j]], [ob[i], ib[j], ib[i]], [ob[i], ob[j], ib[j]]]
        F += [[ob[i], ot[j], ot[i]], [ob[i], ob[j], ot[j]], [ib[i], it[i], it[j]], [ib[i], it[j], ib[j]]]
    return V, np.array(F)


def main() -> None:
    trimesh.Trimesh(*fandisk(), process=False).export("fandisk.obj", include_normals=False)
    trimesh.Trimesh(*tm.shapes.lathe(FLANGE, 64), process=False).export("flange.obj", include_normals=False)
    trimesh.Trimesh(*plate_with_hole(), process=False).export("plate.stl")
    files = ["fandisk.obj", "flange.obj", "plate.stl"]
    look = dict(material=tm.Material.bands("#8fb8de"), outlines="mesh", width=SIZE, height=SIZE, supersample=2)
    before = [tm.render(f, normals="smooth", camera=tm.Camera.fit((0.35, 0.3, 1.0)), up="y", **look).color
              for f in files]
    after = [tm.render(f, **look).color for f in files]
    before = [label(image, f"before: {name}") for image, name in zip(before, files)]
    after = [label(image, f"defaults: {name}") for image, name in zip(after, files)]
    figure = np.concatenate([np.concatenate(before, axis=1), np.concatenate(after, axis=1)], axis=0)
    Image.fromarray(np.ascontiguousarray(figure)).save("cad_files.png", optimize=True)


if __name__ == "__main__":
    main()

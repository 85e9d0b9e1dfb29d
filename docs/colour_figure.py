"""Draws docs/colour.png: colour on the mesh. Left: the smoothed bunny with vertex colours (its
height and depth as red and blue), bands and outlines. Middle: a sphere with a checker texture
on an equirectangular map (uv from longitude and latitude), hatched over the texture's colour.
Right: an icosphere with a colour a face, flat normals, Kang et al.'s tones.
Run from the repository root: ``python docs/colour_figure.py``.
"""

from pathlib import Path

import numpy as np
from PIL import Image

import toonmesh as tm
from toonmesh.bench.effects import sphere_uv
from toonmesh.data import bunny

ROOT = Path(__file__).resolve().parent.parent
SIZE = 360


def main() -> None:
    kw = dict(width=SIZE, height=SIZE, supersample=2, lights=[tm.Light.directional((0.6, -0.5, -1.0))])
    Vb, Fb = bunny()
    Vb = tm.smooth.laplacian(Vb, Fb, iterations=5, preset="paper")
    t = (Vb - Vb.min(0)) / np.ptp(Vb, 0)
    colours = np.stack([0.3 + 0.7 * t[:, 1], np.full(len(Vb), 0.55), 1.0 - 0.7 * t[:, 2]], -1)
    bunny_image = tm.render([tm.Mesh(Vb, Fb, vertex_colors=colours)], outlines="mesh", **kw).color
    V, F = tm.shapes.icosphere(5)
    cells = np.indices((16, 32)).sum(0) % 2
    checker = np.where(cells[..., None] == 1, [230, 120, 40], [250, 235, 200]).astype(np.uint8)
    checker = np.kron(checker, np.ones((16, 16, 1), np.uint8))  # 16 texels a cell: crisp cell borders
    textured = tm.render([tm.Mesh(V, F, uv=sphere_uv(V), texture=checker)], material=tm.Material.hatching(),
                         outlines="mesh", **kw).color
    Vi, Fi = tm.shapes.icosphere(1)
    faces = np.random.default_rng(4).integers(60, 256, (len(Fi), 3)).astype(np.uint8)
    flat = tm.render([tm.Mesh(Vi, Fi, face_colors=faces, normals="flat")], material=tm.Material.lut(tm.kang_table()),
                     outlines="mesh", **kw).color
    row = np.concatenate([bunny_image, textured, flat], axis=1)
    out = ROOT / "docs" / "colour.png"
    Image.fromarray(row).save(out, optimize=True)
    print("wrote", out)


if __name__ == "__main__":
    main()

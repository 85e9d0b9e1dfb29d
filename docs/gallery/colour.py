"""Colour, textures and scenes from files.

Colour on the mesh and scenes from files. Left: the smoothed bunny with
vertex colours (its height and depth as red and blue), bands and outlines. Middle: a sphere with
a checker texture on an equirectangular map (uv from longitude and latitude), toon bands. Right:
a GLB made here with trimesh (three instances of a can whose side and lids are parts with
different PBR base colours), read by ``toonmesh.load``: its node transforms and materials,
with material borders where the parts meet. Needs trimesh to write the GLB
(``pip install 'toonmesh[io]'``).
"""

import tempfile
from pathlib import Path

import numpy as np
import trimesh
from PIL import Image

import toonmesh as tm
from toonmesh.data import bunny
from toonmesh.figures import panels

SIZE = 360


def can_scene(path: Path) -> None:
    """Three cans (side and lids: parts with their own base colours) as a GLB."""
    can = trimesh.creation.cylinder(radius=0.5, height=1.2, sections=48)
    lids = np.abs(can.face_normals[:, 2]) > 0.9
    parts = {
        "side": (~lids, [0.85, 0.2, 0.15, 1.0]),
        "lids": (lids, [0.92, 0.92, 0.88, 1.0]),
    }
    scene = trimesh.Scene()
    for x, angle in [(-1.3, 0.0), (0.0, 0.5), (1.3, 1.0)]:
        pose = trimesh.transformations.rotation_matrix(-np.pi / 2, [1, 0, 0])
        pose = trimesh.transformations.rotation_matrix(angle, [0, 1, 0]) @ pose
        pose[:3, 3] = [x, 0.0, -0.4 * abs(x)]
        for name, (keep, color) in parts.items():
            part = can.submesh([np.flatnonzero(keep)], append=True)
            part.visual = trimesh.visual.TextureVisuals(
                material=trimesh.visual.material.PBRMaterial(baseColorFactor=color)
            )
            scene.add_geometry(
                part, geom_name=name, node_name=f"{name}{x}", transform=pose
            )
    scene.export(path)


def main() -> None:
    kw = dict(
        width=SIZE,
        height=SIZE,
        supersample=2,
        lights=[tm.Light.directional((0.6, -0.5, -1.0))],
    )
    Vb, Fb = bunny()
    Vb = tm.smooth.laplacian(Vb, Fb, iterations=5, preset="paper")
    t = (Vb - Vb.min(0)) / np.ptp(Vb, 0)
    colours = np.stack(
        [0.3 + 0.7 * t[:, 1], np.full(len(Vb), 0.55), 1.0 - 0.7 * t[:, 2]], -1
    )
    bunny_image = tm.render(
        [tm.Mesh(Vb, Fb, vertex_colors=colours)],
        material=tm.Material.bands("#ffffff"),
        outlines="mesh",
        **kw,
    ).color
    V, F = tm.shapes.icosphere(5)
    uv = np.stack(
        [
            np.arctan2(V[:, 2], V[:, 0]) / (2 * np.pi)
            + 0.5,  # longitude and latitude: u right, v up
            np.arcsin(np.clip(V[:, 1], -1, 1)) / np.pi + 0.5,
        ],
        -1,
    )
    cells = np.indices((16, 32)).sum(0) % 2  # a checker of 32 x 16 cells ...
    checker = np.where(cells[..., None] == 1, [230, 120, 40], [250, 235, 200]).astype(
        np.uint8
    )
    checker = np.kron(
        checker, np.ones((16, 16, 1), np.uint8)
    )  # ... of 16 x 16 texels: crisp cell borders
    textured = tm.render(
        [tm.Mesh(V, F, uv=uv, texture=checker)],
        material=tm.Material.bands("#ffffff"),
        outlines="mesh",
        **kw,
    ).color
    with tempfile.TemporaryDirectory() as tmp:
        path = Path(tmp) / "cans.glb"
        can_scene(path)
        cans = tm.load(path)
    scene = tm.render(
        cans,
        material=tm.Material.bands("#ffffff"),
        outlines=tm.Outlines("mesh", material="#2040a0"),
        camera=tm.Camera.fit((0.2, 0.6, 1.0), margin=0.9),
        **kw,
    ).color
    row = panels(
        [bunny_image, textured, scene],
        ["vertex_colors", "uv + texture", 'tm.load("cans.glb")'],
    )
    out = Path("colour.png")
    Image.fromarray(row).save(out, optimize=True)
    print("wrote", out)


if __name__ == "__main__":
    main()

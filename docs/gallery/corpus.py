"""Files others wrote.

Mesh files as other tools write them, made by the script in the folder it runs in: the shipped
meshes exported by trimesh (binary PLY, STL, OFF, GLB, a two-node glTF scene) and hand-written
odd ones (an OBJ of quads with comments and negative indices, a concave polygon, vertices with
no faces: a point cloud, an OBJ of lines, a suffix in capitals). Each is drawn with the
defaults, named; the files refused (an empty one, a face of 2 corners) are listed below the
pictures with their one-line reasons, as ``tm.load`` (or the render) gives them. Needs trimesh
(``pip install 'toonmesh[io]'``).
"""

import warnings
from pathlib import Path

import numpy as np
import trimesh
from PIL import Image, ImageDraw, ImageFont

import toonmesh as tm
from toonmesh.data import cow, fandisk
from toonmesh.figures import panels

TILE, COLUMNS = 150, 6
FONT = ImageFont.load_default(size=12)

QUADS = """# a cube of quads, indices counted from the end
v -1 -1 -1
v 1 -1 -1
v 1 1 -1
v -1 1 -1
v -1 -1 1
v 1 -1 1
v 1 1 1
v -1 1 1
f -8 -5 -6 -7
f -4 -3 -2 -1
f -8 -7 -3 -4
f -6 -5 -1 -2
f -7 -6 -2 -3
f -5 -8 -4 -1
"""
CONCAVE = "v 0 0 0\nv 2 0 0\nv 2 2 0\nv 1 0.6 0\nv 0 2 0\nf 1 2 3 4 5\n"  # an arrow head
LINES = "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 1\nl 1 2 3 4 1\n"
TWO_CORNERS = "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2\n"


def write_files() -> list:
    """The files, written into the current folder; their names."""
    V, F = fandisk()
    trimesh.Trimesh(V, F, process=False).export("fandisk.ply")  # binary PLY
    trimesh.Trimesh(*cow(), process=False).export("cow.stl")
    trimesh.Trimesh(*tm.shapes.pawn(48), process=False).export("pawn.off")
    trimesh.Trimesh(*tm.shapes.teapot(8), process=False).export("teapot.glb")
    scene = trimesh.Scene()
    scene.add_geometry(
        trimesh.Trimesh(*tm.shapes.torus(1.0, 0.35, 48, 24)), node_name="ring"
    )
    scene.add_geometry(
        trimesh.Trimesh(*tm.shapes.icosphere(3)),
        node_name="ball",
        transform=trimesh.transformations.translation_matrix((0, 0.2, 0)),
    )
    scene.export("ring_and_ball.glb")
    np.savetxt("points.xyz", tm.shapes.icosphere(3)[0])  # positions only: a point cloud
    texts = {
        "quads.obj": QUADS,
        "concave.obj": CONCAVE,
        "lines.obj": LINES,
        "CUBE.OBJ": QUADS,
        "points.obj": "".join(
            f"v {x} {y} {z}\n" for x, y, z in tm.shapes.uv_sphere(16, 16)[0]
        ),
        "empty.obj": "",
        "two_corners.obj": TWO_CORNERS,
    }
    for name, text in texts.items():
        Path(name).write_text(text)
    return sorted(
        p.name
        for p in Path(".").iterdir()
        if p.suffix.lower() in (".obj", ".ply", ".stl", ".off", ".glb", ".xyz")
    )


def main() -> None:
    tiles, names, refused = [], [], []
    for name in write_files():
        with warnings.catch_warnings():
            warnings.simplefilter(
                "ignore"
            )  # each file's warnings are its own business here
            try:
                tm.load(name)
                tiles.append(
                    tm.render(name, width=TILE, height=TILE, supersample=2).color
                )
                names.append(name)
            except (ValueError, ImportError) as exc:
                refused.append(str(exc))
    grid = panels(tiles, names, columns=COLUMNS)
    notes = Image.new("RGB", (grid.shape[1], 16 * len(refused) + 8), "white")
    draw = ImageDraw.Draw(notes)
    for k, line in enumerate(refused):
        draw.text((6, 4 + 16 * k), "refused: " + line[:120], fill=(90, 30, 30), font=FONT)
    figure = np.concatenate([grid, np.asarray(notes)], axis=0)
    Image.fromarray(figure).save("corpus.png", optimize=True)


if __name__ == "__main__":
    main()

"""Files and scenes: one geometry placed by several nodes.

A glTF scene written with trimesh, a box placed by four nodes, read back by ``toonmesh.load``
as four meshes that share one pair of arrays (the renderer uploads the box once), and drawn with
outlines and a shadow on a floor. Needs trimesh (``pip install 'toonmesh[io]'``).
"""

import numpy as np
import trimesh
from PIL import Image

import toonmesh as tm

box = trimesh.creation.box()  # one geometry ...
scene = trimesh.Scene()
scene.add_geometry(box, geom_name="box", node_name="a")
for i in range(1, 4):  # ... placed by four nodes
    T = trimesh.transformations.translation_matrix([1.5 * i, 0.5 * i, 0])
    T = T @ trimesh.transformations.rotation_matrix(0.4 * i, [0, 1, 0])
    scene.graph.update(
        frame_to=f"n{i}", frame_from=scene.graph.base_frame, matrix=T, geometry="box"
    )
scene.export("row.glb")

meshes = tm.load("row.glb")  # a list of tm.Mesh, one per placed geometry
assert len(meshes) == 4 and meshes[1].vertices is meshes[0].vertices
floor = tm.Mesh(
    np.array([[-2, -0.5, -2], [7, -0.5, -2], [7, -0.5, 2], [-2, -0.5, 2]], float),
    np.array([[0, 2, 1], [0, 3, 2]]),
    material=tm.Material.bands("#e8e0d0"),
)
r = tm.render(
    [*meshes, floor],
    material=tm.Material.bands("#7fa7d8"),
    outlines="mesh",
    lights=[tm.Light.directional((0.6, -1.0, -0.5), shadows=True)],
    camera=tm.Camera.fit((0.3, 0.6, 1.0)),
    width=640,
    height=320,
)
print(len(meshes), "meshes; passes:", r.passes)
Image.fromarray(r.color).save("scene.png", optimize=True)

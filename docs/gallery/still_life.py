"""A toon still life: hatching, shadows and ink.

The teapot, the bunny, a pawn and a torus on a table, lit by one low sun that casts shadows
across the table, each object in its own material: the teapot cross-hatched along its form, the
others in toon bands (the bunny smoothed first); mesh-space ink at the silhouettes, the
creases and the table's edges. Every model ships with toonmesh (``toonmesh.shapes``,
``toonmesh.data``): the script runs anywhere the package is installed.
"""

import numpy as np

import toonmesh as tm
from toonmesh.data import bunny


def standing(mesh, height, x, z, turn=0.0):
    """``mesh`` scaled to ``height``, turned ``turn`` degrees about y and stood
    on y = 0 at (x, z)."""
    V, F = mesh
    V = (V - V.min(axis=0)) * (height / np.ptp(V[:, 1]))
    V -= [0.5 * V[:, 0].max(), 0.0, 0.5 * V[:, 2].max()]
    a = np.radians(turn)
    V = V @ np.array([[np.cos(a), 0, -np.sin(a)], [0, 1, 0], [np.sin(a), 0, np.cos(a)]])
    return V + [x, 0.0, z], F


def table(half=4.0):
    """A square table top at y = 0, facing up."""
    V = np.array(
        [[-half, 0, -half], [half, 0, -half], [half, 0, half], [-half, 0, half]], float
    )
    return V, np.array([[0, 2, 1], [0, 3, 2]])


def main() -> None:
    V, F = bunny()
    # the scan's noise smoothed away first
    bunny_smoothed = tm.smooth.laplacian(V, F, iterations=5, preset="paper"), F
    torus = tm.shapes.torus(0.7, 0.28, 64, 32)
    bands, hatching = tm.Material.bands, tm.Material.hatching
    objects = [  # name, mesh, height, (x, z) on the table, turn about y, material
        ("teapot", tm.shapes.teapot(10), 1.6, (-0.6, -0.4), -30, hatching("#d9e4f2")),
        ("bunny", bunny_smoothed, 1.5, (1.5, 0.2), -20, bands("#f08a3c")),
        ("pawn", tm.shapes.pawn(48), 1.3, (0.4, 1.4), 0, bands("#8fb8de")),
        ("torus", torus, 0.5, (-1.5, 1.2), 0, bands("#9cc98a")),
    ]
    scene = [tm.Mesh(*table(), name="table", material=bands("#efe3c8"))]
    for name, mesh, height, (x, z), turn, material in objects:
        V, F = standing(mesh, height, x, z, turn)
        scene.append(tm.Mesh(V, F, name=name, material=material))
    sun = tm.Light.directional((0.9, -0.9, -0.5), shadows=True)
    camera = tm.Camera.look_at(
        (0.9, 3.2, 6.4), target=(0.1, 0.55, 0.35), up=(0, 1, 0), fov_y=38.0
    )
    res = tm.render(
        scene,
        camera=camera,
        lights=[sun],
        width=960,
        height=600,
        outlines="mesh",
        background="#fbf7ee",
        supersample=2,
    )
    res.save("still_life.png")
    print("steps:", ", ".join(res.passes))


if __name__ == "__main__":
    main()

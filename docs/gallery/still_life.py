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
    torus = tm.shapes.torus(0.7, 0.28, 64, 32)
    V, F = bunny()
    smooth_bunny = (
        tm.smooth.laplacian(V, F, iterations=5, preset="paper"),
        F,
    )  # the scan's noise off
    scene = [
        tm.Mesh(*table(), name="table", material=tm.Material.bands("#efe3c8")),
        tm.Mesh(
            *standing(tm.shapes.teapot(10), 1.6, -0.6, -0.4, turn=-30),
            name="teapot",
            material=tm.Material.hatching("#d9e4f2"),
        ),
        tm.Mesh(
            *standing(smooth_bunny, 1.5, 1.5, 0.2, turn=-20),
            name="bunny",
            material=tm.Material.bands("#f08a3c"),
        ),
        tm.Mesh(
            *standing(tm.shapes.pawn(48), 1.3, 0.4, 1.4),
            name="pawn",
            material=tm.Material.bands("#8fb8de"),
        ),
        tm.Mesh(
            *standing(torus, 0.5, -1.5, 1.2),
            name="torus",
            material=tm.Material.bands("#9cc98a"),
        ),
    ]
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

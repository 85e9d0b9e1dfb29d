"""The papers' figures.

toonmesh follows three papers, and draws their figures again. Top, Al-Rousan et al.: the raw
bunny and after 3, 5 and 10 iterations of their smoothing, shaded with the thresholded Phong
model (per vertex, as they colour vertices): the band borders go from scattered to clean.
Middle, Kang, Kim and Yoon: their four models (the donut, the chess piece, the teapot and the
sphere, built by ``toonmesh.shapes`` with the paper's face counts) with mesh-space outlines,
their lookup-table shading and a shadow on a floor. Bottom, Borquez and Yepez: the stages of
their pipeline, the normal and depth buffers, the edges found by Sobel on them
(``edges.detect_edges``) and the composite: the edges over the toon bands.
"""

import numpy as np
from PIL import Image

import toonmesh as tm
from toonmesh import edges
from toonmesh.data import bunny
from toonmesh.figures import panels

SIZE = 200


V, F = bunny()
camera = tm.Camera.fit((0.35, 0.3, 1.0))

# Al-Rousan et al.: smoothing before toon shading
toon = tm.Material.thresholded_phong("#f08a3c", t_h=0.1, t_s=0.9, per_vertex=True)
row1 = [
    tm.render(
        V if n == 0 else tm.smooth.laplacian(V, F, iterations=n, preset="paper"),
        F,
        material=toon,
        camera=camera,
        width=SIZE,
        height=SIZE,
    ).color
    for n in (0, 3, 5, 10)
]


# Kang, Kim and Yoon: outlines, a lookup table and shadows
def floor_under(V, F, scale=1.2):
    lo, hi = V.min(axis=0), V.max(axis=0)
    centre, half = (lo + hi) / 2, scale * np.linalg.norm(hi - lo) / 2
    corners = np.array([[-1, 0, -1], [1, 0, -1], [1, 0, 1], [-1, 0, 1]]) * half + [
        centre[0],
        lo[1],
        centre[2],
    ]
    return corners, np.array([[0, 2, 1], [0, 3, 2]])


sun = tm.Light.directional((1.0, -1.2, -0.3), shadows=True)
row2 = []
for (Vm, Fm), angle in (
    (tm.shapes.torus(), 40.0),
    (tm.shapes.pawn(), 50.0),
    (tm.shapes.teapot(), 60.0),
    (tm.shapes.uv_sphere(), 40.0),
):
    scene = [
        tm.Mesh(Vm, Fm, material=tm.Material.lut(tm.kang_table(), color="#4a90d9")),
        tm.Mesh(*floor_under(Vm, Fm), material=tm.Material.lut(color="#d8d0c0")),
    ]
    row2.append(
        tm.render(
            scene,
            camera=tm.Camera.fit((0.3, 0.8, 1.0)),
            lights=[sun],
            width=SIZE,
            height=SIZE,
            outlines=tm.Outlines("mesh", crease_angle=angle, width=2.0),
        ).color
    )

# Borquez and Yepez: two passes, Sobel on the buffers, composite
Vs = tm.smooth.laplacian(V, F, iterations=5, preset="paper")
first = tm.render(
    Vs,
    F,
    material=tm.Material.bands("#8fb8de"),
    camera=camera,
    width=SIZE,
    height=SIZE,
    outputs=("color", "normal", "depth"),
)
pixel = np.linalg.norm(Vs.max(0) - Vs.min(0)) / SIZE
found = edges.detect_edges(
    first.normal, first.depth, normal_threshold=2.0, depth_threshold=40 * pixel
)
inside = np.isfinite(first.depth)
gray = lambda x: (np.clip(x, 0, 1)[..., None].repeat(3, -1) * 255).astype(
    np.uint8
)  # noqa: E731
depth = np.where(inside, first.depth, np.nan)
depth = 1 - (depth - np.nanmin(depth)) / (np.nanmax(depth) - np.nanmin(depth))
composite = first.color[..., :3].copy()
composite[found.mask] = 0
row3 = [
    (np.where(inside[..., None], (first.normal + 1) / 2, 1.0) * 255).astype(np.uint8),
    gray(np.where(inside, 0.2 + 0.8 * np.nan_to_num(depth), 1.0)),
    gray(~found.mask),
    composite,
]

labels = [
    "Al-Rousan: raw",
    "3 iterations",
    "5 iterations",
    "10 iterations",
    "Kang: torus",
    "pawn",
    "teapot",
    "sphere",
    "Borquez: normals",
    "depth",
    "Sobel edges",
    "composite",
]
Image.fromarray(panels(row1 + row2 + row3, labels, columns=4)).save(
    "papers.png", optimize=True
)

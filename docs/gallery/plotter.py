"""A drawing for a pen plotter.

A still life drawn in lines alone, as a pen plotter draws it: the teapot, a pawn, the cow and a
torus on a table, each cut where the objects in front hide it (hidden lines removed exactly),
with silhouettes, creases, the table's edges and suggestive contours (in a second pen, blue).
The figure is the SVG itself, as ``RenderResult.save_svg(order="plotter",
widths="kind")`` writes it: one group per kind (one pen each), centre-line strokes at each kind's
width, and each next stroke started from the end nearest where the pen stopped, so the pen
travels little in the air. The script prints how far: the pen-up travel in the renderer's order
and in the plotter's. Open the SVG in vpype, Inkscape or the plotter's own software.
"""

import re

import numpy as np

import toonmesh as tm
from toonmesh.data import cow

WHITE = tm.Material.bands(
    "#ffffff", thresholds=(2.0,), values=(1.0, 1.0)
)  # one band: only the ink shows


def placed(mesh, height, x, z, name):
    """``mesh`` as a scene item scaled to ``height`` and stood on the table at
    (x, z) by its ``transform`` (the arrays stay as they are: one upload however
    it is placed)."""
    V, F = mesh
    lo, hi = V.min(axis=0), V.max(axis=0)
    s = height / (hi[1] - lo[1])
    transform = np.diag([s, s, s, 1.0])
    transform[:3, 3] = [
        x - s * (lo[0] + hi[0]) / 2,
        -s * lo[1],
        z - s * (lo[2] + hi[2]) / 2,
    ]
    return tm.Mesh(V, F, transform=transform, name=name)


def pen_up_travel(svg: str) -> float:
    """Pixels the pen moves in the air: from each stroke's end to the next one's start."""
    travel, last = 0.0, None
    for points in re.findall(r'points="([^"]+)"', svg):
        xy = np.array(points.replace(",", " ").split(), float).reshape(-1, 2)
        if last is not None:
            travel += float(np.linalg.norm(xy[0] - last))
        last = xy[-1]
    return travel


def main() -> None:
    floor = np.array([[-4.0, 0, -3], [4, 0, -3], [4, 0, 9], [-4, 0, 9]]), np.array(
        [[0, 2, 1], [0, 3, 2]]
    )
    scene = [
        tm.Mesh(*floor, name="table"),
        placed(tm.shapes.teapot(10), 1.6, -0.5, -0.5, "teapot"),
        placed(cow(), 1.3, 1.7, 0.1, "cow"),
        placed(tm.shapes.pawn(48), 1.3, 0.3, 1.3, "pawn"),
        placed(tm.shapes.torus(0.7, 0.28, 64, 32), 0.5, -1.6, 1.1, "torus"),
    ]
    outlines = tm.Outlines(
        "mesh", width=1.4, suggestive=tm.LineStyle(color="#2f5fa8", width=1.0)
    )
    camera = tm.Camera.look_at(
        (0.9, 3.2, 6.4), target=(0.1, 0.55, 0.35), up=(0, 1, 0), fov_y=38.0
    )
    res = tm.render(
        scene,
        camera=camera,
        width=960,
        height=600,
        material=WHITE,
        background="#ffffff",
        outlines=outlines,
        outputs=("color", "lines"),
    )
    res.save_svg("plotter.svg", order="plotter", widths="kind")
    kinds = {k: res.line_kinds.count(k) for k in sorted(set(res.line_kinds))}
    print("strokes by kind:", ", ".join(f"{n} {k}" for k, n in kinds.items()))
    before, after = (
        pen_up_travel(res.svg(order=o, widths="kind")) for o in ("drawing", "plotter")
    )
    print(
        f"pen-up travel: {before:,.0f} px in the renderer's order, "
        f"{after:,.0f} px in the plotter's"
    )


if __name__ == "__main__":
    main()

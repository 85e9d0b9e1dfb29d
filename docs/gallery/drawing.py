"""Engineering drawings: hidden lines and intersection lines.

A small assembly built in the script (a base plate, a bearing block on it, a shaft through the
block with a pulley on its end, two pins through the plate) drawn as an engineering drawing:
white material, an orthographic three-quarter view, the visible lines in black, the lines
behind surfaces dashed in grey (``hidden=True``) and the lines where the shaft and the pins pass
through the block and the plate (the ``intersection`` kind, drawn by default in a scene of
several meshes). Visibility is exact: each line is cut where the scene's surfaces hide it. The
same render written as a pen plotter's SVG (``order="plotter", widths="kind"``): one group per
kind, the hidden group first and dashed. ``python docs/gallery/drawing.py FOLDER WIDTH`` writes
the figures into FOLDER at WIDTH pixels (the README's copy: ``docs 390``).
"""

import sys
from pathlib import Path

import numpy as np

import toonmesh as tm

# white paper: one band, so only the ink shows
PAPER = tm.Material.bands("#ffffff", thresholds=(2.0,), values=(1.0, 1.0))


def pipe(axis, radius, half_length, sections=96):
    """A capped cylinder along ``axis`` (0, 1 or 2: x, y or z) through the origin."""
    profile = [
        (0, -half_length),
        (radius, -half_length),
        (radius, half_length),
        (0, half_length),
    ]
    V, F = tm.shapes.lathe(profile, sections)  # about y
    return V[:, np.roll([0, 1, 2], axis - 1)], F  # y becomes the axis asked for


def part(mesh, name, offset=(0, 0, 0)):
    """A part of the assembly: ``mesh`` (vertices, faces) moved by ``offset`` (mm)."""
    V, F = mesh
    return tm.Mesh(V + np.asarray(offset, float), F, name=name)


def assembly():
    """The parts in mm, y up: plate, bearing block, shaft, pulley and two pins."""
    return [
        part(tm.shapes.box((-70, 0, -40), (70, 10, 40)), "plate"),
        part(tm.shapes.box((-22, 10, -22), (22, 56, 22)), "block"),
        part(
            pipe(0, radius=8, half_length=55), "shaft", (0, 36, 0)
        ),  # along x, through the block
        part(
            pipe(0, radius=22, half_length=4), "pulley", (48, 36, 0)
        ),  # on the shaft's end
        part(
            pipe(1, radius=5, half_length=12, sections=48), "pin", (-50, 5, 22)
        ),  # along y, through the plate
        part(pipe(1, radius=5, half_length=12, sections=48), "pin", (50, 5, -22)),
    ]


def main(folder: Path, width: int = 720) -> None:
    # hidden=True: grey, 2/3 of the width, dashed
    # (or a LineStyle(color, width, dash=...) of your own)
    outlines = tm.Outlines("mesh", width=1.6, hidden=True)
    camera = tm.Camera.fit((1.0, 0.7, 1.3), orthographic=True, margin=1.08)
    res = tm.Renderer().render(
        assembly(),
        camera=camera,
        width=width,
        height=width * 2 // 3,
        material=PAPER,
        background="#ffffff",
        outlines=outlines,
        supersample=2,
        outputs=("color", "lines"),
    )
    folder.mkdir(parents=True, exist_ok=True)
    res.save(folder / "drawing.png")
    res.save_svg(folder / "drawing.svg", order="plotter", widths="kind")
    kinds = {k: res.line_kinds.count(k) for k in sorted(set(res.line_kinds))}
    print("strokes by kind:", ", ".join(f"{n} {k}" for k, n in kinds.items()))
    print("steps:", ", ".join(res.passes))


if __name__ == "__main__":
    main(Path(sys.argv[1]) if len(sys.argv) > 1 else Path("."), *map(int, sys.argv[2:3]))

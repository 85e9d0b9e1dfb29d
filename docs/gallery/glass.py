"""Glass and points.

Left: the bunny in a glass case (``Material.bands(..., opacity=0.3)``), composited exactly in
any order by depth peeling; the bunny's ink stays under the glass, dimmed by it, and the case's
own edges are inked over it (its back edges through its front). Right: the bunny as a scan
would give it, its 35,947 vertices alone as a ``tm.Points`` cloud without normals (estimated
from each point's nearest neighbours), drawn as toon-shaded splats with ink at its silhouette
and depth jumps, and eye-dome lighting (``tm.EyeDome()``) darkening where it lies behind its
neighbours. ``python docs/gallery/glass.py FOLDER WIDTH`` writes the figure into FOLDER at
WIDTH pixels (the README's copy: ``docs 520``).
"""

import sys
from pathlib import Path

from PIL import Image

import toonmesh as tm
from toonmesh.data import bunny
from toonmesh.figures import panels


def glass_case(width: int) -> tm.RenderResult:
    V, F = bunny()
    lo, hi = V.min(axis=0), V.max(axis=0)
    pad = 0.12 * (hi - lo).max()
    case = tm.Mesh(
        *tm.shapes.box(lo - pad, hi + pad),
        name="case",
        material=tm.Material.bands("#9cc8ff", opacity=0.3),
    )
    model = tm.Mesh(V, F, name="bunny", material=tm.Material.bands("#f08a4b"))
    camera = tm.Camera.fit((0.9, 0.5, 1.4), margin=1.05)
    return tm.render(
        [model, case],
        camera=camera,
        width=width,
        height=width,
        outlines="mesh",
        background="#ffffff",
        supersample=2,
    )


def scan(width: int) -> tm.RenderResult:
    V, _ = bunny()
    cloud = tm.Points(V, name="scan", material=tm.Material.bands("#7fb07a"))
    camera = tm.Camera.fit((0.9, 0.5, 1.4), margin=1.05)
    # ink where the depth jumps and where normals turn by more than 80 degrees
    # (a scan's estimated normals are noisy: the default 25 degrees marks its
    # bumps), eye-dome lighting
    return tm.render(
        cloud,
        camera=camera,
        width=width,
        height=width,
        background="#ffffff",
        outlines=tm.Outlines("image", normal_angle=80.0),
        eye_dome=tm.EyeDome(),
    )


def main(folder: Path, width: int = 720) -> None:
    half = width // 2
    left, right = glass_case(half), scan(half)
    folder.mkdir(parents=True, exist_ok=True)
    labels = ["glass: Material.bands(opacity=0.3)", "tm.Points + tm.EyeDome()"]
    Image.fromarray(panels([left.color, right.color], labels)).save(folder / "glass.png")
    print("glass case:", ", ".join(left.passes))
    print("scan:", ", ".join(right.passes))


if __name__ == "__main__":
    main(Path(sys.argv[1]) if len(sys.argv) > 1 else Path("."), *map(int, sys.argv[2:3]))

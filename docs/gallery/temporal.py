"""Lines that hold still.

The raw bunny's suggestive contours over 20 one-degree steps of a turntable (512x512, the eye at
2.4 bounding radii), drawn by ``Renderer.render_many``. Red marks the ink that pops: ink with no
ink within 2 px of where its surface point went in the next frame
(``toonmesh.testing.temporal_popping``), gathered over the 20 steps onto the first frame. Left:
each view on its own (``suggestive_coherence=False``, what a still render draws). Right: the
default, where suggestive contours fade by how fast they slide across the surface and a line
drawn in the frame before stays down to a weaker test (DeCarlo et al. 2004), so lines fade in
and out instead of blinking. ``python docs/gallery/temporal.py FOLDER WIDTH`` writes the figure
into FOLDER at WIDTH pixels (the README's copy: ``docs 520``).
"""

import sys
from pathlib import Path

import numpy as np
from PIL import Image

import toonmesh as tm
from toonmesh.data import bunny
from toonmesh.figures import panels
from toonmesh.testing import temporal_popping

START, STEPS = 60, 20


def turntable(V: np.ndarray, steps: int) -> list:
    """``steps + 1`` cameras one degree apart about +y, the eye at 2.4 bounding radii."""
    centre = 0.5 * (V.min(axis=0) + V.max(axis=0))
    radius = float(np.linalg.norm(V - centre, axis=1).max())
    a = np.radians(np.arange(steps + 1))
    eyes = centre + 2.4 * radius * np.c_[np.sin(a), np.zeros_like(a), np.cos(a)]
    return [
        tm.Camera.look_at(tuple(eye), target=tuple(centre), up=(0, 1, 0), fov_y=40.0)
        for eye in eyes
    ]


def panel(
    renderer: tm.Renderer, mesh: tm.MeshHandle, cameras: list, coherence: bool, size: int
) -> tuple:
    """The first frame with the popping ink in red, at ``size`` pixels, and its label."""
    outlines = tm.Outlines("mesh", suggestive=True, suggestive_coherence=coherence)
    stack = renderer.render_many(
        mesh,
        cameras,
        width=512,
        height=512,
        outlines=outlines,
        material=tm.Material.bands("#e9e4da"),
        background="#ffffff",
        outputs=("color", "outline", "depth"),
    )
    popping = temporal_popping(stack)
    print(
        f"coherence {'on ' if coherence else 'off'}: "
        f"{100 * popping.share:.3f}% of the ink pops per step "
        f"({popping.popped.sum()} pixels over {STEPS} steps)"
    )
    image = stack[0].color[..., :3].copy()
    red = np.zeros(image.shape[:2], bool)
    for where in popping.where:
        red[where[:, 0], where[:, 1]] = True
    # two pixels round each too, so that single pixels show at the page's size
    grown = red.copy()
    for _ in range(2):
        grown[1:] |= grown[:-1].copy()
        grown[:-1] |= grown[1:].copy()
        grown[:, 1:] |= grown[:, :-1].copy()
        grown[:, :-1] |= grown[:, 1:].copy()
    image[grown] = (230, 20, 20)
    image = np.asarray(Image.fromarray(image).resize((size, size), Image.LANCZOS))
    return image, f"suggestive_coherence={coherence}: {100 * popping.share:.3f}% pops"


def main(folder: Path, width: int = 720) -> None:
    V, F = bunny()
    cameras = turntable(V, START + STEPS)[START:]
    renderer = tm.Renderer()
    mesh = renderer.add_mesh(V, F)
    half = width // 2
    folder.mkdir(parents=True, exist_ok=True)
    (left, off), (right, on) = (
        panel(renderer, mesh, cameras, c, half) for c in (False, True)
    )
    Image.fromarray(panels([left, right], [off, on])).save(folder / "temporal.png")


if __name__ == "__main__":
    main(Path(sys.argv[1]) if len(sys.argv) > 1 else Path("."), *map(int, sys.argv[2:3]))

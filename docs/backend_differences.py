"""How far toonmesh's Vulkan and GL backends are apart on the same scenes: the table in
docs/testing.md, and the scenes tests/test_testing.py holds the default tolerances of
toonmesh.testing to.

    python docs/backend_differences.py      # prints the table (both backends must work)

For each scene: the share of pixels that differ at all and by more than the default
IMAGE_LEVELS, the largest difference (8-bit levels), and, where the scene draws lines, the
share of line length farther than LINE_PIXELS from the other backend's lines.
"""

from __future__ import annotations

from typing import Any, Callable, Dict, List

import toonmesh as tm
from toonmesh.data import bunny
from toonmesh.testing import IMAGE_LEVELS, LINE_PIXELS, drawing_difference, image_difference

_LIGHTS = [tm.Light.key(), tm.Light.point((3.0, 1.5, 2.0), color=(1.0, 0.8, 0.6), intensity=0.4)]


def _bunny() -> Any:
    return bunny()


#: name -> render(backend): the scenes measured, each with the renderer's defaults but for
#: what the name says.
SCENES: Dict[str, Callable[[str], tm.RenderResult]] = {
    "bunny, defaults, 256x256": lambda b: tm.render(*_bunny(), width=256, height=256, backend=b),
    "bunny, mesh outlines and lines, 256x256": lambda b: tm.render(
        *_bunny(), outlines="mesh", outputs=("color", "lines"), width=256, height=256, backend=b),
    "bunny, mesh and image outlines, 512x512": lambda b: tm.render(
        *_bunny(), outlines="both", outputs=("color", "lines"), width=512, height=512, backend=b),
    "noisy sphere, bands, two lights, 257x181": lambda b: tm.render(
        *tm.shapes.icosphere(4, noise=0.04, seed=7), material=tm.Material.bands(), lights=_LIGHTS,
        width=257, height=181, backend=b),
    "teapot, Phong, shadow map, image outlines, 320x240": lambda b: tm.render(
        *tm.shapes.teapot(), material=tm.Material.phong(), outlines="image",
        lights=[tm.Light.directional((1.0, -2.0, -0.6), shadows=True)], width=320, height=240, backend=b),
    "teapot, bands, blue-noise dither, rim, paper, 256x256": lambda b: tm.render(
        *tm.shapes.teapot(), material=tm.Material.bands(dither=tm.Dither("blue"), rim=tm.Rim()),
        paper=tm.Paper(), width=256, height=256, backend=b),
    "torus, LUT, 4x MSAA, 200x200": lambda b: tm.render(
        *tm.shapes.torus(segments=40, tube_segments=20), material=tm.Material.lut(), msaa=4,
        width=200, height=200, backend=b),
}


def measure(name: str) -> Dict[str, Any]:
    """The scene rendered on both backends, compared: ``differ`` (the pixels that differ at
    all) and ``beyond`` (by more than IMAGE_LEVELS), each an ImageDifference, ``largest``
    (levels), ``lines`` (share of line length beyond LINE_PIXELS, or None) and the two
    renders."""
    vulkan, gl = SCENES[name]("vulkan"), SCENES[name]("gl")
    at_all = image_difference(vulkan, gl, levels=0)
    beyond = image_difference(vulkan, gl, levels=IMAGE_LEVELS)
    lines = drawing_difference(vulkan, gl, pixels=LINE_PIXELS).share if vulkan.lines is not None else None
    return {"differ": at_all, "beyond": beyond, "largest": at_all.largest, "lines": lines,
            "vulkan": vulkan, "gl": gl}


def table() -> List[str]:
    """The markdown table of every scene."""
    adapter = tm.gpu_info("vulkan")["name"]
    rows = [
        f"| scene (Vulkan against GL, {adapter}) | pixels that differ | beyond {IMAGE_LEVELS} levels | largest (levels) "
        f"| lines beyond {LINE_PIXELS:g} px |",
        "|---|---|---|---|---|",
    ]
    for name in SCENES:
        m = measure(name)
        lines = "-" if m["lines"] is None else f"{m['lines']:.3%}"
        differ, beyond = m["differ"], m["beyond"]
        rows.append(f"| {name} | {differ.differing} ({differ.share:.3%}) | {beyond.differing} ({beyond.share:.4%}) "
                    f"| {m['largest']} | {lines} |")
    return rows


if __name__ == "__main__":
    print("\n".join(table()))

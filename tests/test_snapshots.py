"""The look of toonmesh's renders and line drawings, held to references kept in
tests/__snapshots__ by the toon_snapshot fixture of toonmesh's own pytest plugin: each backend
against the same reference, within the default tolerances (docs/testing.md). After a change to
the look that is meant, refresh them: pytest tests/test_snapshots.py --toon-update."""

from __future__ import annotations

import pytest

import toonmesh as tm
from toonmesh.data import bunny

BACKENDS = ["vulkan", "gl"]


@pytest.mark.parametrize("backend", BACKENDS)
def test_the_bunny_with_mesh_outlines(backend, toon_snapshot):
    V, F = bunny()
    res = tm.render(V, F, backend=backend, width=256, height=256, outlines="mesh", outputs=("color", "lines"))
    toon_snapshot(res, "bunny-mesh-outlines")  # the colour image: bunny-mesh-outlines.png
    toon_snapshot(res, "bunny-mesh-outlines", kind="drawing")  # its lines: bunny-mesh-outlines.svg


@pytest.mark.parametrize("backend", BACKENDS)
def test_the_teapot_with_every_effect(backend, toon_snapshot):
    res = tm.render(
        *tm.shapes.teapot(), backend=backend, width=256, height=192, outlines="both",
        material=tm.Material.bands(dither=tm.Dither("blue"), rim=tm.Rim()), paper=tm.Paper(),
        lights=[tm.Light.directional((1.0, -2.0, -0.6), shadows=True)],
    )
    toon_snapshot(res, "teapot-effects")

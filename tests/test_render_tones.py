"""Tones, not black: by default the darkest band and the shadows keep the material's hue, and
black ink stays visible over them (a box casting a shadow on a floor); the papers' values stay
available as a preset."""

from __future__ import annotations

import numpy as np
import pytest
from scipy import ndimage

import toonmesh as tm
from toonmesh.bench.effects import SHADOW_SCENES

BACKENDS = ["vulkan", "gl"]
LUMA = np.array([0.2126, 0.7152, 0.0722])


def _box_on_floor(material, backend):
    (V, F), direction, eye = SHADOW_SCENES["box on a plane"]
    return tm.render(tm.Mesh(V, F, normals="flat"), material=material, backend=backend,
                     lights=[tm.Light.directional(direction, shadows=True)], camera=tm.Camera.fit(eye),
                     outlines="mesh", width=256, height=256, outputs=("color", "shadow", "outline"))


def _ink_against_shadow(res):
    """Median luma (0-255) of the shadowed pixels near the ink, minus that of the ink over them."""
    luma = res.color[..., :3].astype(float) @ LUMA
    shadow = ndimage.binary_erosion(res.shadow < 0.5, iterations=4)
    ink = (res.outline > 0.9) & shadow
    around = ndimage.binary_dilation(ink, iterations=4) & ~ndimage.binary_dilation(res.outline > 0, iterations=1)
    around &= shadow
    assert ink.sum() > 20 and around.sum() > 50, "the outline should cross the shadow"
    return float(np.median(luma[around]) - np.median(luma[ink]))


@pytest.mark.parametrize("backend", BACKENDS)
def test_ink_shows_over_the_shadow(backend):
    default = _ink_against_shadow(_box_on_floor(tm.Material.bands(), backend))
    paper = _ink_against_shadow(_box_on_floor(tm.Material.bands(preset="paper"), backend))
    assert default >= 25 > paper  # the paper's black shadow swallows the ink


@pytest.mark.parametrize("backend", BACKENDS)
def test_the_shadow_side_keeps_the_colour(backend):
    color = (0.2, 0.5, 0.9)
    res = _box_on_floor(tm.Material.bands(color), backend)
    c = res.color[..., :3].astype(float)
    dark = c[ndimage.binary_erosion(res.shadow < 0.5, iterations=4) & (res.outline == 0)]
    assert len(dark) > 200 and dark.max(axis=1).min() > 40  # not black
    # the hue: the shadowed floor's channels are ordered as the colour's
    m = np.median(dark, axis=0)
    assert m[2] > m[1] > m[0]


def test_presets_and_values():
    default, paper = tm.Material.bands(), tm.Material.bands(preset="paper")
    assert default.values[0] > 0 and paper.values[0] == 0
    assert default.thresholds == paper.thresholds
    assert tm.Material.bands(values=(0.1, 1.0), thresholds=(0.5,), preset="paper").values == pytest.approx([0.1, 1.0])
    assert tm.Material.hatching().values == paper.values  # the tone reaches every stroke layer
    with pytest.raises(ValueError, match="preset"):
        tm.Material.bands(preset="kang")

"""Band borders blended over about a pixel (band_antialias=True, the default): closer to a supersampled frame
at no extra samples, for bands, thresholded Phong and lookup tables, on both backends. The GPU
is held against the CPU reference in src/render/gpu_tests.rs."""

from __future__ import annotations

import numpy as np
import pytest

import toonmesh as tm

BACKENDS = ["vulkan", "gl"]


def _interior_off(material, backend, **kw):
    """Pixels at least 2 px inside the sphere's outline whose colour differs from a 4x4
    supersampled frame's by more than 8 levels, and the frame's distinct colours there."""
    from scipy.ndimage import binary_erosion

    V, F = tm.shapes.icosphere(5)
    common = dict(material=material, outputs=("color", "depth"), width=256, height=256, backend=backend)
    r = tm.render(V, F, **common, **kw)
    reference = tm.render(V, F, supersample=4, **common)
    inner = binary_erosion(np.isfinite(r.depth), iterations=2)
    diff = np.abs(r.color[..., :3].astype(int) - reference.color[..., :3].astype(int)).max(axis=-1)
    return int((diff[inner] > 8).sum()), len(np.unique(r.color[inner][:, :3], axis=0))


@pytest.mark.parametrize("backend", BACKENDS)
@pytest.mark.parametrize("model", ["bands", "thresholded_phong"])
def test_band_borders_come_close_to_supersampling(backend, model):
    material = getattr(tm.Material, model)()
    hard, hard_colours = _interior_off(material, backend, band_antialias=False)
    soft, soft_colours = _interior_off(material, backend)
    assert soft <= 90 < hard
    assert soft_colours > 20 * hard_colours  # the blend shows tones between the bands


@pytest.mark.parametrize("backend", BACKENDS)
def test_lookup_table_borders_are_blended_too(backend):
    hard, hard_colours = _interior_off(tm.Material.lut(), backend, band_antialias=False)
    soft, soft_colours = _interior_off(tm.Material.lut(), backend)
    assert soft < hard and soft_colours > 10 * hard_colours


def test_on_by_default_and_an_option_like_the_others():
    assert tm.RenderOptions().band_antialias is True
    assert tm.RenderOptions(band_antialias=False).replace(width=64).band_antialias is False
    V, F = tm.shapes.icosphere(3)
    a = tm.render(V, F, width=64, height=64)
    b = tm.render(V, F, width=64, height=64, band_antialias=True)
    c = tm.render(V, F, width=64, height=64, band_antialias=False)
    np.testing.assert_array_equal(a.color, b.color)
    assert np.count_nonzero(a.color != c.color) > 0

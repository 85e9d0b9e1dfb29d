"""Any finite mesh renders the same picture as the same mesh moved to the origin at unit size:
positions reach the GPU relative to the mesh's centre and divided by a power of two near its
size, and the frame works in view space divided by another, so float32 keeps its precision at
any scale and distance float64 can hold."""

from __future__ import annotations

import numpy as np
import pytest

import toonmesh as tm
from toonmesh import _core

V, F = _core.icosphere(3, 0.05, 2)
LIGHTS = [tm.Light.key(), tm.Light.point((3.0, 1.0, 2.0), intensity=0.5)]


def picture(scale: float, offset: float, outputs=("color", "outline")):
    lights = [LIGHTS[0], tm.Light.point(tuple(np.array((3.0, 1.0, 2.0)) * scale + offset), intensity=0.5)]
    return tm.render(V * scale + offset, F, lights=lights, width=96, height=96, outlines="mesh",
                     material=tm.Material.thresholded_phong(), outputs=outputs)


@pytest.fixture(scope="module")
def reference():
    return picture(1.0, 0.0)


@pytest.mark.parametrize("scale", [1e-300, 1e-150, 1e-40, 1e-11, 1e11, 1e40, 1e150, 1e300])
@pytest.mark.parametrize("offset_in_sizes", [0.0, 1e6])
def test_tiny_huge_and_far_meshes_render_the_same_picture(reference, scale, offset_in_sizes):
    res = picture(scale, scale * offset_in_sizes)
    differ = (np.abs(res.color.astype(int) - reference.color.astype(int)).max(axis=-1) > 8).mean()
    assert differ <= 0.005, f"{differ:.2%} of pixels differ"
    assert np.abs(res.outline - reference.outline).mean() < 0.01
    assert (res.color[..., :3] != 255).any()  # never a blank image


@pytest.mark.parametrize("offset", [1e10, 1e12])
def test_a_unit_mesh_far_from_the_origin(reference, offset):
    res = picture(1.0, offset)
    differ = (np.abs(res.color.astype(int) - reference.color.astype(int)).max(axis=-1) > 8).mean()
    assert differ <= 0.005, f"{differ:.2%} of pixels differ"


def test_depth_in_world_units_at_any_scale_float32_holds_and_a_clear_error_beyond():
    d1 = picture(1.0, 0.0, ("depth",)).depth
    d2 = picture(1e-11, 0.0, ("depth",)).depth
    both = np.isfinite(d1)
    assert np.array_equal(both, np.isfinite(d2))
    np.testing.assert_allclose(d2[both], d1[both] * 1e-11, rtol=1e-5)
    with pytest.raises(ValueError, match="depth.*float32"):
        picture(1e-100, 0.0, ("depth",))

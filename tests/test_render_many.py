"""Many views in flight: the same bits as rendering each view alone, stacked arrays, and a
stream of renders that allocates nothing new."""

from __future__ import annotations

import numpy as np
import pytest

import toonmesh as tm
from toonmesh import _core
from toonmesh.testing import assert_drawings_close, assert_images_close

BACKENDS = ["vulkan", "gl"]


@pytest.mark.parametrize("backend", BACKENDS)
def test_render_many_gives_the_bits_of_each_view_alone(backend):
    V, F = _core.icosphere(3, 0.04, 4)
    r = tm.Renderer(backend)
    mesh = r.add_mesh(V, F)
    cams = [tm.Camera.fit((np.sin(a), 0.3, np.cos(a))) for a in np.linspace(0, 2 * np.pi, 7, endpoint=False)]
    kw = dict(width=64, height=48, outputs=("color", "depth", "outline", "lines"), outlines="both")
    stack = r.render_many(mesh, cams, **kw)
    assert len(stack) == 7 and stack.color.shape == (7, 48, 64, 4) and stack.depth.shape == (7, 48, 64)
    assert stack.normal is None
    for i, cam in enumerate(cams):
        alone = r.render(mesh, camera=cam, **kw)
        assert_images_close(stack[i], alone, levels=0, share=0.0)
        assert_images_close(stack.color[i], alone, levels=0, share=0.0)
        assert np.array_equal(stack[i].depth, alone.depth, equal_nan=True)
        assert np.array_equal(stack[i].outline, alone.outline)
        assert_drawings_close(stack[i], alone, pixels=0.0, share=0.0)
        assert np.array_equal(stack[i].view_matrix, alone.view_matrix)
    assert not np.array_equal(stack.color[0], stack.color[1])


def test_render_many_checks_its_cameras():
    r = tm.Renderer()
    V, F = _core.icosphere(1, 0.0, 0)
    mesh = r.add_mesh(V, F)
    with pytest.raises(TypeError, match="cameras\\[1\\]"):
        r.render_many(mesh, [tm.Camera.fit(), "front"])
    with pytest.raises(TypeError, match="cameras"):
        r.render_many(mesh, 5)
    assert len(r.render_many(mesh, [], width=8, height=8)) == 0

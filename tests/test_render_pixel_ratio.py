"""``RenderOptions.pixel_ratio``: a frame at twice the size with ``pixel_ratio=2`` is the same
picture, sharper (the lengths given in pixels, line widths, hatch spacing, dither cells, scale
with it); without it the lines are as thin in output pixels as before. Bad ratios are refused
naming the argument."""

from __future__ import annotations

import math

import numpy as np
import pytest

import toonmesh as tm
from toonmesh.data import bunny

BACKENDS = ["vulkan", "gl"]


@pytest.fixture(scope="module")
def mesh():
    return bunny()


def _halved(image: np.ndarray) -> np.ndarray:
    """``image`` (H, W, ...) averaged over 2x2 blocks."""
    h, w = image.shape[0] // 2 * 2, image.shape[1] // 2 * 2
    x = image[:h, :w].astype(np.float64)
    return (x[0::2, 0::2] + x[1::2, 0::2] + x[0::2, 1::2] + x[1::2, 1::2]) / 4


@pytest.mark.parametrize("backend", BACKENDS)
def test_twice_the_size_at_pixel_ratio_two_draws_lines_as_wide(backend, mesh):
    def ink(kind, size, **ratio):
        out = tm.render(*mesh, width=size, height=size, outlines=tm.Outlines(kind, width=2.0), outputs="outline",
                        backend=backend, **ratio).outline
        return np.asarray(out, np.float64)

    # mesh-space lines: the ink's coverage in output pixels doubles along the lines at twice
    # the size, and doubles again across them where the widths scale with the ratio
    one, sharp, thin = ink("mesh", 120), ink("mesh", 240, pixel_ratio=2), ink("mesh", 240)
    assert sharp.sum() == pytest.approx(4 * one.sum(), rel=0.1), (one.sum(), sharp.sum())
    assert thin.sum() < 0.6 * sharp.sum(), (thin.sum(), sharp.sum())
    # and the sharp frame, averaged down, lies where the small one does
    near = np.abs(_halved(sharp) - one) < 0.5
    assert near.mean() > 0.99, near.mean()
    # image-space edges are as wide too (the edges found at twice the size are fewer: finer detail)
    one, sharp, thin = ink("image", 120), ink("image", 240, pixel_ratio=2), ink("image", 240)
    assert thin.sum() < 0.6 * sharp.sum() and sharp.sum() > 3 * one.sum(), (one.sum(), sharp.sum(), thin.sum())


@pytest.mark.parametrize("material", [
    tm.Material.hatching("#d0d0d0", spacing=6.0, width=1.5),
    tm.Material.hatching("#d0d0d0", spacing=6.0, width=1.5, mode="triplanar"),
    tm.Material.bands("#d0d0d0", dither=tm.Dither("bayer4", scale=3.0)),
], ids=["field hatching", "triplanar hatching", "dither"])
def test_hatch_strokes_and_dither_cells_keep_their_size_on_screen(mesh, material):
    def frame(size, **ratio):
        return tm.render(*mesh, material=material, width=size, height=size, **ratio).color[..., :3].astype(np.float64)

    one = frame(128)
    sharp, plain = _halved(frame(256, pixel_ratio=2)), _halved(frame(256))
    # averaged down, the frame at pixel ratio 2 is the small one's picture; without the ratio
    # the strokes and cells are half as large on screen
    off_sharp, off_plain = np.abs(sharp - one).mean(), np.abs(plain - one).mean()
    assert off_sharp < 0.75 * off_plain, (off_sharp, off_plain)


def test_the_ratio_is_a_setting_like_the_others():
    o = tm.RenderOptions(width=64, pixel_ratio=1.5)
    assert o.pixel_ratio == 1.5 and tm.RenderOptions().pixel_ratio == 1.0
    assert eval(repr(o), {"tm": tm, **vars(tm)}) == o
    assert o.replace(pixel_ratio=None).pixel_ratio == 1.0


@pytest.mark.parametrize("bad", [0, 0.1, 9, math.nan, math.inf, -1])
def test_a_ratio_out_of_range_is_refused_by_name(mesh, bad):
    with pytest.raises(ValueError, match=r"^pixel_ratio: must be in \[0\.25, 8\]"):
        tm.render(*mesh, width=16, height=16, pixel_ratio=bad)


def test_a_ratio_that_is_not_a_number_is_refused_by_name():
    with pytest.raises(TypeError, match="pixel_ratio"):
        tm.RenderOptions(pixel_ratio="2")

"""Paper grain (`render(..., paper=tm.Paper(...))`): over the finished image, tones, hatching and
ink alike, fixed to the screen or to the surfaces, from the built-in grain or the user's image;
one pass of its own, only when asked for. The pixels are held against the CPU reference in Rust
(`render::effects::paper::gpu_tests`); here, what a user sees."""

from __future__ import annotations

import pickle

import numpy as np
import pytest

import toonmesh as tm

V, F = tm.shapes.icosphere(3)
KW = dict(width=80, height=64, outlines="mesh")


def _ortho(x: float = 0.0) -> tm.Camera:
    return tm.Camera.orthographic((x, 0.0, 5.0), target=(x, 0.0, 0.0), height=2.5)


def test_paper_runs_one_pass_after_the_ink_and_only_when_asked():
    plain = tm.render(V, F, **KW)
    paper = tm.render(V, F, paper=tm.Paper(), **KW)
    assert "paper" not in plain.passes
    assert [p for p in paper.passes if p != "paper"] == plain.passes
    at = paper.passes.index("paper")  # after the shading and the ink, before the readbacks
    assert paper.passes.index("shade") < at < paper.passes.index("readback_color")
    assert all(paper.passes.index(p) < at for p in ("lines", "edges") if p in paper.passes)
    surface = tm.render(V, F, paper=tm.Paper(space="surface"), **KW)
    assert "paper" in surface.passes and ("gbuffer" in surface.passes or "shade" in surface.passes)
    # no colour asked for: nothing to lay the grain on
    assert "paper" not in tm.render(V, F, paper=tm.Paper(), outputs=("depth",), **KW).passes


def test_the_grain_lightens_pigment_and_a_flat_grain_changes_nothing():
    plain = tm.render(V, F, **KW).color
    full = tm.render(V, F, paper=tm.Paper(np.ones((4, 4))), **KW).color
    assert np.array_equal(full, plain)  # every peak takes all the pigment; the paper is white
    rough = tm.render(V, F, paper=tm.Paper(strength=1.0, tone=0.0), **KW).color
    assert (rough.astype(int) >= plain.astype(int) - 1).all()  # valleys refuse pigment: lighter
    ink = plain[..., :3].max(axis=2) < 40  # the ink lines
    assert ink.sum() > 50 and (rough[ink][:, :3].max(axis=1) > 60).mean() > 0.3  # the ink is broken up
    blank = tm.render(V, F, paper=tm.Paper(np.zeros((2, 2)), strength=1.0, tone=0.0), **KW).color
    assert (blank[..., :3] == 255).all()  # all valley, no tone: bare white paper


def test_screen_grain_stays_while_surface_grain_moves_with_the_scene():
    # the camera moves 8 pixels to the right: the scene moves 8 pixels to the left in the image;
    # one flat tone, so that the grain is all that varies
    step = 8 * 2.5 / 64
    flat = tm.Material.bands("#808080", thresholds=[0.5], values=[1.0, 1.0])
    for space, follows in (("screen", False), ("surface", True)):
        kw = dict(paper=tm.Paper(space=space, strength=1.0, scale=2.0), material=flat, width=80, height=64,
                  outputs=("color", "depth"))
        a = tm.render(V, F, camera=_ortho(0.0), **kw)
        b = tm.render(V, F, camera=_ortho(step), **kw)
        # pixels on the sphere in both frames, at the same point and at the same pixel
        both = np.isfinite(a.depth[:, 16:60]) & np.isfinite(b.depth[:, 8:52]) & np.isfinite(b.depth[:, 16:60])
        same_point = np.abs(a.color[:, 16:60, 0].astype(int) - b.color[:, 8:52, 0].astype(int))[both]
        same_pixel = np.abs(a.color[:, 16:60, 0].astype(int) - b.color[:, 16:60, 0].astype(int))[both]
        assert both.sum() > 500
        if follows:
            assert same_point.mean() < 0.5 * same_pixel.mean(), (same_point.mean(), same_pixel.mean())
        else:
            assert same_pixel.mean() < 0.5 * same_point.mean(), (same_pixel.mean(), same_point.mean())


def test_paper_is_a_setting_like_the_others():
    p = tm.Paper(space="surface", scale=3.0, strength=0.8, tone=0.0)
    assert eval(repr(p), {"Paper": tm.Paper}) == p
    assert pickle.loads(pickle.dumps(p)) == p and p.replace(tone=0.2).tone == 0.2
    img = tm.Paper(np.array([[0, 255], [128, 64]], np.uint8))
    assert img.grain.dtype == np.float32 and img.grain.shape == (2, 2)
    np.testing.assert_allclose(img.grain, [[0.0, 1.0], [128 / 255, 64 / 255]], atol=1e-6)
    rgb = tm.Paper(np.full((3, 5, 3), 0.5))
    assert rgb.grain.shape == (3, 5) and np.allclose(rgb.grain, 0.5)
    assert pickle.loads(pickle.dumps(img)) == img
    assert tm.RenderOptions(paper=p).paper == p and tm.RenderOptions().paper is None


@pytest.mark.parametrize(
    "grain, exc, match",
    [
        ("rough", TypeError, "^grain: expected an \\(H, W\\) or \\(H, W, C\\) NumPy array"),
        (np.zeros(5), ValueError, "^grain: expected an \\(H, W\\) or \\(H, W, C\\) array, got 1 dimensions"),
        (np.zeros((2, 2, 5)), ValueError, "^grain: expected 1 to 4 channels"),
        (np.array([[0.0, 1.5]]), ValueError, "^grain\\[0, 1\\]: values must be in \\[0, 1\\]"),
        (np.array([[0.0, np.nan]]), ValueError, "^grain\\[0, 1\\]"),
        (np.array([[300, 0]]), ValueError, "^grain\\[0, 0\\]: values must be in \\[0, 255\\]"),
        (np.zeros((0, 3)), ValueError, "^grain: expected sides of 1 to 4096"),
        (np.array([["a"]]), TypeError, "^grain: expected an array of integers"),
    ],
)
def test_a_bad_grain_is_named(grain, exc, match):
    with pytest.raises(exc, match=match):
        tm.Paper(grain)

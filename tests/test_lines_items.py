"""``tm.Lines`` drawn as ink: at their width and colour along the projected segments, cut where
a surface covers them (the exact rule and the depth rule), dashed behind surfaces with
``hidden=True``, in the SVG as their own group, in a scene of lines alone, placed by their
transform, scaled by the pixel ratio, framed by the fitted camera, and refused with the argument
named when they are wrong."""

from __future__ import annotations

import re

import numpy as np
import pytest

import toonmesh as tm
from toonmesh.bench.lines import slab

BACKENDS = ["vulkan", "gl"]
SQUARE = np.array([[-1.0, -1.0, 0.0], [1.0, -1.0, 0.0], [1.0, 1.0, 0.0], [-1.0, 1.0, 0.0]])
SQUARE_SEGMENTS = np.array([[0, 1], [1, 2], [2, 3], [3, 0]])
# looking down -z at the origin, 4 world units high
FRONT = tm.Camera.orthographic((0.0, 0.0, 5.0), height=4.0)
RED = (1.0, 0.0, 0.0)


def to_pixels(res, points):
    """World points to the pixel coordinates of ``res`` (x right, y down)."""
    p = np.c_[points, np.ones(len(points))] @ (res.projection @ res.view_matrix).T
    ndc = p[:, :2] / p[:, 3:]
    return np.c_[(ndc[:, 0] * 0.5 + 0.5) * res.width, (0.5 - ndc[:, 1] * 0.5) * res.height]


def distance_to_segments(res, points, segments):
    """Each pixel centre's distance (pixels) to the nearest of the projected segments."""
    s = to_pixels(res, points)
    ys, xs = np.mgrid[0:res.height, 0:res.width] + 0.5
    p = np.stack([xs, ys], axis=-1)
    best = np.full((res.height, res.width), np.inf)
    for i, j in segments:
        a, b = s[i], s[j]
        ab = b - a
        t = np.clip(((p - a) @ ab) / (ab @ ab), 0.0, 1.0)
        best = np.minimum(best, np.linalg.norm(p - (a + t[..., None] * ab), axis=-1))
    return best


def red(color):
    c = color[..., :3].astype(int)
    return (c[..., 0] > 200) & (c[..., 1] < 90) & (c[..., 2] < 90)


def length(polylines):
    return float(sum(np.linalg.norm(np.diff(p, axis=0), axis=1).sum() for p in polylines))


@pytest.mark.parametrize("backend", BACKENDS)
def test_a_square_is_inked_at_its_width_and_colour_along_its_segments(backend):
    square = tm.Lines(SQUARE, SQUARE_SEGMENTS, color=RED, width=4.0)
    res = tm.Renderer(backend).render([square], camera=FRONT, width=200, height=200, outlines="mesh",
                                      outputs=("color", "outline", "lines"))
    d = distance_to_segments(res, SQUARE, SQUARE_SEGMENTS)
    # red where the centre line runs, paper a little beyond the ink's half width
    assert red(res.color[d < 1.0]).all()
    assert (res.outline[d > 2.0 + 1.0] == 0).all() and (res.color[d > 3.5][:, :3] == 255).all()
    # the coverage across a side (x = 150) sums to the width (antialiased ink, 4 pixels)
    across = res.outline[100, 140:160]
    assert across.sum() == pytest.approx(4.0, abs=0.15), across
    # in the lines: one closed stroke round the square, of the Lines' kind and width
    assert res.line_kinds == ["lines"] and res.line_items == [0]
    assert length(res.lines) == pytest.approx(4 * 100.0, rel=0.01)
    assert np.allclose(res.line_widths[0], 4.0)
    assert res.line_inks == [(RED, 4.0)]


@pytest.mark.parametrize("backend", BACKENDS)
@pytest.mark.parametrize("visibility", ["exact", "depth"])
def test_a_segment_behind_a_box_is_cut_where_the_box_covers_it(backend, visibility):
    box = tm.Mesh(*slab((-1, -1, -1), (1, 1, 1)), normals="flat")
    behind = np.array([[-1.8, 0.3, -2.0], [1.8, 0.3, -2.0]])
    wire = tm.Lines(behind, color=RED, width=3.0)
    res = tm.Renderer(backend).render([box, wire], camera=FRONT, width=200, height=200,
                                      outlines=tm.Outlines("mesh", visibility=visibility),
                                      outputs=("color", "lines"))
    a, b = to_pixels(res, behind)
    row = int(a[1])
    xs = np.arange(int(a[0]) + 1, int(b[0]))
    box_x = to_pixels(res, np.array([[-1.0, 0, 1], [1.0, 0, 1]]))[:, 0]
    outside = (xs < box_x[0] - 3) | (xs > box_x[1] + 3)
    inside = (xs > box_x[0] + 3) & (xs < box_x[1] - 3)
    on_row = red(res.color[row, xs])
    assert on_row[outside].all(), "the wire shows beside the box"
    assert not on_row[inside].any(), "the box hides the wire behind it"
    # its visible pieces in the lines, the hidden part left out
    mine = [p for p, k in zip(res.lines, res.line_kinds) if k == "lines"]
    want = (b[0] - a[0]) - (box_x[1] - box_x[0])
    assert len(mine) == 2 and length(mine) == pytest.approx(want, abs=3.0)


@pytest.mark.parametrize("backend", BACKENDS)
def test_the_hidden_part_is_dashed_with_hidden_lines(backend):
    box = tm.Mesh(*slab((-1, -1, -1), (1, 1, 1)), normals="flat")
    behind = np.array([[-1.8, 0.3, -2.0], [1.8, 0.3, -2.0]])
    res = tm.Renderer(backend).render([box, tm.Lines(behind, color=RED, width=3.0)], camera=FRONT, width=200,
                                      height=200, outlines=tm.Outlines("mesh", hidden=True),
                                      outputs=("color", "outline", "lines"))
    a, b = to_pixels(res, behind)
    box_x = to_pixels(res, np.array([[-1.0, 0, 1], [1.0, 0, 1]]))[:, 0]
    xs = np.arange(int(box_x[0]) + 4, int(box_x[1]) - 4)
    inked = res.outline[int(a[1]), xs] > 0.5
    assert 0.25 < inked.mean() < 0.75, inked.mean()
    assert np.count_nonzero(np.diff(inked.astype(int))) >= 6
    assert not red(res.color[int(a[1]), xs]).any(), "in the hidden lines' grey, not the wire's red"
    hidden = [p for p, k in zip(res.lines, res.line_kinds) if k == "hidden" and abs(p[:, 1] - a[1]).max() < 1]
    assert length(hidden) == pytest.approx(box_x[1] - box_x[0], abs=3.0)


@pytest.mark.parametrize("backend", BACKENDS)
def test_the_svg_draws_each_lines_item_as_its_own_group_on_top(backend):
    box = tm.Mesh(*slab((-1, -1, -1), (1, 1, 1)), normals="flat")
    ends = np.array([[x, y, 1.5] for y in (-1.2, 0.0, 1.2) for x in (-1.5, 1.5)])
    apart = tm.Lines(ends, np.array([[0, 1], [2, 3], [4, 5]]), color=RED, width=2.0)
    square = tm.Lines(SQUARE * 1.4 + [0, 0, 1.5], SQUARE_SEGMENTS, width=1.0)
    r = tm.Renderer(backend)
    res = r.render([box, apart, square], camera=FRONT, width=200, height=200, outlines="mesh",
                   outputs=("color", "lines"))
    svg = res.svg()
    groups = re.findall(r'<g id="([\w-]+)"', svg)
    assert groups[-2:] == ["lines-0", "lines-1"] and len(groups) > 2, groups
    body = {g: b for g, b in re.findall(r'<g id="([\w-]+)"[^>]*>(.*?)</g>', svg, re.S)}
    assert body["lines-0"].count("<polyline") == 3
    assert body["lines-1"].count("<polyline") == 1
    assert re.search(r'<g id="lines-0"[^>]*stroke="#ff0000"[^>]*stroke-width="2"', svg)
    one = r.render([apart], camera=FRONT, width=200, height=200, outputs=("lines",)).svg()
    assert re.findall(r'<g id="([\w-]+)"', one) == ["lines"]


@pytest.mark.parametrize("backend", BACKENDS)
def test_a_scene_of_lines_alone_is_drawn_and_framed(backend):
    far = tm.Lines(SQUARE + [100.0, 50.0, 0.0], SQUARE_SEGMENTS)
    r = tm.Renderer(backend)
    for outlines in (None, "image"):
        res = r.render(far, width=160, height=120, outlines=outlines, outputs=("color", "lines"))
        assert "item_lines" in res.passes and "lines" in res.passes and "silhouettes" not in res.passes
        ink = res.color[..., :3].min(axis=-1) < 128
        assert ink.sum() > 100
        # the fitted camera frames the square, far from the origin: its corners on the image
        corners = to_pixels(res, SQUARE + [100.0, 50.0, 0.0])
        assert (corners >= 0).all() and (corners[:, 0] <= 160).all() and (corners[:, 1] <= 120).all()
        # the outlines' ink: black, at their width
        dark = res.color[ink][:, :3]
        assert dark.min() < 20
        assert np.allclose(res.line_widths[0], tm.LineStyle().width)
    # beside a mesh at the origin, the fitted camera frames both
    box = tm.Mesh(*slab((-1, -1, -1), (1, 1, 1)), normals="flat")
    both = r.render([box, far], width=160, height=120, outputs=("color",))
    corners = to_pixels(both, SQUARE + [100.0, 50.0, 0.0])
    assert (corners >= 0).all() and (corners[:, 0] <= 160).all() and (corners[:, 1] <= 120).all()
    # no Lines item: no line step
    plain = r.render(None, width=64, height=64, outputs=("color",))
    assert "item_lines" not in plain.passes and "lines" not in plain.passes
    # render_many draws them in every view as render does
    cams = [tm.Camera.orthographic((0.0, 0.0, 5.0), (100, 50, 0), height=4.0)] * 2
    stack = r.render_many([far], cams, width=80, height=80)
    alone = r.render([far], camera=cams[0], width=80, height=80)
    assert np.array_equal(stack.color[1], alone.color) and (alone.color[..., 0] < 128).sum() > 50


@pytest.mark.parametrize("backend", BACKENDS)
def test_the_transform_places_the_lines_and_the_pixel_ratio_scales_their_width(backend):
    r = tm.Renderer(backend)
    shift = np.eye(4)
    shift[:3, 3] = [0.3, -0.2, 0.0]
    kw = dict(camera=FRONT, width=200, height=200, outputs=("color", "lines"))
    moved = r.render(tm.Lines(SQUARE, SQUARE_SEGMENTS, transform=shift, width=3.0), **kw)
    given = r.render(tm.Lines(SQUARE + [0.3, -0.2, 0.0], SQUARE_SEGMENTS, width=3.0), **kw)
    plain = r.render(tm.Lines(SQUARE, SQUARE_SEGMENTS, width=3.0), **kw)
    assert np.abs(moved.color.astype(int) - given.color.astype(int)).max() <= 1
    assert not np.array_equal(moved.color, plain.color)
    # twice the pixels at pixel ratio 2: the ink twice as wide, the same drawing
    kw2 = dict(camera=FRONT, width=400, height=400, pixel_ratio=2.0, outlines="mesh", outputs=("outline", "lines"))
    kw1 = dict(kw2, width=200, height=200, pixel_ratio=1.0)
    for width in (None, 3.0):
        one = r.render(tm.Lines(SQUARE, SQUARE_SEGMENTS, width=width), **kw1)
        two = r.render(tm.Lines(SQUARE, SQUARE_SEGMENTS, width=width), **kw2)
        w = tm.LineStyle().width if width is None else width
        assert one.outline[100, 140:160].sum() == pytest.approx(w, abs=0.15)
        assert two.outline[200, 280:320].sum() == pytest.approx(2 * w, abs=0.3)
        assert np.allclose(two.line_widths[0], 2 * w)


def test_bad_lines_are_refused_naming_the_argument():
    with pytest.raises(ValueError, match="positions"):
        tm.Lines(np.zeros((3, 2)))
    with pytest.raises(ValueError, match="positions"):
        tm.Lines([[0, 0, 0], [np.nan, 0, 0]])
    with pytest.raises(IndexError, match="segments"):
        tm.Lines(SQUARE, [[0, 4]])
    with pytest.raises(TypeError, match="segments"):
        tm.Lines(SQUARE, [[0.0, 1.0]])
    with pytest.raises(ValueError, match="width"):
        tm.Lines(SQUARE, width=-1.0)
    with pytest.raises(ValueError, match="color"):
        tm.Lines(SQUARE, color=(2.0, 0.0, 0.0))
    # what the core checks once placed in a scene names the item
    lines = tm.Lines(SQUARE, SQUARE_SEGMENTS)
    lines.width = 1000.0
    with pytest.raises(ValueError, match=r"lines\[0\]\.width"):
        tm.render([lines], width=32, height=32)
    lines = tm.Lines(SQUARE, SQUARE_SEGMENTS)
    lines.segments = np.array([[0, 9]])
    with pytest.raises(IndexError, match=r"lines\[1\]\.segments"):
        tm.render([tm.Lines(SQUARE), lines], width=32, height=32)
    with pytest.raises(ValueError, match="'lines' needs"):
        tm.render(None, width=32, height=32, outputs=("lines",))

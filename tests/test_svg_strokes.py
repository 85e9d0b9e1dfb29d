"""Strokes of a line drawing as the SVG draws them: smoothed along their length
(RenderResult.strokes(smooth=...), svg(smooth=...)), and drawn with the widths the ink has
(RenderResult.line_widths; filled outlines in the SVG where the outlines taper or scale width by
depth)."""

from __future__ import annotations

import re

import numpy as np
import pytest

import toonmesh as tm
from toonmesh.rendering import _strokes
from toonmesh.bench.render import stroke_stats
from toonmesh.data import bunny

SIZE = 400


@pytest.fixture(scope="module")
def raw_bunny():
    """The raw bunny's lines (smooth contours: a scan's wobble in them)."""
    V, F = bunny()
    return tm.render(V, F, outputs=("lines",), width=SIZE, height=SIZE, outlines=tm.Outlines("mesh"))


def _closed(line):
    return len(line) > 2 and np.array_equal(line[0], line[-1])


def test_smoothing_straightens_strokes_within_its_radius_and_keeps_their_ends(raw_bunny):
    res = raw_bunny
    raw = [p for p, _, _ in res.strokes(simplify=0)]
    assert all(np.array_equal(a, b) for a, b in zip(raw, res.lines)), "smooth=0, simplify=0: the lines as they are"
    turning = stroke_stats(raw)[3]
    for radius in (1.0, 3.0):
        smooth = [p for p, _, _ in res.strokes(smooth=radius, simplify=0)]
        assert stroke_stats(smooth)[3] < (0.85 if radius == 1.0 else 0.65) * turning
        for before, after in zip(res.lines, smooth):
            assert after.shape == before.shape
            assert np.hypot(*(after - before).T).max() <= radius + 1e-9
            if _closed(before):
                np.testing.assert_array_equal(after[0], after[-1])
            else:
                np.testing.assert_array_equal(after[[0, -1]], before[[0, -1]])
    assert any(_closed(l) for l in res.lines) or len(res.lines) > 10
    # the SVG smooths the same way, before it simplifies
    assert res.svg(smooth=0) == res.svg() != res.svg(smooth=2.0)


def test_smoothing_keeps_straight_lines_and_rounds_corners():
    # unevenly spaced points on a straight line stay on it, where they were: the line is
    # integrated along its length, not averaged point by point
    x = np.array([0.0, 0.3, 0.4, 2.0, 2.1, 5.0, 5.2, 9.0])
    line = np.column_stack([x, 0.5 * x])
    np.testing.assert_allclose(_strokes.smoothed(line, 2.0), line, atol=1e-12)
    # a square's corners are cut, by less than the radius, and it stays closed
    t = np.linspace(0, 1, 21)[:-1]
    side = lambda a, b: a + (b - a) * t[:, None]  # noqa: E731
    c = [np.array(p, float) for p in ((0, 0), (20, 0), (20, 20), (0, 20))]
    square = np.vstack([side(c[i], c[(i + 1) % 4]) for i in range(4)] + [c[0][None]])
    round_ = _strokes.smoothed(square, 3.0)
    np.testing.assert_array_equal(round_[0], round_[-1])
    moved = np.hypot(*(round_ - square).T)
    assert 0.3 < moved[20] <= 3.0 and moved[10] < 1e-9  # a corner moves in, a side's middle stays
    # zigzag: much less turning, ends pinned
    zig = np.column_stack([np.arange(30.0), 0.4 * (np.arange(30) % 2)])
    flat = _strokes.smoothed(zig, 2.0)
    assert stroke_stats([flat])[3] < 0.2 * stroke_stats([zig])[3]
    np.testing.assert_array_equal(flat[[0, -1]], zig[[0, -1]])


def _old_svg(res, simplify=_strokes.SIMPLIFY):
    """The SVG before widths and smoothing: one polyline per stroke, per kind at its width."""
    out = [
        '<?xml version="1.0" encoding="UTF-8"?>',
        f'<svg xmlns="http://www.w3.org/2000/svg" width="{res.width}" height="{res.height}" '
        f'viewBox="0 0 {res.width} {res.height}">',
    ]
    for kind in sorted(set(res.line_kinds)):
        style = res.outlines.styles[kind]
        color = "#" + "".join(f"{round(c * 255):02x}" for c in style.color)
        out.append(f'<g id="{kind}" fill="none" stroke="{color}" stroke-width="{style.width:g}" '
                   'stroke-linecap="round" stroke-linejoin="round">')
        for l, k in zip(res.lines, res.line_kinds):
            if k == kind:
                points = " ".join(f"{x:.2f},{y:.2f}" for x, y in _strokes.simplified(l, simplify))
                out.append(f'<polyline points="{points}"/>')
        out.append("</g>")
    out.append("</svg>")
    return "\n".join(out) + "\n"


def test_default_svg_is_one_polyline_per_stroke_at_its_kinds_width(raw_bunny):
    res = raw_bunny
    assert res.svg() == _old_svg(res) == res.svg(widths="auto") == res.svg(widths="kind")
    assert "<path" not in res.svg() and res.svg(widths="point").count("<path") == len(res.lines)
    for widths, kind in zip(res.line_widths, res.line_kinds):
        assert widths.dtype == np.float32
        np.testing.assert_array_equal(widths, np.float32(res.outlines.styles[kind].width))


def _svg_capsules(svg, kind):
    """Each filled stroke of `kind`'s group as (centres (K, 2), widths (K,)): read back from its
    segments' half discs."""
    group = svg.split(f'<g id="{kind}"')[1].split("</g>")[0]
    strokes = []
    for d in re.findall(r'<path d="([^"]+)"', group):
        centres, widths = [], []
        for sub in d.split("Z")[:-1]:
            n = [float(v) for v in re.findall(r"-?\d+\.?\d*", sub)]
            # M p0 A r r 0 0 1 p1 L p2 A r r 0 0 1 p3: ends at the middles of p0 p1 and p2 p3
            a, ra = (np.array(n[0:2]) + np.array(n[7:9])) / 2, n[2]
            b, rb = (np.array(n[9:11]) + np.array(n[16:18])) / 2, n[11]
            if not centres:
                centres, widths = [a], [2 * ra]
            centres.append(b)
            widths.append(2 * rb)
        strokes.append((np.array(centres), np.array(widths)))
    return strokes


def _ink_across(outline, p, direction, reach):
    """The ink coverage summed across the line through `p` (perpendicular to `direction`), in
    pixels: the line's width where nothing else is near."""
    n = np.array([-direction[1], direction[0]]) / np.hypot(*direction)
    steps = np.arange(-reach, reach + 1e-9, 0.125)
    q = p + steps[:, None] * n - 0.5  # pixel centres at integer + 0.5
    x0, y0 = np.floor(q[:, 0]).astype(int), np.floor(q[:, 1]).astype(int)
    fx, fy = q[:, 0] - x0, q[:, 1] - y0
    h, w = outline.shape
    at = lambda y, x: outline[np.clip(y, 0, h - 1), np.clip(x, 0, w - 1)]  # noqa: E731
    v = (at(y0, x0) * (1 - fx) * (1 - fy) + at(y0, x0 + 1) * fx * (1 - fy)
         + at(y0 + 1, x0) * (1 - fx) * fy + at(y0 + 1, x0 + 1) * fx * fy)
    return float(v.sum() * 0.125)


def _fine_cube(n=17):
    """A unit cube whose faces are n x n grids: each edge a chain of n - 1 segments, so that the
    taper, set at the chains' points, shapes each edge."""
    G, g = tm.shapes.grid(n)
    uv = G[:, :2] - 0.5
    V, F = [], []
    for a in range(3):
        e = np.eye(3)[[a, (a + 1) % 3, (a + 2) % 3]]
        for side in (-1, 1):
            F.append((g if side > 0 else g[:, ::-1]) + sum(map(len, V)))
            V.append(0.5 * side * e[0] + uv[:, :1] * e[1] + uv[:, 1:] * e[2])
    return np.vstack(V), np.vstack(F)


def test_svg_under_taper_thins_toward_stroke_ends_as_the_ink_does():
    camera = tm.Camera.look_at(eye=(2.0, 1.5, 3.0), target=(0, 0, 0))
    cube = tm.Mesh(*_fine_cube(), normals="flat")
    # the rim is a closed silhouette (no ends, no taper); the three edges at the near corner are
    # ridges, each an open chain
    outlines = tm.Outlines("mesh", width=6.0, taper=60.0)
    res = tm.render(cube, outlines=outlines, camera=camera, outputs=("outline", "lines"), width=SIZE, height=SIZE)
    svg = res.svg()
    # the tapered ridges are filled outlines (a kind whose width does not change is drawn as
    # polylines)
    ridge_group = svg.split('<g id="ridge"')[1].split("</g>")[0]
    assert "<polyline" not in ridge_group and 'fill="#000000"' in ridge_group
    strokes = _svg_capsules(svg, "ridge")
    ridges = [(l, w) for l, w, k in zip(res.lines, res.line_widths, res.line_kinds) if k == "ridge"]
    assert len(strokes) == len(ridges) >= 1
    rim = [l for l, k in zip(res.lines, res.line_kinds) if k == "silhouette"]
    rim_group = svg.split('<g id="silhouette"')[1].split("</g>")[0]
    assert len(rim) == 1 and _closed(rim[0]) and 'stroke-width="6"' in rim_group and "<polyline" in rim_group
    checked = 0
    for (centres, widths), (line, line_widths) in zip(strokes, ridges):
        np.testing.assert_allclose(centres[[0, -1]], line[[0, -1]], atol=0.01)
        np.testing.assert_allclose(widths[[0, -1]], line_widths[[0, -1]], atol=0.02)
        # thinner toward both ends (each within the taper of its chain's end) than in between
        assert widths[0] < widths.max() - 1 and widths[-1] < widths.max() - 1
        assert widths.min() >= 0.2 * 6.0 - 0.02
        # the widths the SVG draws are the ink's, at points along the stroke away from the ends
        seg = np.hypot(*np.diff(centres, axis=0).T)
        s = np.concatenate([[0], np.cumsum(seg)])
        for f in (0.2, 0.35, 0.5, 0.65, 0.8):
            at = f * s[-1]
            p = np.array([np.interp(at, s, centres[:, 0]), np.interp(at, s, centres[:, 1])])
            w = float(np.interp(at, s, widths))
            others = [c for c, _ in strokes if c is not centres] + rim
            if min(np.hypot(*(o - p).T).min() for o in others) < 12:
                continue  # another stroke's ink is near
            k = min(np.searchsorted(s, at), len(centres) - 1)
            direction = centres[k] - centres[max(k - 1, 0)]
            assert abs(_ink_across(res.outline, p, direction, w / 2 + 3) - w) < 0.35, (f, w)
            checked += 1
    assert checked >= 5
    # widths="kind": centre lines at the kind's width, as a plotter draws them
    kind = res.svg(widths="kind")
    assert "<path" not in kind and 'stroke-width="6"' in kind


def test_svg_widths_follow_depth():
    V, F = tm.shapes.icosphere(4)
    shift = np.eye(4)
    shift[:3, 3] = (1.5, 0.0, -4.0)
    scene = [tm.Mesh(V, F, transform=np.eye(4)), tm.Mesh(V, F, transform=shift)]
    cam = tm.Camera.look_at(eye=(0.5, 0.0, 4.0), target=(0.7, 0, -2.0))
    res = tm.render(scene, outlines=tm.Outlines("mesh", width=3.0, width_by_depth=True), camera=cam,
                    outputs=("lines",), width=SIZE, height=SIZE)
    # one rim each: the near sphere's (the bigger one) drawn wider than the width, the far one's narrower
    assert len(res.lines) == 2
    near, far = (w for _, w in sorted(zip(res.lines, res.line_widths), key=lambda lw: -np.ptp(lw[0][:, 1])))
    assert near.min() > 1.2 * 3.0 and far.max() < 0.9 * 3.0
    strokes = _svg_capsules(res.svg(), "silhouette")
    assert len(strokes) == len(res.lines)
    for (_, widths), w in zip(strokes, res.line_widths):
        assert abs(widths.max() - w.max()) < 0.02


def _greedy_every_stroke(lines):
    """The plotter rule tried against every undrawn stroke at each step (n squared): the
    reference order."""
    starts = np.array([l[0] for l in lines])
    ends = np.array([l[-1] for l in lines])
    todo = np.ones(len(lines), bool)
    pen, out = np.zeros(2), []
    for _ in lines:
        ds = np.where(todo, np.hypot(*(starts - pen).T), np.inf)
        de = np.where(todo, np.hypot(*(ends - pen).T), np.inf)
        i, j = int(np.argmin(ds)), int(np.argmin(de))
        flip = bool(de[j] < ds[i])
        k = j if flip else i
        todo[k] = False
        out.append((k, flip))
        pen = starts[k] if flip else ends[k]
    return out


def _random_strokes(n, seed):
    rng = np.random.default_rng(seed)
    starts = rng.uniform(0, 1000, (n, 2))
    return [np.stack([s, s + rng.normal(0, 10, 2)]) for s in starts]


def test_plotter_order_travels_no_further_than_the_greedy_rule_and_scales():
    small = _random_strokes(500, 1)
    order = _strokes.plotter_order(small)
    assert order == _greedy_every_stroke(small)
    drawn = lambda lines, order: [lines[i][::-1] if flip else lines[i] for i, flip in order]  # noqa: E731
    greedy = _strokes.pen_travel(drawn(small, _greedy_every_stroke(small)))
    assert _strokes.pen_travel(drawn(small, order)) <= greedy < 0.2 * _strokes.pen_travel(small)
    # many strokes: each drawn once, in the order's time (its speed is the benchmark's)
    many = _random_strokes(20_000, 2)
    order = _strokes.plotter_order(many)
    assert sorted(i for i, _ in order) == list(range(len(many)))
    assert _strokes.pen_travel(drawn(many, order)) < 0.05 * _strokes.pen_travel(many)
    assert _strokes.plotter_order([]) == []


def test_bad_strokes_are_refused_naming_the_argument():
    from toonmesh import _core

    line = np.array([[0.0, 0.0], [1.0, 1.0], [2.0, 0.0]])
    with pytest.raises(ValueError, match=r"lines\[0\]: expected shape \(K, 2\)"):
        _strokes.drawn([np.zeros((3, 3))], [None], 0.0, 0.25)
    with pytest.raises(ValueError, match=r"lines\[0\]: point 1 is not finite"):
        _strokes.drawn([np.array([[0.0, 0.0], [np.nan, 1.0]])], [None], 0.0, 0.25)
    with pytest.raises(ValueError, match=r"widths\[0\]: expected one width per point \(3\), got 2"):
        _strokes.kept(line, 0.25, np.ones(2, np.float32))
    with pytest.raises(ValueError, match="simplify"):
        _strokes.simplified(line, -1.0)
    with pytest.raises(ValueError, match="smooth"):
        _strokes.smoothed(line, float("nan"))
    with pytest.raises(ValueError, match="ends: expected as many as starts"):
        _core._plotter_order(np.zeros((2, 2)), np.zeros((1, 2)))
    with pytest.raises(ValueError, match=r"groups\[0\].widths: filled outlines need one widths array per line"):
        _core._svg_document(10, 10, [("ridge", "#000000", None, None, [line], None)])
    with pytest.raises(ValueError, match=r"groups\[0\].widths: expected one widths array per line \(2\), got 1"):
        _core._svg_document(10, 10, [("ridge", "#000000", 1.0, None, [line, line], [np.ones(3)])])
    with pytest.raises(TypeError, match=r"groups\[0\].color"):
        _core._svg_document(10, 10, [("ridge", 7, 1.0, None, [line], None)])

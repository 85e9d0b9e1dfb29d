"""Mesh outlines drawn with smooth contours (Outlines(contours="smooth")) and suggestive contours
(Outlines(suggestive=...)) in a render, on both backends: the lines the per-view functions of
toonmesh.edges find, with hidden parts removed, in the line drawing, the ink and the SVG."""

from __future__ import annotations

import pickle

import numpy as np
import pytest

import toonmesh as tm
from test_curvature import _torus

BACKENDS = ["vulkan", "gl"]
SIZE = 400


def _pieces(res, kind):
    lens = [np.linalg.norm(np.diff(l, axis=0), axis=1).sum() for l, k in zip(res.lines, res.line_kinds) if k == kind]
    return np.array(lens)


def test_defaults_and_pickling():
    o = tm.Outlines()
    assert o.contours == "auto" and o.suggestive_threshold == 0.01
    assert o.styles["suggestive"] is None  # drawn only when asked for
    assert "suggestive" in tm._core.LINE_KINDS
    s = tm.Outlines("mesh", contours="smooth", suggestive="#3050a0", suggestive_threshold=0.2)
    assert s.contours == "smooth" and s.suggestive_threshold == 0.2
    assert s.styles["suggestive"].color == pytest.approx((0x30 / 255, 0x50 / 255, 0xA0 / 255))
    assert pickle.loads(pickle.dumps(s)) == s and hash(pickle.loads(pickle.dumps(s))) == hash(s)
    with pytest.raises(ValueError, match="contours"):
        tm.Outlines(contours="zigzag")


@pytest.mark.parametrize("backend", BACKENDS)
def test_smooth_contours_of_a_noisy_sphere_are_few_long_strokes(backend):
    V, F = tm.shapes.icosphere(5, noise=0.003, seed=0)
    kw = dict(outputs=("color", "lines"), width=SIZE, height=SIZE, backend=backend)
    faces = tm.render(V, F, outlines=tm.Outlines("mesh", contours="faces"), **kw)
    smooth = tm.render(V, F, outlines=tm.Outlines("mesh", contours="smooth"), **kw)
    f, s = _pieces(faces, "silhouette"), _pieces(smooth, "silhouette")
    # the rim of the sphere as drawn: a circle; measure its radius from the smooth lines' points
    points = np.concatenate([l for l, k in zip(smooth.lines, smooth.line_kinds) if k == "silhouette"])
    centre = np.array([SIZE / 2, SIZE / 2])  # the default camera frames the sphere in the middle
    radius = np.linalg.norm(points - centre, axis=1)
    r0 = np.median(radius)
    assert np.percentile(np.abs(radius - r0), 90) < 0.02 * r0  # on one circle, no staircase
    rim = 2 * np.pi * r0
    assert len(s) <= 40 < len(f)
    assert s.sum() < 1.3 * rim < f.sum()
    # the picture keeps its silhouette ink where the face-edge rule had it
    ink = lambda r: np.count_nonzero(r.color[..., :3].max(axis=2) < 40)  # noqa: E731
    assert ink(smooth) > 0.3 * ink(faces)


def _silhouette_ink(res):
    return sorted(np.round(np.concatenate([l for l, k in zip(res.lines, res.line_kinds) if k == "silhouette"]), 3).tolist())


@pytest.mark.parametrize("backend", BACKENDS)
def test_the_default_rule_follows_the_shading(backend):
    from toonmesh.bench.effects import box

    kw = dict(outputs=("color", "lines"), width=SIZE, height=SIZE, backend=backend)
    at = lambda rule, mesh: tm.render(mesh, outlines=tm.Outlines("mesh", contours=rule), **kw)  # noqa: E731
    # flat-shaded: the face-edge rule
    V, F = tm.shapes.icosphere(3, noise=0.01, seed=1)
    flat = tm.Mesh(V, F, normals="flat")
    assert _silhouette_ink(at("auto", flat)) == _silhouette_ink(at("faces", flat))
    # smooth-shaded: smooth contours between creases ...
    smooth = tm.Mesh(V, F)
    assert _silhouette_ink(at("auto", smooth)) == _silhouette_ink(at("smooth", smooth))
    assert _silhouette_ink(at("auto", smooth)) != _silhouette_ink(at("faces", smooth))
    # ... and face edges on them: a cube drawn with smooth normals keeps its straight outline
    Vb, Fb = box((0.0, 0.0, 0.0), 0.5)
    cube = tm.Mesh(Vb, Fb)
    camera = tm.Camera.look_at(eye=(2.0, 1.5, 3.0), target=(0, 0, 0))
    a = tm.render(cube, outlines=tm.Outlines("mesh"), camera=camera, **kw)
    b = tm.render(cube, outlines=tm.Outlines("mesh", contours="faces"), camera=camera, **kw)
    np.testing.assert_array_equal(a.color, b.color)
    assert "silhouette" in a.line_kinds


@pytest.mark.parametrize("backend", BACKENDS)
def test_suggestive_contours_are_drawn_only_where_there_are_some(backend):
    red = tm.Outlines("mesh", suggestive=(1.0, 0.0, 0.0), suggestive_threshold=0.0, width=2.0)
    kw = dict(outputs=("color", "lines"), width=SIZE, height=SIZE, backend=backend, outlines=red)
    V, F, _, _ = _torus()
    camera = tm.Camera.look_at(eye=(0.0, -4.0, 2.5), target=(0, 0, 0), up=(0, 0, 1))
    torus = tm.render(V, F, camera=camera, **kw)
    assert "suggestive" in torus.line_kinds
    c = torus.color.astype(int)
    reddish = (c[..., 0] > 150) & (c[..., 1] < 60) & (c[..., 2] < 60)
    assert np.count_nonzero(reddish) > 50
    # the visible lines are the per-view function's, minus hidden parts
    found = tm.edges.suggestive_contours(V, F, eye=(0.0, -4.0, 2.5), threshold=0.0, weld=True)
    P = torus.projection @ torus.view_matrix
    pts = np.concatenate(found)
    h = np.c_[pts, np.ones(len(pts))] @ P.T
    px = np.c_[(h[:, 0] / h[:, 3] * 0.5 + 0.5) * SIZE, (0.5 - h[:, 1] / h[:, 3] * 0.5) * SIZE]
    drawn = np.concatenate([l for l, k in zip(torus.lines, torus.line_kinds) if k == "suggestive"])
    gaps = np.min(np.linalg.norm(drawn[:, None, :] - px[None, ::4, :], axis=2), axis=1)
    assert np.median(gaps) < 1.0
    # a convex shape has none
    Vs, Fs = tm.shapes.icosphere(4)
    sphere = tm.render(Vs * [1.5, 1.0, 0.7], Fs, **kw)
    assert "suggestive" not in sphere.line_kinds
    c = sphere.color.astype(int)
    assert np.count_nonzero((c[..., 0] > 150) & (c[..., 1] < 60) & (c[..., 2] < 60)) == 0


def test_suggestive_contours_of_a_scan_use_the_curvature_at_a_feature_size():
    from toonmesh.data import bunny

    V, F = bunny()
    r = tm.Renderer()
    mesh = r.add_mesh(V, F)
    kw = dict(outputs=("color", "lines"), width=SIZE, height=SIZE)
    counts, passes = {}, set()
    for smoothing in (0.0, None, 3.0):
        res = r.render(mesh, outlines=tm.Outlines("mesh", suggestive=True, curvature_smoothing=smoothing), **kw)
        counts[smoothing] = res.line_kinds.count("suggestive")
        passes.add(tuple(res.passes))
    assert counts[0.0] > 4 * counts[None] > 0 and counts[3.0] <= counts[None]
    # faded by strength: thin (a fifth of the width) at the threshold, full width well past it
    res = r.render(mesh, outlines=tm.Outlines("mesh", suggestive=True), **kw)
    width = res.outlines.styles["suggestive"].width
    faded = np.concatenate([w for w, k in zip(res.line_widths, res.line_kinds) if k == "suggestive"])
    assert faded.min() >= 0.2 * width - 1e-4 and faded.max() <= width + 1e-4
    assert faded.min() < 0.4 * width and faded.max() > 0.8 * width
    others = np.concatenate([w for w, k in zip(res.line_widths, res.line_kinds) if k != "suggestive"])
    assert np.all(others == res.outlines.styles["silhouette"].width)
    # the knob changes which lines, not which passes run
    assert len(passes) == 1
    assert tm.Outlines("mesh").curvature_smoothing is None
    # asked for where no mesh lines are drawn: refused, not dropped
    with pytest.raises(ValueError, match="suggestive.*mesh"):
        tm.Outlines("image", suggestive=True)
    assert tm.Outlines("both", suggestive=True).styles["suggestive"] is not None
    assert pickle.loads(pickle.dumps(tm.Outlines("mesh", curvature_smoothing=1.5))).curvature_smoothing == 1.5


def test_svg_has_a_suggestive_group():
    V, F, _, _ = _torus(n_u=120, n_v=40)
    camera = tm.Camera.look_at(eye=(0.0, -4.0, 2.5), target=(0, 0, 0), up=(0, 0, 1))
    res = tm.render(V, F, camera=camera, outputs=("lines",), width=200, height=200,
                    outlines=tm.Outlines("mesh", contours="smooth", suggestive=True, suggestive_threshold=0.0))
    svg = res.svg()
    assert 'id="suggestive"' in svg and 'id="silhouette"' in svg


def _svg_lines(svg, kind):
    group = svg.split(f'<g id="{kind}"')[1].split("</g>")[0]
    return [np.array([[float(v) for v in p.split(",")] for p in pts.split()])
            for pts in (chunk.split('"')[1] for chunk in group.split("<polyline points=")[1:])]


def _segment_distance(p, a, b):
    ab, ap = b - a, p - a
    t = np.clip(ap @ ab / max(ab @ ab, 1e-300), 0, 1)
    return np.hypot(*(ap - t * ab))


def test_svg_for_a_pen_plotter():
    from toonmesh.rendering import _strokes

    V, F = tm.shapes.icosphere(4, noise=0.01, seed=3)
    res = tm.render(V, F, outputs=("lines",), width=300, height=300,
                    outlines=tm.Outlines("mesh", contours="smooth", crease_angle=20.0))
    drawing = _svg_lines(res.svg(simplify=0), "ridge")
    plotter = _svg_lines(res.svg(order="plotter", simplify=0), "ridge")
    assert res.svg() == res.svg(simplify=0.25) != res.svg(simplify=0)  # the default
    assert len(drawing) == len(plotter) > 20
    # the same strokes, some drawn the other way round, in an order with much less pen travel
    key = lambda l: tuple(np.round(l if tuple(l[0]) <= tuple(l[-1]) else l[::-1], 2).ravel())  # noqa: E731
    assert sorted(map(key, drawing)) == sorted(map(key, plotter))
    assert _strokes.pen_travel(plotter) < 0.5 * _strokes.pen_travel(drawing)
    # simplified: fewer points, the ends kept, every dropped point within the tolerance
    for tol in (0.25, 1.0):
        simple = _svg_lines(res.svg(simplify=tol), "ridge")
        assert sum(map(len, simple)) < sum(map(len, drawing))
        for full, s in zip(drawing, simple):
            assert np.allclose(full[[0, -1]], s[[0, -1]])
            far = max(min(_segment_distance(p, s[i], s[i + 1]) for i in range(len(s) - 1)) for p in full)
            assert far <= tol + 0.01  # + the SVG's rounding to 0.01 px
    with pytest.raises(ValueError, match="order"):
        res.svg(order="random")
    with pytest.raises(ValueError, match="simplify"):
        res.svg(simplify=-1)
    with pytest.raises(TypeError, match="simplify"):
        res.svg(simplify="0.5")


def test_short_crease_pieces_are_dropped_on_a_scan_and_kept_on_a_cad_part():
    from conftest import load_mesh
    from toonmesh.data import bunny

    def creases(V, F, **kw):
        res = tm.render(V, F, outputs=("lines",), width=400, height=400,
                        outlines=tm.Outlines("mesh", silhouette=False, **kw))
        return [l for l, k in zip(res.lines, res.line_kinds) if k in ("ridge", "valley")]

    assert tm.Outlines().min_crease_length == 0.02
    V, F = bunny()
    every, default = creases(V, F, min_crease_length=0.0), creases(V, F)
    assert len(default) < 0.8 * len(every)
    V, F = load_mesh("fandisk")
    cad_every, cad_default = creases(V, F, min_crease_length=0.0), creases(V, F)
    assert len(cad_default) == len(cad_every) > 0
    for a, b in zip(cad_default, cad_every):
        np.testing.assert_array_equal(a, b)
    # far too long a piece asked for: no crease at all
    assert creases(V, F, min_crease_length=100.0) == []


def test_zig_zag_crease_pieces_are_dropped_on_a_scan_and_kept_on_a_cad_part():
    from conftest import load_mesh
    from toonmesh.bench.render import stroke_stats
    from toonmesh.data import bunny

    r = tm.Renderer()

    def creases(mesh, **kw):
        res = r.render(mesh, outputs=("lines",), width=600, height=600, outlines=tm.Outlines("mesh", **kw))
        return [l for l, k in zip(res.lines, res.line_kinds) if k in ("ridge", "valley")]

    assert tm.Outlines().max_crease_turn == 30.0
    scan = r.add_mesh(*bunny())
    n_short, short_under_5, _, turn_short = stroke_stats(creases(scan, max_crease_turn=180.0))
    n, under_5, _, turn = stroke_stats(creases(scan))
    # measured: 99 strokes under the shortest-piece rule alone, 21 with the turn rule; the
    # saw-tooth pieces along the ears' rims go, so the strokes left turn less per pixel and
    # fewer of them are dashes
    assert 0 < n < 0.4 * n_short
    assert turn < 0.8 * turn_short and under_5 < short_under_5
    # a bound of 0 drops every piece with a vertex of two creases that is not a coarse curve
    assert len(creases(scan, max_crease_turn=0.0)) < n
    cad = r.add_mesh(*load_mesh("fandisk"))
    plain = creases(cad, min_crease_length=0.0, max_crease_turn=180.0)
    default = creases(cad)
    assert len(default) == len(plain) > 0
    for a, b in zip(default, plain):
        np.testing.assert_array_equal(a, b)


def _ink_per_pixel_of_line(res, kind):
    """Ink coverage summed over the picture per pixel of visible line of `kind`: its mean width."""
    length = _pieces(res, kind).sum()
    return res.outline.sum() / length


@pytest.mark.parametrize("backend", BACKENDS)
def test_strokes_taper_at_their_ends_and_widen_nearer(backend):
    from toonmesh.bench.effects import box

    kw = dict(outputs=("outline", "lines"), width=SIZE, height=SIZE, backend=backend)
    camera = tm.Camera.look_at(eye=(2.0, 1.5, 3.0), target=(0, 0, 0))
    cube = tm.Mesh(*box((0.0, 0.0, 0.0), 0.5), normals="flat")
    ridges = dict(silhouette=False, width=4.0)
    plain = tm.render(cube, outlines=tm.Outlines("mesh", **ridges), camera=camera, **kw)
    tapered = tm.render(cube, outlines=tm.Outlines("mesh", taper=60.0, **ridges), camera=camera, **kw)
    # the three ridges at the near corner are open strokes: thinner toward their ends
    assert tapered.lines and [l.tolist() for l in tapered.lines] == [l.tolist() for l in plain.lines]
    assert _ink_per_pixel_of_line(tapered, "ridge") < 0.8 * _ink_per_pixel_of_line(plain, "ridge")
    # a closed silhouette has no ends
    rim = dict(crease=False, width=4.0)
    loop = tm.render(cube, outlines=tm.Outlines("mesh", **rim), camera=camera, **kw)
    np.testing.assert_array_equal(tm.render(cube, outlines=tm.Outlines("mesh", taper=60.0, **rim), camera=camera,
                                            **kw).outline, loop.outline)
    # width by depth: of two equal spheres, the nearer one's rim is drawn wider
    V, F = tm.shapes.icosphere(4)
    shift = np.eye(4)
    shift[:3, 3] = (1.5, 0.0, -4.0)
    scene = [tm.Mesh(V, F, transform=np.eye(4)), tm.Mesh(V, F, transform=shift)]
    cam = tm.Camera.look_at(eye=(0.5, 0.0, 4.0), target=(0.7, 0, -2.0))
    o = dict(outputs=("outline",), width=SIZE, height=SIZE, backend=backend, camera=cam)
    flat = tm.render(scene, outlines=tm.Outlines("mesh", width=3.0), **o).outline
    deep = tm.render(scene, outlines=tm.Outlines("mesh", width=3.0, width_by_depth=True), **o).outline
    left, right = slice(0, SIZE // 4), slice(int(SIZE * 0.7), SIZE)  # only the near, only the far sphere
    assert deep[:, left].sum() > 1.2 * flat[:, left].sum()
    assert deep[:, right].sum() < 0.9 * flat[:, right].sum()


def test_strokes_of_different_kinds_join_when_asked():
    from toonmesh.data import bunny

    V, F = bunny()
    kw = dict(outputs=("lines",), width=SIZE, height=SIZE)
    # every crease piece long enough drawn, zig-zags too: many creases meet the silhouette
    every = dict(max_crease_turn=180.0)
    apart = tm.render(V, F, outlines=tm.Outlines("mesh", **every), **kw)
    joined = tm.render(V, F, outlines=tm.Outlines("mesh", join_kinds=True, **every), **kw)
    assert tm.Outlines().join_kinds is False and tm.Outlines(join_kinds=True).join_kinds is True
    length = lambda r: sum(np.linalg.norm(np.diff(l, axis=0), axis=1).sum() for l in r.lines)  # noqa: E731
    assert len(joined.lines) < 0.85 * len(apart.lines)
    # the same ink, in fewer strokes: joins add at most a line's width per join
    assert length(apart) <= length(joined) <= length(apart) + 1.5 * (len(apart.lines) - len(joined.lines))
    assert set(joined.line_kinds) <= set(apart.line_kinds)


@pytest.mark.parametrize("backend", BACKENDS)
def test_material_borders_between_scene_items(backend):
    # a square in two halves, each a mesh with its own material: where they meet is a material
    # border, the rest of their rim stays boundary
    V, F = tm.shapes.grid(9)  # 8 x 8 squares: x = 0.5 is a row of edges
    centres = V[F].mean(axis=1)
    left, right = F[centres[:, 0] < 0.5], F[centres[:, 0] >= 0.5]
    kw = dict(outputs=("color", "lines"), width=SIZE, height=SIZE, backend=backend,
              camera=tm.Camera.look_at(eye=(0.5, 0.5, 2.0), target=(0.5, 0.5, 0.0)))
    two = [tm.Mesh(V, left, material=tm.Material.bands("#d04040")), tm.Mesh(V, right, material=tm.Material.bands("#4040d0"))]
    r = tm.render(two, outlines=tm.Outlines("mesh", material="#00ff00", width=3.0), **kw)
    border = [l for l, k in zip(r.lines, r.line_kinds) if k == "material"]
    assert len(border) == 1 and "boundary" in r.line_kinds
    x = border[0][:, 0]
    assert np.ptp(x) < 1.0 and np.ptp(border[0][:, 1]) > 0.5 * SIZE  # the vertical line at x = 0.5
    c = r.color.astype(int)
    green = (c[..., 1] > 200) & (c[..., 0] < 60) & (c[..., 2] < 60)
    assert green.sum() > 2 * 0.5 * SIZE
    # one mesh: no borders; borders off: the line is a boundary again
    one = tm.render(V, F, outlines=tm.Outlines("mesh"), **kw)
    assert "material" not in one.line_kinds
    off = tm.render(two, outlines=tm.Outlines("mesh", material=False), **kw)
    rim = lambda res: _pieces(res, "boundary").sum()  # noqa: E731
    assert "material" not in off.line_kinds and rim(off) > rim(r) + 0.5 * SIZE
    assert r.passes == off.passes  # borders are lines of the same passes


def test_a_double_sided_sheet_is_drawn_as_one_surface():
    # a sheet stored twice, once per side (leaves, cloth): welded, its lines are the single
    # sheet's, its border, not every edge of the grid as non-manifold silhouettes
    V, F = tm.shapes.grid(10)
    double = (np.r_[V, V], np.r_[F, F[:, ::-1] + len(V)])
    camera = tm.Camera.look_at((0.3, -0.8, 1.5), target=(0.5, 0.5, 0.0))
    kw = dict(camera=camera, width=200, height=200, outputs=("outline", "lines"))
    single = tm.render(V, F, outlines=tm.Outlines("mesh"), **kw)
    both = tm.render(*double, outlines=tm.Outlines("mesh", suggestive=True), **kw)
    assert set(both.line_kinds) == {"boundary"} == set(single.line_kinds)
    assert len(both.lines) == len(single.lines)
    np.testing.assert_allclose(np.concatenate(both.lines), np.concatenate(single.lines), atol=1e-6)
    assert np.count_nonzero(both.outline > 0.5) == np.count_nonzero(single.outline > 0.5)
    # as stored (no welding), the two layers are two sheets, each with its border
    apart = tm.render(*double, outlines=tm.Outlines("mesh", weld=False), **kw)
    assert len(apart.lines) == 2 * len(single.lines)

"""Ink outlines in the render: the plan for every combination (shadows included), mesh-space lines on a cube (what
is visible, hidden, and how wide), image-space edges against ``edges.detect_edges``, vector lines
and their SVG, and the settings' objects."""

from __future__ import annotations

import itertools
import pickle
import re

import numpy as np
import pytest

import toonmesh as tm
from toonmesh import _core

BACKENDS = ["vulkan", "gl"]

# A unit cube, faces wound outward.
CUBE_V = np.array([[x, y, z] for x in (-1.0, 1.0) for y in (-1.0, 1.0) for z in (-1.0, 1.0)])
CUBE_F = np.array(
    [
        [0, 1, 3], [0, 3, 2], [4, 6, 7], [4, 7, 5],  # x = -1, x = +1
        [0, 4, 5], [0, 5, 1], [2, 3, 7], [2, 7, 6],  # y = -1, y = +1
        [0, 2, 6], [0, 6, 4], [1, 5, 7], [1, 7, 3],  # z = -1, z = +1
    ]
)
# Seen from a corner: three faces show, with 9 of the 12 edges (6 silhouettes, 3 creases).
CORNER = tm.Camera.orthographic((3.0, 2.5, 2.0), height=4.0)


def _expected_passes(outlines, outputs, msaa, supersample, casting=False):
    """The plan rules (src/render/plan.rs), restated, for the default (exact) visibility: vector
    lines are cut on the host and need no depth."""
    mesh = outlines in ("mesh", "both")
    image = outlines in ("image", "both")
    color, normal, depth, outline, lines, shadow = (
        n in outputs for n in ("color", "normal", "depth", "outline", "lines", "shadow"))
    ink = color or outline
    draw_image, draw_lines, vector = image and ink, mesh and ink, mesh and lines
    geometry = "nd" if (normal or draw_image or shadow) else ("d" if (depth or draw_lines) else None)
    single = msaa == 1 and supersample == 1
    passes = []
    if mesh and (draw_lines or vector):
        passes.append("silhouettes")
    if casting and (color or shadow):
        passes.append("shadow_map")
    if color:
        passes.append("shade")
    if geometry and not (color and single):
        passes.append("gbuffer")
    if color and supersample > 1:
        passes.append("downsample")
    if shadow:
        passes.append("shadow")
    if draw_image:
        passes += ["edge_bits", "edges"]  # the default image rule, "discontinuity"
    if draw_lines:
        passes.append("lines")
    if color:
        passes.append("readback_color")
    want_depth = depth
    if normal and want_depth:
        passes.append("readback_normal_depth")
    elif normal:
        passes.append("readback_normal")
    elif want_depth:
        passes.append("readback_depth")
    if outline:
        passes.append("readback_outline")
    if shadow:
        passes.append("readback_shadow")
    if vector:
        passes.append("visible_lines")
    return passes


OUTPUT_SETS = [
    s
    for n in range(1, 4)
    for s in itertools.combinations(("color", "normal", "depth", "outline", "lines", "shadow"), n)
]
CASTING = [tm.Light.directional((0.3, -1.0, -0.6), shadows=True)]


@pytest.fixture(scope="module")
def cube_renderer():
    r = tm.Renderer()
    return r, r.add_mesh(CUBE_V, CUBE_F, normals="flat")


@pytest.mark.parametrize("casting", [False, True], ids=["no shadows", "shadows"])
@pytest.mark.parametrize("outlines", [None, "mesh", "image", "both"])
def test_the_plan_holds_for_every_combination(cube_renderer, outlines, casting):
    r, cube = cube_renderer
    lights = CASTING if casting else None
    checked = 0
    for outputs, (msaa, ss) in itertools.product(OUTPUT_SETS, [(1, 1), (4, 1), (1, 2), (4, 2)]):
        needs_outlines = "outline" in outputs and outlines is None
        needs_lines = "lines" in outputs and outlines not in ("mesh", "both")
        needs_shadows = "shadow" in outputs and not casting
        kw = dict(outputs=outputs, outlines=outlines, msaa=msaa, supersample=ss, width=16, height=12, lights=lights)
        if needs_outlines or needs_lines or needs_shadows:
            with pytest.raises(ValueError, match="outputs"):
                r.render(cube, **kw)
            continue
        res = r.render(cube, **kw)
        assert res.passes == _expected_passes(outlines, outputs, msaa, ss, casting), (outputs, msaa, ss)
        for name in ("color", "normal", "depth", "outline", "shadow"):
            assert (getattr(res, name) is not None) == (name in outputs)
        assert (res.lines is not None) == ("lines" in outputs)
        checked += 1
    assert checked >= 28


@pytest.mark.parametrize("backend", BACKENDS)
def test_the_cube_shows_its_nine_visible_edges_whole_and_hides_the_rest(backend):
    res = tm.render(CUBE_V, CUBE_F, normals="flat", camera=CORNER, width=300, height=300, backend=backend,
                    outlines=tm.Outlines("mesh", silhouette="#ff0000", crease="#0000ff", width=2.0),
                    outputs=("color", "lines", "outline"))
    P = res.projection @ res.view_matrix
    h = np.c_[CUBE_V, np.ones(8)] @ P.T
    px = np.c_[(h[:, 0] / h[:, 3] * 0.5 + 0.5) * 300, (0.5 - h[:, 1] / h[:, 3] * 0.5) * 300]
    edges = {tuple(sorted(e)) for f in CUBE_F for e in ((f[0], f[1]), (f[1], f[2]), (f[2], f[0]))}
    edges = {e for e in edges if np.count_nonzero(CUBE_V[e[0]] != CUBE_V[e[1]]) == 1}  # the 12 cube edges
    view_dir = -np.linalg.inv(res.view_matrix)[:3, 2]
    hidden_corner = int(np.argmin(CUBE_V @ -view_dir))  # the corner farthest from the eye
    visible = [e for e in edges if hidden_corner not in e]
    assert len(visible) == 9
    total = sum(np.linalg.norm(np.diff(line, axis=0), axis=1).sum() for line in res.lines)
    expected = sum(np.linalg.norm(px[a] - px[b]) for a, b in visible)
    # every visible edge whole (not broken by its own faces), nothing of the three hidden ones
    assert abs(total - expected) < 0.02 * expected, (total, expected)
    for a, b in visible:
        t = np.linspace(0, 1, 20)[:, None]
        samples = px[a] * (1 - t) + px[b] * t
        assert _distance_to_lines(samples, res.lines).max() < 1.0
    # kinds: 6 silhouette edges around, 3 creases (ridges) inside, in their colours
    assert set(res.line_kinds) == {"silhouette", "ridge"}
    red = np.all(res.color[..., :3] == (255, 0, 0), axis=-1).sum()
    blue = np.all(res.color[..., :3] == (0, 0, 255), axis=-1).sum()
    assert red > 6 * 60 and blue > 3 * 60
    assert np.isclose(res.outline.max(), 1.0) and res.outline.min() == 0.0


def _distance_to_lines(points: np.ndarray, lines) -> np.ndarray:
    """Distance of each point to the nearest segment of the polylines."""
    a = np.concatenate([p[:-1] for p in lines])
    b = np.concatenate([p[1:] for p in lines])
    ab = b - a
    t = np.clip(np.einsum("pkj,kj->pk", points[:, None, :] - a[None], ab) / np.maximum((ab * ab).sum(-1), 1e-12), 0, 1)
    closest = a[None] + t[..., None] * ab[None]
    return np.linalg.norm(points[:, None, :] - closest, axis=-1).min(axis=1)


def _line_width(outline: np.ndarray) -> float:
    """Ink per unit length of the square's top edge: its width in pixels."""
    columns = outline[: outline.shape[0] // 2].sum(axis=0)
    return float(np.median(columns[columns > 0.5]))


def test_lines_keep_their_width_in_output_pixels_at_any_size_and_supersampling():
    # a square seen face on: its boundary is four axis-aligned lines
    V = np.array([[-1, -1, 0], [1, -1, 0], [1, 1, 0], [-1, 1, 0]], float)
    F = np.array([[0, 1, 2], [0, 2, 3]])
    cam = tm.Camera.orthographic((0, 0, 5), height=3.0)
    widths = []
    for size, ss in [(120, 1), (240, 1), (240, 2), (480, 1)]:
        res = tm.render(V, F, camera=cam, width=size, height=size, supersample=ss,
                        outlines=tm.Outlines("mesh", width=3.0), outputs=("color", "outline"))
        widths.append(_line_width(res.outline))
    assert np.allclose(widths, 3.0, atol=0.15), widths
    same = [tm.render(V, F, camera=cam, width=240, height=240, supersample=ss, outlines="mesh", outputs="outline").outline for ss in (1, 3)]
    assert np.array_equal(same[0], same[1])


@pytest.mark.parametrize("backend", BACKENDS)
def test_image_edges_agree_with_detect_edges_on_the_same_buffers(backend):
    V, F = _core.icosphere(4, 0.04, 5)
    V2 = V * 0.5 + (0.6, 0.1, 1.2)
    scene = [tm.Mesh(V, F), tm.Mesh(V2, F)]
    outlines = tm.Outlines("image", depth_threshold=0.05, image_rule="paper")
    res = tm.render(scene, camera=tm.Camera.look_at((0.3, 0.4, 5.0), fov_y=40), width=257, height=193, backend=backend,
                    outlines=outlines, outputs=("color", "normal", "depth", "outline"))
    cpu = tm.edges.detect_edges(res.normal, res.depth, normal_threshold=outlines.normal_threshold,
                                depth_threshold=outlines.depth_threshold)
    gpu = res.outline > 0.5
    agree = float((gpu == cpu.mask).mean())
    assert cpu.mask.sum() > 500
    assert agree >= 0.999, agree
    # a disagreement only where a gradient lies within float rounding of its threshold
    for y, x in zip(*np.nonzero(gpu != cpu.mask)):
        near = [abs(float(g[y, x]) - t) <= 1e-5 * max(1.0, t)
                for g, t in ((cpu.normal_gradient, outlines.normal_threshold), (cpu.depth_gradient, outlines.depth_threshold))]
        assert any(near), (y, x)


def test_the_same_defaults_as_detect_edges():
    import inspect

    sig = inspect.signature(tm.edges.detect_edges)
    o = tm.Outlines()
    assert o.normal_threshold == sig.parameters["normal_threshold"].default
    assert np.float32(o.depth_threshold) == np.float32(sig.parameters["depth_threshold"].default)
    # the edge functions' None is the core's default, the renderer's too
    assert inspect.signature(tm.edges.feature_edges).parameters["crease_angle"].default is None
    assert o.crease_angle == tm.edges.feature_edges(CUBE_V, CUBE_F).crease_angle


def test_svg_holds_the_visible_lines(tmp_path):
    res = tm.render(CUBE_V, CUBE_F, camera=CORNER, width=200, height=150, outlines="mesh", outputs=("color", "lines"))
    path = tmp_path / "cube.svg"
    res.save_svg(path)
    text = path.read_text()
    assert 'width="200" height="150"' in text
    polylines = re.findall(r'<polyline points="([^"]+)"', text)
    assert len(polylines) == len(res.lines)
    first = np.array([[float(v) for v in p.split(",")] for p in polylines[0].split()])
    assert any(line.shape == first.shape and np.allclose(first, line, atol=0.01) for line in res.lines)
    no_lines = tm.render(CUBE_V, CUBE_F, width=8, height=8, outlines="mesh")
    with pytest.raises(ValueError, match="lines"):
        no_lines.svg()


def test_kinds_can_be_left_out_and_creases_follow_the_angle(cube_renderer):
    r, cube = cube_renderer
    only_sil = r.render(cube, camera=CORNER, outlines=tm.Outlines("mesh", crease=False), outputs=("color", "lines"), width=100, height=100)
    assert set(only_sil.line_kinds) == {"silhouette"}
    flat = r.render(cube, camera=CORNER, outlines=tm.Outlines("mesh", crease_angle=95.0), outputs=("color", "lines"), width=100, height=100)
    assert set(flat.line_kinds) == {"silhouette"}  # the cube's 90 degree creases are below 95
    none = r.render(cube, camera=CORNER, outlines=tm.Outlines("mesh", silhouette=False, crease=False), outputs="outline", width=100, height=100)
    assert none.outline.max() == 0.0


def test_settings_pickle_and_compare_by_value():
    objects = [
        tm.Material.bands("#336699", thresholds=(0.1, 0.6), values=(0.2, 0.5, 1.0)),
        tm.Material.thresholded_phong(t_h=0.2, highlight="paper", per_vertex=True),
        tm.Material.lut(np.linspace(0.1, 1, 7)),
        tm.Material.phong(shininess=12),
        tm.Material.lambert(),
        tm.Light.point((1, 2, 3), color=(0.5, 0.25, 1.0), intensity=0.75, space="camera"),
        tm.Light.key(),
        tm.Camera.look_at((1, 2, 3), (0, 1, 0), up=(0, 0, 1), fov_y=50, near=0.1, far=20),
        tm.Camera.fit((1, 0, 0), orthographic=True),
        tm.Camera.orthographic((0, 0, 5), height=3),
        tm.Outlines("both", silhouette=tm.LineStyle("#ff0000", 3), crease=False, image="#00ff00", crease_angle=40, weld=False,
                    max_crease_turn=45),
        tm.LineStyle((0.1, 0.2, 0.3), 2.5),
    ]
    for obj in objects:
        back = pickle.loads(pickle.dumps(obj))
        assert back == obj and type(back) is type(obj) and hash(back) == hash(obj), obj
        assert repr(back) == repr(obj)
    assert tm.Material.bands() != tm.Material.bands("#000000")
    with pytest.raises(AttributeError):
        objects[0].model = "lut"  # frozen


def test_edge_index_gives_the_renderers_outline_set():
    idx = tm.edges.EdgeIndex(CUBE_V, CUBE_F)
    edges, kinds = idx.outlines(eye=(3.0, 2.5, 2.0), kinds=True)
    assert np.array_equal(edges, idx.outlines(eye=(3.0, 2.5, 2.0)))
    # the 12 cube edges: a hexagon of 6 silhouettes around, the other 6 are convex creases
    assert len(edges) == 12 and sorted(map(tuple, edges)) == list(map(tuple, edges))
    assert (kinds == "silhouette").sum() == 6 and (kinds == "ridge").sum() == 6
    sil = idx.silhouette(eye=(3.0, 2.5, 2.0))
    assert {tuple(e) for e in edges[kinds == "silhouette"]} == {tuple(e) for e in sil}



@pytest.mark.parametrize("backend", BACKENDS)
@pytest.mark.parametrize("scale", [0.01, 1.0, 658.0])
def test_image_lines_honour_width_and_scale(backend, scale):
    """The default image rule: ink across a silhouette is `width` pixels (within 0.5 + 0.25
    width), centred within 1.5 px of it, at any model scale; and a large model is not inked
    solid (the paper rule's depth threshold is in world units)."""
    V, F = _core.icosphere(4, 0.0, 0)
    for width in (1.0, 2.0, 4.0):
        res = tm.render(V * scale, F, width=300, height=300, backend=backend, outputs=("outline", "depth"),
                        camera=tm.Camera.look_at((0.0, 0.0, 5.0 * scale), (0, 0, 0), fov_y=40),
                        outlines=tm.Outlines("image", width=width))
        for row in (120, 150, 180):
            surface = np.flatnonzero(np.isfinite(res.depth[row]))
            for rim, side in ((surface[0], -1), (surface[-1] + 1, 1)):  # the boundary's x
                xs = np.arange(rim - 12, rim + 12)
                ink = res.outline[row, xs]
                total = float(ink.sum())
                centre = float((xs + 0.5) @ ink / total)
                assert abs(total - width) <= 0.5 + 0.25 * width, (width, row, total)
                assert abs(centre - rim) <= 1.5, (width, row, centre, rim)
        inside = np.isfinite(res.depth)
        assert (res.outline[inside] > 0.5).mean() < 0.1
    if scale == 658.0:
        paper = tm.render(V * scale, F, width=300, height=300, backend=backend, outputs=("outline", "depth"),
                          outlines=tm.Outlines("image", image_rule="paper"))
        assert (paper.outline[np.isfinite(paper.depth)] > 0.5).mean() > 0.9  # why the default changed


def test_the_paper_image_rule_runs_sobel_alone():
    V, F = _core.icosphere(2, 0.0, 0)
    for rule, passes in (("discontinuity", ["edge_bits", "edges"]), ("paper", ["edges"])):
        res = tm.render(V, F, width=32, height=32, outlines=tm.Outlines("both", image_rule=rule))
        assert res.passes == ["silhouettes", "shade", *passes, "lines", "readback_color"]

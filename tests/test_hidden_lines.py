"""Exact visibility of mesh-space lines, hidden lines drawn on request and intersection lines:
lines under a thin sheet stay hidden (the depth rule lets them through), a cube's three hidden
edges come back dashed in the picture, in ``lines`` and in the SVG, ``max_occlusion`` chooses how
deep, crossing pipes get their intersection curves, and the command line has the flags. (The
scenes are the ``lines`` benchmark's.)"""

from __future__ import annotations

import re
import subprocess
import sys

import numpy as np
import pytest

import toonmesh as tm
from toonmesh.bench.lines import pipe, sheet_over_beams, slab

BACKENDS = ["vulkan", "gl"]
# Seen from a corner: the cube's corner (-1, -1, -1) and its three edges are behind it.
CORNER = tm.Camera.orthographic((3.0, 2.5, 2.0), height=4.0)
HIDDEN_CORNER = np.array([-1.0, -1.0, -1.0])


def to_pixels(res, points):
    """World points to the pixel coordinates of ``res`` (x right, y down)."""
    p = np.c_[points, np.ones(len(points))] @ (res.projection @ res.view_matrix).T
    ndc = p[:, :2] / p[:, 3:]
    return np.c_[(ndc[:, 0] * 0.5 + 0.5) * res.width, (0.5 - ndc[:, 1] * 0.5) * res.height]


def length(polylines):
    return float(sum(np.linalg.norm(np.diff(p, axis=0), axis=1).sum() for p in polylines))


@pytest.mark.parametrize("backend", BACKENDS)
def test_beams_under_a_thin_sheet_stay_hidden(backend):
    sheet, *beams = [tm.Mesh(*m, normals="flat") for m in sheet_over_beams((0.001, 0.005))]
    r = tm.Renderer(backend)
    cam = tm.Camera.look_at((0.3, 3.0, 0.6), (0, 0, 0), fov_y=45)
    kw = dict(camera=cam, width=400, height=300, outputs=("color", "outline", "lines"))
    for visibility, most in (("exact", 20), ("depth", None)):
        o = tm.Outlines("mesh", visibility=visibility)
        alone = r.render([sheet], outlines=o, **kw)
        under = r.render([sheet] + beams, outlines=o, **kw)
        differ = int(((alone.outline > 0.1) != (under.outline > 0.1)).sum())
        if most is None:
            # the depth rule's tolerance lets the beams' edges through: the case exactness fixes
            assert differ > 500, differ
        else:
            assert differ <= most, differ
            assert length(under.lines) == pytest.approx(length(alone.lines), abs=2.0)


@pytest.mark.parametrize("backend", BACKENDS)
def test_a_cube_s_hidden_edges_come_back_dashed(backend):
    V, F = slab((-1, -1, -1), (1, 1, 1))
    o = tm.Outlines("mesh", hidden=True)
    assert o.hidden.dash > 0 and o.hidden.width < o.silhouette.width and o.hidden.color != o.silhouette.color
    res = tm.render(V, F, normals="flat", camera=CORNER, width=300, height=300, outlines=o,
                    outputs=("color", "outline", "lines"), backend=backend)
    hidden = [p for p, k in zip(res.lines, res.line_kinds) if k == "hidden"]
    ends = [HIDDEN_CORNER + 2 * np.eye(3)[i] for i in range(3)]
    want = sum(np.linalg.norm(np.diff(to_pixels(res, np.array([HIDDEN_CORNER, e])), axis=0)) for e in ends)
    assert length(hidden) == pytest.approx(want, rel=0.10)
    # every hidden point lies on one of the three edges
    segs = [to_pixels(res, np.array([HIDDEN_CORNER, e])) for e in ends]
    for p in np.concatenate(hidden):
        d = min(abs((b - a)[0] * (p - a)[1] - (b - a)[1] * (p - a)[0]) / np.linalg.norm(b - a) for a, b in segs)
        assert d < 0.5, p
    # the visible lines are those without hidden lines
    plain = tm.render(V, F, normals="flat", camera=CORNER, width=300, height=300, outlines=tm.Outlines("mesh"),
                      outputs=("lines",), backend=backend)
    visible = [p for p, k in zip(res.lines, res.line_kinds) if k != "hidden"]
    assert length(visible) == pytest.approx(length(plain.lines), rel=1e-6)
    # in the picture: dashes along a hidden edge, ink and paper in turn, in the hidden grey
    a, b = to_pixels(res, np.array([HIDDEN_CORNER, ends[0]]))
    ts = np.linspace(0.15, 0.85, 200)
    along = [res.outline[int(y), int(x)] for x, y in a + np.outer(ts, b - a)]
    inked = np.array(along) > 0.5
    assert 0.25 < inked.mean() < 0.75, inked.mean()
    assert np.count_nonzero(np.diff(inked.astype(int))) >= 6
    grey = res.color[int(a[1] + (b[1] - a[1]) * ts[np.argmax(inked)]), int(a[0] + (b[0] - a[0]) * ts[np.argmax(inked)])]
    assert grey[0] > 40, grey  # grey, not the black of the visible lines
    # the SVG: a dashed group of its own, under the visible ones
    svg = res.svg(order="plotter")
    groups = re.findall(r'<g id="(\w+)"[^>]*>', svg)
    assert groups[0] == "hidden", groups
    assert re.search(r'<g id="hidden"[^>]*stroke-dasharray="[\d.]+ [\d.]+"', svg)


def test_max_occlusion_chooses_how_deep_hidden_lines_go():
    # two boxes one behind the other: the back box's far edges sit behind four faces
    front, back = slab((-1, -1, 1), (1, 1, 2)), slab((-1.2, -1.2, -3), (1.2, 1.2, -2))
    cam = tm.Camera.look_at((0.2, 0.3, 8.0), (0, 0, 0), fov_y=40)
    meshes = [tm.Mesh(*front, normals="flat"), tm.Mesh(*back, normals="flat")]
    depth = {}
    for most in (None, 1, 2, 3):
        o = tm.Outlines("mesh", hidden=True, max_occlusion=most)
        res = tm.render(meshes, camera=cam, width=240, height=240, outlines=o, outputs=("lines",))
        depth[most] = length([p for p, k in zip(res.lines, res.line_kinds) if k == "hidden"])
    assert depth[1] > 0
    assert depth[1] < depth[2] < depth[3] <= depth[None] + 1e-6, depth
    with pytest.raises(ValueError, match="max_occlusion"):
        tm.Outlines(max_occlusion=0)
    with pytest.raises(ValueError, match="hidden.*depth"):
        tm.Outlines(hidden=True, visibility="depth")


def test_the_command_line_draws_hidden_lines(tmp_path):
    V, F = slab((-1, -1, -1), (1, 1, 1))
    path = tmp_path / "cube.obj"
    path.write_text("".join(f"v {x} {y} {z}\n" for x, y, z in V) + "".join(f"f {a + 1} {b + 1} {c + 1}\n" for a, b, c in F))
    out = tmp_path / "cube.svg"
    run = subprocess.run([sys.executable, "-m", "toonmesh", "edges", str(path), "-o", str(out), "--hidden",
                          "--eye", "3", "2.5", "2"], capture_output=True, text=True)
    assert run.returncode == 0, run.stderr
    assert "of the line length is hidden" in run.stdout
    svg = out.read_text()
    assert '<g id="hidden"' in svg and "stroke-dasharray" in svg
    run = subprocess.run([sys.executable, "-m", "toonmesh", "edges", str(path), "-o", str(out), "--max-occlusion", "0"],
                         capture_output=True, text=True)
    assert run.returncode != 0 and "--max-occlusion" in run.stderr


def test_crossing_pipes_get_intersection_lines_in_the_picture_and_the_svg():
    pipes = [tm.Mesh(*pipe(0), normals="auto"), tm.Mesh(*pipe(1), normals="auto")]
    cam = tm.Camera.look_at((4.0, 3.0, 6.0), (0, 0, 0), fov_y=40)
    kw = dict(camera=cam, width=320, height=240, outputs=("color", "lines"))
    res = tm.render(pipes, outlines="mesh", **kw)
    assert "intersections" in res.passes
    crossing = [p for p, k in zip(res.lines, res.line_kinds) if k == "intersection"]
    assert crossing and len(crossing) <= 4, len(crossing)  # chained into a few strokes
    # the visible curves lie where both pipes' silhouettes of their crossing say: on the segment
    # of the picture between the pipes' meeting points, and long
    assert length(crossing) > 150, length(crossing)
    assert '<g id="intersection"' in res.svg()
    # asked away, or a single mesh: no step, no line
    off = tm.render(pipes, outlines=tm.Outlines("mesh", intersection=False), **kw)
    assert "intersections" not in off.passes and "intersection" not in off.line_kinds
    assert "intersections" not in tm.render(*pipe(0), outlines="mesh", **kw).passes
    # the ink differs from the render without them only along the curves
    assert int(np.any(res.color != off.color, axis=-1).sum()) > 150
    # one renderer, the pipes kept: the lines follow a pipe that moves (kept lines are keyed by
    # the pipes' placement) and stay while only the camera does
    r = tm.Renderer()
    a, b = r.add_mesh(*pipe(0)), r.add_mesh(*pipe(1))
    shifted = np.eye(4)
    shifted[2, 3] = 0.5
    views = {}
    for name, transform, camera in (("first", None, cam), ("again", None, cam), ("moved", shifted, cam),
                                    ("back", None, cam)):
        out = r.render([tm.Mesh(a), tm.Mesh(b, transform=transform)], outlines="mesh",
                       **dict(kw, camera=camera))
        views[name] = [p for p, k in zip(out.lines, out.line_kinds) if k == "intersection"]
    assert length(views["first"]) == pytest.approx(length(views["again"]), abs=1e-9)
    assert length(views["back"]) == pytest.approx(length(views["first"]), abs=1e-9)
    assert abs(length(views["moved"]) - length(views["first"])) > 5.0


@pytest.mark.parametrize("scale, offset", [(1e-3, 0.0), (1e4, 0.0), (1.0, 1e6)])
def test_exactness_holds_at_any_scale_and_far_from_the_origin(scale, offset):
    # the sheet and the beams (1 mm and 5 mm under it at scale 1) shrunk, grown or moved far
    # away: nothing shows through, the sheet's own lines stay whole, the cube's hidden edges
    # keep their length
    moved = np.diag([scale, scale, scale, 1.0])
    moved[:3, 3] = offset
    sheet, *beams = [tm.Mesh(*m, normals="flat", transform=moved) for m in sheet_over_beams((0.001, 0.005))]
    eye = np.array([0.3, 3.0, 0.6]) * scale + offset
    cam = tm.Camera.look_at(eye, (offset, offset, offset), fov_y=45)
    kw = dict(camera=cam, width=400, height=300, outputs=("outline", "lines"), outlines=tm.Outlines("mesh", hidden=True))
    alone, under = tm.render([sheet], **kw), tm.render([sheet] + beams, **kw)
    seen = lambda res: [p for p, k in zip(res.lines, res.line_kinds) if k != "hidden"]  # noqa: E731
    assert np.isfinite(np.concatenate(under.lines)).all()
    assert length(seen(under)) == pytest.approx(length(seen(alone)), abs=2.0)
    assert length(seen(alone)) > 500
    # the same drawing as at scale 1 at the origin
    plain = [tm.Mesh(*sheet_over_beams((0.001, 0.005))[0], normals="flat")]
    at_one = tm.render(plain, **dict(kw, camera=tm.Camera.look_at((0.3, 3.0, 0.6), (0, 0, 0), fov_y=45)))
    assert length(seen(alone)) == pytest.approx(length(seen(at_one)), abs=1.0)
    # the beams are there, behind the sheet: as hidden lines
    hidden = [p for p, k in zip(under.lines, under.line_kinds) if k == "hidden"]
    assert length(hidden) > length([p for p, k in zip(alone.lines, alone.line_kinds) if k == "hidden"]) + 500

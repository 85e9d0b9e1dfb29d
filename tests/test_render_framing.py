"""The first view: each file format's up axis (glTF and OBJ y, STL, PLY and 3MF z), ``up=`` and
``--up`` to override it, and ``Camera.fit``: a three-quarter view about the up axis, across the
scene's longest horizontal extent, as near as the meshes allow, so that the model fills the
frame."""

from __future__ import annotations

import math
from typing import Tuple

import numpy as np
import pytest

import toonmesh as tm
from conftest import load_mesh, need
from toonmesh.data import bunny

WIDE, TALL = (400, 300), (300, 400)


def z_up(V: np.ndarray) -> np.ndarray:
    """A y-up mesh as a z-up file holds it (Blender's conversion: y up becomes z up, the front
    +z becomes -y)."""
    return np.c_[V[:, 0], -V[:, 2], V[:, 1]]


def bottle(segments: int = 32) -> Tuple[np.ndarray, np.ndarray]:
    """A bottle 2.8 tall and 0.6 wide, standing on y."""
    profile = [(0.0, 0.0), (0.3, 0.0), (0.3, 2.0), (0.12, 2.4), (0.12, 2.8), (0.0, 2.8)]
    return tm.shapes.lathe(profile, segments=segments)


def fill(r: tm.RenderResult) -> Tuple[float, float, Tuple[int, int], Tuple[int, int]]:
    """The share of the frame's height and width the model covers, and the room (pixels) left
    above and below it, and left and right of it."""
    covered = np.isfinite(r.depth)
    rows, cols = np.flatnonzero(covered.any(axis=1)), np.flatnonzero(covered.any(axis=0))
    H, W = covered.shape
    return ((rows[-1] - rows[0] + 1) / H, (cols[-1] - cols[0] + 1) / W, (int(rows[0]), int(H - 1 - rows[-1])),
            (int(cols[0]), int(W - 1 - cols[-1])))


def pixel_of(r: tm.RenderResult, point) -> np.ndarray:
    """Where a world point lands in the image (x right, y down)."""
    clip = r.projection @ r.view_matrix @ np.append(point, 1.0)
    ndc = clip[:2] / clip[3]
    return np.array([(ndc[0] + 1) / 2 * r.width, (1 - ndc[1]) / 2 * r.height])


def test_a_z_up_stl_renders_upright_by_default(tmp_path):
    """A teapot written z up, as 3D-printing tools and Blender take an STL: drawn upright, the
    same view as the y-up OBJ of it (each file's front is its convention's)."""
    trimesh = need("trimesh")
    V, F = load_mesh("teapot")
    trimesh.Trimesh(z_up(V), F, process=False).export(tmp_path / "teapot.stl")
    trimesh.Trimesh(V, F, process=False).export(tmp_path / "teapot.obj")
    stl = tm.render(tmp_path / "teapot.stl", width=320, height=240, outputs=("color", "depth"))
    obj = tm.render(tmp_path / "teapot.obj", width=320, height=240, outputs=("color", "depth"))
    assert (stl.up, obj.up) == ("z", "y")
    lid, base = pixel_of(stl, [0.0, 0.0, V[:, 1].max()]), pixel_of(stl, [0.0, 0.0, 0.0])
    assert lid[1] < base[1] - 0.5 * 240 * 0.5, "the lid above the base"
    assert abs(lid[0] - base[0]) < 0.1 * 320, "upright: straight above it"
    same = np.isfinite(stl.depth) == np.isfinite(obj.depth)
    assert same.mean() > 0.995, "the same view of the same teapot"


def test_each_format_has_its_up_axis_and_up_overrides_it(tmp_path):
    trimesh = need("trimesh")
    V, F = tm.shapes.icosphere(1)
    expected = {"stl": "z", "ply": "z", "obj": "y", "glb": "y", "off": "y"}
    for suffix, up in expected.items():
        path = tmp_path / f"ball.{suffix}"
        trimesh.Trimesh(V, F, process=False).export(path)
        convention = tm.load(path)[0].up
        assert convention == (None if suffix == "off" else up), suffix  # OFF has no convention
        assert tm.render(path, width=16, height=16).up == up, suffix
        assert tm.render(path, width=16, height=16, up="x").up == "x", suffix
        assert [m.up for m in tm.load(path, up="x")] == ["x"]
    # arrays name no axis: y, the default, unless up= says
    assert tm.render(V, F, width=16, height=16).up == "y"
    assert tm.render(V, F, width=16, height=16, up="z").up == "z"
    with pytest.raises(ValueError, match="^up: "):
        tm.load(tmp_path / "ball.stl", up="w")
    with pytest.raises(ValueError, match="^up: "):
        tm.Mesh(V, F, up="up")
    with pytest.raises(ValueError, match="^up: "):
        tm.render(V, F, up="-z")


def test_meshes_of_different_up_axes_need_up(tmp_path):
    V, F = tm.shapes.icosphere(1)
    scene = [tm.Mesh(V, F, up="y"), tm.Mesh(V + 3, F), tm.Mesh(V - 3, F, up="z")]
    with pytest.raises(ValueError, match=r"^up: meshes\[0\] has up axis y and meshes\[2\] has z: give up="):
        tm.render(scene, width=16, height=16)
    assert tm.render(scene, width=16, height=16, up="z").up == "z"
    assert tm.render(scene[:2], width=16, height=16).up == "y"


def scenes():
    """A representative set of the render tests' models, as the default camera sees them."""
    V, F = load_mesh("teapot")
    yield "teapot, z up", tm.Mesh(z_up(V), F, up="z")
    yield "bottle", tm.Mesh(*bottle())
    yield "bottle, z up", tm.Mesh(z_up(bottle()[0]), bottle()[1], up="z")
    yield "bunny", tm.Mesh(*bunny())
    yield "sphere", tm.Mesh(*tm.shapes.icosphere(3))
    yield "torus", tm.Mesh(*tm.shapes.torus())
    yield "pawn", tm.Mesh(*tm.shapes.pawn())
    yield "fandisk", tm.Mesh(*load_mesh("fandisk"))
    yield "flat grid", tm.Mesh(*tm.shapes.grid(8))
    long_box = np.array([[i & 1, (i >> 1) & 1, (i >> 2) & 1] for i in range(8)], float) * [0.5, 0.5, 8.0]
    hull = [[0, 2, 3], [0, 3, 1], [4, 5, 7], [4, 7, 6], [0, 1, 5], [0, 5, 4], [2, 6, 7], [2, 7, 3], [0, 4, 6],
            [0, 6, 2], [1, 3, 7], [1, 7, 5]]
    yield "a rod along z", tm.Mesh(long_box, np.array(hull))
    B, G = bunny()
    yield "two bunnies", [tm.Mesh(B, G), tm.Mesh(B, G, transform=np.diag([1.0, 1.0, 1.0, 1.0]) + np.eye(4, k=3) * 0.3)]


@pytest.mark.parametrize("size", [WIDE, TALL], ids=["wide", "tall"])
def test_every_model_fills_the_frame(size):
    """The issue's target is half the frame's height or width; the fit touches the frame's edges
    at 1 / margin (95%) across the axis that limits it (2.5% of room each side), and sits
    midway across the other."""
    w, h = size
    for name, scene in scenes():
        r = tm.render(scene, width=w, height=h, outputs=("depth",))
        height, width, vertical, horizontal = fill(r)
        assert max(height, width) >= 0.9, (name, height, width)
        assert min(height, width) >= 0.1, (name, height, width)
        for share, room, size_px in ((height, vertical, h), (width, horizontal, w)):
            if share >= 0.9:
                assert max(room) <= 0.05 * size_px + 2, (name, room)


def test_a_bottle_stands_and_fills_the_height():
    V, F = bottle()
    for up, verts in (("y", V), ("z", z_up(V))):
        r = tm.render(tm.Mesh(verts, F, up=up), width=400, height=300, outputs=("depth",))
        height, width, _, _ = fill(r)
        assert height >= 0.9 and width < 0.5, (up, height, width)
        top = [0.0, 2.8, 0.0] if up == "y" else [0.0, 0.0, 2.8]
        assert pixel_of(r, top)[1] < pixel_of(r, [0.0, 0.0, 0.0])[1] - 200


def test_the_view_looks_across_the_longest_horizontal_extent():
    """A rod along z (y up) is seen from its side: its length runs across the image."""
    V = np.array([[i & 1, (i >> 1) & 1, (i >> 2) & 1] for i in range(8)], float) * [0.5, 0.5, 8.0]
    F = np.array([[0, 2, 3], [0, 3, 1], [4, 5, 7], [4, 7, 6], [0, 1, 5], [0, 5, 4], [2, 6, 7], [2, 7, 3],
                  [0, 4, 6], [0, 6, 2], [1, 3, 7], [1, 7, 5]])
    r = tm.render(V, F, width=400, height=300, outputs=("depth",))
    a, b = pixel_of(r, [0.25, 0.25, 0.0]), pixel_of(r, [0.25, 0.25, 8.0])
    along = b - a
    assert abs(along[0]) > 3 * abs(along[1]) and abs(along[0]) > 0.75 * 400
    # rotated a quarter about y, the same rod along x is seen from the front, the same way
    turned = tm.render(V[:, [2, 1, 0]], F[:, ::-1], width=400, height=300, outputs=("depth",))
    assert abs(fill(turned)[1] - fill(r)[1]) < 0.02


def test_the_three_quarter_view_and_its_turns():
    """Camera.fit() looks from 30 degrees round from the front toward the side and 25 above;
    turn= turns it about the up axis, as a turntable does."""
    V, F = tm.shapes.icosphere(2)
    r = tm.render(V, F, width=64, height=64)
    d = r.view_matrix[2, :3]  # toward the eye
    assert math.degrees(math.asin(d[1])) == pytest.approx(25.0, abs=1e-6)
    assert math.degrees(math.atan2(d[0], d[2])) == pytest.approx(30.0, abs=1e-6)
    quarter = tm.render(V, F, width=64, height=64, camera=tm.Camera.fit(turn=90))
    d = quarter.view_matrix[2, :3]
    assert math.degrees(math.atan2(d[0], d[2])) == pytest.approx(120.0, abs=1e-6)
    whole = tm.render(V, F, width=64, height=64, camera=tm.Camera.fit(turn=360))
    assert np.allclose(whole.view_matrix, r.view_matrix, atol=1e-9)
    assert repr(tm.Camera.fit()) == "Camera.fit()"
    assert tm.Camera.fit(turn=45).turn == 45.0 and tm.Camera.fit().direction is None
    with pytest.raises(ValueError, match="^turn: "):
        tm.Camera.fit(turn=math.nan)
    # straight down the up axis, the image's up is the back: the front at the bottom
    top = tm.render(V, F, width=64, height=64, camera=tm.Camera.fit((0.0, 1.0, 0.0)))
    assert np.allclose(top.view_matrix[1, :3], [0.0, 0.0, -1.0], atol=1e-9)


def test_the_command_line_says_which_up_axis_it_used(tmp_path, capsys, monkeypatch):
    trimesh = need("trimesh")
    from toonmesh.cli import main

    monkeypatch.chdir(tmp_path)
    V, F = load_mesh("teapot")
    trimesh.Trimesh(z_up(V), F, process=False).export(tmp_path / "teapot.stl")
    trimesh.Trimesh(V, F, process=False).export(tmp_path / "teapot.off")
    assert main(["render", "teapot.stl", "-o", "a.npz", "--size", "64x48", "--outputs", "depth"]) == 0
    out = capsys.readouterr().out
    assert "teapot.stl: up z (the .stl convention; --up to change)" in out
    with np.load(tmp_path / "a.npz") as z:
        expected = tm.render(tmp_path / "teapot.stl", width=64, height=48, outputs=("depth",))
        assert np.array_equal(z["depth"], expected.depth)
    assert main(["render", "teapot.stl", "-o", "b.png", "--size", "64x48", "--up", "y"]) == 0
    assert "teapot.stl: up y (--up)" in capsys.readouterr().out
    assert main(["render", "teapot.off", "-o", "c.png", "--size", "64x48"]) == 0
    assert "teapot.off: up y (the default; .off has no convention; --up to change)" in capsys.readouterr().out
    assert main(["edges", "teapot.stl", "-o", "lines.svg", "--size", "64x48"]) == 0
    assert "teapot.stl: up z (the .stl convention" in capsys.readouterr().out
    assert main(["render", "teapot.stl", "-o", "d.png", "--up", "w"]) == 2
    err = capsys.readouterr().err
    assert "--up" in err and len(err.splitlines()) == 1


def test_an_empty_scene_is_framed_by_the_unit_sphere():
    for camera in (tm.Camera.fit(), tm.Camera.fit(orthographic=True), tm.Camera.fit((1.0, 0.0, 0.0), turn=30)):
        r = tm.render(None, camera=camera, width=8, height=8, outputs=("color", "depth"))
        assert np.isfinite(r.view_matrix).all() and np.isinf(r.depth).all()


def plate(normal, width: float = 4.0, height: float = 3.0, thickness: float = 0.05, center=(0.0, 0.0, 0.0)):
    """A closed rectangular plate (a thin box) whose faces look along ``normal``."""
    n = np.asarray(normal, float) / np.linalg.norm(normal)
    a = np.cross(n, [0.0, 0.0, 1.0] if abs(n[2]) < 0.9 else [1.0, 0.0, 0.0])
    a /= np.linalg.norm(a)
    b = np.cross(n, a)
    corners = np.array([[x, y, z] for z in (-0.5, 0.5) for y in (-0.5, 0.5) for x in (-0.5, 0.5)])
    V = np.asarray(center) + corners[:, :1] * width * a + corners[:, 1:2] * height * b + corners[:, 2:] * thickness * n
    F = np.array([[0, 2, 1], [1, 2, 3], [4, 5, 6], [5, 7, 6], [0, 1, 4], [1, 5, 4],
                  [2, 6, 3], [3, 6, 7], [0, 4, 2], [2, 4, 6], [1, 3, 5], [3, 7, 5]])
    return V, F


def _off_normal(r: tm.RenderResult, normal) -> float:
    """Degrees between the view's direction and the plate's normal (either side)."""
    back = np.linalg.inv(r.view_matrix)[:3, 2]  # the view's +z: from the scene toward the eye
    return math.degrees(math.acos(min(1.0, abs(float(back @ normal)) / np.linalg.norm(normal))))


@pytest.mark.parametrize("normal", [(1, 0, 0), (0, 1, 0), (0, 0, 1), (1, 0.2, -0.7), (0.3, 1, 0.2), (-1, 0.05, 0.4)],
                         ids=["facing-x", "lying", "facing-front", "tilted", "tilted-lying", "standing-askew"])
@pytest.mark.parametrize("scale", [0.01, 1.0, 1e4])
def test_a_flat_part_is_seen_from_its_front(normal, scale):
    """A plate or a sheet is never seen within 30 degrees of edge-on by default, at any size or
    tilt: it is seen as the three-quarter view sees the front (about 38 degrees off its normal),
    covering a good share of the frame. The usual view of a plate facing the front is kept."""
    V, F = plate(normal)
    r = tm.render(V * scale, F, width=400, height=300, outputs=("color", "depth"))
    off = _off_normal(r, np.asarray(normal, float))
    covered = float(np.isfinite(r.depth).mean())
    assert off <= 60.0 + 1e-6, off
    assert covered >= 0.15, covered
    if normal == (0, 0, 1):  # facing the front: the three-quarter view as for any model
        assert abs(off - math.degrees(math.acos(math.cos(math.radians(30)) * math.cos(math.radians(25))))) < 0.5, off


def test_a_thick_part_keeps_the_three_quarter_view():
    """A slab a fifth as thick as it is wide is no plate: lying down, it is seen from the usual
    view, 25 degrees above the horizon (65 off its normal); as a plate, from 38 off it."""
    up = np.array([0.0, 1.0, 0.0])
    slab = tm.render(*plate(up, thickness=0.6), width=400, height=300, outputs=("depth",))
    sheet = tm.render(*plate(up, thickness=0.05), width=400, height=300, outputs=("depth",))
    assert abs(_off_normal(slab, up) - 65.0) < 0.5, _off_normal(slab, up)
    assert abs(_off_normal(sheet, up) - 38.3) < 0.5, _off_normal(sheet, up)

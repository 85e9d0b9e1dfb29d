"""The command line on real files: what `smooth` keeps, what `render` draws by default, what a
broken file gives, and the README's command examples run as written."""

from __future__ import annotations

import argparse
import re
import shlex
from pathlib import Path

import numpy as np
import pytest

import toonmesh as tm
from conftest import MESHES, need
from test_cli import in_process, one_line_error, read_png

README = Path(__file__).resolve().parent.parent / "README.md"


def test_smooth_keeps_texture_coordinates_and_closes_no_seam(tmp_path, capsys):
    trimesh = need("trimesh")
    src = str(MESHES / "spot.obj")  # UV seams: positions listed once, corners split by their UVs
    out = str(tmp_path / "spot-smooth.obj")
    in_process(capsys, "smooth", src, out, "--iterations", "5")
    before = trimesh.load(src, process=False, maintain_order=False)
    after = trimesh.load(out, process=False, maintain_order=False)
    assert np.array_equal(before.faces, after.faces)
    np.testing.assert_allclose(after.visual.uv, before.visual.uv, atol=1e-7)
    moved = np.linalg.norm(after.vertices - before.vertices, axis=1)
    assert moved.max() > 1e-3  # it was smoothed
    # copies of one position (split at a seam) moved together: welded, no crack
    _, group = np.unique(before.vertices, axis=0, return_inverse=True)
    group = group.ravel()
    spread = max(np.ptp(after.vertices[group == g], axis=0).max() for g in np.unique(group[np.bincount(group)[group] > 1]))
    assert spread < 1e-7


def test_smooth_keeps_vertex_and_face_colours(tmp_path, capsys):
    trimesh = need("trimesh")
    V, F = tm.shapes.icosphere(2, noise=0.05, seed=2)
    rng = np.random.default_rng(0)
    for kind in ("vertex", "face"):
        m = trimesh.Trimesh(V, F, process=False)
        colours = rng.integers(0, 256, ((len(V) if kind == "vertex" else len(F)), 4), dtype=np.uint8)
        colours[:, 3] = 255
        if kind == "vertex":
            m.visual.vertex_colors = colours
        else:
            m.visual.face_colors = colours
        src, out = str(tmp_path / f"{kind}.ply"), str(tmp_path / f"{kind}-out.ply")
        m.export(src)
        in_process(capsys, "smooth", src, out)
        back = trimesh.load(out, process=False)
        got = back.visual.vertex_colors if kind == "vertex" else back.visual.face_colors
        assert np.array_equal(got, colours), kind
        assert not np.allclose(back.vertices, V, atol=1e-6)


def test_smooth_keeps_hard_edges_where_the_file_had_them(tmp_path, capsys):
    trimesh = need("trimesh")
    cube = trimesh.creation.box()
    cube.unmerge_vertices()  # a flat-shaded cube: each side's corners have their side's normal
    src, out = str(tmp_path / "cube.obj"), str(tmp_path / "cube-smooth.obj")
    src_text = trimesh.exchange.obj.export_obj(cube, include_normals=True, include_texture=False)
    Path(src).write_text(src_text)
    in_process(capsys, "smooth", src, out, "--iterations", "2", "--boundary", "free")
    back = trimesh.load(out, process=False, maintain_order=False)
    assert np.array_equal(back.faces, cube.faces)
    n, file_normals = np.asarray(back.vertex_normals), np.asarray(cube.vertex_normals)
    _, position = np.unique(np.round(back.vertices, 9), axis=0, return_inverse=True)
    position = position.ravel()
    assert position.max() + 1 == 8  # welded: the corners moved together
    for p in range(8):
        here = np.flatnonzero(position == p)
        sides = np.unique(np.round(file_normals[here], 6), axis=0)
        assert len(sides) == 3  # three sides meet at a corner of the cube
        per_side = [n[here[np.all(np.round(file_normals[here], 6) == side, axis=1)]] for side in sides]
        for copies in per_side:  # copies on one side shade as one
            assert np.allclose(copies, copies[0], atol=1e-9)
        firsts = np.array([c[0] for c in per_side])
        assert (firsts @ firsts.T)[~np.eye(3, dtype=bool)].max() < np.cos(np.radians(45))  # hard edges stay


def test_a_truncated_or_broken_file_exits_1_naming_it(tmp_path, capsys):
    cut = tmp_path / "cut.obj"
    cut.write_text("v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nf 1 2 3\nf 1 2 4\nf 1 3")
    for command in (["render", str(cut), "-o", str(tmp_path / "x.png")], ["smooth", str(cut), str(tmp_path / "y.obj")],
                    ["edges", str(cut), "-o", str(tmp_path / "z.svg")]):
        r = in_process(capsys, *command, check=False)
        assert r.returncode == 1
        one_line_error(r, "cut.obj", "line 7")
    r = in_process(capsys, "render", "bunnny", "-o", str(tmp_path / "x.png"), check=False)
    one_line_error(r, "bunnny: no such file", "bunny")


def test_render_draws_a_glb_scene_with_its_instances(tmp_path, capsys):
    from test_load import instanced_scene

    path = str(tmp_path / "row.glb")
    instanced_scene(4, spacing=2.0).export(path)  # apart as the three-quarter view sees them
    r = in_process(capsys, "render", path, "-o", str(tmp_path / "row.png"), "--size", "96x48")
    assert "48 faces" in r.stdout  # 4 instances of a 12-face box, drawn
    img = read_png(tmp_path / "row.png")
    covered = (img[..., :3] < 250).any(axis=2).any(axis=0)
    runs = np.count_nonzero(covered[1:] & ~covered[:-1]) + int(covered[0])
    assert runs == 4  # four boxes side by side


def test_render_takes_the_effects_flags(tmp_path, capsys):
    base = ["render", "bunny", "--size", "64x48", "--outlines", "none"]
    in_process(capsys, *base, "-o", str(tmp_path / "plain.png"))
    images = {}
    for name, flags in {"shadows": ["--shadows"], "hatching": ["--style", "hatching"],
                        "dither": ["--dither", "bayer4"], "both": ["--outlines", "both"]}.items():
        in_process(capsys, *base, *flags, "-o", str(tmp_path / f"{name}.png"))
        images[name] = read_png(tmp_path / f"{name}.png")
    plain = read_png(tmp_path / "plain.png")
    for name, img in images.items():
        assert not np.array_equal(img, plain), name
    r = in_process(capsys, *base, "--hatch-spacing", "9", "-o", str(tmp_path / "x.png"), check=False)
    assert r.returncode == 2 and "--style hatching" in r.stderr


def _options(parser: argparse.ArgumentParser):
    for action in parser._actions:
        if isinstance(action, argparse._SubParsersAction):
            for name, sub in action.choices.items():
                yield from ((name, a) for a in sub._actions)


def test_help_states_every_default():
    from toonmesh.cli import build_parser

    missing = []
    for command, action in _options(build_parser()):
        if not action.option_strings or action.required or command == "bench":
            continue
        if isinstance(action, (argparse._HelpAction, argparse._VersionAction)):
            continue
        text = action.help or ""
        if "default" not in text.lower():
            missing.append(f"{command} {action.option_strings[-1]}")
    assert missing == [], f"--help gives no default for {missing}"


def test_render_draws_the_demo_outlines_by_default():
    from toonmesh.cli import DEMO_OUTLINES, build_parser, render_options

    args = build_parser().parse_args(["render", "bunny", "-o", "x.png"])
    assert render_options(args)["outlines"] == DEMO_OUTLINES


def readme_commands():
    text = README.read_text()
    start = text.index("in order, in an empty folder:")
    block = re.search(r"```sh\n(.*?)```", text[start:], flags=re.S).group(1)
    return [shlex.split(line.split("  #")[0]) for line in block.splitlines() if line.startswith("toonmesh ")]


def test_the_readme_commands_run_as_written_in_an_empty_folder(tmp_path, capsys, monkeypatch):
    need("trimesh")
    monkeypatch.chdir(tmp_path)
    commands = readme_commands()
    assert len(commands) >= 10
    for cmd in commands:
        if cmd[1:] == ["--version"]:
            with pytest.raises(SystemExit) as e:
                in_process(capsys, *cmd[1:])
            assert e.value.code == 0
            continue
        r = in_process(capsys, *cmd[1:], check=False)
        assert r.returncode == 0, (cmd, r.stderr)
    assert {"bunny.png", "smooth.ply", "bunny.glb", "lines.svg", "lines.npz", "toonmesh-demo.png"} <= set(
        p.name for p in tmp_path.iterdir())
    assert len(list((tmp_path / "frames").iterdir())) == 16
    # the edges NPZ holds what the README says it holds
    text = README.read_text()
    said = text[text.index("NPZ holds the visible polylines"):text.index("- **bench**")]
    named = set(re.findall(r"`(\w+)`", said))
    with np.load(tmp_path / "lines.npz") as z:
        assert set(z.files) == named
        starts, points = z["starts"], z["points"]
        assert starts[0] == 0 and starts[-1] == len(points) and len(z["kinds"]) == len(starts) - 1


def test_render_draws_a_glb_in_its_own_colours(tmp_path, capsys):
    from test_load import coloured_scene, hues

    path = coloured_scene(tmp_path / "coloured.glb")
    in_process(capsys, "render", path, "-o", str(tmp_path / "c.png"), "--size", "120x60", "--outlines", "none")
    red, blue = hues(read_png(tmp_path / "c.png"))
    assert red > 0.4 and blue > 0.2, (red, blue)
    in_process(capsys, "render", path, "-o", str(tmp_path / "g.png"), "--size", "120x60", "--color", "#00ff00")
    red, blue = hues(read_png(tmp_path / "g.png"))
    assert red < 0.05 and blue < 0.05  # --color multiplies them: green light on red and blue


def test_render_hatches_a_coloured_file_in_either_mode(tmp_path, capsys):
    from test_load import coloured_scene

    path = coloured_scene(tmp_path / "coloured.glb")
    out = str(tmp_path / "h.png")
    # strokes along the principal directions take the file's colours as the triplanar ones do
    for mode in ("field", "triplanar"):
        in_process(capsys, "render", path, "-o", out, "--size", "64x64", "--style", "hatching", "--hatch-mode", mode)
        assert read_png(out).shape[:2] == (64, 64)
    bad = in_process(capsys, "render", path, "-o", out, "--hatch-mode", "triplanar", check=False)
    assert bad.returncode != 0 and "--hatch-mode" in bad.stderr

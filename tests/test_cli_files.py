"""The command line on real files: what `smooth` keeps, what `render` draws by default, what a
broken file gives, and the command line page's examples (docs/cli.md) run as written."""

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

CLI_PAGE = Path(__file__).resolve().parent.parent / "docs" / "cli.md"


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
    # its edges smoothed too (a blob, and a warning says so): the normals still split where the file's did
    r = in_process(capsys, "smooth", src, out, "--iterations", "2", "--boundary", "free", "--crease-angle", "180",
                   check=False)
    assert r.returncode == 0 and "smoothing moved a vertex" in r.stderr
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
    """(command, action, required): required where the action, or one of its group, must be given."""
    for action in parser._actions:
        if isinstance(action, argparse._SubParsersAction):
            for name, sub in action.choices.items():
                one_of = {id(a) for g in sub._mutually_exclusive_groups if g.required for a in g._group_actions}
                yield from ((name, a, a.required or id(a) in one_of) for a in sub._actions)


def test_help_states_every_default():
    from toonmesh.cli import build_parser

    missing = []
    for command, action, required in _options(build_parser()):
        if not action.option_strings or required or command == "bench":
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


def page_commands():
    text = CLI_PAGE.read_text()
    start = text.index("in order, in an empty folder:")
    block = re.search(r"```sh\n(.*?)```", text[start:], flags=re.S).group(1)
    return [shlex.split(line.split("  #")[0]) for line in block.splitlines() if line.startswith("toonmesh ")]


def test_the_cli_page_commands_run_as_written_in_an_empty_folder(tmp_path, capsys, monkeypatch):
    need("trimesh")
    monkeypatch.chdir(tmp_path)
    commands = page_commands()
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
    # the edges NPZ holds what the page says it holds
    text = CLI_PAGE.read_text()
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


# ------------------------------------------------------------------------------------------------
# toonmesh smooth: what it writes, where, and how far it moves a CAD part


def textured_obj(folder: Path, rgb, name: str = "in.obj") -> str:
    """A box with UVs and a one-colour texture, as trimesh writes it: its texture named
    material_0.png, as any two such files in two folders name theirs."""
    trimesh, Image = need("trimesh"), need("PIL.Image")
    folder.mkdir(parents=True, exist_ok=True)
    m = trimesh.creation.box()
    material = trimesh.visual.material.SimpleMaterial(image=Image.new("RGB", (4, 4), rgb))
    m.visual = trimesh.visual.TextureVisuals(uv=np.random.default_rng(0).random((len(m.vertices), 2)), material=material)
    m.export(str(folder / name))
    assert (folder / "material_0.png").exists()
    return str(folder / name)


def drawn(path):
    """(mean drawn RGB in [0, 1], the colour keywords) of each mesh tm.load gives: texture
    (one colour here) times the colours the material colour is folded into, or the colours."""
    import warnings

    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        meshes = tm.load(str(path))
    out = []
    for m in meshes:
        rgb = np.ones(3)
        for key in ("texture", "vertex_colors", "face_colors"):
            if key in m.colors:
                c = np.asarray(m.colors[key], dtype=np.float64).reshape(-1, np.shape(m.colors[key])[-1])[:, :3]
                rgb = rgb * c.mean(axis=0) / (255.0 if np.asarray(m.colors[key]).dtype == np.uint8 else 1.0)
        out.append((rgb, sorted(m.colors)))
    return out


def test_smooth_names_the_texture_after_the_output(tmp_path, capsys):
    red = textured_obj(tmp_path / "red", (220, 20, 20))
    blue = textured_obj(tmp_path / "blue", (20, 20, 220))
    out = tmp_path / "out"
    out.mkdir()
    in_process(capsys, "smooth", red, "-o", str(out / "red.obj"))
    in_process(capsys, "smooth", blue, "-o", str(out / "blue.obj"))  # the same folder: nothing overwritten
    # red.ply's texture would be red.png, the OBJ's: refused, naming it, unless --force
    one_line_error(in_process(capsys, "smooth", red, "-o", str(out / "red.ply"), check=False),
                   f"would replace {out / 'red.png'}", "--force")
    assert not (out / "red.ply").exists()
    in_process(capsys, "smooth", red, "-o", str(out / "red.ply"), "--force")
    in_process(capsys, "smooth", red, "-o", str(out / "red2.ply"))
    assert sorted(p.name for p in out.iterdir()) == sorted(["blue.mtl", "blue.obj", "blue.png", "red.mtl", "red.obj",
                                                             "red.png", "red.ply", "red2.ply", "red2.png"])
    for name, rgb in (("red.obj", (220, 20, 20)), ("blue.obj", (20, 20, 220)), ("red.ply", (220, 20, 20))):
        ((colour, keys),) = drawn(out / name)
        assert keys == ["texture", "uv"] and np.allclose(colour * 255, rgb), (name, colour)
    assert "comment TextureFile red2.png" in (out / "red2.ply").read_bytes()[:300].decode(errors="replace")


def test_smooth_never_replaces_its_input_or_a_file_it_did_not_write(tmp_path, capsys):
    folder = tmp_path / "rifle"
    folder.mkdir()
    in_process(capsys, "smooth", textured_obj(tmp_path / "src", (200, 120, 40)), "-o", str(folder / "rifle.obj"))
    files = lambda: {p.name: p.read_bytes() for p in folder.iterdir()}  # noqa: E731
    before = files()
    assert sorted(before) == ["rifle.mtl", "rifle.obj", "rifle.png"]
    # over its input: refused, nothing written
    rifle = str(folder / "rifle.obj")
    one_line_error(in_process(capsys, "smooth", rifle, "-o", rifle, check=False), rifle, "file being read", "--force")
    one_line_error(in_process(capsys, "smooth", rifle, rifle, check=False), "file being read")
    assert files() == before
    # beside files of another: an unrelated rifle2.mtl and rifle2.png are kept, naming them
    (folder / "rifle2.mtl").write_text("newmtl mine\nKd 0 0 1\n")
    (folder / "rifle2.png").write_bytes(before["rifle.png"][:-1] + b"\x00")
    theirs = files()
    line = one_line_error(in_process(capsys, "smooth", rifle, "-o", str(folder / "rifle2.obj"), check=False),
                          str(folder / "rifle2.mtl"), str(folder / "rifle2.png"), "--force")
    assert "not written by this run" in line
    assert files() == theirs  # nothing written, nothing replaced, no temporary file left
    # with --force: written, in place, through temporary files renamed (none left)
    in_process(capsys, "smooth", rifle, "-o", rifle, "--iterations", "1", "--force")
    assert sorted(files()) == sorted(theirs)
    ((colour, keys),) = drawn(folder / "rifle.obj")
    assert keys == ["texture", "uv"] and np.allclose(colour * 255, (200, 120, 40))


def test_smooth_writes_no_texture_for_a_mesh_without_one(tmp_path, capsys):
    header = ("ply\nformat ascii 1.0\nelement vertex 4\nproperty float x\nproperty float y\nproperty float z\n{uv}"
              "element face 2\nproperty list uchar int vertex_indices\nend_header\n")
    rows = [[0, 0, 0], [1, 0, 0], [1, 1, 0], [0, 1, 0.1]]
    for uv in (False, True):
        name = "uv" if uv else "plain"
        text = header.format(uv="property float s\nproperty float t\n" if uv else "")
        text += "".join(" ".join(map(str, r + ([r[0], r[1]] if uv else []))) + "\n" for r in rows)
        src = tmp_path / f"{name}.ply"
        src.write_text(text + "3 0 1 2\n3 0 2 3\n")
        for suffix in (".obj", ".ply", ".glb"):
            out = tmp_path / name / f"out{suffix}"
            out.parent.mkdir(exist_ok=True)
            in_process(capsys, "smooth", str(src), "-o", str(out), "--iterations", "1")
            assert b"TextureFile" not in out.read_bytes()[:400] and b"mtllib" not in out.read_bytes()
            ((colour, keys),) = drawn(out)
            assert "texture" not in keys and np.allclose(colour, 1.0), (name, suffix, keys, colour)
        assert sorted(p.name for p in (tmp_path / name).iterdir()) == ["out.glb", "out.obj", "out.ply"]
    uvs = need("trimesh").load(str(tmp_path / "uv" / "out.obj"), process=False).visual.uv
    assert uvs is not None and len(uvs) == 4  # the texture coordinates are kept


def test_smooth_keeps_colours_uvs_and_materials_where_the_format_holds_them(tmp_path, capsys):
    trimesh = need("trimesh")
    sources = {"texture": textured_obj(tmp_path / "t", (40, 200, 60))}
    (tmp_path / "kd.mtl").write_text("newmtl paint\nKd 0.8 0.3 0.1\n")  # a material colour, no texture
    box = trimesh.creation.box()
    text = trimesh.exchange.obj.export_obj(box, include_normals=False, include_texture=False, header=None)
    (tmp_path / "kd.obj").write_text("mtllib kd.mtl\nusemtl paint\n" + text)
    sources["MTL colour"] = str(tmp_path / "kd.obj")
    pbr = box.copy()
    pbr.visual = trimesh.visual.TextureVisuals(material=trimesh.visual.material.PBRMaterial(
        baseColorFactor=[60, 120, 200, 255]))  # linear light
    sources["glTF factor"] = str(tmp_path / "pbr.glb")
    pbr.export(sources["glTF factor"])
    for kind in ("vertex", "face"):
        m = box.copy()
        n = len(m.vertices) if kind == "vertex" else len(m.faces)
        setattr(m.visual, f"{kind}_colors", np.tile([30, 90, 210, 255], (n, 1)).astype(np.uint8))
        sources[f"{kind} colours"] = str(tmp_path / f"{kind}.ply")
        m.export(sources[f"{kind} colours"])
    # where the format holds it, each is drawn as before; where not, a warning names what is lost
    holds_not = {".obj": {"face colours"}, ".stl": set(sources), ".off": set(sources)}
    for what, src in sources.items():
        ((before, _),) = drawn(src)
        assert not np.allclose(before, 1.0), what  # each source has a colour of its own
        for suffix in (".obj", ".ply", ".glb", ".stl", ".off"):
            # a folder per format: an OBJ's and a PLY's texture would share a name (refused, see above)
            out = tmp_path / "out" / suffix[1:] / f"{what.replace(' ', '-')}{suffix}"
            out.parent.mkdir(parents=True, exist_ok=True)
            r = in_process(capsys, "smooth", src, "-o", str(out), "--iterations", "1", check=False)
            assert r.returncode == 0, r.stderr
            ((after, _),) = drawn(out)
            if what in holds_not.get(suffix, ()):
                assert "warning" in r.stderr and "not written" in r.stderr, (what, suffix, r.stderr)
                continue
            assert r.stderr == "", (what, suffix, r.stderr)
            np.testing.assert_allclose(after, before, atol=2.5 / 255, err_msg=f"{what} to {suffix}")


def test_smooth_takes_a_glb_of_one_mesh_and_a_scene_part_by_part(tmp_path, capsys):
    trimesh = need("trimesh")
    from test_load import coloured_scene

    # one mesh placed by a node: kept placed in a GLB, written where it is placed elsewhere
    V, F = tm.shapes.icosphere(2, noise=0.02, seed=1)
    one = trimesh.Scene()
    place = trimesh.transformations.rotation_matrix(0.7, [0, 0, 1]) @ trimesh.transformations.translation_matrix([3, 0, 0])
    one.add_geometry(trimesh.Trimesh(V, F, process=False), geom_name="ball", transform=place)
    src = str(tmp_path / "one.glb")
    one.export(src)
    in_process(capsys, "smooth", src, "-o", str(tmp_path / "one-out.glb"), "--iterations", "3")
    (m,) = tm.load(str(tmp_path / "one-out.glb"))
    np.testing.assert_allclose(m.transform, place, atol=1e-6)
    moved = np.linalg.norm(m.vertices - V, axis=1)
    assert 1e-4 < moved.max() < 0.05  # smoothed, in its own frame
    in_process(capsys, "smooth", src, "-o", str(tmp_path / "one-out.ply"), "--iterations", "3")
    (w,) = tm.load(str(tmp_path / "one-out.ply"))
    np.testing.assert_allclose(w.vertices, m.vertices @ place[:3, :3].T + place[:3, 3], atol=1e-5)
    # a scene of several meshes (one of them placed twice): each part smoothed, colours and places kept
    scene = coloured_scene(tmp_path / "scene.glb")
    in_process(capsys, "smooth", scene, "-o", str(tmp_path / "scene-out.glb"))
    before, after = tm.load(scene), tm.load(str(tmp_path / "scene-out.glb"))
    key = lambda m: tuple(np.round(m.transform[:3, 3], 6))  # noqa: E731
    assert sorted(map(key, before)) == sorted(map(key, after))
    assert sorted(map(str, [k for _, k in drawn(scene)])) == sorted(map(str, [k for _, k in drawn(tmp_path / "scene-out.glb")]))
    # parts apart from each other are smoothed as each alone would be, in its own frame
    ball = trimesh.Trimesh(V, F, process=False)
    V2, F2 = tm.shapes.icosphere(1, noise=0.05, seed=2)
    two = trimesh.Scene()
    two.add_geometry(ball, geom_name="ball", node_name="b1", transform=place)
    two.graph.update(frame_to="b2", frame_from=two.graph.base_frame, geometry="ball",
                     matrix=trimesh.transformations.translation_matrix([0, 5, 0]))
    two.add_geometry(trimesh.Trimesh(V2, F2, process=False), geom_name="small", node_name="s",
                     transform=trimesh.transformations.scale_matrix(2.0))
    two.export(str(tmp_path / "two.glb"))
    in_process(capsys, "smooth", str(tmp_path / "two.glb"), "-o", str(tmp_path / "two-out.glb"))
    got = {len(m.vertices): m.vertices for m in tm.load(str(tmp_path / "two-out.glb"))}
    for V0, F0 in ((V, F), (V2, F2)):
        np.testing.assert_allclose(got[len(V0)], tm.smooth.taubin(V0, F0), atol=1e-6)  # a GLB holds float32
    r = in_process(capsys, "smooth", scene, "-o", str(tmp_path / "scene.ply"), check=False)
    assert r.returncode == 1
    one_line_error(r, "scene.glb holds 3 placed meshes", "write a .glb", "scene.glb)")
    assert not (tmp_path / "scene.ply").exists()


def test_smooth_keeps_parts_that_share_an_edge_together(tmp_path, capsys):
    """An OBJ of two materials is two meshes that share the vertices along their border:
    smoothed together (welded), the border moves as one and does not open."""
    V, F = tm.shapes.icosphere(2, noise=0.03, seed=4)
    upper = V[F].mean(axis=1)[:, 1] > 0
    lines = ["mtllib two.mtl"] + [f"v {x:.9f} {y:.9f} {z:.9f}" for x, y, z in V]
    for name, chosen in (("a", upper), ("b", ~upper)):
        lines += [f"usemtl {name}"] + [f"f {i + 1} {j + 1} {k + 1}" for i, j, k in F[chosen]]
    (tmp_path / "two.obj").write_text("\n".join(lines) + "\n")
    (tmp_path / "two.mtl").write_text("newmtl a\nKd 1 0 0\nnewmtl b\nKd 0 0 1\n")
    r = in_process(capsys, "smooth", str(tmp_path / "two.obj"), "-o", str(tmp_path / "two.glb"), "--iterations", "5")
    assert "in 2 parts" in r.stdout
    a, b = tm.load(str(tmp_path / "two.glb"))
    points = lambda m: {tuple(p) for p in np.round(m.vertices[np.unique(m.faces)], 6)}  # noqa: E731
    border = np.intersect1d(F[upper], F[~upper])
    assert len(points(a) & points(b)) == len(border)  # every border vertex at one smoothed place in both parts
    assert not points(a) & {tuple(p) for p in np.round(V[border], 6)}  # and the border moved


def test_smooth_takes_o_as_the_other_commands_and_its_positional_form(tmp_path, capsys):
    src = str(MESHES / "spot.obj")
    in_process(capsys, "smooth", src, "-o", str(tmp_path / "a.ply"))
    in_process(capsys, "smooth", src, str(tmp_path / "b.ply"))
    assert (tmp_path / "a.ply").read_bytes() == (tmp_path / "b.ply").read_bytes()
    one_line_error(in_process(capsys, "smooth", src, check=False), "-o", "missing")
    one_line_error(in_process(capsys, "smooth", src, str(tmp_path / "c.ply"), "-o", str(tmp_path / "d.ply"), check=False),
                   "-o", "twice")


def cad_parts():
    """Coarse CAD parts as an STL export holds them: few long triangles, flat faces, sharp edges."""
    trimesh = need("trimesh")
    yield "box", trimesh.creation.box((2.0, 1.0, 0.5))
    yield "cylinder", trimesh.creation.cylinder(0.5, 2.0, sections=32)
    yield "washer", trimesh.creation.annulus(0.3, 0.6, 0.4, sections=48)


def test_the_default_smoothing_keeps_a_cad_part_and_a_large_move_is_named(tmp_path, capsys):
    for name, part in cad_parts():
        src = str(tmp_path / f"{name}.stl")
        part.export(src)
        r = in_process(capsys, "smooth", src, "-o", str(tmp_path / f"{name}-out.stl"))
        share = float(re.search(r"\(([\d.]+)% of the bounding-box diagonal\)", r.stdout).group(1))
        assert share < 0.5, (name, r.stdout)  # edges and corners kept: the part is the part
        # the plain Laplacian across the creases rounds it into a blob: named in a warning
        r = in_process(capsys, "smooth", src, "-o", str(tmp_path / f"{name}-blob.stl"), "--method", "laplacian",
                       "--crease-angle", "180", check=False)
        assert r.returncode == 0
        assert re.search(r"warning: .*blob\.stl: smoothing moved a vertex [\d.]+% of the model's size", r.stderr), r.stderr
    # a scan is smoothed as before, without a warning; a CAD part of many faces barely moves
    for mesh, most in (("stanford-bunny", 1.0), ("fandisk", 1.0), ("rocker-arm", 2.0)):
        r = in_process(capsys, "smooth", str(MESHES / f"{mesh}.obj"), "-o", str(tmp_path / f"{mesh}.ply"))
        share = float(re.search(r"\(([\d.]+)% of the bounding-box diagonal\)", r.stdout).group(1))
        assert 0.05 < share < most, (mesh, share)
    one_line_error(in_process(capsys, "smooth", src, "-o", str(tmp_path / "x.stl"), "--crease-angle", "200",
                              check=False), "--crease-angle", "180")


def test_smooth_and_edges_of_points_or_lines_alone_say_so_in_one_line(tmp_path, capsys):
    need("trimesh")
    corpus = Path(__file__).resolve().parent / "data" / "corpus" / "trimesh"
    cloud, wire = str(corpus / "points_agisoft.xyz"), str(corpus / "obj_wireframe.obj")
    r = in_process(capsys, "smooth", cloud, "-o", str(tmp_path / "s.ply"), check=False)
    one_line_error(r, "points_agisoft.xyz: no triangles in the file (it holds 100 points)")
    r = in_process(capsys, "edges", wire, "-o", str(tmp_path / "e.svg"), check=False)
    one_line_error(r, "obj_wireframe.obj: no triangles in the file (it holds 12 segments)")
    assert not (tmp_path / "s.ply").exists() and not (tmp_path / "e.svg").exists()


CORPUS = Path(__file__).resolve().parent / "data" / "corpus"


@pytest.mark.parametrize("name, drawn", [
    ("khronos/MeshPrimitiveModes.gltf", "16 faces, 7 points, 19 segments"),
    ("trimesh/points_emptyface.ply", "1,024 points"),
    ("trimesh/obj_wireframe.obj", "12 segments"),
])
def test_render_draws_other_projects_point_and_line_files(tmp_path, capsys, name, drawn):
    """Points drawn as splats, lines as ink: the file's picture has them, and the summary line
    counts what was drawn."""
    out = tmp_path / "out.png"
    r = in_process(capsys, "render", str(CORPUS / name), "-o", str(out), "--size", "200x150")
    assert f"(200x150, {drawn})" in r.stdout, r.stdout
    img = read_png(out)[..., :3].astype(int)
    dark = (img.max(axis=2) < 80).sum()  # ink
    toned = ((img.max(axis=2) - img.min(axis=2)) > 60).sum()  # the splats' and faces' colour
    assert dark > 100, dark
    if "points" in drawn or "faces" in drawn:
        assert toned > 300, toned
    else:
        assert toned == 0, toned  # lines alone: only ink on white

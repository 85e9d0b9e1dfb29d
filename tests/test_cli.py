"""The command line, end to end in subprocesses, as a user runs it: `toonmesh` and `python -m toonmesh`."""

from __future__ import annotations

import inspect
import json
import os
import shutil
import subprocess
import sys
from pathlib import Path

import numpy as np
import pytest

import toonmesh as tm
from conftest import MESHES, need

SPOT = str(MESHES / "spot.obj")  # 2,930 vertices: small enough to render in a few ms


def toonmesh(*args: str, cwd: Path, env: dict = None, check: bool = True) -> subprocess.CompletedProcess:
    """Runs `python -m toonmesh ARGS` (the console script runs the same main())."""
    r = subprocess.run([sys.executable, "-m", "toonmesh", *args], cwd=cwd, capture_output=True, text=True,
                       timeout=120, env=env)
    if check:
        assert r.returncode == 0, r.stderr
        assert r.stderr == "", r.stderr  # quiet: no warnings, no Mesa chatter, no progress bar off a terminal
    return r


def in_process(capsys, *args: str, check: bool = True) -> subprocess.CompletedProcess:
    """The same main() in this process (no interpreter start, trimesh import and GPU set-up per
    call), as a CompletedProcess."""
    from toonmesh.cli import main

    capsys.readouterr()
    rc = main(list(args))
    out, err = capsys.readouterr()
    r = subprocess.CompletedProcess(args, rc, out, err)
    if check:
        assert rc == 0 and err == "", err
    return r


def read_png(path) -> np.ndarray:
    Image = need("PIL.Image")
    return np.asarray(Image.open(path))


def one_line_error(r: subprocess.CompletedProcess, *words: str) -> str:
    assert r.returncode != 0
    assert r.stdout == ""
    assert "Traceback" not in r.stderr
    lines = r.stderr.splitlines()
    assert len(lines) == 1, r.stderr
    for w in words:
        assert w in lines[0], lines[0]
    return lines[0]


def write_mesh(path: Path, V: np.ndarray, F: np.ndarray) -> str:
    trimesh = need("trimesh")
    trimesh.Trimesh(V, F, process=False).export(str(path))
    return str(path)


def test_version_names_the_package_version(tmp_path):
    r = toonmesh("--version", cwd=tmp_path)
    assert r.stdout.strip() == f"toonmesh {tm.__version__}"


def test_console_script_is_installed(tmp_path):
    exe = shutil.which("toonmesh", path=os.path.dirname(sys.executable))
    assert exe, "the toonmesh console script is not next to this Python"
    r = subprocess.run([exe, "--version"], capture_output=True, text=True, timeout=60)
    assert r.returncode == 0 and r.stdout.strip() == f"toonmesh {tm.__version__}"


def test_render_one_mesh_gives_the_api_image(tmp_path):
    need("trimesh")
    r = toonmesh("render", SPOT, "-o", "spot.png", "--size", "64x48", cwd=tmp_path)
    assert "wrote spot.png (64x48" in r.stdout
    from toonmesh.data import load_obj

    from toonmesh.cli import DEMO_OUTLINES

    V, F = load_obj(SPOT)
    # the default camera is the y-up front view; the default lines are the demo's
    expected = tm.render(V, F, width=64, height=48, outlines=DEMO_OUTLINES).color
    assert np.array_equal(read_png(tmp_path / "spot.png"), expected)
    assert DEMO_OUTLINES.kind == "mesh" and DEMO_OUTLINES.crease_angle == 60.0


def test_render_turntable_of_several_meshes_into_a_folder(tmp_path, capsys, monkeypatch):
    monkeypatch.chdir(tmp_path)
    need("trimesh")
    ico = write_mesh(tmp_path / "ball.ply", *tm.shapes.icosphere(2, noise=0.05, seed=3))
    # in a subprocess, whose stderr is no terminal: no progress bar, stderr stays empty
    toonmesh("render", SPOT, ico, "-o", "frames", "--views", "3", "--size", "40x30", "--style", "thresholded-phong",
             cwd=tmp_path)
    names = sorted(os.listdir(tmp_path / "frames"))
    assert names == [f"{stem}-{k:03d}.png" for stem in ("ball", "spot") for k in range(3)]
    frames = [read_png(tmp_path / "frames" / f"spot-{k:03d}.png") for k in range(3)]
    assert all(f.shape == (30, 40, 4) for f in frames)
    assert not np.array_equal(frames[0], frames[1]) and not np.array_equal(frames[1], frames[2])
    in_process(capsys, "render", SPOT, "-o", "front.png", "--size", "40x30", "--style", "thresholded-phong")
    assert np.array_equal(frames[0], read_png(tmp_path / "front.png"))  # view 0 is the front view


def test_render_a_turntable_as_a_video(tmp_path, capsys, monkeypatch):
    # -o turn.gif|turn.mp4 with --views N: the turntable's frames, in order, as one file
    monkeypatch.chdir(tmp_path)
    Image = need("PIL.Image")
    imageio_ffmpeg = need("imageio_ffmpeg")
    args = ("--size", "40x30", "--style", "thresholded-phong")
    in_process(capsys, "render", SPOT, "-o", "frames", "--views", "4", *args)
    r = in_process(capsys, "render", SPOT, "-o", "turn.gif", "--views", "4", "--fps", "8", *args)
    assert "wrote turn.gif (4 frames at 8 fps, 40x30)" in r.stdout and "spot.obj: up y" in r.stdout
    gif = Image.open(tmp_path / "turn.gif")
    assert gif.n_frames == 4 and gif.size == (40, 30) and abs(gif.info["duration"] - 125) <= 10  # centiseconds
    for k in range(4):  # each frame the turntable's view k (GIF's palette rounds the colours)
        gif.seek(k)
        want = read_png(tmp_path / "frames" / f"spot-{k:03d}.png")[..., :3].astype(int)
        assert np.abs(np.asarray(gif.convert("RGB")).astype(int) - want).mean() < 4.0
    in_process(capsys, "render", SPOT, "-o", "out/turn.mp4", "--views", "6", "--fps", "12", *args)
    assert imageio_ffmpeg.count_frames_and_secs(str(tmp_path / "out" / "turn.mp4")) == (6, 0.5)
    in_process(capsys, "render", SPOT, "-o", "turn.webm", "--views", "6", "--fps", "12", *args)
    assert imageio_ffmpeg.count_frames_and_secs(str(tmp_path / "turn.webm")) == (6, 0.5)
    # --video: the same turntable, by default DEFAULT_SECONDS at --fps all the way round
    r = in_process(capsys, "render", SPOT, "--video", "spin.gif", "--fps", "3", *args)
    assert "wrote spin.gif (12 frames at 3 fps, 40x30)" in r.stdout, r.stdout
    gif = Image.open(tmp_path / "spin.gif")
    assert gif.n_frames == 12
    gif.seek(3)  # a quarter turn: the view turned by 90 degrees, as --views 4's second frame
    want = read_png(tmp_path / "frames" / "spot-001.png")[..., :3].astype(int)
    assert np.abs(np.asarray(gif.convert("RGB")).astype(int) - want).mean() < 4.0
    for bad, words in [
        (("-o", "x.gif", "--views", "1"), ("-o", "--views N with N >= 2")),
        (("--video", "x.png"), ("--video", ".gif, .mp4, .webm")),
        (("--video", "x.gif", "-o", "y.gif"), ("--video", "not allowed with")),
        (("-o", "x.gif", "--views", "3", "--outputs", "color,depth"), ("-o", "colour output only")),
        (("-o", "x.mp4", "--views", "3", "--size", "41x30"), ("--size", "even width and height")),
    ]:
        r = in_process(capsys, "render", SPOT, *bad, check=False)
        one_line_error(r, *words)
    one_line_error(in_process(capsys, "render", SPOT, SPOT, "-o", "x.gif", "--views", "3", check=False),
                   "-o", "one mesh")
    assert not any((tmp_path / n).exists() for n in ("x.gif", "x.mp4"))


def test_up_z_shows_a_z_up_mesh_as_y_up_shows_the_original(tmp_path, capsys, monkeypatch):
    monkeypatch.chdir(tmp_path)
    V, F = tm.shapes.icosphere(2, noise=0.2, seed=1)
    V = V * [1.0, 1.6, 0.7]  # no symmetry to hide a wrong axis
    y_up = write_mesh(tmp_path / "y.ply", V, F)
    z_up = write_mesh(tmp_path / "z.ply", np.stack([V[:, 0], -V[:, 2], V[:, 1]], axis=1), F)
    in_process(capsys, "render", y_up, "-o", "y.png", "--size", "48x40", "--up", "y")
    in_process(capsys, "render", z_up, "-o", "z.png", "--size", "48x40")  # a PLY is z up by default
    in_process(capsys, "render", z_up, "-o", "z_as_y.png", "--size", "48x40", "--up", "y")
    y, z = read_png(tmp_path / "y.png").astype(int), read_png(tmp_path / "z.png").astype(int)
    assert np.abs(y - z).max() <= 2  # same picture (positions went through float32 in PLY)
    assert not np.array_equal(y, read_png(tmp_path / "z_as_y.png"))


def test_render_float_outputs_write_npz(tmp_path, capsys, monkeypatch):
    monkeypatch.chdir(tmp_path)
    need("trimesh")
    in_process(capsys, "render", SPOT, "-o", "spot.npz", "--size", "32x24", "--outputs", "color,depth", "--smooth", "2")
    with np.load(tmp_path / "spot.npz") as z:
        assert z["color"].shape == (24, 32, 4) and z["depth"].shape == (24, 32)
        assert np.isfinite(z["depth"]).any() and np.isinf(z["depth"]).any()
        assert z["view_matrix"].shape == (4, 4)


def test_outlines_flag_draws_ink(tmp_path, capsys, monkeypatch):
    monkeypatch.chdir(tmp_path)
    need("trimesh")
    PIL = need("PIL.Image")
    dark = {}
    for kind in ("none", "mesh"):
        r = in_process(capsys, "render", SPOT, "-o", f"{kind}.png", "--size", "96x72", "--outlines", kind, check=False)
        assert r.returncode == 0, r.stderr
        rgb = np.asarray(PIL.open(tmp_path / f"{kind}.png"))[..., :3]
        dark[kind] = int((rgb.max(axis=2) < 40).sum())
    assert dark["mesh"] > dark["none"] + 50, dark


def test_rim_and_paper_flags_give_the_api_image(tmp_path, capsys, monkeypatch):
    monkeypatch.chdir(tmp_path)
    need("trimesh")
    from toonmesh.cli import DEMO_OUTLINES
    from toonmesh.data import load_obj

    r = in_process(capsys, "render", SPOT, "-o", "rim.png", "--size", "64x48", "--rim", "lit", "--rim-width", "0.4",
                   "--rim-color", "#ff8000", "--paper", "surface", "--paper-strength", "0.6", check=False)
    assert r.returncode == 0, r.stderr
    V, F = load_obj(SPOT)
    material = tm.Material.bands(rim=tm.Rim("#ff8000", width=0.4, side="lit"))
    expected = tm.render(V, F, width=64, height=48, outlines=DEMO_OUTLINES, material=material,
                         paper=tm.Paper(space="surface", strength=0.6))
    assert "paper" in expected.passes
    assert np.array_equal(read_png(tmp_path / "rim.png"), expected.color)


def test_smooth_command_matches_the_api(tmp_path):
    V, F = tm.shapes.icosphere(3, noise=0.03, seed=0)
    src = write_mesh(tmp_path / "noisy.obj", V, F)
    r = toonmesh("smooth", src, "smoothed.ply", "--method", "taubin", "--iterations", "4", cwd=tmp_path)
    assert "642 vertices" in r.stdout and "wrote smoothed.ply" in r.stdout
    trimesh = need("trimesh")
    out = trimesh.load(tmp_path / "smoothed.ply", process=False)
    V_obj = trimesh.load(src, process=False).vertices  # what the command read
    expected = tm.smooth.taubin(np.asarray(V_obj), F, iterations=4)
    assert np.abs(np.asarray(out.vertices) - expected).max() < 1e-6
    assert np.array_equal(np.asarray(out.faces), F)


def test_smooth_flags_of_a_methods_keywords_reach_it(tmp_path, capsys):
    """--lamb, --mu, --step, ...: each keyword of the method, from the core's description, reaches
    the function as given; a flag of another method's keyword, or a value out of the described
    range, is a bad command line naming the flag."""
    trimesh = need("trimesh")
    V, F = tm.shapes.icosphere(3, noise=0.03, seed=0)
    src = write_mesh(tmp_path / "noisy.obj", V, F)
    V_obj = np.asarray(trimesh.load(src, process=False).vertices)
    for flags, expected in [
        (["--method", "taubin", "--lamb", "0.4", "--mu", "-0.45", "--iterations", "3"],
         tm.smooth.taubin(V_obj, F, lamb=0.4, mu=-0.45, iterations=3)),
        (["--method", "implicit", "--step", "2.5", "--tol", "1e-9", "--max-iter", "500", "--volume-constraint"],
         tm.smooth.implicit(V_obj, F, step=2.5, tol=1e-9, max_iter=500, volume_constraint=True)),
        (["--method", "hc", "--alpha", "0.2", "--beta", "0.7"], tm.smooth.hc(V_obj, F, alpha=0.2, beta=0.7)),
    ]:
        in_process(capsys, "smooth", src, "-o", str(tmp_path / "out.ply"), "--crease-angle", "180", "--force", *flags)
        out = trimesh.load(tmp_path / "out.ply", process=False)
        assert np.abs(np.asarray(out.vertices) - expected).max() < 1e-6, flags
        assert not np.allclose(expected, V_obj), flags  # the flags made a difference a test can see
    r = in_process(capsys, "smooth", src, "-o", str(tmp_path / "x.ply"), "--method", "laplacian", "--mu", "-0.5",
                   check=False)
    one_line_error(r, "--mu", "laplacian takes no such option", "--lamb")
    r = in_process(capsys, "smooth", src, "-o", str(tmp_path / "x.ply"), "--method", "taubin", "--mu", "0.5",
                   check=False)
    one_line_error(r, "--mu", "[-1, 0]")
    assert r.returncode == 2 and not (tmp_path / "x.ply").exists()


def test_smooth_weld_passes_through_or_says_it_is_not_there_yet(tmp_path, capsys, monkeypatch):
    monkeypatch.chdir(tmp_path)
    src = write_mesh(tmp_path / "m.obj", *tm.shapes.icosphere(1))
    r = in_process(capsys, "smooth", src, "out.obj", "--weld", check=False)
    if "weld" in inspect.signature(tm.smooth.laplacian).parameters:
        assert r.returncode == 0, r.stderr
    else:
        one_line_error(r, "--weld", "not available")


def _cube() -> tuple:
    V = np.array([[x, y, z] for x in (-1.0, 1.0) for y in (-1.0, 1.0) for z in (-1.0, 1.0)])
    F = np.array([[0, 1, 3], [0, 3, 2], [4, 6, 7], [4, 7, 5], [0, 4, 5], [0, 5, 1],
                  [2, 3, 7], [2, 7, 6], [0, 2, 6], [0, 6, 4], [1, 5, 7], [1, 7, 3]])
    return V, F


def test_edges_svg_draws_the_nine_visible_cube_edges(tmp_path, capsys, monkeypatch):
    monkeypatch.chdir(tmp_path)
    cube = write_mesh(tmp_path / "cube.off", *_cube())
    r = toonmesh("edges", cube, "-o", "cube.svg", "--size", "200x150", cwd=tmp_path)
    svg = (tmp_path / "cube.svg").read_text()
    assert 'width="200" height="150"' in svg and "<svg" in svg
    # seen from the front, above and to the side: 3 faces, so 9 of the 12 creases; the 3 that meet
    # at the far corner are hidden (the face diagonals are flat, not creases). The 6 around are
    # one closed silhouette; the 3 meeting at the near corner are ridges, two of them joined
    # into one stroke through the corner.
    assert svg.count('<g id="silhouette"') == 1 and svg.count('<g id="ridge"') == 1
    assert svg.count("<polyline") == 3 and "hidden" not in svg
    assert "3 visible polylines" in r.stdout
    in_process(capsys, "edges", cube, "-o", "all.svg", "--size", "200x150", "--hidden")
    svg = (tmp_path / "all.svg").read_text()
    hidden = svg[svg.index('<g id="hidden"'):]
    assert hidden.index("</g>") > hidden.index("<polyline")  # the hidden group has lines
    assert svg.index('<g id="hidden"') < svg.index('<g id="silhouette"')  # drawn underneath


def test_edges_npz_has_the_arrays_and_an_orthographic_view_along_minus_eye(tmp_path, capsys, monkeypatch):
    monkeypatch.chdir(tmp_path)
    V, F = _cube()
    cube = write_mesh(tmp_path / "cube.ply", V, F)
    in_process(capsys, "edges", cube, "-o", "cube.npz", "--eye", "0", "0", "5", "--size", "100x100")
    with np.load(tmp_path / "cube.npz") as z:
        assert len(z["crease"]) == 12 and len(z["boundary"]) == 0
        assert z["projection"][3, 3] == 1.0  # orthographic
        # looking straight down -z: one square silhouette around the z = +1 face
        assert list(z["kinds"]) == ["silhouette"] and z["starts"].tolist() == [0, len(z["points"])]
        p = z["points"]
        assert np.allclose(p[0], p[-1]) and len(p) == 5  # a closed square
        assert z["widths"].dtype == np.float32 and np.all(z["widths"] == tm.LineStyle().width)
        assert (p[:, 0].max() - p[:, 0].min()) > 30 and (p[:, 1].max() - p[:, 1].min()) > 30


@pytest.mark.parametrize(
    "args, words",
    [
        (["render", "missing.obj", "-o", "x.png"], ["missing.obj", "no such file"]),
        (["render", SPOT, "-o", "x.png", "--size", "0x5"], ["--size", "0x5"]),
        (["render", SPOT, "-o", "x.png", "--up", "w"], ["--up", "'w'"]),
        (["render", SPOT, "-o", "x.jpg"], ["-o", ".jpg"]),
        (["render", SPOT, SPOT, "-o", "x.png"], ["-o", "folder"]),
        (["render", SPOT, "-o", "x.png", "--outputs", "colour"], ["--outputs", "colour"]),
        (["render", SPOT, "-o", "x.png", "--normals", "sharp"], ["--normals", "sharp"]),
        (["render", SPOT, "-o", "x.png", "--normals", "auto:wide"], ["--normals", "auto:wide"]),
        (["render", SPOT, "-o", "x.png", "--normals", "auto:-5"], ["normals", "180"]),
        (["render", SPOT, "-o", "x.png", "--rim", "both", "--rim-width", "1.5"], ["--rim-width", "[0, 1]"]),
        (["render", SPOT, "-o", "x.png", "--paper", "screen", "--paper-strength", "-1"], ["--paper-strength"]),
        (["smooth", "nothere.ply", "out.obj"], ["nothere.ply", "no such file"]),
        (["edges", SPOT, "-o", "lines.pdf"], [".svg or .npz"]),
        (["render", SPOT, "-o", "x.png", "--bogus"], ["--bogus"]),
        ([], ["COMMAND"]),
    ],
)
def test_mistakes_print_one_line_and_fail(tmp_path, capsys, monkeypatch, args, words):
    monkeypatch.chdir(tmp_path)
    r = in_process(capsys, *args, check=False)
    one_line_error(r, *words)
    assert not (tmp_path / "x.png").exists()


def test_an_unreadable_mesh_is_one_line(tmp_path, capsys, monkeypatch):
    monkeypatch.chdir(tmp_path)
    need("trimesh")
    (tmp_path / "bad.obj").write_text("this is not a mesh\n")
    (tmp_path / "bad.ply").write_bytes(b"ply\nformat binary_little_endian 1.0\nelement vertex 99\n")
    one_line_error(in_process(capsys, "render", "bad.obj", "-o", "b.png", check=False), "bad.obj")
    one_line_error(in_process(capsys, "smooth", "bad.ply", "b.obj", check=False), "bad.ply")


def test_missing_trimesh_is_one_line_naming_the_extra(tmp_path, capsys, monkeypatch):
    monkeypatch.chdir(tmp_path)
    monkeypatch.setitem(sys.modules, "trimesh", None)  # import trimesh now raises ImportError
    one_line_error(in_process(capsys, "render", SPOT, "-o", "x.png", check=False), "trimesh", "toonmesh[io]")
    one_line_error(in_process(capsys, "smooth", SPOT, "x.obj", check=False), "trimesh", "toonmesh[io]")


def test_bench_json_has_every_table_row_as_a_record(tmp_path):
    r = toonmesh("bench", "edges", "--quick", "--json", "edges.json", cwd=tmp_path)
    records = json.loads((tmp_path / "edges.json").read_text())
    printed_rows = [l for l in r.stdout.splitlines() if l.startswith("| ") and not l.startswith("| case")]
    assert len(records) == len(printed_rows) > 0
    rec = records[0]
    assert rec["suite"] == "edges" and rec["table"] == "Mesh-space outlines"
    assert isinstance(rec["toonmesh"], float) and rec["units"]["toonmesh"] == "ms"


def test_bench_accuracy_runs_only_the_tables_of_error_against_time(tmp_path):
    r = toonmesh("bench", "edges", "--accuracy", "--json", "edges.json", cwd=tmp_path, check=False)
    assert r.returncode == 0 and r.stdout == ""  # the edges suite has none: nothing is timed
    assert "[edges] has no accuracy tables" in r.stderr
    assert json.loads((tmp_path / "edges.json").read_text()) == []
    # (notebooks/accuracy_vs_time.ipynb runs the smooth and render suites' accuracy tables)


def test_bench_json_values():
    from toonmesh.bench._timing import record_value, recording, table

    assert record_value("47.8 ms") == (47.8, "ms")
    assert record_value("3.3x") == (3.3, "x")
    assert record_value("2.00e-02") == (0.02, None)
    assert record_value("1,024") == (1024.0, None)
    assert record_value("-") == (None, None) and record_value("") == (None, None)
    assert record_value(float("nan")) == (None, None) and record_value(np.int64(3)) == (3, None)
    assert record_value("icosphere(5)") == ("icosphere(5)", None)
    with recording("s") as rows:
        table(["a", "b"], [("x", "1.5 ms"), ("y", 2)], title="T")
    assert rows == [{"suite": "s", "table": "T", "row": 0, "a": "x", "b": 1.5, "units": {"b": "ms"}},
                    {"suite": "s", "table": "T", "row": 1, "a": "y", "b": 2}]
    table(["a"], [("z",)])  # outside recording: nothing kept
    assert len(rows) == 2


def test_bench_refuses_unknown_options_before_running_anything(tmp_path):
    r = subprocess.run([sys.executable, "-m", "toonmesh.bench", "smooth", "--quik"], capture_output=True, text=True,
                       timeout=60)
    assert r.returncode == 2
    assert "unrecognised arguments: --quik" in r.stderr
    assert r.stdout == ""
    one_line_error(toonmesh("bench", "smooth", "--quik", cwd=tmp_path, check=False), "--quik")


def test_bench_thread_scaling_table_restores_the_thread_count():
    from toonmesh.bench.smooth import scaling_table

    before = tm.get_num_threads()
    text = scaling_table("10k", 1)
    assert tm.get_num_threads() == before
    rows = [l for l in text.splitlines() if l.startswith("| ") and "threads" not in l]
    assert len(rows) >= 4  # one row per job at 1 thread at least
    assert rows[0].split("|")[2].strip() == "1"
    assert all(float(r.split("|")[3]) > 0 for r in rows)
    assert "1.00x" in rows[0]


def test_demo_still_renders_the_bunny(tmp_path):
    r = toonmesh("demo", "--out", "demo.png", "--width", "80", "--height", "60", cwd=tmp_path)
    assert "wrote demo.png (80x60)" in r.stdout
    img = read_png(tmp_path / "demo.png")
    assert img.shape == (60, 80, 4) and len(np.unique(img.reshape(-1, 4), axis=0)) > 3


def test_edges_and_render_take_the_contour_rule_and_suggestive_contours(tmp_path, capsys, monkeypatch):
    monkeypatch.chdir(tmp_path)
    bunny = str(Path(tm.__file__).parent / "data" / "bunny.obj")
    in_process(capsys, "edges", bunny, "-o", "faces.svg", "--size", "300x300", "--contours", "faces")
    in_process(capsys, "edges", bunny, "-o", "smooth.svg", "--size", "300x300", "--contours", "smooth", "--suggestive")
    faces, smooth = (tmp_path / "faces.svg").read_text(), (tmp_path / "smooth.svg").read_text()

    def silhouettes(svg: str) -> int:
        group = svg.split('<g id="silhouette"')[1].split("</g>")[0]
        return group.count("<polyline")

    assert silhouettes(smooth) < silhouettes(faces) / 1.5  # long strokes instead of staircases
    in_process(capsys, "edges", bunny, "-o", "flowing.svg", "--size", "300x300", "--contours", "smooth", "--suggestive",
               "--smooth-strokes", "2")
    flowing = (tmp_path / "flowing.svg").read_text()
    assert flowing != smooth and silhouettes(flowing) == silhouettes(smooth)  # the same strokes, smoothed
    one_line_error(in_process(capsys, "edges", bunny, "-o", "x.svg", "--smooth-strokes", "-1", check=False), "--smooth-strokes")
    assert '<g id="suggestive"' in smooth and '<g id="suggestive"' not in faces
    # the curvature of suggestive contours at the one-ring: the scan's noise draws
    in_process(capsys, "edges", bunny, "-o", "raw.svg", "--size", "300x300", "--suggestive", "--curvature-smoothing", "0")

    def strokes(svg: str, kind: str) -> int:
        group = svg.split(f'<g id="{kind}"')[1].split("</g>")[0]
        return group.count("<polyline") + group.count("<path")

    assert strokes((tmp_path / "raw.svg").read_text(), "suggestive") > 3 * strokes(smooth, "suggestive")
    one_line_error(in_process(capsys, "edges", bunny, "-o", "x.svg", "--suggestive", "--curvature-smoothing", "-1",
                              check=False), "curvature_smoothing")
    one_line_error(in_process(capsys, "render", bunny, "-o", "x.png", "--outlines", "image", "--suggestive",
                              check=False), "--suggestive")
    one_line_error(in_process(capsys, "edges", bunny, "-o", "x.svg", "--eye", "0", "0", "0", check=False), "--eye")
    # for a pen plotter: ordered strokes, every point kept
    in_process(capsys, "edges", bunny, "-o", "plot.svg", "--size", "300x300", "--order", "plotter", "--simplify", "0")
    in_process(capsys, "edges", bunny, "-o", "simple.svg", "--size", "300x300", "--order", "plotter")
    plot = (tmp_path / "plot.svg").read_text()
    assert plot != (tmp_path / "faces.svg").read_text() and plot.count(",") > (tmp_path / "simple.svg").read_text().count(",")
    one_line_error(in_process(capsys, "edges", bunny, "-o", "x.svg", "--simplify", "-1", check=False), "--simplify")
    in_process(capsys, "render", bunny, "-o", "b.png", "--size", "64x64", "--outlines", "mesh", "--contours", "smooth")
    assert (tmp_path / "b.png").stat().st_size > 0
    one_line_error(in_process(capsys, "edges", bunny, "-o", "x.svg", "--contours", "zigzag", check=False), "--contours")


def test_edges_joins_strokes_of_different_kinds_when_asked(tmp_path, capsys, monkeypatch):
    monkeypatch.chdir(tmp_path)
    bunny = str(Path(tm.__file__).parent / "data" / "bunny.obj")
    in_process(capsys, "edges", bunny, "-o", "apart.svg", "--size", "300x300")
    in_process(capsys, "edges", bunny, "-o", "joined.svg", "--size", "300x300", "--join-kinds")
    apart, joined = ((tmp_path / n).read_text().count("<polyline") for n in ("apart.svg", "joined.svg"))
    assert joined < apart

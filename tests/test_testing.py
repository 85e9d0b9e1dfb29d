"""toonmesh.testing and its pytest plugin: the comparisons of meshes, images and line drawings,
the snapshot references (in a fresh folder, through pytest run as a user runs it), the default
tolerances between the two backends, and what a missing peer does."""

from __future__ import annotations

import importlib.util
import io
import os
import re
import struct
import subprocess
import sys
import textwrap
import zlib
from pathlib import Path

import numpy as np
import pytest

import toonmesh as tm
from toonmesh.testing import _drawings, _png
from toonmesh.data import bunny
from toonmesh.testing import (
    IMAGE_LEVELS,
    IMAGE_SHARE,
    LINE_SHARE,
    PeerMissingError,
    Snapshot,
    assert_drawings_close,
    assert_images_close,
    assert_mesh_close,
    drawing_difference,
    image_difference,
    mesh_difference,
    need_peer,
    smoothing_vs_pymeshlab,
    smoothing_vs_trimesh,
)

from conftest import RENDER_BACKENDS, need, need_backend

ROOT = Path(__file__).resolve().parent.parent


# ------------------------------------------------------------------------------------------------
# Meshes


def test_mesh_close_is_relative_to_the_diagonal_at_any_scale():
    V, F = tm.shapes.icosphere(2, noise=0.05, seed=1)
    for scale in (1e-290, 1e-6, 1.0, 1e6, 1e290):
        W = V * scale
        moved = W.copy()
        moved[7] += 1e-8 * scale  # 1.7e-8 of the size: within 1e-6 of the diagonal
        d = assert_mesh_close((moved, F), (W, F))
        assert d.vertex == 7 and d.relative < 1e-7
        moved[7] += 1e-5 * scale
        with pytest.raises(AssertionError, match=r"vertex 7 is .* of the bounding-box diagonal.*1 of 162 vertices"):
            assert_mesh_close((moved, F), (W, F))
        assert_mesh_close((moved, F), (W, F), rtol=1e-4)
        assert_mesh_close((moved, F), (W, F), rtol=0.0, atol=1e-4 * scale)


def test_mesh_close_checks_the_faces_in_any_order_and_rotation():
    V, F = tm.shapes.icosphere(1)
    shuffled = np.roll(F[::-1], 1, axis=1)  # rows reversed, corners rotated: the same triangles
    assert_mesh_close((V, shuffled), (V, F))
    flipped = F.copy()
    flipped[5] = flipped[5, ::-1]
    with pytest.raises(AssertionError, match=r"1 of the 80 faces.*face 5 .*flipped"):
        assert_mesh_close((V, flipped), (V, F))
    assert_mesh_close((V, flipped), (V, F), check_faces=False)
    with pytest.raises(AssertionError, match="actual has 79 faces, expected 80"):
        assert_mesh_close((V, F[1:]), (V, F))
    with pytest.raises(AssertionError, match="actual has 41 vertices, expected 42"):
        assert_mesh_close(V[1:], V)
    assert_mesh_close(V, (V, F))  # positions alone: the faces are not compared


def test_mesh_inputs_are_read_not_changed():
    trimesh = need("trimesh")
    V, F = tm.shapes.icosphere(1)
    before = V.copy(), F.copy()
    d = mesh_difference(trimesh.Trimesh(V, F, process=False), (V.astype(np.float32), F))
    assert d.largest < 1e-6 and d.distances.shape == (len(V),)
    np.testing.assert_array_equal(V, before[0])
    np.testing.assert_array_equal(F, before[1])
    with pytest.raises(ValueError, match="^expected: positions must be finite; vertex 3"):
        bad = V.copy()
        bad[3, 0] = np.nan
        mesh_difference(V, bad)
    with pytest.raises(IndexError, match="^actual: face index 42 outside"):
        assert_mesh_close((V, F + 1), (V, F))


# ------------------------------------------------------------------------------------------------
# Images


def test_images_close_counts_pixels_beyond_the_levels():
    a = np.zeros((100, 100, 4), np.uint8)
    b = a.copy()
    b[:3, :3] = 8  # 9 pixels at the tolerance: the same
    b[50, 60, 1] = 200  # one beyond it
    d = assert_images_close(a, b)
    assert (d.differing, d.largest, d.at, d.share) == (1, 200, (60, 50), 1e-4)
    assert image_difference(a, b, levels=0).differing == 10
    b[10:14, 10:14] = 255  # 17 pixels beyond: 0.17%
    with pytest.raises(AssertionError, match=r"0\.170% of the pixels \(17\).*largest difference is 255 levels"):
        assert_images_close(a, b)
    assert_images_close(a, b, share=0.002)
    with pytest.raises(AssertionError, match="images differ in size: actual 100x100, expected 99x100"):
        assert_images_close(a, b[:, 1:])


def test_images_take_renders_floats_and_bools():
    res = tm.render(*tm.shapes.icosphere(2), width=32, height=24)
    assert_images_close(res, res.color, levels=0, share=0.0)
    assert_images_close(res.color / 255.0, res, levels=0, share=0.0)
    mask = res.color[..., 3] > 0
    assert image_difference(mask, mask.astype(np.uint8) * 255, levels=0).differing == 0
    with pytest.raises(ValueError, match=r"^actual: a float image must hold finite values in \[0, 1\]"):
        image_difference(res.color * 2.0, res)
    with pytest.raises(ValueError, match="^expected: the render has no colour image"):
        image_difference(res, tm.render(*tm.shapes.icosphere(1), width=32, height=24, outputs=("depth",)))


def test_the_default_tolerance_holds_between_vulkan_and_gl():
    """Every scene of docs/backend_differences.py (the table of docs/testing.md) passes
    between the backends with the defaults."""
    for backend in RENDER_BACKENDS:
        need_backend(backend)
    spec = importlib.util.spec_from_file_location("backend_differences", ROOT / "docs" / "backend_differences.py")
    table = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(table)
    for name in table.SCENES:
        m = table.measure(name)
        assert_images_close(m["vulkan"], m["gl"])
        assert m["beyond"].share <= IMAGE_SHARE / 10, name  # with room to spare
        if m["vulkan"].lines is not None:
            assert_drawings_close(m["vulkan"], m["gl"])


# ------------------------------------------------------------------------------------------------
# Line drawings


@pytest.fixture(scope="module")
def bunny_lines():
    V, F = bunny()
    return tm.render(V, F, outlines="mesh", outputs=("lines",), width=200, height=200)


def _jitter(svg: str, amount: float, seed: int = 0) -> str:
    """The SVG with every coordinate moved by up to ``amount`` (float noise)."""
    rng = np.random.default_rng(seed)

    def noisy(m: re.Match) -> str:
        return re.sub(r"\d+\.\d+", lambda n: f"{float(n.group()) + rng.uniform(-amount, amount):.3f}", m.group())

    return re.sub(r'(points|d)="[^"]*"', noisy, svg)


def test_drawings_compare_as_geometry_within_pixels(bunny_lines):
    svg = bunny_lines.svg()
    d = assert_drawings_close(_jitter(svg, 0.05), bunny_lines)
    assert 0.0 < d.largest < 0.2 and d.share == 0.0
    # the same lines split into other strokes, drawn in another order: the same drawing
    assert drawing_difference(bunny_lines.svg(order="plotter"), svg).largest < 1e-9
    # moved 3 pixels: all of it differs
    moved = [p + (3.0, 0.0) for p in bunny_lines.lines]
    d = drawing_difference(moved, list(bunny_lines.lines))
    assert d.share > 0.5 and 2.8 < d.largest < 3.2
    with pytest.raises(AssertionError, match=r"of the line length lies farther than 1 px.*largest distance is 3"):
        assert_drawings_close(moved, list(bunny_lines.lines))
    assert_drawings_close(moved, list(bunny_lines.lines), pixels=3.5)


def test_drawings_compare_styles_and_kinds(bunny_lines):
    svg = bunny_lines.svg()
    thicker = svg.replace('id="silhouette" fill="none" stroke="#000000" stroke-width="1.5"',
                          'id="silhouette" fill="none" stroke="#000000" stroke-width="2"')
    assert thicker != svg
    with pytest.raises(AssertionError, match=r"the silhouette lines' style .* is \('#000000', '2', 'none'\)"):
        assert_drawings_close(thicker, svg)
    renamed = svg.replace('id="ridge"', 'id="valley2"')
    d = drawing_difference(renamed, svg)
    assert "the ridge lines are only in the reference" in d.only and "the valley2 lines are only in actual" in d.only


def test_filled_outlines_are_read_as_their_outlines():
    V, F = bunny()
    res = tm.render(V, F, outlines=tm.Outlines("mesh", taper=5.0), outputs=("lines",), width=160, height=160)
    svg = res.svg()
    assert "<path" in svg
    drawing = _drawings.parse_svg(svg)
    assert drawing.width == 160 and sum(len(g.strokes) for g in drawing.groups.values()) >= len(res.lines)
    assert_drawings_close(_jitter(svg, 0.05), svg)
    # the outline of a stroke lies within its width of the stroke
    assert drawing_difference(svg, res.svg(widths="kind")).largest < 3.0


def test_path_commands_are_read_by_their_end_points():
    strokes = _drawings.path_strokes("M1,2 L3,4 h2 v-1 l1,1 A1,1 0 0 1 9,9 Z m1,1 C0,0 0,0 5,5")
    np.testing.assert_array_equal(strokes[0], [[1, 2], [3, 4], [5, 4], [5, 3], [6, 4], [9, 9], [1, 2]])
    np.testing.assert_array_equal(strokes[1], [[2, 3], [5, 5]])


def test_nearest_is_exact_at_every_distance():
    rng = np.random.default_rng(4)
    a, b = rng.random((500, 2)) * 300, rng.random((40, 2)) * 300
    brute = np.sqrt(((a[:, None] - b[None]) ** 2).sum(-1)).min(1)
    np.testing.assert_allclose(_drawings.nearest(a, b, 1.0), brute, rtol=0, atol=1e-12)


# ------------------------------------------------------------------------------------------------
# Snapshots, called directly


def test_snapshot_names_writes_and_clears(tmp_path):
    img = np.zeros((8, 8, 3), np.uint8)
    snap = Snapshot(tmp_path / "s", "test_x[gl]", update=True)
    assert snap(img) == tmp_path / "s" / "test_x[gl].png"
    assert snap(img) == tmp_path / "s" / "test_x[gl]-2.png"
    assert snap(img, "shared/name") == tmp_path / "s" / "shared_name.png"
    assert len(snap.written) == 3
    # a reference that still matches is not written again
    before = (tmp_path / "s" / "test_x[gl].png").stat().st_mtime_ns
    Snapshot(tmp_path / "s", "test_x[gl]", update=True)(img + 3)
    assert (tmp_path / "s" / "test_x[gl].png").stat().st_mtime_ns == before
    # a failure leaves the actual and difference images; a pass clears them
    check = Snapshot(tmp_path / "s", "test_x[gl]")
    changed = img.copy()
    changed[2:5, 2:5] = 200
    with pytest.raises(AssertionError, match=r"test_x\[gl\]\.png differs: 14\.062% of the pixels \(9\)"):
        check(changed)
    assert (tmp_path / "s" / "test_x[gl].actual.png").exists()
    diff = _png.decode((tmp_path / "s" / "test_x[gl].diff.png").read_bytes())
    assert tuple(diff[3, 3]) == (255, 0, 0, 255) and tuple(diff[0, 0]) != (255, 0, 0, 255)
    np.testing.assert_array_equal(_png.decode((tmp_path / "s" / "test_x[gl].actual.png").read_bytes()), changed)
    Snapshot(tmp_path / "s", "test_x[gl]")(img)
    assert not (tmp_path / "s" / "test_x[gl].actual.png").exists() and not (tmp_path / "s" / "test_x[gl].diff.png").exists()
    # strict and loose
    with pytest.raises(AssertionError):
        Snapshot(tmp_path / "s", "test_x[gl]")(img + 1, levels=0)
    Snapshot(tmp_path / "s", "test_x[gl]")(changed, share=0.2)


def test_snapshot_of_a_drawing(tmp_path, bunny_lines):
    snap = Snapshot(tmp_path, "t", update=True)
    assert snap(bunny_lines).suffix == ".svg"
    Snapshot(tmp_path, "t")(_jitter(bunny_lines.svg(), 0.05))
    res = tm.render(*bunny(), outlines="mesh", outputs=("color", "lines"), width=200, height=200)
    Snapshot(tmp_path, "t")(res, kind="drawing")  # its lines, not its colour image
    with pytest.raises(AssertionError, match=r"t\.svg differs"):
        Snapshot(tmp_path, "t")([p + 2.0 for p in bunny_lines.lines], kind="drawing")
    assert (tmp_path / "t.diff.svg").read_text().startswith("<?xml")


def _unfilter(rows: np.ndarray, kinds: np.ndarray) -> np.ndarray:
    """PNG's five row filters undone, pixel by pixel, as its specification writes them: the
    test's own reading of (H, W, C) filtered bytes, row ``y`` under filter ``kinds[y]``."""
    h, w, c = rows.shape
    out = np.zeros((h, w, c), np.int64)
    for y in range(h):
        for x in range(w):
            left = out[y, x - 1] if x else np.zeros(c, np.int64)
            up = out[y - 1, x] if y else np.zeros(c, np.int64)
            upper_left = out[y - 1, x - 1] if x and y else np.zeros(c, np.int64)
            p = left + up - upper_left
            pa, pb, pc = np.abs(p - left), np.abs(p - up), np.abs(p - upper_left)
            paeth = np.where((pa <= pb) & (pa <= pc), left, np.where(pb <= pc, up, upper_left))
            pred = [np.zeros(c, np.int64), left, up, (left + up) // 2, paeth][int(kinds[y])]
            out[y, x] = (rows[y, x].astype(np.int64) + pred) & 0xFF
    return out.astype(np.uint8)


def test_references_written_by_other_tools_are_read():
    """A PNG with every row filter (Pillow's and toonmesh's own encoder choose them per row)."""
    res = tm.render(*bunny(), width=96, height=64)
    np.testing.assert_array_equal(_png.decode(res.png_bytes()), res.color)
    np.testing.assert_array_equal(_png.decode(_png.encode(res.color)), res.color)
    rows = np.random.default_rng(2).integers(0, 256, (5, 7, 3)).astype(np.uint8)
    filtered = _unfilter(rows, np.array([0, 1, 2, 3, 4]))  # every filter, the slow way
    by_hand = np.concatenate([np.arange(5, dtype=np.uint8)[:, None], rows.reshape(5, -1)], axis=1)
    header = struct.pack(">IIBBBBB", 7, 5, 8, 2, 0, 0, 0)
    one_filter_a_row = (b"\x89PNG\r\n\x1a\n" + _png._chunk(b"IHDR", header)
                        + _png._chunk(b"IDAT", zlib.compress(by_hand.tobytes())) + _png._chunk(b"IEND", b""))
    np.testing.assert_array_equal(_png.decode(one_filter_a_row), filtered)
    pil = need("PIL.Image")
    buf = io.BytesIO()
    pil.fromarray(filtered).save(buf, "PNG")
    np.testing.assert_array_equal(_png.decode(buf.getvalue()), filtered)
    with pytest.raises(ValueError, match="^ref.png: not a PNG file"):
        _png.decode(b"GIF89a", "ref.png")


# ------------------------------------------------------------------------------------------------
# The plugin in a fresh folder, through pytest as a user runs it


def test_pyproject_declares_the_pytest11_entry_point():
    import tomllib

    project = tomllib.loads((ROOT / "pyproject.toml").read_text())["project"]
    # named as its module: -p toonmesh.pytest_plugin is then a no-op where it is installed
    assert project["entry-points"]["pytest11"] == {"toonmesh.pytest_plugin": "toonmesh.pytest_plugin"}


USER_TEST = '''
import os

import toonmesh as tm
from toonmesh.data import bunny


def test_bunny(toon_snapshot):
    V, F = bunny()
    if os.environ.get("SMOOTH_FIRST"):
        V = tm.smooth.laplacian(V, F)
    toon_snapshot(tm.render(V, F, width=160, height=160, outlines="mesh", outputs=("color", "lines")))


def test_bunny_lines(toon_snapshot):
    V, F = bunny()
    if os.environ.get("SMOOTH_FIRST"):
        V = tm.smooth.laplacian(V, F)
    toon_snapshot(tm.render(V, F, width=160, height=160, outlines="mesh", outputs=("lines",)))
'''


def _pytest(folder: Path, *args: str, smooth: bool = False) -> subprocess.CompletedProcess:
    """pytest run in ``folder`` with toonmesh's plugin named (a no-op where its entry point is
    installed, and the way to load it where it is not, as in an editable build)."""
    env = dict(os.environ, SMOOTH_FIRST="1" if smooth else "")
    env.pop("PYTEST_ADDOPTS", None)
    return subprocess.run(
        [sys.executable, "-m", "pytest", "-q", "-p", "no:cacheprovider", "-p", "toonmesh.pytest_plugin", *args],
        cwd=folder, env=env, capture_output=True, text=True, timeout=300)


def test_snapshot_workflow_in_a_fresh_folder(tmp_path):
    (tmp_path / "pytest.ini").write_text("[pytest]\n")
    (tmp_path / "test_user.py").write_text(textwrap.dedent(USER_TEST))
    refs = tmp_path / "__snapshots__"
    # no reference: both fail, saying how to write it, and leave what it would hold
    r = _pytest(tmp_path)
    assert r.returncode == 1 and "2 failed" in r.stdout, r.stdout + r.stderr
    assert "no reference" in r.stdout and "pytest --toon-update" in r.stdout
    assert (refs / "test_bunny.actual.png").exists() and (refs / "test_bunny_lines.actual.svg").exists()
    # --toon-update writes them and passes, listing them
    r = _pytest(tmp_path, "--toon-update")
    assert r.returncode == 0, r.stdout + r.stderr
    assert "wrote 2 references" in r.stdout
    assert sorted(p.name for p in refs.iterdir()) == ["test_bunny.png", "test_bunny_lines.svg"]
    png = (refs / "test_bunny.png").read_bytes()
    # unchanged: passes, and writes nothing
    r = _pytest(tmp_path)
    assert r.returncode == 0 and "2 passed" in r.stdout, r.stdout + r.stderr
    assert (refs / "test_bunny.png").read_bytes() == png
    # the mesh smoothed before rendering: both fail, with the reference, the share, the largest
    # difference, and the actual and difference images beside the reference
    r = _pytest(tmp_path, smooth=True)
    assert r.returncode == 1 and "2 failed" in r.stdout, r.stdout + r.stderr
    assert re.search(r"test_bunny\.png differs: [\d.]+% of the pixels \(\d+\) differ by more than 8 levels; "
                     r"the largest difference is \d+ levels", r.stdout), r.stdout
    assert re.search(r"test_bunny_lines\.svg differs: [\d.]+% of the line length", r.stdout), r.stdout
    for name in ("test_bunny.actual.png", "test_bunny.diff.png", "test_bunny_lines.actual.svg", "test_bunny_lines.diff.svg"):
        assert (refs / name).exists(), name
    assert "toonmesh/testing" not in r.stdout  # the traceback ends at the user's line (none of the package's testing/)
    # refreshed on purpose: passes again, and the stale actual and difference images go
    assert _pytest(tmp_path, "--toon-update", smooth=True).returncode == 0
    assert sorted(p.name for p in refs.iterdir()) == ["test_bunny.png", "test_bunny_lines.svg"]


def test_the_example_test_file_of_the_docs_runs(tmp_path):
    """docs/testing.md's complete example: --toon-update writes its references, then it passes."""
    text = (ROOT / "docs" / "testing.md").read_text()
    (example,) = re.findall(r"```python\n(# test_my_mesh_code\.py\n.*?)```", text, flags=re.S)
    (tmp_path / "pytest.ini").write_text("[pytest]\n")
    (tmp_path / "test_my_mesh_code.py").write_text(example)
    r = _pytest(tmp_path, "--toon-update")
    assert r.returncode == 0 and "wrote 4 references" in r.stdout, r.stdout + r.stderr
    r = _pytest(tmp_path)
    assert r.returncode == 0 and "6 passed" in r.stdout, r.stdout + r.stderr


# ------------------------------------------------------------------------------------------------
# Missing peers and the cross-checks


def test_a_missing_peer_skips_under_pytest_and_fails_in_ci(monkeypatch):
    monkeypatch.delenv("CI", raising=False)
    with pytest.raises(pytest.skip.Exception, match="no_such_peer is not installed"):
        need_peer("no_such_peer")
    monkeypatch.setenv("CI", "true")
    with pytest.raises(PeerMissingError, match="CI=true"):
        need_peer("no_such_peer")
    # outside pytest: a clear exception (an ImportError)
    monkeypatch.delenv("CI")
    monkeypatch.delenv("PYTEST_CURRENT_TEST", raising=False)
    monkeypatch.delenv("PYTEST_VERSION", raising=False)
    with pytest.raises(ImportError, match=r"no_such_peer is not installed \(for this\): install it"):
        need_peer("no_such_peer", "for this")
    assert need_peer("numpy") is np


def test_cross_checks_refuse_what_the_peer_lacks_before_needing_it():
    V, F = tm.shapes.icosphere(1, noise=0.05, seed=2)
    before = V.copy()
    with pytest.raises(ValueError, match="^method: pymeshlab has no implicit smoothing"):
        smoothing_vs_pymeshlab(V, F, "implicit")
    with pytest.raises(ValueError, match="^pinned: pymeshlab's smoothing filters have no pinned vertices"):
        smoothing_vs_pymeshlab(V, F, pinned=[0])
    with pytest.raises(ValueError, match="^weights:"):
        smoothing_vs_trimesh(V, F, weights="cotangent")
    with pytest.raises(ValueError, match="^weld:"):
        smoothing_vs_trimesh(V, F, weld=True)
    with pytest.raises(TypeError, match="^preset:"):
        smoothing_vs_trimesh(V, F, preset="pymeshlab")
    np.testing.assert_array_equal(V, before)
    need("trimesh")
    d = smoothing_vs_trimesh(V, F, "hc", iterations=3)
    assert d.relative < 1e-9 and d.distances.shape == (len(V),)
    np.testing.assert_array_equal(V, before)

"""Shading normals: "smooth", "flat" and "auto" (vertices split at creases, as Blender's auto
smooth does). Boxes shade with one band a face, curved parts stay as smooth as "smooth"."""

from __future__ import annotations

import math
from typing import Any, Tuple

import numpy as np
import pytest

import toonmesh as tm
from conftest import need
from toonmesh.data import bunny

SIZE = 160
CAMERA = tm.Camera.fit((0.6, 0.5, 1.0))  # sees the +x, +y and +z faces of a box


def box() -> Tuple[np.ndarray, np.ndarray]:
    """A unit cube about the origin: 8 shared vertices, 12 outward triangles."""
    V = np.array([[i & 1, (i >> 1) & 1, (i >> 2) & 1] for i in range(8)], float) - 0.5
    quads = [[0, 2, 3, 1], [4, 5, 7, 6], [0, 1, 5, 4], [2, 6, 7, 3], [0, 4, 6, 2], [1, 3, 7, 5]]
    return V, np.array([t for q in quads for t in ([q[0], q[1], q[2]], [q[0], q[2], q[3]])])


def cylinder(segments: int = 48, rows: int = 4) -> Tuple[np.ndarray, np.ndarray]:
    """A closed cylinder: a side of `rows` rows between two flat caps (fans from the poles)."""
    side = [(0.5, y) for y in np.linspace(-0.5, 0.5, rows + 1)]
    return tm.shapes.lathe([(0.0, -0.5), *side, (0.0, 0.5)], segments=segments)


def shade(V: np.ndarray, F: np.ndarray, normals: Any, camera: tm.Camera = CAMERA) -> tm.RenderResult:
    return tm.render(V, F, normals=normals, camera=camera, width=SIZE, height=SIZE, outputs=("color", "normal"),
                     material=tm.Material.bands())


def inner(mask: np.ndarray, steps: int = 2) -> np.ndarray:
    """`mask` eroded by `steps` pixels (4-neighbourhood): away from edges and the silhouette."""
    m = mask.copy()
    for _ in range(steps):
        m[1:] &= m[:-1].copy()
        m[:-1] &= m[1:].copy()
        m[:, 1:] &= m[:, :-1].copy()
        m[:, :-1] &= m[:, 1:].copy()
    return m


def faces_seen(flat: tm.RenderResult) -> list:
    """One pixel mask per visible face of a flat-shaded render, found by its normal."""
    n = flat.normal.reshape(-1, 3)
    seen = n[np.any(n != 0, axis=1)]
    directions = np.unique(np.round(seen, 3), axis=0)
    return [np.all(np.abs(flat.normal - d) < 2e-3, axis=-1) for d in directions]


def colours(image: np.ndarray, mask: np.ndarray) -> int:
    return len(np.unique(image[mask].reshape(-1, 4), axis=0))


def test_a_cube_shades_one_band_a_face_with_auto_and_not_with_smooth():
    V, F = box()
    flat, auto, smooth = (shade(V, F, n) for n in ("flat", "auto", "smooth"))
    masks = faces_seen(flat)
    assert len(masks) == 3
    for m in masks:
        core = inner(m)
        assert core.sum() > 200
        assert colours(auto.color, core) == 1, "each face one band"
    assert max(colours(smooth.color, inner(m)) for m in masks) >= 2, "smooth bends the bands across the corners"
    # the split normals are the faces' own: the same normal image as flat shading
    covered = np.any(flat.normal != 0, axis=-1)
    assert np.array_equal(covered, np.any(auto.normal != 0, axis=-1))
    assert np.abs(auto.normal - flat.normal).max() < 1e-5


def test_a_smooth_sphere_and_torus_shade_as_smooth_bit_for_bit():
    for V, F in (tm.shapes.icosphere(3), tm.shapes.icosphere(2, noise=0.005, seed=4),
                 tm.shapes.torus(segments=64, tube_segments=32)):
        smooth, auto = shade(V, F, "smooth"), shade(V, F, "auto")
        assert np.array_equal(smooth.color, auto.color)
        assert np.array_equal(smooth.normal, auto.normal)


def test_a_cylinder_keeps_smooth_sides_and_flat_caps():
    V, F = cylinder()
    camera = tm.Camera.fit((0.3, 0.8, 1.0))  # sees the top cap and the side
    flat, auto, smooth = (shade(V, F, n, camera) for n in ("flat", "auto", "smooth"))
    up = flat.view_matrix[:3, :3] @ np.array([0.0, 1.0, 0.0])  # world +y in view space
    cap = np.abs(flat.normal @ up - 1.0) < 1e-4
    side = np.any(flat.normal != 0, axis=-1) & (np.abs(flat.normal @ up) < 1e-4)
    assert inner(cap).sum() > 300 and inner(side).sum() > 300
    # caps: one flat normal; smooth shading tilts it toward the rim
    assert np.abs(auto.normal[cap] - up).max() < 1e-4
    assert np.abs(smooth.normal[cap] @ up).min() < 0.9
    # sides: horizontal normals (the cap's normal does not leak in), interpolated as smoothly
    # as by smooth shading: the same normals where its rows do not touch a cap
    assert np.abs(auto.normal[side] @ up).max() < 1e-4
    middle = side & (np.abs(smooth.normal @ up) < 1e-6)
    assert middle.sum() > 300
    assert np.abs(auto.normal[middle] - smooth.normal[middle]).max() < 1e-6
    distinct = lambda r: len(np.unique(np.round(r.normal[side], 3), axis=0))  # noqa: E731
    assert distinct(auto) > 5 * distinct(flat), "not faceted"


def test_the_crease_angle_decides_what_splits():
    V, F = box()
    smooth = shade(V, F, "smooth")
    # the cube's edges are 90 degrees: above that nothing splits, so the upload is the smooth one
    assert np.array_equal(shade(V, F, ("auto", 91)).color, smooth.color)
    assert np.array_equal(shade(V, F, ("auto", 89)).color, shade(V, F, "auto").color)
    # the icosahedron's faces meet at 41.8 degrees: split at 30, smooth at 45
    V, F = tm.shapes.icosphere(0)
    assert np.array_equal(shade(V, F, ("auto", 30)).normal, shade(V, F, "flat").normal)
    assert np.array_equal(shade(V, F, ("auto", 45)).normal, shade(V, F, "smooth").normal)


def test_the_bunny_keeps_smooth_normals_by_default():
    """The default stays "smooth": the scanned bunny has 1,355 edges sharper than 30 degrees
    (noise and thin ears), and "auto" moves band edges along them."""
    V, F = bunny()
    default = tm.render(V, F, width=SIZE, height=SIZE, camera=CAMERA, outputs=("color", "normal"))
    smooth, auto = shade(V, F, "smooth"), shade(V, F, "auto")
    assert np.array_equal(default.color, smooth.color)
    covered = np.any(smooth.normal != 0, axis=-1)
    changed = np.any(smooth.color != auto.color, axis=-1)[covered].mean()
    assert 0.0 < changed < 0.05


def test_degenerate_faces_and_nonmanifold_edges_stay_finite():
    V, F = box()
    # a point on edge 0-1, a fin on the same edge (non-manifold), an unused vertex
    V = np.vstack([V, [[0.0, -0.5, -0.5], [0.0, -1.0, -1.2], [9.0, 9.0, 9.0]]])
    F = np.vstack([F, [[0, 0, 1], [0, 8, 1], [0, 1, 9], [1, 0, 9], [2, 2, 2]]])
    for normals in ("auto", ("auto", 0), ("auto", 180), "smooth", "flat"):
        r = tm.render(V, F, normals=normals, camera=CAMERA, width=64, height=64, outputs=("color", "normal", "depth"))
        assert np.isfinite(r.normal).all(), normals
        assert np.all(np.isfinite(r.depth) | (r.depth == np.inf)), normals
        assert np.any(r.normal != 0)


def test_a_degenerate_only_mesh_stays_finite():
    V = np.array([[0.0, 0, 0], [1, 0, 0], [2, 0, 0], [0, 1, 0]])
    r = tm.render(V, np.array([[0, 1, 2], [3, 3, 3]]), normals="auto", width=16, height=16, outputs=("color", "normal"))
    assert np.isfinite(r.normal).all()


def test_normals_is_kept_in_its_shortest_spelling():
    V, F = box()
    assert tm.Mesh(V, F, normals=("auto", 30)).normals == "auto"
    assert tm.Mesh(V, F, normals=("auto", np.float32(45))).normals == ("auto", 45.0)
    assert tm.Mesh(V, F).normals == "smooth"
    r = tm.Renderer()
    h = r.add_mesh(V, F, normals=("auto", 10))
    try:
        assert h.normals == ("auto", 10.0) and "('auto', 10.0)" in repr(h)
    finally:
        r.remove_mesh(h)


@pytest.mark.parametrize(
    "value, error",
    [
        ("sharp", ValueError),
        ("Auto", ValueError),
        (("smooth", 30), ValueError),
        (("auto", -1), ValueError),
        (("auto", 180.5), ValueError),
        (("auto", math.nan), ValueError),
        (("auto", math.inf), ValueError),
        (("auto", "45"), TypeError),
        (("auto", True), TypeError),
        (("auto",), TypeError),
        (["auto", 45], TypeError),
        (b"auto", TypeError),
        (None, TypeError),
        (30, TypeError),
    ],
)
def test_bad_normals_are_refused_naming_the_argument(value, error):
    V, F = box()
    r = tm.Renderer()
    for call in (lambda: tm.Mesh(V, F, normals=value), lambda: r.add_mesh(V, F, normals=value),
                 lambda: tm.render(V, F, normals=value, width=8, height=8)):
        with pytest.raises(error, match="^normals: "):
            call()
    assert r._engine.mesh_count == 0  # nothing was uploaded


def test_the_command_line_passes_normals_through(tmp_path, capsys, monkeypatch):
    trimesh = need("trimesh")
    from toonmesh.cli import main
    from toonmesh.data import load_obj

    monkeypatch.chdir(tmp_path)
    trimesh.Trimesh(*box(), process=False).export(str(tmp_path / "cube.obj"))
    V, F = load_obj(tmp_path / "cube.obj")  # what the command reads
    for flag, normals in (("auto", "auto"), ("auto:95", ("auto", 95.0)), ("flat", "flat")):
        assert main(["render", "cube.obj", "-o", "c.npz", "--size", "48x40", "--outputs", "color,normal",
                     "--normals", flag]) == 0
        expected = tm.render(V, F, normals=normals, width=48, height=40, outputs=("color", "normal"))
        with np.load(tmp_path / "c.npz") as z:
            assert np.array_equal(z["normal"], expected.normal), flag
    capsys.readouterr()
    # a value the core refuses is a usage error naming the flag, with argparse's status
    assert main(["render", "cube.obj", "-o", "x.png", "--normals", "auto:200"]) == 2
    err = capsys.readouterr().err
    assert "normals" in err and "180" in err and len(err.splitlines()) == 1

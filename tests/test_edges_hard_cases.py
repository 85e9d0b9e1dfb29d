"""Hard cases for the outline rules: angles near 0 and 180 degrees, zero-area faces, UV-seam
duplicates, grazing views with many faces edge-on, and an eye placed on the surface."""

import numpy as np
import pytest
from conftest_edges import MESHES, is_sorted_unique, need, oracle, rows

import toonmesh as tm
from toonmesh import edges as te


def hinge(fold_degrees):
    """Two triangles on edge 0-1 (the x axis); the second is folded down by ``fold_degrees``."""
    t = np.radians(fold_degrees)
    V = np.array([[0, 0, 0], [1, 0, 0], [0.5, 1, 0], [0.5, -np.cos(t), -np.sin(t)]], dtype=np.float64)
    return V, np.array([[0, 1, 2], [1, 0, 3]])


@pytest.mark.parametrize("fold", [1e-7, 1e-4, 0.01, 1.0, 45.0, 90.0, 135.0, 179.0, 179.99, 180 - 1e-4, 180 - 1e-7])
def test_crease_angle_precise_near_0_and_180(fold):
    V, F = hinge(fold)
    fe = te.feature_edges(V, F, crease_angle=0.0)
    assert fe.crease.tolist() == [[0, 1]]
    # atan2(|n1 x n2|, n1 . n2) keeps about 1e-15 relative precision at both ends; acos(n1 . n2)
    # would be off by ~1e-6 degrees near 0 and 180
    assert fe.crease_angles[0] == pytest.approx(fold, rel=1e-8, abs=1e-12)
    assert fe.crease_convex[0]  # folding down is a ridge
    Vu, Fu = hinge(-fold)
    assert not te.feature_edges(Vu, Fu, crease_angle=0.0).crease_convex[0]  # folding up: a valley
    # the threshold is strict and exact for angles a hair either side of it
    assert len(te.feature_edges(V, F, crease_angle=fold * (1 - 1e-6)).crease) == 1
    assert len(te.feature_edges(V, F, crease_angle=min(180.0, fold * (1 + 1e-6))).crease) == 0


def test_coplanar_faces_are_never_creases():
    V, F = tm.shapes.grid(20)
    for angle in (0.0, 1e-9, 30.0):
        assert len(te.feature_edges(V, F, crease_angle=angle).crease) == 0


def test_zero_area_faces_never_create_or_hide_creases_at_random():
    trimesh = need("trimesh")
    V, F = tm.shapes.grid(6)
    V = V.copy()
    # add a zero-area face on the grid edge 0-1 (three collinear points) and a repeated index
    n = len(V)
    V = np.vstack([V, [[0.1, 0.0, 0.0], [0.3, 0.0, 0.0]]])
    F = np.vstack([F, [[0, 1, n], [1, 1, 7]]])
    fe = te.feature_edges(V, F, crease_angle=30.0)
    assert fe.degenerate_faces.tolist() == [len(F) - 2, len(F) - 1]
    assert len(fe.crease) == 0
    # trimesh gives the zero-area face a zero normal, i.e. 90 degrees to its neighbours
    mesh = trimesh.Trimesh(V, F, process=False)
    assert np.any(np.isclose(mesh.face_adjacency_angles, np.pi / 2))
    # the same answer for float32 and on repeated calls, and no silhouettes through them
    fe32 = te.feature_edges(V.astype(np.float32), F, crease_angle=30.0)
    assert np.array_equal(fe32.degenerate_faces, fe.degenerate_faces)
    assert len(te.silhouette(V, F, eye=(0.5, 0.5, 2.0))) == 0


def test_degenerate_face_on_a_real_crease_is_reported_not_guessed():
    # a folded strip where one face on the fold has collapsed to zero area: the fold edges next
    # to it are not creases (no normal), the rest of the fold is, every time
    V = np.array(
        [[0, 0, 0], [1, 0, 0], [2, 0, 0], [0, 1, 0], [1, 1, 0], [2, 1, 0], [0, 0, -1], [1, 0, -1], [2, 0, -1]],
        dtype=np.float64,
    )
    F = np.array(
        [[0, 1, 4], [0, 4, 3], [1, 2, 5], [1, 5, 4], [1, 0, 6], [1, 6, 7], [2, 1, 7], [2, 7, 8]], dtype=np.int64
    )
    base = te.feature_edges(V, F, crease_angle=30.0)
    assert rows(base.crease) == {(0, 1), (1, 2)}
    V2 = V.copy()
    V2[4] = [0.5, 0, 0]  # face [0, 1, 4] collapses onto the fold line
    for _ in range(3):
        fe = te.feature_edges(V2, F, crease_angle=30.0)
        assert 0 in fe.degenerate_faces
        assert (0, 1) not in rows(fe.crease)


def test_uv_seam_duplicates_show_as_boundaries_and_weld_removes_them():
    trimesh = need("trimesh")
    mesh = trimesh.load(MESHES / "spot.obj", process=False, force="mesh")
    plain = te.feature_edges(mesh)
    welded = te.feature_edges(mesh, weld=True)
    assert len(plain.boundary) > 0 and len(welded.boundary) == 0
    # welding is exact: the merged mesh's feature edges, in original indices
    merged = trimesh.Trimesh(mesh.vertices, mesh.faces, process=False)
    merged.merge_vertices(digits_vertex=15, merge_tex=True, merge_norm=True)
    assert len(te.feature_edges(merged).boundary) == 0
    index = te.EdgeIndex(mesh, weld=True)
    assert len(index.boundary) == 0
    s = index.silhouette(eye=(2, 1, 3))
    assert len(s) > 0 and is_sorted_unique(s)
    # every silhouette vertex is the representative (smallest index) of its position
    reps = {}
    for i, p in enumerate(map(tuple, mesh.vertices.tolist())):
        reps.setdefault(p, i)
    assert all(reps[tuple(mesh.vertices[v].tolist())] == v for v in np.unique(s))


def test_split_sphere_seam():
    V, F = tm.shapes.icosphere(3)
    # duplicate the vertices with x > 0, y ~ 0 and let faces on one side use the copies
    seam = np.flatnonzero((np.abs(V[:, 1]) < 1e-9) & (V[:, 0] > 0))
    copy = {v: len(V) + k for k, v in enumerate(seam)}
    V2 = np.vstack([V, V[seam]])
    F2 = F.copy()
    side = V[F].mean(axis=1)[:, 1] > 0
    for f in np.flatnonzero(side):
        F2[f] = [copy.get(v, v) for v in F2[f]]
    assert len(te.feature_edges(V2, F2).boundary) > 0
    assert len(te.feature_edges(V2, F2, weld=True).boundary) == 0
    assert np.array_equal(te.silhouette(V2, F2, eye=(0, 0, 4), weld=True), te.silhouette(V, F, eye=(0, 0, 4)))


def test_grazing_view_of_a_flat_grid():
    V, F = tm.shapes.grid(30)
    # in the plane: every face edge-on, so every face is back-facing and there is no silhouette
    assert len(te.silhouette(V, F, eye=(0.5, -3.0, 0.0))) == 0
    assert len(te.silhouette(V, F, direction=(0.0, 1.0, 0.0))) == 0
    # a hair above the plane: every face faces the eye, still no silhouette
    assert len(te.silhouette(V, F, eye=(0.5, -3.0, 1e-12))) == 0
    # a noisy grid at a grazing angle: many faces nearly edge-on, the rule still matches
    Vn, Fn = tm._core.grid(40, 1e-4, 3)
    for view in (dict(eye=(0.5, -5.0, 1e-4)), dict(direction=(0.0, 1.0, -1e-5)), dict(eye=(-3.0, 0.2, 0.0))):
        expected, close = oracle(Vn, Fn, **view)
        got = rows(te.silhouette(Vn, Fn, **view))
        assert got - close == expected - close
        assert len(got) > 20


def test_cube_seen_along_an_axis():
    # side faces exactly edge-on count as back-facing: the silhouette is the front square
    V = np.array(
        [[0, 0, 0], [1, 0, 0], [1, 1, 0], [0, 1, 0], [0, 0, 1], [1, 0, 1], [1, 1, 1], [0, 1, 1]], dtype=np.float64
    )
    F = np.array(
        [
            [0, 2, 1], [0, 3, 2], [4, 5, 6], [4, 6, 7], [0, 1, 5], [0, 5, 4],
            [1, 2, 6], [1, 6, 5], [2, 3, 7], [2, 7, 6], [3, 0, 4], [3, 4, 7],
        ]
    )  # fmt: skip
    front_square = {(4, 5), (5, 6), (6, 7), (4, 7)}
    assert rows(te.silhouette(V, F, direction=(0, 0, -1))) == front_square
    assert rows(te.silhouette(V, F, eye=(0.5, 0.5, 5.0))) == front_square
    fe = te.feature_edges(V, F, crease_angle=45.0)
    assert len(fe.crease) == 12 and np.all(fe.crease_convex) and np.allclose(fe.crease_angles, 90.0)


@pytest.mark.parametrize("where", ["vertex", "face", "edge"])
def test_eye_on_the_surface(where):
    V, F = tm._core.icosphere(3, 0.01, 4)
    if where == "vertex":
        eye = V[17]
    elif where == "face":
        eye = V[F[40]].mean(axis=0)
    else:
        eye = V[F[40, :2]].mean(axis=0)
    eye = tuple(eye)
    got = te.silhouette(V, F, eye=eye)
    expected, close = oracle(V, F, eye=eye)
    assert rows(got) - close == expected - close
    assert np.array_equal(got, te.EdgeIndex(V, F).silhouette(eye=eye))
    # from on (or just inside) a convex surface every face is back-facing or edge-on
    assert is_sorted_unique(got)


def test_trimesh_input_and_float32():
    trimesh = need("trimesh")
    mesh = trimesh.load(MESHES / "fandisk.obj", process=False, force="mesh")
    before = mesh.vertices.copy()
    a = te.feature_edges(mesh)
    b = te.feature_edges(np.asarray(mesh.vertices), np.asarray(mesh.faces))
    assert np.array_equal(a.crease, b.crease)
    assert np.array_equal(mesh.vertices, before)
    s64 = rows(te.silhouette(mesh, eye=(1, 2, 3)))
    s32 = rows(te.silhouette(mesh.vertices.astype(np.float32), mesh.faces, eye=(1, 2, 3)))
    assert len(s64 ^ s32) <= 0.01 * len(s64)

"""The meshes made in code (toonmesh.shapes): Kang, Kim and Yoon's test models with the paper's
face counts, closed where they should be, consistently oriented and facing outward, with no
degenerate faces; lathe's rules."""

from __future__ import annotations

import numpy as np
import pytest
from scipy.sparse import coo_matrix
from scipy.sparse.csgraph import connected_components

import toonmesh as tm
from toonmesh import edges

# name: (mesh, the paper's face count)
KANG_MODELS = {
    "donut": (tm.shapes.torus(), 450),
    "chess piece": (tm.shapes.pawn(), 480),
    "teapot": (tm.shapes.teapot(), 1024),
    "sphere": (tm.shapes.uv_sphere(), 264),
}


def edge_faces(F):
    """Each undirected edge's number of faces, and how often each directed edge occurs."""
    directed = np.concatenate([F[:, [0, 1]], F[:, [1, 2]], F[:, [2, 0]]])
    _, per_edge = np.unique(np.sort(directed, axis=1), axis=0, return_counts=True)
    _, per_directed = np.unique(directed, axis=0, return_counts=True)
    return per_edge, per_directed


def outward_measure(V, F):
    """Six times the signed volume of the cones from the vertices' mean: the volume for a closed
    surface, and positive for an open part whose faces face away from its middle."""
    c = V[np.unique(F)].mean(axis=0)
    p = V[F] - c
    return np.einsum("ij,ij->", p[:, 0], np.cross(p[:, 1], p[:, 2]))


def parts(V, F):
    """The faces of each connected part (parts sharing only a vertex count as one)."""
    n = len(V)
    adjacency = coo_matrix((np.ones(2 * len(F)), (np.repeat(F[:, 0], 2), F[:, 1:].ravel())), shape=(n, n))
    _, label = connected_components(adjacency, directed=False)
    return [F[label[F[:, 0]] == k] for k in np.unique(label[F[:, 0]])]


@pytest.mark.parametrize("name", list(KANG_MODELS))
def test_kang_models_have_the_papers_face_counts_and_clean_faces(name):
    (V, F), paper_faces = KANG_MODELS[name]
    assert V.dtype == np.float64 and F.dtype == np.int64 and V.shape[1] == 3 and F.shape[1] == 3
    assert abs(len(F) - paper_faces) <= 0.035 * paper_faces  # the teapot: 992 of its 1024 triangles
    assert len(np.unique(F)) == len(V), "every vertex is used"
    fe = edges.feature_edges(V, F)
    assert len(fe.degenerate_faces) == 0 and len(fe.nonmanifold) == 0
    normals = np.cross(V[F[:, 1]] - V[F[:, 0]], V[F[:, 2]] - V[F[:, 0]])
    assert np.isfinite(normals / np.linalg.norm(normals, axis=1, keepdims=True)).all()


@pytest.mark.parametrize("name", ["donut", "chess piece", "sphere"])
def test_the_closed_models_are_closed_and_face_outward(name):
    (V, F), _ = KANG_MODELS[name]
    per_edge, per_directed = edge_faces(F)
    assert (per_edge == 2).all(), "every edge has two faces"
    assert (per_directed == 1).all(), "each edge is walked both ways: consistently oriented"
    assert outward_measure(V, F) > 0


def test_closed_models_enclose_the_volume_of_their_shape():
    V, F = tm.shapes.torus(2.0, 0.5, segments=200, tube_segments=100)
    assert outward_measure(V, F) / 6 == pytest.approx(2 * np.pi**2 * 2.0 * 0.5**2, rel=1e-3)
    V, F = tm.shapes.uv_sphere(200, 100)
    assert outward_measure(V, F) / 6 == pytest.approx(4 / 3 * np.pi, rel=1e-3)
    assert np.linalg.norm(V, axis=1) == pytest.approx(1.0)


@pytest.mark.parametrize("n", [2, 3, 4, 7])
def test_the_teapot_is_its_patches_welded_each_part_oriented_outward(n):
    V, F = tm.shapes.teapot(n)
    assert len(F) == 64 * n * n - 8 * n
    per_edge, per_directed = edge_faces(F)
    assert per_edge.max() == 2 and (per_directed == 1).all()
    # Open only where Newell's surface is: the lid's and the rim's circles, both ends of the
    # spout and of the handle, 4 patches each, n edges a patch.
    assert (per_edge == 1).sum() == 4 * 4 * n
    pieces = parts(V, F)
    assert len(pieces) == 3  # body with handle (they share a point), lid, spout
    assert all(outward_measure(V, part) > 0 for part in pieces)
    lo, hi = V.min(axis=0), V.max(axis=0)
    assert lo[1] == pytest.approx(0.0) and hi[1] == pytest.approx(3.15)
    assert hi[0] > -lo[0], "the spout points toward +x"


def test_lathe_poles_close_the_ends_and_the_profile_direction_sets_the_facing():
    profile = [(0.0, 0.0), (1.0, 0.0), (1.0, 1.0), (0.0, 1.0)]  # a closed cylinder
    V, F = tm.shapes.lathe(profile, segments=16)
    assert len(V) == 2 * 16 + 2 and len(F) == 16 + 2 * 16 + 16
    per_edge, _ = edge_faces(F)
    assert (per_edge == 2).all()
    assert outward_measure(V, F) > 0
    V2, F2 = tm.shapes.lathe(profile[::-1], segments=16)
    assert outward_measure(V2, F2) < 0
    V3, F3 = tm.shapes.lathe(profile[1:3], segments=16)  # a tube, open at both ends
    per_edge, _ = edge_faces(F3)
    assert (per_edge == 1).sum() == 2 * 16 and len(F3) == 2 * 16


@pytest.mark.parametrize("segments", [3, 24, 100])
def test_pawn_and_sphere_counts_follow_their_formulas(segments):
    V, F = tm.shapes.pawn(segments)
    assert (len(V), len(F)) == (10 * segments + 2, 20 * segments)
    V, F = tm.shapes.uv_sphere(segments, 7)
    assert (len(V), len(F)) == (segments * 6 + 2, 2 * segments * 6)
    V, F = tm.shapes.torus(segments=segments, tube_segments=5)
    assert (len(V), len(F)) == (5 * segments, 10 * segments)


def test_shapes_render():
    """The models render as they are: the uploaded meshes draw something in every view."""
    r = tm.Renderer()
    for (V, F), _ in KANG_MODELS.values():
        res = r.render(r.add_mesh(V, F), width=32, height=32, outputs=("color", "depth"))
        assert np.isfinite(res.depth).mean() > 0.1


def test_a_box_spans_its_corners_closed_and_facing_outward():
    lo, hi = (-1.0, 0.0, -2.0), (3.0, 0.5, 2.0)
    V, F = tm.shapes.box(lo, hi)
    assert V.dtype == np.float64 and V.shape == (8, 3) and F.dtype == np.int64 and F.shape == (12, 3)
    np.testing.assert_array_equal(V.min(axis=0), lo)
    np.testing.assert_array_equal(V.max(axis=0), hi)
    per_edge, per_directed = edge_faces(F)
    assert (per_edge == 2).all() and (per_directed == 1).all()
    assert outward_measure(V, F) / 6 == pytest.approx(4.0 * 0.5 * 4.0)
    V, _ = tm.shapes.box()
    np.testing.assert_array_equal(np.abs(V), 0.5)  # the unit cube about the origin


@pytest.mark.parametrize("lo, hi, error, words", [
    ((0, 0), (1, 1, 1), TypeError, "lo: expected 3 numbers"),
    ((0, 0, 0), "abc", TypeError, "hi: expected 3 numbers"),
    ((0, 0, np.nan), (1, 1, 1), ValueError, "lo: must be finite"),
    ((0, 0, 0), (1, 0, 1), ValueError, "hi: must exceed lo on every axis"),
])
def test_a_box_names_a_bad_corner(lo, hi, error, words):
    with pytest.raises(error) as caught:
        tm.shapes.box(lo, hi)
    assert words in str(caught.value)

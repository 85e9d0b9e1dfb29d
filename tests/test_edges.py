"""Mesh-space outlines cross-validated against trimesh and a brute-force NumPy oracle."""

import numpy as np
import pytest
from conftest_edges import is_sorted_unique, load, need, normals_and_degenerate, oracle, random_views, rotation, rows

import toonmesh as tm
from toonmesh import edges as te

# ---------------------------------------------------------------------------------------------
# feature edges vs trimesh


@pytest.mark.parametrize("name", ["stanford-bunny.obj", "teapot.obj", "fandisk.obj", "rocker-arm.obj", "suzanne.obj"])
def test_boundary_matches_trimesh(name):
    trimesh = need("trimesh")
    mesh = load(name)
    fe = te.feature_edges(mesh)
    es = mesh.edges_sorted
    expected = es[trimesh.grouping.group_rows(es, require_count=1)]
    expected = expected[expected[:, 0] != expected[:, 1]]  # toonmesh has no self-edges a-a
    assert rows(fe.boundary) == rows(expected)
    assert is_sorted_unique(fe.boundary)
    if name in ("stanford-bunny.obj", "teapot.obj"):
        assert len(fe.boundary) > 0


@pytest.mark.parametrize("name", ["fandisk.obj", "rocker-arm.obj"])
@pytest.mark.parametrize("angle", [10.0, 30.0, 60.0])
@pytest.mark.parametrize("seed", [None, 1, 2])
def test_creases_match_trimesh(name, angle, seed):
    trimesh = need("trimesh")
    mesh = load(name)
    if seed is not None:
        mesh = trimesh.Trimesh(mesh.vertices @ rotation(seed).T, mesh.faces, process=False)
    fe = te.feature_edges(mesh.vertices, mesh.faces, crease_angle=angle)
    theta = np.radians(angle)
    adj_angles = mesh.face_adjacency_angles
    adj_edges = np.sort(mesh.face_adjacency_edges, axis=1)
    _, degenerate = normals_and_degenerate(mesh.vertices, mesh.faces)
    usable = ~degenerate[mesh.face_adjacency].any(axis=1)
    margin = np.radians(1e-4)
    near = np.abs(adj_angles - theta) < margin
    expected = rows(adj_edges[usable & (adj_angles > theta) & ~near])
    ambiguous = rows(adj_edges[near])
    got = rows(fe.crease) - ambiguous
    assert got == expected
    assert len(expected) > 0
    assert is_sorted_unique(fe.crease)
    # the reported angles agree with trimesh's to well within the margin
    lookup = {e: a for e, a in zip(map(tuple, adj_edges.tolist()), adj_angles)}
    ours = np.radians(fe.crease_angles)
    theirs = np.array([lookup[tuple(e)] for e in fe.crease.tolist()])
    assert np.max(np.abs(ours - theirs)) < 1e-6
    assert np.all(fe.crease_angles > angle)


def test_fandisk_has_ridges_and_valleys():
    fe = te.feature_edges(load("fandisk.obj"), crease_angle=30.0)
    assert len(fe.ridge) > 0 and len(fe.valley) > 0
    assert len(fe.ridge) + len(fe.valley) == len(fe.crease)


def test_nonmanifold_edge_of_suzanne():
    mesh = load("suzanne.obj")
    fe = te.feature_edges(mesh)
    uniq, counts = np.unique(mesh.edges_sorted, axis=0, return_counts=True)
    expected = uniq[(counts >= 3) & (uniq[:, 0] != uniq[:, 1])]
    assert len(expected) >= 1
    assert rows(fe.nonmanifold) == rows(expected)
    assert not rows(fe.nonmanifold) & rows(fe.crease)


def test_float32_and_int32_inputs_agree():
    mesh = load("fandisk.obj")
    a = te.feature_edges(mesh.vertices, mesh.faces)
    b = te.feature_edges(mesh.vertices.astype(np.float32), mesh.faces.astype(np.int32))
    assert rows(a.boundary) == rows(b.boundary)
    assert len(rows(a.crease) ^ rows(b.crease)) <= 2  # only edges within float32 rounding of 30 degrees


def test_inputs_not_modified_and_any_memory_order():
    V, F = tm._core.icosphere(2, 0.05, 3)
    V2, F2 = np.asfortranarray(V), np.asfortranarray(F)
    Vc, Fc = V.copy(), F.copy()
    a = te.feature_edges(V, F, crease_angle=5.0)
    b = te.feature_edges(V2, F2, crease_angle=5.0)
    assert np.array_equal(a.crease, b.crease) and np.array_equal(V, Vc) and np.array_equal(F, Fc)
    assert len(a.crease) > 0


def test_bad_input_names_the_argument():
    V, F = tm.shapes.icosphere(1)
    with pytest.raises(ValueError, match="crease_angle"):
        te.feature_edges(V, F, crease_angle=200)
    with pytest.raises(IndexError, match="faces"):
        te.feature_edges(V, F + len(V))
    with pytest.raises(ValueError, match="vertices"):
        te.feature_edges(V[:, :2], F)
    with pytest.raises(TypeError, match="vertices"):
        te.feature_edges(V.astype(np.int32), F)
    bad = V.copy()
    bad[0, 0] = np.nan
    with pytest.raises(ValueError, match="vertices"):
        te.silhouette(bad, F, eye=(0, 0, 3))
    with pytest.raises(ValueError, match="eye"):
        te.silhouette(V, F)
    with pytest.raises(ValueError, match="eye"):
        te.silhouette(V, F, eye=(0, 0, 1), direction=(0, 0, 1))
    with pytest.raises(ValueError, match="direction"):
        te.silhouette(V, F, direction=(0, 0, 0))
    with pytest.raises(ValueError, match="eye"):
        te.silhouette(V, F, eye=(0, np.inf, 0))


# ---------------------------------------------------------------------------------------------
# silhouettes vs a brute-force oracle

@pytest.mark.parametrize("name", ["stanford-bunny.obj", "teapot.obj", "fandisk.obj", "suzanne.obj", "cow.obj"])
def test_silhouette_matches_oracle(name):
    mesh = load(name)
    V, F = np.asarray(mesh.vertices), np.asarray(mesh.faces)
    rng = np.random.default_rng(hash(name) % 2**32)
    index = te.EdgeIndex(V, F)
    for view in random_views(rng, V, 3):
        expected, close = oracle(V, F, **view)
        got = index.silhouette(**view)
        assert is_sorted_unique(got)
        assert rows(got) - close == expected - close, view
        assert np.array_equal(got, te.silhouette(V, F, **view))
        assert len(expected) > 0


@pytest.mark.parametrize("seed", [0, 1, 2])
def test_silhouette_random_rotations_float32(seed):
    V, F = tm._core.icosphere(4, 0.02, seed)
    V = (V @ rotation(seed).T).astype(np.float32)
    index = te.EdgeIndex(V, F)
    rng = np.random.default_rng(seed)
    for view in random_views(rng, V.astype(np.float64), 4):
        expected, close = oracle(V, F, **view)
        got = rows(index.silhouette(**view))
        assert got - close == expected - close


def test_edge_index_is_immutable_and_thread_safe():
    from concurrent.futures import ThreadPoolExecutor

    V, F = tm._core.icosphere(4, 0.01, 5)
    index = te.EdgeIndex(V, F)
    eyes = [(np.cos(t) * 4, np.sin(t) * 4, 0.5) for t in np.linspace(0, 2 * np.pi, 16)]
    serial = [index.silhouette(eye=e) for e in eyes]
    with ThreadPoolExecutor(4) as pool:
        parallel = list(pool.map(lambda e: index.silhouette(eye=e), eyes))
    assert all(np.array_equal(a, b) for a, b in zip(serial, parallel))
    V[:] = 0  # the index copied the input
    assert np.array_equal(index.silhouette(eye=eyes[0]), serial[0])
    with pytest.raises(ValueError):
        index.vertices[0, 0] = 1.0


def test_results_independent_of_thread_count():
    V, F = tm._core.icosphere(5, 0.02, 9)
    try:
        out = []
        for n in (1, 2, 3):
            tm.set_num_threads(n)
            fe = te.feature_edges(V, F, crease_angle=3.0)
            out.append((fe.crease, fe.crease_angles, te.silhouette(V, F, eye=(1, 2, 3))))
        for o in out[1:]:
            assert all(np.array_equal(a, b) for a, b in zip(o, out[0]))
    finally:
        tm.set_num_threads(0)


# ---------------------------------------------------------------------------------------------
# chains and segments


def test_chains_cover_every_edge_once():
    mesh = load("teapot.obj")
    fe = te.feature_edges(mesh)
    polylines = te.chains(fe.boundary)
    assert sum(len(c) - 1 for c in polylines) == len(fe.boundary)
    walked = set()
    for c in polylines:
        assert c.dtype == np.int64
        walked |= rows(np.stack([c[:-1], c[1:]], axis=1))
    assert walked == rows(fe.boundary)
    sil = te.silhouette(mesh, eye=(3, 2, 5))
    assert sum(len(c) - 1 for c in te.chains(sil)) == len(sil)
    assert te.chains(np.zeros((0, 2), dtype=np.int64)) == []


def test_segments_shape_and_dtype():
    V, F = tm.shapes.icosphere(2)
    e = te.silhouette(V, F, direction=(0, 0, 1))
    seg = te.segments(V, e)
    assert seg.shape == (len(e), 2, 3) and seg.dtype == np.float64
    assert np.array_equal(seg[:, 0], V[e[:, 0]])
    assert te.segments(V.astype(np.float32), e).dtype == np.float32
    with pytest.raises(IndexError):
        te.segments(V, [[0, len(V)]])
    index = te.EdgeIndex(V, F)
    assert np.array_equal(index.segments(e), seg)


def test_outlines_union():
    mesh = load("fandisk.obj")
    index = te.EdgeIndex(mesh, crease_angle=40.0)
    out = index.outlines(eye=(0, 0, 10))
    assert is_sorted_unique(out)
    assert rows(out) == rows(index.silhouette(eye=(0, 0, 10))) | rows(index.crease) | rows(index.boundary)
    assert np.array_equal(index.feature_edges(40.0).crease, te.feature_edges(mesh, crease_angle=40.0).crease)


def test_outlines_union_matches_row_unique_on_open_and_closed_meshes():
    V, F = tm._core.icosphere(4, 0.03, 2)
    open_F = F[: len(F) // 2]  # half a sphere: a boundary loop, creases and silhouettes overlap
    for faces in (F, open_F):
        index = te.EdgeIndex(V, faces, crease_angle=10.0)
        for eye in [(0, 0, 5), (3, -2, 1), (0, 0, 0.1)]:
            sil = index.silhouette(eye=eye)
            ref = np.unique(np.concatenate([sil, index.boundary, index.crease, index.nonmanifold]), axis=0)
            out = index.outlines(eye=eye)
            assert out.dtype == np.int64 and np.array_equal(out, ref)
        assert np.array_equal(index.features.outlines, np.unique(
            np.concatenate([index.boundary, index.crease, index.nonmanifold]), axis=0))
    # No feature edges at all.
    empty = te.FeatureEdges(*(np.zeros((0, 2), np.int64) for _ in range(2)), np.zeros(0), np.zeros(0, bool),
                            np.zeros((0, 2), np.int64), np.zeros(0, np.int64), 30.0)
    assert empty.outlines.shape == (0, 2) and empty.outlines.dtype == np.int64

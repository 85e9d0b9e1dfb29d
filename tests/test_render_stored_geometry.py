"""Geometry as files store it, drawn as the surface it describes: a sheet stored double-sided
(each face twice, back to back), a part stored as many separate pieces (triangle strips split
apart, one mesh each), and a pole stored as a row of copies of one vertex (its faces collapsed
to lines once welded). The files are written here, as exporters write them."""

from __future__ import annotations

import warnings

import numpy as np
import pytest
import trimesh

import toonmesh as tm

BACKENDS = ["vulkan", "gl"]
SIZE = 240


def _write_obj(path, V, F):
    with open(path, "w") as out:
        out.writelines(f"v {x!r} {y!r} {z!r}\n" for x, y, z in np.asarray(V, float).tolist())
        out.writelines(f"f {a + 1} {b + 1} {c + 1}\n" for a, b, c in np.asarray(F).tolist())
    return path


def _sheet(n=30):
    """A curved square sheet, (n x n) vertices."""
    u, v = np.meshgrid(np.linspace(-1, 1, n), np.linspace(-1, 1, n))
    V = np.stack([u, 0.3 * np.sin(2 * u) + 0.2 * v * v, v], -1).reshape(-1, 3)
    a = (np.arange(n - 1)[:, None] * n + np.arange(n - 1)[None, :]).ravel()
    F = np.concatenate([np.stack([a, a + 1, a + n + 1], 1), np.stack([a, a + n + 1, a + n], 1)])
    return V, F


def _changed(a, b):
    """The share of pixels whose colour differs by more than 8 levels."""
    return float((np.abs(a.astype(int) - b.astype(int)).max(-1) > 8).mean())


@pytest.mark.parametrize("backend", BACKENDS)
@pytest.mark.parametrize("normals", [None, "smooth"])
def test_a_seat_stored_double_sided_is_drawn_once(tmp_path, backend, normals):
    # each face again the other way round, on the same vertices and starting at another
    # corner: drawn as stored, the shared vertices' normals cancel and the shading is noise
    V, F = _sheet()
    back = F[:, [1, 0, 2]]
    single = _write_obj(tmp_path / "single.obj", V, F)
    double = _write_obj(tmp_path / "double.obj", V, np.concatenate([F, back]))
    kw = dict(width=SIZE, height=SIZE, backend=backend, normals=normals, outlines="mesh",
              outputs=("color", "lines"))
    one = tm.render(single, **kw)
    with pytest.warns(UserWarning, match=f"{len(F)} of the {2 * len(F)} faces lie back to back"):
        two = tm.render(double, **kw)
    assert _changed(one.color, two.color) < 0.001
    assert sorted(two.line_kinds) == sorted(one.line_kinds)
    # a face colour each: the first face of a pair gives its colour
    colors = np.concatenate([np.tile([0.8, 0.2, 0.2], (len(F), 1)), np.tile([0.2, 0.2, 0.8], (len(F), 1))])
    with pytest.warns(UserWarning, match="back to back"):
        red = tm.render(tm.Mesh(V, np.concatenate([F, back]), face_colors=colors, normals=normals),
                        **{k: v for k, v in kw.items() if k != "normals"})
    covered = red.color[..., 3] > 0
    assert (red.color[covered][:, 0] >= red.color[covered][:, 2]).all()


def test_a_single_sided_mesh_says_nothing_of_backs():
    V, F = _sheet(8)
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        # the same face twice the same way round is no back
        tm.render(V, np.concatenate([F, F]), width=64, height=64)


def _box_pieces(n_pieces):
    """A box, subdivided, as one mesh and as `n_pieces` meshes each with its own vertices."""
    box = trimesh.creation.box(extents=(2.0, 1.0, 1.5)).subdivide().subdivide()
    pieces = []
    for part in np.array_split(np.random.default_rng(1).permutation(len(box.faces)), n_pieces):
        piece = trimesh.Trimesh(box.vertices, box.faces[np.sort(part)], process=False)
        piece.remove_unreferenced_vertices()
        pieces.append(piece)
    return box, pieces


def _ink(res):
    return res.outline > 0.5


@pytest.mark.parametrize("backend", BACKENDS)
def test_a_part_stored_as_pieces_draws_only_its_real_edges(tmp_path, backend):
    # a GLB of 23 pieces with one material: the pieces' borders are seams inside one surface,
    # drawn where the whole part has a line (its box edges, as creases; its silhouette), not as
    # material borders or boundaries across the flat faces
    box, pieces = _box_pieces(23)
    scene = trimesh.Scene()
    for k, piece in enumerate(pieces):
        scene.add_geometry(piece, geom_name=f"piece{k}")
    path = tmp_path / "pieces.glb"
    scene.export(path)
    kw = dict(width=SIZE, height=SIZE, backend=backend, outlines="mesh", outputs=("outline", "lines"),
              camera=tm.Camera.fit((1.0, 0.8, 1.3)))
    whole = tm.render(box.vertices, box.faces, **kw)
    apart = tm.render(path, **kw)
    assert len(tm.load(path)) == 23
    assert set(apart.line_kinds) <= {"silhouette", "ridge", "valley"}, set(apart.line_kinds)
    a, b = _ink(whole), _ink(apart)
    assert abs(int(a.sum()) - int(b.sum())) < 0.05 * a.sum()
    assert (a & b).sum() > 0.9 * a.sum()
    # pieces of different colours keep their borders, as material borders
    colored = [tm.Mesh(p.vertices, p.faces, face_colors=np.tile(c, (len(p.faces), 1)))
               for p, c in zip(pieces, np.random.default_rng(2).random((len(pieces), 3)))]
    assert "material" in tm.render(colored, **kw).line_kinds
    # and so do pieces with different materials
    mats = [tm.Mesh(p.vertices, p.faces, material=tm.Material.bands(c))
            for p, c in zip(pieces, ["#d04040", "#4040d0"] * 12)]
    assert "material" in tm.render(mats, **kw).line_kinds


@pytest.mark.parametrize("backend", BACKENDS)
def test_a_fold_between_pieces_is_a_crease_and_a_turn_away_a_silhouette(backend):
    # two halves of a cylinder's side meeting along two lines, seen across one of them: the
    # seam facing the camera is no line, the seams on the rim are silhouettes; two flat plates
    # meeting at 90 degrees: a ridge
    cyl = trimesh.creation.cylinder(radius=1.0, height=2.0, sections=48)
    side = cyl.faces[np.abs(cyl.face_normals[:, 2]) < 0.5]
    centres = cyl.vertices[side].mean(axis=1)
    halves = [tm.Mesh(cyl.vertices, side[centres[:, 0] >= 0]), tm.Mesh(cyl.vertices, side[centres[:, 0] < 0])]
    kw = dict(width=SIZE, height=SIZE, backend=backend, outlines="mesh", outputs=("outline", "lines"))
    cam = tm.Camera.look_at(eye=(0.0, 6.0, 0.5), target=(0.0, 0.0, 0.0), up=(0.0, 0.0, 1.0))
    whole = tm.render(cyl.vertices, side, camera=cam, **kw)
    apart = tm.render(halves, camera=cam, **kw)
    assert set(apart.line_kinds) == set(whole.line_kinds)
    a, b = _ink(whole), _ink(apart)
    assert abs(int(a.sum()) - int(b.sum())) < 0.05 * a.sum()
    V = np.array([[0, 0, 0], [1, 0, 0], [1, 1, 0], [0, 1, 0], [0, 1, -1], [0, 0, -1]], float)
    plates = [tm.Mesh(V, np.array([[0, 1, 2], [0, 2, 3]])), tm.Mesh(V, np.array([[0, 3, 4], [0, 4, 5]]))]
    # seen from outside the fold both faces face the camera: a ridge; from the other side of
    # the wall, the fold is where the surface turns away: a silhouette
    outside = tm.render(plates, camera=tm.Camera.look_at(eye=(-2, 2, 2), target=(0.3, 0.5, -0.3)), **kw)
    assert sorted(outside.line_kinds) == ["boundary", "boundary", "ridge"], outside.line_kinds
    across = tm.render(plates, camera=tm.Camera.look_at(eye=(2, 2, 2), target=(0.3, 0.5, -0.3)), **kw)
    assert sorted(across.line_kinds) == ["boundary", "boundary", "silhouette"], across.line_kinds


def _capsule(seg=50, rings=12, copies=True):
    """A capsule whose poles are stored as a row of copies of one point (one per segment, as
    a UV sphere exports: the faces between two copies collapse once welded), or as one vertex
    each with a fan of triangles around it (`copies=False`)."""
    phis = np.r_[np.linspace(-np.pi / 2, 0, rings // 2 + 1), np.linspace(0, np.pi / 2, rings // 2 + 1)]
    offsets = np.r_[np.full(rings // 2 + 1, -0.75), np.full(rings // 2 + 1, 0.75)]
    V, rows = [], []
    for phi, off in zip(phis, offsets):
        pole = abs(abs(phi) - np.pi / 2) < 1e-9
        c = 0.0 if pole else np.cos(phi)
        count = 1 if pole and not copies else seg
        rows.append([len(V) + min(k, count - 1) for k in range(seg)])
        V += [[0.5 * c * np.cos(2 * np.pi * k / seg), 0.5 * np.sin(phi) + off, 0.5 * c * np.sin(2 * np.pi * k / seg)]
              for k in range(count)]
    F = []
    for a, b in zip(rows[:-1], rows[1:]):
        for k in range(seg):
            k1 = (k + 1) % seg
            F += [f for f in ([a[k], b[k], b[k1]], [a[k], b[k1], a[k1]]) if len(set(f)) == 3]
    return np.array(V), np.array(F)


@pytest.mark.parametrize("backend", BACKENDS)
def test_a_pole_of_copies_is_not_inked_as_a_blob(tmp_path, backend):
    V, F = _capsule()
    path = _write_obj(tmp_path / "capsule.obj", V, F)
    fe = tm.edges.feature_edges(V, F, weld=True)
    assert len(fe.nonmanifold) == 0 and len(fe.boundary) == 0
    kw = dict(width=SIZE, height=SIZE, backend=backend, outlines="mesh", outputs=("outline", "lines"),
              camera=tm.Camera.fit((0.0, 1.0, 0.6)))
    stored = tm.render(path, **kw)
    clean = tm.render(*_capsule(copies=False), **kw)
    assert set(stored.line_kinds) == {"silhouette"}
    a, b = _ink(clean), _ink(stored)
    assert abs(int(a.sum()) - int(b.sum())) < 0.05 * a.sum()

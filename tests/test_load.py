"""toonmesh.load and files as scenes: what a file carries is read, what it claims but does not
hold is refused with the file's name, and instances of one geometry are uploaded once.

Every GLB, PLY and OBJ here is written at run time (by trimesh or by hand) into tmp_path.
"""

from __future__ import annotations

import os
import tracemalloc
import warnings

import numpy as np
import pytest

import toonmesh as tm
from conftest import need
from toonmesh.files import _load


def box(size: float = 1.0):
    trimesh = need("trimesh")
    return trimesh.creation.box(extents=(size, size, size))


def image(h: int = 4, w: int = 8, seed: int = 0):
    Image = need("PIL.Image")
    return Image.fromarray(np.random.default_rng(seed).integers(0, 256, (h, w, 3), dtype=np.uint8))


def textured_glb(path, *, extras: bool = False) -> str:
    """A box with UVs, a base colour texture and factor (and, with ``extras``, what toonmesh
    does not draw: emissive colour, a normal map)."""
    trimesh = need("trimesh")
    m = box()
    uv = np.random.default_rng(1).random((len(m.vertices), 2))
    kw = dict(emissiveFactor=[1.0, 0.5, 0.0], normalTexture=image(seed=2)) if extras else {}
    material = trimesh.visual.material.PBRMaterial(baseColorFactor=[255, 128, 64, 255], baseColorTexture=image(),
                                                   **kw)
    m.visual = trimesh.visual.TextureVisuals(uv=uv, material=material)
    m.export(str(path))
    return str(path)


def instanced_scene(n: int, nested: bool = False, spacing: float = 1.5):
    """One box placed by ``n`` nodes ``spacing`` apart along x (trimesh's scene graph, one
    geometry); with ``nested``, each node is the child of a rotated parent."""
    trimesh = need("trimesh")
    s = trimesh.Scene()
    s.add_geometry(box(0.5), geom_name="box", node_name="n0")
    for i in range(1, n):
        T = trimesh.transformations.translation_matrix([spacing * i, 0.0, 0.0])
        if nested:
            parent = f"p{i}"
            R = trimesh.transformations.rotation_matrix(0.3 * i, [0, 1, 0])
            s.graph.update(frame_to=parent, frame_from=s.graph.base_frame, matrix=R)
            s.graph.update(frame_to=f"n{i}", frame_from=parent, matrix=T, geometry="box")
        else:
            s.graph.update(frame_to=f"n{i}", frame_from=s.graph.base_frame, matrix=T, geometry="box")
    return s


def surfaces(path):
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        return _load.read_surfaces(path)


# ------------------------------------------------------------------------------------------------
# What a file carries


def test_a_textured_glb_gives_its_uvs_texture_and_base_colour(tmp_path):
    path = textured_glb(tmp_path / "t.glb")
    ((s, T),) = surfaces(path)
    assert s.uv is not None and s.uv.shape == (len(s.vertices), 2)
    assert s.texture is not None and s.texture.shape == (4, 8, 4) and s.texture.dtype == np.uint8
    assert np.array_equal(s.texture[..., :3], np.asarray(image()))
    srgb = tm._core._srgb_from_linear(np.array([1.0, 128 / 255, 64 / 255]))  # the factor is linear: as drawn
    np.testing.assert_allclose(s.base_color, [*srgb, 1.0])
    assert T is not None and T.shape == (4, 4)
    meshes = tm.load(path)
    assert len(meshes) == 1 and isinstance(meshes[0], tm.Mesh)


def test_what_is_not_drawn_is_named_in_one_warning(tmp_path):
    path = textured_glb(tmp_path / "t.glb", extras=True)
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        tm.load(path)
    assert len(caught) == 1, [str(w.message) for w in caught]
    text = str(caught[0].message)
    assert path in text and "emissive" in text and "normal maps" in text
    with warnings.catch_warnings():
        warnings.simplefilter("error")  # a file with nothing to ignore loads silently
        tm.load(textured_glb(tmp_path / "plain.glb"))


def test_a_vertex_coloured_glb_and_ply_give_their_colours(tmp_path):
    m = box()
    colors = np.random.default_rng(3).integers(0, 256, (len(m.vertices), 4), dtype=np.uint8)
    colors[:, 3] = 255
    m.visual.vertex_colors = colors
    for name in ("c.glb", "c.ply"):
        m.export(str(tmp_path / name))
        ((s, _),) = surfaces(str(tmp_path / name))
        assert s.vertex_colors is not None
        assert np.array_equal(s.vertex_colors, colors), name


def test_several_materials_give_several_meshes(tmp_path):
    (tmp_path / "two.mtl").write_text("newmtl red\nKd 1 0 0\nnewmtl blue\nKd 0 0 1\n")
    (tmp_path / "two.obj").write_text(
        "mtllib two.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nv 1 1 0\nusemtl red\nf 1 2 3\nusemtl blue\nf 2 4 3\n")
    placed = surfaces(str(tmp_path / "two.obj"))
    colours = sorted(tuple(np.round(s.base_color[:3], 3)) for s, _ in placed)
    assert colours == [(0.0, 0.0, 1.0), (1.0, 0.0, 0.0)]
    assert sum(len(s.faces) for s, _ in placed) == 2


def test_a_glb_of_several_materials_gives_a_mesh_per_material(tmp_path):
    trimesh = need("trimesh")
    scene = trimesh.Scene()
    for i, factor in enumerate(([255, 0, 0, 255], [0, 0, 255, 255])):
        m = box()
        m.apply_translation([2.0 * i, 0, 0])
        material = trimesh.visual.material.PBRMaterial(baseColorFactor=factor)
        m.visual = trimesh.visual.TextureVisuals(uv=np.zeros((len(m.vertices), 2)), material=material)
        scene.add_geometry(m, geom_name=f"part{i}")
    path = str(tmp_path / "two.glb")
    scene.export(path)
    placed = surfaces(path)
    colours = sorted(tuple(np.round(s.base_color, 9)) for s, _ in placed)
    assert colours == [(0.0, 0.0, 1.0, 1.0), (1.0, 0.0, 0.0, 1.0)]
    assert len(tm.load(path)) == 2


def test_instances_share_their_arrays_and_compose_node_transforms(tmp_path):
    scene = instanced_scene(6, nested=True)
    path = str(tmp_path / "inst.glb")
    scene.export(path)
    meshes = tm.load(path)
    assert len(meshes) == 6
    assert all(m.vertices is meshes[0].vertices and m.faces is meshes[0].faces for m in meshes)
    expected = sorted(tuple(np.round(scene.graph[n][0][:3, 3], 9)) for n in scene.graph.nodes_geometry)
    got = sorted(tuple(np.round(m.transform[:3, 3], 9)) for m in meshes)
    assert got == expected
    # a child of a rotated parent: translation rotated with it (not only the node's own matrix)
    assert any(abs(t[2]) > 0.1 for t in got)


def test_a_scene_and_a_path_render_like_the_merged_mesh_and_upload_once(tmp_path, monkeypatch):
    scene = instanced_scene(5)
    path = tmp_path / "inst.glb"
    scene.export(str(path))
    merged = scene.to_mesh()
    # a fixed camera: a fit one frames the union of the meshes' bounding spheres, not the merged mesh's
    camera = tm.Camera.look_at((3.0, 3.0, 8.0), (3.0, 0.0, 0.0))
    renderer = tm.rendering._render.shared_renderer(None)
    uploads = []
    real = type(renderer)._add  # every upload goes through it
    monkeypatch.setattr(type(renderer), "_add", lambda self, *a, **k: uploads.append(1) or real(self, *a, **k))
    from_scene = tm.render(scene, camera=camera, width=96, height=64).color
    assert len(uploads) == 1  # one geometry, five instances
    from_path = tm.render(path, camera=camera, width=96, height=64).color
    from_str = tm.render(str(path), camera=camera, width=96, height=64).color
    assert len(uploads) == 3
    whole = tm.render(np.asarray(merged.vertices), np.asarray(merged.faces), camera=camera, width=96, height=64).color
    assert np.array_equal(from_scene, from_path) and np.array_equal(from_path, from_str)
    assert np.array_equal(from_scene, whole)
    assert (from_scene[..., :3] < 200).any(axis=2).mean() > 0.02  # the boxes are there


def test_a_scene_where_a_mesh_is_expected_says_what_to_do():
    scene = instanced_scene(2)
    with pytest.raises(TypeError, match="vertices: a trimesh.Scene"):
        tm.smooth.laplacian(scene)
    with pytest.raises(TypeError, match="toonmesh.load"):
        tm.edges.feature_edges("mesh.obj")


# ------------------------------------------------------------------------------------------------
# What a file claims but does not hold


def obj(tmp_path, text: str, name: str = "m.obj") -> str:
    path = tmp_path / name
    path.write_bytes(text.encode())
    return str(path)


def test_an_obj_cut_off_mid_line_is_refused_naming_the_line(tmp_path):
    path = obj(tmp_path, "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nf 1 2 3\nf 1 2 4\nf 1 3")
    with pytest.raises(ValueError) as e:
        tm.load(path)
    assert path in str(e.value) and "line 7" in str(e.value) and "cut off" in str(e.value)


def test_an_obj_face_past_its_vertices_is_refused(tmp_path):
    path = obj(tmp_path, "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\nf 1 2 9\n")
    with pytest.raises(ValueError, match=r"m\.obj: line 5: face index 9 points past the 3 vertices"):
        tm.load(path)
    path = obj(tmp_path, "v 0 0 0\nv 1 0 0\nv 0 1 0\nf -1 -2 -4\n", "neg.obj")
    with pytest.raises(ValueError, match=r"neg\.obj: line 4: face index -4"):
        tm.load(path)
    path = obj(tmp_path, "v 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0 0\nf 1/1 2/2 3/1\n", "vt.obj")
    with pytest.warns(UserWarning, match=r"vt\.obj: line 5: a face names texture coordinate 2, of 1 listed"):
        tm.load(path)  # positions kept (tests/test_files_read.py)


def test_non_finite_vertices_name_the_file_and_the_1_based_vertex(tmp_path):
    path = obj(tmp_path, "v 0 0 0\nv 1 nan 0\nv 0 1 0\nf 1 2 3\n")
    with pytest.raises(ValueError, match=r"m\.obj: vertex 2 \(line 2\) is not finite"):
        tm.load(path)
    trimesh = need("trimesh")
    V = np.array([[0, 0, 0], [1, 0, 0], [0, 1, 0], [0, 0, np.inf]], dtype=np.float64)
    ply = str(tmp_path / "inf.ply")
    trimesh.Trimesh(V, [[0, 1, 2], [0, 2, 3]], process=False).export(ply)
    with pytest.raises(ValueError, match=r"inf\.ply: vertex 4 is not finite"):
        tm.load(ply)


PLY_STRIPS = """ply
format ascii 1.0
element vertex 6
property float x
property float y
property float z
element tristrips 1
property list int int vertex_indices
end_header
0 0 0
0 1 0
1 0 0
1 1 0
2 0 0
2 1 0
8 0 1 2 3 4 5 -1 0
"""


def test_ply_triangle_strips_are_read_with_alternating_winding(tmp_path):
    path = tmp_path / "strip.ply"
    path.write_text(PLY_STRIPS)
    ((s, _),) = surfaces(str(path))
    assert len(s.faces) == 4  # six vertices in one strip; the restart leaves one index: no triangle
    corners = s.vertices[s.faces]
    normals = np.cross(corners[:, 1] - corners[:, 0], corners[:, 2] - corners[:, 0])
    assert np.all(normals[:, 2] < 0) and np.allclose(normals[:, :2], 0)  # all wound the same way
    r = tm.render(str(path), width=32, height=32)
    assert (r.color[..., :3] < 250).any()


def test_binary_ply_strips_with_colours_are_read_and_a_cut_one_refused(tmp_path):
    header = (b"ply\nformat binary_big_endian 1.0\nelement vertex 4\nproperty float x\nproperty float y\n"
              b"property float z\nproperty uchar red\nproperty uchar green\nproperty uchar blue\n"
              b"element tristrips 2\nproperty list uchar int vertex_indices\nend_header\n")
    rows = np.zeros(4, dtype=[("p", ">f4", 3), ("c", "u1", 3)])
    rows["p"] = [[0, 0, 0], [1, 0, 0], [0, 1, 0], [1, 1, 0]]
    rows["c"] = [[255, 0, 0], [0, 255, 0], [0, 0, 255], [9, 9, 9]]
    strips = bytes([4]) + np.array([0, 1, 2, 3], ">i4").tobytes() + bytes([3]) + np.array([0, 1, 3], ">i4").tobytes()
    path = tmp_path / "strips.ply"
    path.write_bytes(header + rows.tobytes() + strips)
    ((s, _),) = surfaces(str(path))
    assert s.faces.tolist() == [[0, 1, 2], [2, 1, 3], [0, 1, 3]]
    np.testing.assert_array_equal(s.vertices, rows["p"])
    assert np.array_equal(s.vertex_colors[:, :3], rows["c"]) and np.all(s.vertex_colors[:, 3] == 255)
    cut = tmp_path / "cut.ply"
    cut.write_bytes(header + rows.tobytes() + strips[:-6])
    with pytest.raises(ValueError, match="cut.ply: the 'tristrips' elements are cut off"):
        tm.load(str(cut))


def test_a_ply_header_claiming_more_than_the_file_holds_is_refused_before_allocating(tmp_path):
    header = ("ply\nformat binary_little_endian 1.0\nelement vertex 1000000000\nproperty float x\n"
              "property float y\nproperty float z\nelement face 1\nproperty list uchar int vertex_indices\nend_header\n")
    path = tmp_path / "big.ply"
    path.write_bytes(header.encode() + np.zeros(12, np.float32).tobytes())
    tracemalloc.start()
    try:
        with pytest.raises(ValueError) as e:
            tm.load(str(path))
        peak = tracemalloc.get_traced_memory()[1]
    finally:
        tracemalloc.stop()
    assert "big.ply" in str(e.value) and "1,000,000,000 'vertex'" in str(e.value)
    assert peak < 50e6


def test_very_many_instances_or_materials_are_refused_naming_the_limit(tmp_path, monkeypatch):
    monkeypatch.setattr(_load, "MAX_INSTANCES", 8)
    path = str(tmp_path / "many.glb")
    instanced_scene(12).export(path)
    with pytest.raises(ValueError, match="12 nodes place meshes; toonmesh draws at most 8 mesh instances"):
        tm.load(path)
    with pytest.raises(ValueError, match="at most 8 mesh instances"):
        tm.render(instanced_scene(12), width=8, height=8)
    # a material (and so a texture) per face
    monkeypatch.setattr(_load, "MAX_MATERIALS", 4)
    lines = ["mtllib m.mtl"] + [f"v {i} {i % 2} 0" for i in range(12)]
    lines += [f"usemtl m{i}\nf {i + 1} {i + 2} {i + 3}" for i in range(10)]
    path = obj(tmp_path, "\n".join(lines) + "\n")
    with pytest.raises(ValueError, match="10 materials .* at most 4 materials"):
        tm.load(path)
    trimesh = need("trimesh")
    scene = trimesh.Scene()
    for i in range(6):
        m = box()
        m.visual = trimesh.visual.TextureVisuals(uv=np.zeros((len(m.vertices), 2)),
                                                 material=trimesh.visual.material.PBRMaterial(baseColorFactor=[i, 0, 0, 255]))
        scene.add_geometry(m, geom_name=f"g{i}")
    with pytest.raises(ValueError, match="scene: 6 materials; toonmesh reads at most 4"):
        tm.render(scene, width=8, height=8)


def test_load_refuses_what_is_not_a_mesh_file(tmp_path):
    with pytest.raises(TypeError, match="path: expected a file path"):
        tm.load(3)
    with pytest.raises(FileNotFoundError, match="nope.obj: no such file"):
        tm.load(str(tmp_path / "nope.obj"))
    with pytest.raises(IsADirectoryError):
        tm.load(tmp_path)
    points = tmp_path / "points.ply"
    points.write_text("ply\nformat ascii 1.0\nelement vertex 2\nproperty float x\nproperty float y\n"
                      "property float z\nend_header\n0 0 0\n1 1 1\n")
    (cloud,) = tm.load(str(points))  # points alone are points, not a refusal
    assert isinstance(cloud, tm.Points) and cloud.positions.tolist() == [[0, 0, 0], [1, 1, 1]]
    points.write_text("ply\nformat ascii 1.0\nelement vertex 0\nproperty float x\nproperty float y\n"
                      "property float z\nend_header\n")
    with pytest.raises(ValueError, match=r"points.ply: no triangles in the file \(nor points or lines\)"):
        tm.load(str(points))
    bad = tmp_path / "bad.glb"
    bad.write_bytes(b"not a glb at all, really")
    with pytest.raises(ValueError, match="bad.glb: not a GLB file"):
        tm.load(str(bad))


def test_the_scenes_benchmark_uploads_the_instances_once():
    from toonmesh.bench import scenes

    rows = scenes.rows(count=12, faces=200, size=48, repeat=1)
    assert rows[0][2] == "1 upload(s)"
    assert rows[0][6] == f"{12 * len(scenes.instances(12, 200)[0][1]):,}"


def test_a_glb_cut_short_or_claiming_more_than_it_holds_is_refused(tmp_path):
    import json
    import struct

    path = tmp_path / "row.glb"
    instanced_scene(3).export(str(path))
    data = path.read_bytes()
    cut = tmp_path / "cut.glb"
    cut.write_bytes(data[:-40])
    with pytest.raises(ValueError, match=r"cut\.glb: the binary buffer claims [\d,]+ bytes but the file holds"):
        tm.load(str(cut))
    n = struct.unpack("<I", data[12:16])[0]
    doc = json.loads(data[20:20 + n])
    doc["accessors"][0]["count"] = 10**9
    text = json.dumps(doc).encode()
    text += b" " * (-len(text) % 4)
    rest = data[20 + n:]
    claim = tmp_path / "claim.glb"
    claim.write_bytes(data[:8] + struct.pack("<I", 20 + len(text) + len(rest)) + struct.pack("<II", len(text), 0x4E4F534A)
                      + text + rest)
    with pytest.raises(ValueError, match=r"claim\.glb: accessor 0 claims 1,000,000,000 elements"):
        tm.load(str(claim))


def coloured_scene(path):
    """Two instances of a red box and one textured blue box, as a GLB."""
    trimesh = need("trimesh")
    red = box(0.8)
    red.visual.vertex_colors = np.tile([220, 20, 20, 255], (len(red.vertices), 1)).astype(np.uint8)
    blue = box(0.8)
    Image = need("PIL.Image")
    texture = Image.fromarray(np.tile(np.array([20, 40, 230], np.uint8), (4, 4, 1)))
    blue.visual = trimesh.visual.TextureVisuals(uv=np.full((len(blue.vertices), 2), 0.5),
                                                material=trimesh.visual.material.PBRMaterial(baseColorTexture=texture))
    s = trimesh.Scene()
    s.add_geometry(red, geom_name="red", node_name="r0")
    s.graph.update(frame_to="r1", frame_from=s.graph.base_frame, geometry="red",
                   matrix=trimesh.transformations.translation_matrix([1.5, 0, 0]))
    s.add_geometry(blue, geom_name="blue", node_name="b", transform=trimesh.transformations.translation_matrix([3, 0, 0]))
    s.export(str(path))
    return str(path)


def hues(color):
    """Shares of the covered pixels that are red-dominant and blue-dominant."""
    rgb = color[..., :3].astype(int)
    covered = (rgb < 245).any(axis=2)
    red = covered & (rgb[..., 0] > rgb[..., 1] + 40) & (rgb[..., 0] > rgb[..., 2] + 40)
    blue = covered & (rgb[..., 2] > rgb[..., 0] + 40) & (rgb[..., 2] > rgb[..., 1] + 40)
    return red.sum() / covered.sum(), blue.sum() / covered.sum()


def test_a_file_renders_in_its_own_colours_with_its_instances_uploaded_once(tmp_path, monkeypatch):
    path = coloured_scene(tmp_path / "coloured.glb")
    meshes = tm.load(path)
    assert len(meshes) == 3
    reds = [m for m in meshes if "vertex_colors" in m.colors]
    assert len(reds) == 2 and reds[0].colors["vertex_colors"] is reds[1].colors["vertex_colors"]
    assert sum("texture" in m.colors for m in meshes) == 1
    renderer = tm.rendering._render.shared_renderer(None)
    uploads = []
    real = type(renderer)._add
    monkeypatch.setattr(type(renderer), "_add", lambda self, *a, **k: uploads.append(1) or real(self, *a, **k))
    camera = tm.Camera.look_at((1.5, 2.0, 6.0), (1.5, 0.0, 0.0))
    color = tm.render(path, camera=camera, width=120, height=60).color
    assert len(uploads) == 2  # the red box once for its two nodes, the blue box once
    red, blue = hues(color)
    assert red > 0.4 and blue > 0.2, (red, blue)  # the file's colours, not the default orange
    # a material given is the user's: it multiplies the file's colours
    dark = tm.render(path, camera=camera, width=120, height=60, material=tm.Material.bands("#404040")).color
    assert dark[..., :3].astype(int).sum() < color[..., :3].astype(int).sum()


def test_the_whole_file_obj_check_agrees_with_the_line_scan(tmp_path):
    from toonmesh.files import _checks as _file_checks

    texts = [
        "v 0 0 0\nv 1 0 0\nv 0 1 0\nvn 0 0 1\nf 1//1 2//1 3//1\nf -3//-1 -2//1 -1//1\n",
        "# a comment\nmtllib m.mtl\nv 0 0 0 1 0 0\nv 1 0 0 0 1 0\r\nv 0 1 0 0 0 1\nvt 0 0\nvt 1 0\nvn 0 0 1\n"
        "usemtl a\nf 1/1/1 2/2/1 3/1/1\nusemtl b\nf 3/2/1 2/1/1 1/1/1\nusemtl a\n",
        "v 0 0 0\nv 1 0 0\nv 0 1 0\n  v 1 1 0\nf 1 2 3 4\n",  # indented: the line scan reads it
        "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3 # a comment after it\n",
        "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1/1 2 3\n",  # corners written two ways: refused by the line scan
        "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 4\n",
    ]
    paths = [str(p) for p in (tmp_path / f"{i}.obj" for i in range(len(texts)))]
    for path, text in zip(paths, texts):
        with open(path, "w") as f:
            f.write(text)
    data_dir = os.path.join(os.path.dirname(__file__), "data", "meshes")
    paths += [os.path.join(data_dir, name) for name in sorted(os.listdir(data_dir)) if name.endswith(".obj")]
    fast = 0
    for path in paths:
        with open(path, "rb") as f:
            data = f.read()
        try:
            expected = _file_checks._check_obj_by_line(path, data)
        except ValueError as e:
            expected = str(e)
            assert _file_checks._obj_counts_at_once(data) is None
        at_once = _file_checks._obj_counts_at_once(data)
        fast += at_once is not None
        assert at_once in (None, expected)
    assert fast >= len(paths) - 4  # all but the files the line scan must read (or refuse)

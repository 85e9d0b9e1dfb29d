"""Point and line files read by ``tm.load`` as ``tm.Points`` and ``tm.Lines``: other projects'
files (tests/data/corpus: Khronos' MeshPrimitiveModes, trimesh's point clouds and wireframe
OBJ, PDAL's PLY point clouds) held against what their own documentation and an independent
parse say, and hand-written edge cases (binary and ASCII PLY, negative OBJ indices, malformed
rows named by their line)."""

from __future__ import annotations

import base64
import json
import struct
import warnings
from pathlib import Path

import numpy as np
import pytest

import toonmesh as tm
from conftest import need
from toonmesh.files._load import read_surfaces

CORPUS = Path(__file__).resolve().parent / "data" / "corpus"

#: MeshPrimitiveModes' vertices (its README: a regular hexagon about vertex 0).
HEXAGON = np.array([[0, 0, 0], [0.866, -0.5, 0], [0.866, 0.5, 0], [0, 1, 0], [-0.866, 0.5, 0], [-0.866, -0.5, 0],
                    [0, -1, 0]])


def kinds(items):
    return [type(i).__name__ for i in items]


def segment_ends(lines):
    """Each segment as the sorted pair of its ends' world coordinates (rounded), a set."""
    P = lines.positions @ lines.transform[:3, :3].T + lines.transform[:3, 3] if lines.transform is not None \
        else lines.positions
    return {tuple(sorted((tuple(np.round(P[a], 3)), tuple(np.round(P[b], 3))))) for a, b in lines.segments}


# ------------------------------------------------------------------------------------------------
# other projects' files


def test_every_gltf_primitive_mode_is_read_with_its_node():
    need("trimesh")
    path = str(CORPUS / "khronos" / "MeshPrimitiveModes.gltf")
    items = tm.load(path)
    by_name = {i.name: i for i in items}
    assert sorted(kinds(items)) == ["Lines"] * 3 + ["Mesh"] * 3 + ["Points"]
    assert all(i.source == path and i.up == "y" for i in items)
    # the nodes' translations, as the file's nodes give them
    at = {"POINTS": (0, 3), "LINES": (-2, 0), "LINE_LOOP": (0, 0), "LINE_STRIP": (2, 0)}
    for mode, (x, y) in at.items():
        item = by_name[f"mesh with {mode}"]
        assert np.allclose(item.transform, [[1, 0, 0, x], [0, 1, 0, y], [0, 0, 1, 0], [0, 0, 0, 1]])
    points = by_name["mesh with POINTS"]
    assert np.allclose(points.positions, HEXAGON, atol=1e-3) and points.normals is None and points.colors is None
    pair = lambda a, b, x, y: tuple(sorted((tuple(np.round(HEXAGON[a] + (x, y, 0), 3)),  # noqa: E731
                                            tuple(np.round(HEXAGON[b] + (x, y, 0), 3)))))
    # LINES [0, 1, 0, 2, ...]: spokes from the centre; the loop closes 6 -> 0; the strip does not
    assert segment_ends(by_name["mesh with LINES"]) == {pair(0, k, -2, 0) for k in range(1, 7)}
    assert segment_ends(by_name["mesh with LINE_LOOP"]) == {pair(k, (k + 1) % 7, 0, 0) for k in range(7)}
    assert segment_ends(by_name["mesh with LINE_STRIP"]) == {pair(k, k + 1, 2, 0) for k in range(6)}
    # the triangles are read as before, each mesh where its node puts it
    faces = {m.name: len(m.faces) for m in items if isinstance(m, tm.Mesh)}
    assert faces == {"mesh with TRIANGLES": 6, "mesh with GL_TRIANGLE_STRIP": 4, "mesh with GL_TRIANGLE_FAN": 6}


def ply_rows(path):
    """The rows of an ASCII PLY after its header, parsed by NumPy (not toonmesh's reader)."""
    text = Path(path).read_text()
    return np.loadtxt(text[text.index("end_header") + len("end_header"):].strip().splitlines(), ndmin=2)


def test_a_point_cloud_ply_gives_its_points():
    need("trimesh")
    path = CORPUS / "trimesh" / "points_emptyface.ply"  # 1,024 points and 'element face 0'
    (points,) = tm.load(path)
    assert isinstance(points, tm.Points) and len(points) == 1024
    assert np.allclose(points.positions, ply_rows(path), atol=1e-6)
    assert points.up == "z" and points.transform is None and points.source == str(path)


def test_a_ply_point_with_normal_colour_and_other_properties():
    need("trimesh")
    (point,) = tm.load(CORPUS / "pdal" / "text_extradim.ply")  # uchar red green alpha, char blue, int omg
    row = ply_rows(CORPUS / "pdal" / "text_extradim.ply")[0]
    assert np.allclose(point.positions, [row[:3]]) and np.allclose(point.normals, [row[3:6]])
    assert point.colors.dtype == np.uint8 and point.colors.tolist() == [[63, 200, 64, 255]]


def test_binary_point_clouds_from_other_projects():
    need("trimesh")
    (pdal,) = tm.load(CORPUS / "pdal" / "simple_binary.ply")  # CloudCompare's, no face element
    assert len(pdal) == 3 and np.isfinite(pdal.positions).all()
    (trimesh_points,) = tm.load(CORPUS / "trimesh" / "points_bin.ply")
    (ascii_points,) = tm.load(CORPUS / "trimesh" / "points_ascii.ply")  # the same 5 points, written as text
    assert np.allclose(trimesh_points.positions, ascii_points.positions, atol=1e-6)


def test_a_ply_whose_normals_are_zero_is_read_without_them():
    need("trimesh")
    path = CORPUS / "trimesh" / "ply_points_bin.ply"  # 8 cube corners, every normal (0, 0, 0)
    with pytest.warns(UserWarning, match=f"{path}: the file's normal of point 1 is zero"):
        (points,) = tm.load(path)
    assert points.normals is None and sorted(map(tuple, points.positions.tolist())) == sorted(
        (x, y, z) for x in (-1, 1) for y in (-1, 1) for z in (-1, 1))


def test_an_obj_wireframe_gives_the_cube_edges():
    need("trimesh")
    (lines,) = tm.load(CORPUS / "trimesh" / "obj_wireframe.obj")  # 8 corners, 12 'l' elements
    assert isinstance(lines, tm.Lines) and len(lines) == 12 and lines.up == "y"
    ends = segment_ends(lines)
    # each a cube edge: two corners that differ along one axis
    assert len(ends) == 12 and all(np.count_nonzero(np.subtract(a, b)) == 1 for a, b in ends)


@pytest.mark.parametrize("name, width", [("points_agisoft.xyz", 6), ("points_cloudcompare.xyz", 7)])
def test_xyz_files_give_positions_and_colours(name, width):
    need("trimesh")
    path = CORPUS / "trimesh" / name
    rows = np.loadtxt(path, ndmin=2)
    (points,) = tm.load(path)
    assert rows.shape[1] == width and len(points) == len(rows)
    assert np.allclose(points.positions, rows[:, :3])  # large coordinates kept in float64
    assert points.colors.dtype == np.uint8 and np.array_equal(points.colors, rows[:, 3:width].astype(np.uint8))
    assert points.normals is None and points.up is None


# ------------------------------------------------------------------------------------------------
# PLY written here


def ply_file(path, fmt, rows, props, extra=""):
    """A PLY of vertices ``rows`` with ``props`` [(type, name)], ASCII or binary."""
    head = f"ply\nformat {fmt} 1.0\nelement vertex {len(rows)}\n" + "".join(f"property {t} {n}\n" for t, n in props)
    head += extra + "end_header\n"
    if fmt == "ascii":
        body = "".join(" ".join(str(v) for v in row) + "\n" for row in rows).encode()
    else:
        order = "<" if fmt == "binary_little_endian" else ">"
        codes = {"float": "f", "double": "d", "uchar": "B", "ushort": "H", "int": "i"}
        body = b"".join(struct.pack(order + "".join(codes[t] for t, _ in props), *row) for row in rows)
    Path(path).write_bytes(head.encode() + body)
    return str(path)


POINT_PROPS = [("float", "x"), ("float", "y"), ("double", "z"), ("float", "nx"), ("float", "ny"), ("float", "nz"),
               ("uchar", "red"), ("uchar", "green"), ("uchar", "blue")]
POINT_ROWS = [(0.5, -1.0, 2.25, 0, 0, 1, 255, 0, 10), (1.0, 2.0, 3.0, 0, 1, 0, 0, 128, 255),
              (-4.0, 0.0, 1.0, 1, 0, 0, 7, 8, 9)]


@pytest.mark.parametrize("fmt", ["ascii", "binary_little_endian", "binary_big_endian"])
def test_a_ply_of_vertices_alone_is_points_in_every_encoding(tmp_path, fmt):
    need("trimesh")
    (points,) = tm.load(ply_file(tmp_path / "p.ply", fmt, POINT_ROWS, POINT_PROPS))
    rows = np.array(POINT_ROWS, dtype=np.float64)
    assert np.array_equal(points.positions, rows[:, :3]) and np.array_equal(points.normals, rows[:, 3:6])
    assert points.colors.dtype == np.uint8 and np.array_equal(points.colors, rows[:, 6:9].astype(np.uint8))


def test_float_and_16_bit_ply_colours_are_read_in_zero_to_one(tmp_path):
    need("trimesh")
    props = [("float", "x"), ("float", "y"), ("float", "z"), ("float", "red"), ("float", "green"),
             ("float", "blue"), ("float", "alpha")]
    (floats,) = tm.load(ply_file(tmp_path / "f.ply", "binary_little_endian", [(0, 0, 0, 0.25, 0.5, 1.0, 0.5)], props))
    assert np.allclose(floats.colors, [[0.25, 0.5, 1.0, 0.5]])
    props = [("float", "x"), ("float", "y"), ("float", "z"), ("ushort", "red"), ("ushort", "green"), ("ushort", "blue")]
    (wide,) = tm.load(ply_file(tmp_path / "u.ply", "ascii", [(0, 0, 0, 65535, 0, 32768)], props))
    assert np.allclose(wide.colors, [[1.0, 0.0, 32768 / 65535]])


def test_ply_edges_are_lines_and_checked(tmp_path):
    need("trimesh")
    V = [(0, 0, 0), (1, 0, 0), (1, 1, 0)]
    edges = "element edge 2\nproperty int vertex1\nproperty int vertex2\n"
    path = tmp_path / "e.ply"
    ply_file(path, "ascii", V, POINT_PROPS[:2] + [("float", "z")], edges)
    path.write_text(path.read_text() + "0 1\n1 2\n")
    (lines,) = tm.load(path)
    assert isinstance(lines, tm.Lines) and segment_ends(lines) == {((0, 0, 0), (1, 0, 0)), ((1, 0, 0), (1, 1, 0))}
    path.write_text(path.read_text().replace("1 2\n", "1 3\n"))
    with pytest.raises(ValueError, match=r"e\.ply: edge 2 names a vertex outside the 3 vertices: \[1, 3\]"):
        tm.load(path)


def test_a_ply_with_faces_and_edges_gives_a_mesh_and_lines(tmp_path):
    need("trimesh")
    path = tmp_path / "fe.ply"
    path.write_text("ply\nformat ascii 1.0\nelement vertex 4\nproperty float x\nproperty float y\nproperty float z\n"
                    "element face 1\nproperty list uchar int vertex_indices\n"
                    "element edge 1\nproperty int vertex1\nproperty int vertex2\nend_header\n"
                    "0 0 0\n1 0 0\n0 1 0\n0 0 1\n3 0 1 2\n0 3\n")
    mesh, lines = tm.load(path)
    assert len(mesh.faces) == 1 and segment_ends(lines) == {((0, 0, 0), (0, 0, 1))} and lines.up == "z"


def test_a_ply_cut_short_or_not_finite_is_refused(tmp_path):
    need("trimesh")
    xyz = POINT_PROPS[:2] + [("float", "z")]
    path = ply_file(tmp_path / "nan.ply", "ascii", [(0, 0, 0), (1, float("nan"), 0)], xyz)
    with pytest.raises(ValueError, match=r"nan\.ply: vertex 2 is not finite"):
        tm.load(path)
    path = tmp_path / "cut.ply"
    ply_file(path, "binary_little_endian", POINT_ROWS, POINT_PROPS)
    path.write_bytes(path.read_bytes()[:-5])
    with pytest.raises(ValueError, match=r"cut\.ply: "):
        tm.load(path)


# ------------------------------------------------------------------------------------------------
# OBJ written here


def obj(tmp_path, text, name="m.obj"):
    path = tmp_path / name
    path.write_text(text)
    return str(path)


SQUARE = "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\n"


def test_obj_polylines_with_negative_indices(tmp_path):
    need("trimesh")
    # 'l 1 2 3' is two segments; -1 is the last vertex listed before the element
    (lines,) = tm.load(obj(tmp_path, SQUARE + "l 1 2 3\nl -1 -4\n"))
    assert len(lines) == 3 and lines.source.endswith("m.obj")
    assert segment_ends(lines) == {((0, 0, 0), (1, 0, 0)), ((1, 0, 0), (1, 1, 0)), ((0, 0, 0), (0, 1, 0))}


def test_an_obj_with_faces_and_lines_gives_both(tmp_path):
    need("trimesh")
    items = tm.load(obj(tmp_path, SQUARE + "v 5 5 5\nf 1 2 3\nf 1 3 4\nl 4/1 5/1\n"))
    assert kinds(items) == ["Mesh", "Lines"]
    mesh, lines = items
    assert len(mesh.faces) == 2 and segment_ends(lines) == {((0, 1, 0), (5, 5, 5))}
    assert mesh.up == lines.up == "y"


def test_obj_points_with_colours_and_normals(tmp_path):
    need("trimesh")
    text = ("v 0 0 0 1 0 0\nv 1 0 0 0 1 0\nv 0 1 0 0 0 1\n"
            "vn 0 0 1\nvn 0 0 2\nvn 1 0 0\n")
    (points,) = tm.load(obj(tmp_path, text))
    assert isinstance(points, tm.Points) and points.positions.tolist() == [[0, 0, 0], [1, 0, 0], [0, 1, 0]]
    assert np.allclose(points.colors, np.eye(3)) and points.normals[2].tolist() == [1, 0, 0]
    (chosen,) = tm.load(obj(tmp_path, SQUARE + "p 2 -1\n", "p.obj"))  # 'p': the points named
    assert chosen.positions.tolist() == [[1, 0, 0], [0, 1, 0]]


@pytest.mark.parametrize("text, message", [
    (SQUARE + "l 1\n", r"m\.obj: line 5: a line element needs 2 or more points, got 1"),
    (SQUARE + "l 1 9\n", r"m\.obj: line 5: index 9 points past the 4 vertices in the file"),
    (SQUARE + "l 1 -5\n", r"m\.obj: line 5: line index -5 points past the 4 vertices listed before it"),
    ("v 0 0 0\nl 1 0\nv 1 1 1\n", r"m\.obj: line 2: line index 0 points past the 1 vertices listed before it"),
    (SQUARE + "\nl 1 x\n", r"m\.obj: line 6: not an index in 'l 1 x'"),
    (SQUARE + "p 7\n", r"m\.obj: line 5: index 7 points past the 4 vertices in the file"),
])
def test_malformed_obj_lines_are_named_by_line(tmp_path, text, message):
    need("trimesh")
    with pytest.raises(ValueError, match=message):
        tm.load(obj(tmp_path, text))


# ------------------------------------------------------------------------------------------------
# XYZ written here


def test_xyz_columns_commas_and_comments(tmp_path):
    need("trimesh")
    path = tmp_path / "n.xyz"
    path.write_text("# x y z nx ny nz\n0,0,0, 0,0,1\n\n1 2 3 0 1 0\n")
    (points,) = tm.load(path)  # six columns of unit vectors: normals
    assert points.positions.tolist() == [[0, 0, 0], [1, 2, 3]] and points.normals.tolist() == [[0, 0, 1], [0, 1, 0]]
    assert points.colors is None
    path.write_text("0 0 0 0.5 0.25 1\n1 1 1 0 0 0\n")  # not unit vectors: colours in [0, 1]
    (points,) = tm.load(path)
    assert points.normals is None and np.allclose(points.colors, [[0.5, 0.25, 1], [0, 0, 0]])
    path.write_text("0 0 0 0 0 1 255 0 0\n")  # nine: normals, then colour codes
    (points,) = tm.load(path)
    assert points.normals.tolist() == [[0, 0, 1]] and points.colors.tolist() == [[255, 0, 0]]


@pytest.mark.parametrize("text, message", [
    ("0 0 0\n1 1\n", r"p\.xyz: line 2: 2 numbers, but the rows before have 3"),
    ("# c\n0 0 zero\n", r"p\.xyz: line 2: not a number: 'zero'"),
    ("0 0 0\n1 inf 0\n", r"p\.xyz: line 2: point 2 is not finite"),
    ("0 0 0 1 1\n", r"p\.xyz: line 1: 5 numbers a row"),
    ("# nothing\n\n", r"p\.xyz: no triangles in the file \(nor points or lines\)"),
])
def test_malformed_xyz_rows_are_named_by_line(tmp_path, text, message):
    need("trimesh")
    path = tmp_path / "p.xyz"
    path.write_text(text)
    with pytest.raises(ValueError, match=message):
        tm.load(path)


# ------------------------------------------------------------------------------------------------
# glTF written here


def gltf(path, primitives, nodes, arrays):
    """A glTF of one mesh with ``primitives``, placed by ``nodes``; ``arrays``: one accessor each,
    (values, componentType, type, normalized)."""
    blob, views, accessors = b"", [], []
    for values, component, kind, normalized in arrays:
        data = np.ascontiguousarray(values).tobytes()
        views.append({"buffer": 0, "byteOffset": len(blob), "byteLength": len(data)})
        accessor = {"bufferView": len(views) - 1, "componentType": component, "count": len(values), "type": kind}
        if normalized:
            accessor["normalized"] = True
        accessors.append(accessor)
        blob += data + b"\0" * (-len(data) % 4)
    doc = {"asset": {"version": "2.0"}, "scene": 0, "scenes": [{"nodes": [0]}], "nodes": nodes,
           "meshes": [{"name": "cloud", "primitives": primitives}], "accessors": accessors, "bufferViews": views,
           "buffers": [{"byteLength": len(blob),
                        "uri": "data:application/octet-stream;base64," + base64.b64encode(blob).decode()}]}
    path.write_text(json.dumps(doc))
    return str(path)


XYZ = np.array([[0, 0, 0], [1, 0, 0], [0, 2, 0], [0, 0, 3]], np.float32)


def test_gltf_points_with_normals_and_colours_under_nested_nodes(tmp_path):
    need("trimesh")
    normals = np.array([[0, 0, 1]] * 4, np.float32)
    colours = np.array([[255, 0, 0, 255], [0, 255, 0, 255], [0, 0, 255, 255], [255, 255, 255, 0]], np.uint8)
    # node 0 turns 90 degrees about z and doubles; its children 1 and 2 place the mesh, moved along x
    turn = [0, 0, np.sin(np.pi / 4), np.cos(np.pi / 4)]
    nodes = [{"children": [1, 2], "rotation": turn, "scale": [2, 2, 2]},
             {"mesh": 0, "translation": [1, 0, 0]}, {"mesh": 0, "translation": [0, 0, 5]}]
    path = gltf(tmp_path / "c.gltf", [{"attributes": {"POSITION": 0, "NORMAL": 1, "COLOR_0": 2}, "mode": 0}], nodes,
                [(XYZ, 5126, "VEC3", False), (normals, 5126, "VEC3", False), (colours, 5121, "VEC4", True)])
    a, b = tm.load(path)
    assert isinstance(a, tm.Points) and a.name == "cloud" and a.positions is b.positions  # one geometry, shared
    world = a.positions @ a.transform[:3, :3].T + a.transform[:3, 3]
    # the child's (1, 0, 0) turned and doubled: (0, 2, 0); a point's (1, 0, 0) turned: (0, 2, 0) more
    assert np.allclose(world, [[0, 2, 0], [0, 4, 0], [-4, 2, 0], [0, 2, 6]], atol=1e-6)
    assert np.allclose(b.transform[:3, 3], [0, 0, 10])
    assert np.allclose(a.normals, normals) and np.allclose(a.colors, colours / 255.0)


def test_gltf_lines_without_indices_and_a_points_only_file(tmp_path):
    need("trimesh")
    for mode, segments in ((1, {(0, 1), (2, 3)}), (2, {(0, 1), (1, 2), (2, 3), (0, 3)}), (3, {(0, 1), (1, 2), (2, 3)})):
        path = gltf(tmp_path / f"l{mode}.gltf", [{"attributes": {"POSITION": 0}, "mode": mode}], [{"mesh": 0}],
                    [(XYZ, 5126, "VEC3", False)])
        (lines,) = tm.load(path)
        want = {tuple(sorted((tuple(XYZ[a].astype(float)), tuple(XYZ[b].astype(float))))) for a, b in segments}
        assert isinstance(lines, tm.Lines) and segment_ends(lines) == want, mode
    with pytest.raises(ValueError, match=r"l1\.gltf: no triangles in the file \(it holds 2 segments\)"):
        read_surfaces(str(tmp_path / "l1.gltf"))  # what the 'smooth' command reads: triangles


@pytest.mark.parametrize("mode, indices, message", [
    (1, [0, 1, 2], r"mesh 0 \(cloud\) primitive 0 \(LINES\): LINES takes pairs of vertices, got 3"),
    (3, [0, 9], r"mesh 0 \(cloud\) primitive 0 \(LINE_STRIP\): index 2 \(9\) points past the 4 vertices"),
    (0, [0, 4], r"mesh 0 \(cloud\) primitive 0 \(POINTS\): index 2 \(4\) points past the 4 vertices"),
])
def test_malformed_gltf_lines_and_points_are_named(tmp_path, mode, indices, message):
    need("trimesh")
    path = gltf(tmp_path / "bad.gltf", [{"attributes": {"POSITION": 0}, "indices": 1, "mode": mode}], [{"mesh": 0}],
                [(XYZ, 5126, "VEC3", False), (np.array(indices, np.uint16), 5123, "SCALAR", False)])
    with pytest.raises(ValueError, match=r"bad\.gltf: " + message):
        tm.load(path)


def test_a_gltf_with_triangles_and_points_gives_both_without_a_warning(tmp_path):
    need("trimesh")
    path = gltf(tmp_path / "both.gltf", [{"attributes": {"POSITION": 0}, "indices": 1},
                                         {"attributes": {"POSITION": 0}, "mode": 0}], [{"mesh": 0}],
                [(XYZ, 5126, "VEC3", False), (np.array([0, 1, 2], np.uint16), 5123, "SCALAR", False)])
    with warnings.catch_warnings():
        warnings.simplefilter("error")  # no "not drawn: points"
        items = tm.load(path)
    assert kinds(items) == ["Mesh", "Points"] and len(items[0].faces) == 1 and len(items[1]) == 4


def test_a_gltf_material_colours_its_lines_and_points(tmp_path):
    need("trimesh")
    path = gltf(tmp_path / "m.gltf", [{"attributes": {"POSITION": 0}, "mode": 3, "material": 0},
                                      {"attributes": {"POSITION": 0}, "mode": 0, "material": 0}], [{"mesh": 0}],
                [(XYZ, 5126, "VEC3", False)])
    doc = json.loads(Path(path).read_text())
    doc["materials"] = [{"pbrMetallicRoughness": {"baseColorFactor": [1.0, 0.214041, 0.0, 1.0]}}]
    Path(path).write_text(json.dumps(doc))
    lines, points = tm.load(path, up="z")
    assert np.allclose(lines.color, (1.0, 0.5, 0.0), atol=1e-3)  # linear 0.214 is sRGB 0.5, as a mesh's base colour
    assert np.allclose(points.colors, [(1.0, 0.5, 0.0)] * 4, atol=1e-3)
    assert lines.up == points.up == "z"


def test_points_and_lines_in_an_archive(tmp_path):
    need("trimesh")
    import zipfile

    path = tmp_path / "scan.zip"
    with zipfile.ZipFile(path, "w") as z:
        z.writestr("cloud.xyz", "0 0 0\n1 1 1\n")
        z.writestr("wire.obj", SQUARE + "l 1 2 3 4 1\n")
    items = tm.load(path)
    assert sorted(kinds(items)) == ["Lines", "Points"] and all(i.source == str(path) for i in items)
    assert len(next(i for i in items if isinstance(i, tm.Lines))) == 4
    with zipfile.ZipFile(path, "w") as z:
        z.writestr("cloud.xyz", "0 0 0\n1 1\n")
    with pytest.raises(ValueError, match=r"scan\.zip:cloud\.xyz: line 2: 2 numbers"):  # named inside the archive
        tm.load(path)


def test_glb_lines_read_from_the_binary_chunk(tmp_path):
    need("trimesh")
    doc = json.loads(Path(gltf(tmp_path / "l.gltf", [{"attributes": {"POSITION": 0}, "mode": 2}],
                               [{"mesh": 0, "matrix": [2, 0, 0, 0, 0, 2, 0, 0, 0, 0, 2, 0, 1, 2, 3, 1]}],
                               [(XYZ, 5126, "VEC3", False)])).read_text())
    blob = base64.b64decode(doc["buffers"][0].pop("uri").split(",", 1)[1])
    text = json.dumps(doc).encode()
    text += b" " * (-len(text) % 4)
    body = struct.pack("<II", len(text), 0x4E4F534A) + text + struct.pack("<II", len(blob), 0x004E4942) + blob
    path = tmp_path / "l.glb"
    path.write_bytes(b"glTF" + struct.pack("<II", 2, 12 + len(body)) + body)
    (loop,) = tm.load(path)
    assert len(loop) == 4 and np.allclose(loop.positions, XYZ)  # a closed loop of the 4 vertices
    assert np.allclose(loop.transform, [[2, 0, 0, 1], [0, 2, 0, 2], [0, 0, 2, 3], [0, 0, 0, 1]])  # column-major

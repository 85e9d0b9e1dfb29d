"""What files others wrote hold, read as they mean it: texture paths written on Windows
(backslashes, another letter case), a white material kept white, vertex colours on only some
vertices named in a warning, concave polygons triangulated without overlap."""

from __future__ import annotations

import os
import warnings

import numpy as np
import pytest

import toonmesh as tm
from toonmesh.files._load import carries_colour
from conftest import need


def textured_square(folder, map_kd: str, image_name: str) -> str:
    Image = need("PIL.Image")
    need("trimesh")
    folder.mkdir(parents=True, exist_ok=True)
    Image.new("RGB", (4, 4), (30, 160, 90)).save(folder / image_name)
    (folder / "m.mtl").write_text(f"newmtl wall\nKd 1 1 1\nmap_Kd {map_kd}\n")
    (folder / "m.obj").write_text("mtllib m.mtl\nusemtl wall\nv 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\n"
                                  "vt 0 0\nvt 1 0\nvt 1 1\nvt 0 1\nf 1/1 2/2 3/3\nf 1/1 3/3 4/4\n")
    return str(folder / "m.obj")


@pytest.mark.parametrize("map_kd, image_name", [
    (".\\wal67ar_small.jpg", "wal67ar_small.jpg"),  # Windows' relative path
    ("textures\\Wall.PNG", "textures/wall.png"),  # a folder, backslashes and another case
    ("WALL.png", "wall.png"),
])
def test_texture_paths_written_on_windows_are_found(tmp_path, map_kd, image_name):
    (tmp_path / "textures").mkdir()
    path = textured_square(tmp_path, map_kd, image_name)
    with warnings.catch_warnings():
        warnings.simplefilter("error")  # no "not found"
        (mesh,) = tm.load(path)
    texture = np.asarray(mesh.colors["texture"])
    assert np.allclose(texture[..., :3].reshape(-1, 3).mean(axis=0), (30, 160, 90), atol=2)


def test_a_white_material_is_drawn_white(tmp_path):
    need("trimesh")
    (tmp_path / "w.mtl").write_text("newmtl white\nKd 1 1 1\n")
    (tmp_path / "w.obj").write_text("mtllib w.mtl\nusemtl white\nv 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n")
    (mesh,) = tm.load(str(tmp_path / "w.obj"))
    assert np.allclose(mesh.colors["vertex_colors"], 1.0)
    result = tm.render(str(tmp_path / "w.obj"), width=32, height=32)
    lit = result.color[..., :3].reshape(-1, 3)
    lit = lit[np.any(lit != lit[0], axis=1)]  # the triangle, not the background
    assert len(lit) and np.all(np.abs(lit.astype(int) - lit.mean(axis=1, keepdims=True)) <= 3)  # grey shades, not orange


@pytest.mark.parametrize("whole", [True, False])  # the whole-file scan, and the line scan (a comment after a face)
def test_vertex_colours_on_only_some_vertices_are_named(tmp_path, whole):
    need("trimesh")
    comment = "" if whole else " # here"
    path = tmp_path / "some.obj"
    path.write_text(f"v 0 0 0 1 0 0{comment}\nv 1 0 0\nv 0 1 0 0 1 0\nv 1 1 0\nv 2 0 0\nf 1 2 3\nf 2 4 3\nf 2 5 4{comment}\n")
    with pytest.warns(UserWarning) as caught:
        tm.load(str(path))
    (note,) = [str(w.message) for w in caught]
    assert note.startswith(f"{path}: vertex colours on 2 of the 5 vertices (the first on line 1): not drawn"), note


def test_comments_after_statements_are_read_as_comments(tmp_path):
    need("trimesh")
    path = tmp_path / "commented.obj"
    path.write_text("v 0 0 0 # origin\nv 1 0 0\t# x\nv 0 1 0\nv 1 1 0\nf 1 2 3 # first\nf 2 4 3#second\n")
    (mesh,) = tm.load(str(path))
    assert mesh.faces.tolist() == [[0, 1, 2], [1, 3, 2]] and mesh.vertices.shape == (4, 3)


def polygon_obj(path, corners: np.ndarray, tilt: bool = True) -> str:
    """One face of the given (n, 2) corners, tilted out of the xy plane."""
    rot = np.array([[1, 0, 0], [0, np.cos(0.6), -np.sin(0.6)], [0, np.sin(0.6), np.cos(0.6)]]) if tilt else np.eye(3)
    V = np.c_[corners, np.zeros(len(corners))] @ rot.T + [3, -1, 2]
    path.write_text("".join(f"v {x:.17g} {y:.17g} {z:.17g}\n" for x, y, z in V)
                    + "f " + " ".join(str(i + 1) for i in range(len(V))) + "\n")
    return str(path)


def shoelace(xy: np.ndarray) -> float:
    return 0.5 * abs(float(np.sum(xy[:, 0] * np.roll(xy[:, 1], -1) - np.roll(xy[:, 0], -1) * xy[:, 1])))


def covered(mesh) -> float:
    c = mesh.vertices[mesh.faces]
    return float(np.linalg.norm(np.cross(c[:, 1] - c[:, 0], c[:, 2] - c[:, 0]), axis=1).sum() / 2)


@pytest.mark.parametrize("shape", ["star", "comb", "L"])
def test_a_concave_polygon_is_triangulated_without_overlap(tmp_path, shape):
    need("trimesh")
    if shape == "star":  # 64 corners, every other one pulled in
        t = np.linspace(0, 2 * np.pi, 64, endpoint=False)
        xy = np.c_[np.cos(t), np.sin(t)] * np.where(np.arange(64) % 2, 0.3, 1.0)[:, None]
    elif shape == "comb":  # teeth: a fan about the first corner crosses every gap
        top = [[x, 1.0 if k % 2 == 0 else 0.2] for k, x in enumerate(np.linspace(4, 0, 9))]
        xy = np.array([[0, 0], [4, 0]] + [[4, 1.0]] + top[1:-1] + [[0, 1.0]], float)
    else:
        xy = np.array([[2, 1], [1, 1], [1, 2], [0, 2], [0, 0], [2, 0]], float)  # a fan from an arm's end crosses the notch
    (mesh,) = tm.load(polygon_obj(tmp_path / f"{shape}.obj", xy))
    assert len(mesh.faces) == len(xy) - 2
    assert covered(mesh) == pytest.approx(shoelace(xy), rel=0.02)


def star64() -> np.ndarray:
    """A 64-corner star (every other corner pulled in): its fan about the first corner covers
    many times its area."""
    t = np.linspace(0, 2 * np.pi, 64, endpoint=False)
    return np.c_[np.cos(t), np.sin(t)] * np.where(np.arange(64) % 2, 0.3, 1.0)[:, None]


def polygon_file(path, corners: np.ndarray, form: str, extra: bool = False) -> str:
    """One face of the given (n, 2) corners, tilted out of the xy plane, as a PLY (ASCII or
    binary) or an OFF; ``extra``: a triangle and a quad beside it (trimesh lays out such a mix
    of polygons in its own order)."""
    import struct

    rot = np.array([[1, 0, 0], [0, np.cos(0.6), -np.sin(0.6)], [0, np.sin(0.6), np.cos(0.6)]])
    V = np.c_[corners, np.zeros(len(corners))] @ rot.T + [3, -1, 2]
    faces = [list(range(len(V)))]
    if extra:
        n = len(V)
        V = np.r_[V, [[5, 5, 0], [6, 5, 0], [6, 6, 0], [5, 6, 0]]]
        faces = [[n, n + 1, n + 2]] + faces + [[n, n + 1, n + 2, n + 3]]
    if form == "off":
        path.write_text(f"OFF\n{len(V)} {len(faces)} 0\n" + "".join(f"{x:.17g} {y:.17g} {z:.17g}\n" for x, y, z in V)
                        + "".join(f"{len(f)} " + " ".join(map(str, f)) + "\n" for f in faces))
        return str(path)
    header = (f"ply\nformat {'ascii' if form == 'ply' else 'binary_little_endian'} 1.0\nelement vertex {len(V)}\n"
              "property double x\nproperty double y\nproperty double z\n"
              f"element face {len(faces)}\nproperty list uchar int vertex_indices\nend_header\n")
    if form == "ply":
        body = "".join(f"{x:.17g} {y:.17g} {z:.17g}\n" for x, y, z in V) + "".join(
            f"{len(f)} " + " ".join(map(str, f)) + "\n" for f in faces)
        path.write_text(header + body)
    else:
        path.write_bytes(header.encode() + V.astype("<f8").tobytes() + b"".join(
            struct.pack("<B", len(f)) + np.asarray(f, "<i4").tobytes() for f in faces))
    return str(path)


@pytest.mark.parametrize("form, extra", [("ply", False), ("ply", True), ("binary ply", False), ("binary ply", True),
                                         ("off", False), ("off", True)])
def test_a_concave_polygon_in_ply_and_off_is_triangulated_without_overlap(tmp_path, form, extra):
    need("trimesh")
    xy = star64()
    suffix = ".off" if form == "off" else ".ply"
    (mesh,) = tm.load(polygon_file(tmp_path / f"star{suffix}", xy, form, extra))
    assert len(mesh.faces) == len(xy) - 2 + (3 if extra else 0)
    assert covered(mesh) == pytest.approx(shoelace(xy) + (1.5 if extra else 0), rel=0.02)


def test_a_convex_polygon_keeps_its_fan(tmp_path):
    need("trimesh")
    t = np.linspace(0, 2 * np.pi, 12, endpoint=False)
    (mesh,) = tm.load(polygon_obj(tmp_path / "round.obj", np.c_[np.cos(t), np.sin(t)]))
    assert mesh.faces.tolist() == [[0, i, i + 1] for i in range(1, 11)]


def fan_gltf(path, indexed: bool, material: dict = None) -> str:
    """A hexagon as one triangle fan (glTF mode 6), with texture coordinates."""
    import base64
    import json

    t = np.linspace(0, 2 * np.pi, 6, endpoint=False)
    xyz = np.c_[np.cos(t), np.sin(t), np.zeros(6)].astype(np.float32)
    uv = (xyz[:, :2] * 0.5 + 0.5).astype(np.float32)
    order = np.array([0, 1, 2, 3, 4, 5], np.uint16)[::-1 if indexed else 1].copy()
    blob = xyz.tobytes() + uv.tobytes() + (order.tobytes() if indexed else b"")
    primitive = {"attributes": {"POSITION": 0, "TEXCOORD_0": 1}, "mode": 6}
    doc = {"asset": {"version": "2.0"}, "scenes": [{"nodes": [0]}], "scene": 0, "nodes": [{"mesh": 0}],
           "meshes": [{"primitives": [primitive]}],
           "accessors": [{"bufferView": 0, "componentType": 5126, "count": 6, "type": "VEC3",
                          "min": xyz.min(axis=0).tolist(), "max": xyz.max(axis=0).tolist()},
                         {"bufferView": 1, "componentType": 5126, "count": 6, "type": "VEC2"}],
           "bufferViews": [{"buffer": 0, "byteLength": 72}, {"buffer": 0, "byteOffset": 72, "byteLength": 48}],
           "buffers": [{"byteLength": len(blob),
                        "uri": "data:application/octet-stream;base64," + base64.b64encode(blob).decode()}]}
    if indexed:
        doc["bufferViews"].append({"buffer": 0, "byteOffset": 120, "byteLength": 12})
        doc["accessors"].append({"bufferView": 2, "componentType": 5123, "count": 6, "type": "SCALAR"})
        primitive["indices"] = 2
    if material is not None:
        doc.update(material)
        primitive["material"] = 0
    path.write_text(json.dumps(doc))
    return str(path)


@pytest.mark.parametrize("indexed", [False, True])
def test_triangle_fans_are_drawn(tmp_path, indexed):
    need("trimesh")
    (mesh,) = tm.load(fan_gltf(tmp_path / "fan.gltf", indexed))
    assert len(mesh.faces) == 4
    assert covered(mesh) == pytest.approx(shoelace(mesh.vertices[:, :2]), rel=1e-6)  # the hexagon, once
    result = tm.render(str(tmp_path / "fan.gltf"), width=48, height=48)
    assert (np.any(result.color[..., :3] != result.color[0, 0, :3], axis=-1)).mean() > 0.2  # drawn, not refused


def test_a_specular_glossiness_material_draws_its_diffuse_texture(tmp_path):
    import base64
    import io

    Image = need("PIL.Image")
    need("trimesh")
    png = io.BytesIO()
    Image.new("RGB", (4, 4), (200, 40, 160)).save(png, format="PNG")
    material = {
        "extensionsUsed": ["KHR_materials_pbrSpecularGlossiness"],
        "materials": [{"extensions": {"KHR_materials_pbrSpecularGlossiness": {
            "diffuseTexture": {"index": 0}, "specularFactor": [0.2, 0.2, 0.2], "glossinessFactor": 0.5}}}],
        "textures": [{"source": 0}],
        "images": [{"uri": "data:image/png;base64," + base64.b64encode(png.getvalue()).decode()}],
    }
    with pytest.warns(UserWarning, match="not drawn: specular and glossiness"):
        (mesh,) = tm.load(fan_gltf(tmp_path / "glossy.gltf", False, material))
    texture = np.asarray(mesh.colors["texture"])
    assert np.allclose(texture[..., :3].reshape(-1, 3).mean(axis=0), (200, 40, 160), atol=2)


def test_a_glb_of_triangle_fans_keeps_its_binary_chunk(tmp_path):
    import base64
    import json
    import struct

    need("trimesh")
    doc = json.loads(open(fan_gltf(tmp_path / "fan.gltf", True)).read())
    blob = base64.b64decode(doc["buffers"][0].pop("uri").split(",", 1)[1])
    blob += b"\0" * (-len(blob) % 4)
    text = json.dumps(doc).encode()
    text += b" " * (-len(text) % 4)
    body = struct.pack("<II", len(text), 0x4E4F534A) + text + struct.pack("<II", len(blob), 0x004E4942) + blob
    (tmp_path / "fan.glb").write_bytes(b"glTF" + struct.pack("<II", 2, 12 + len(body)) + body)
    (glb,) = tm.load(str(tmp_path / "fan.glb"))
    (gltf,) = tm.load(str(tmp_path / "fan.gltf"))
    assert np.array_equal(glb.faces, gltf.faces) and np.array_equal(glb.vertices, gltf.vertices)
    assert len(glb.faces) == 4


MODEL_3MF = """<?xml version="1.0" encoding="UTF-8"?>
<model unit="millimeter" xmlns="http://schemas.microsoft.com/3dmanufacturing/core/2015/02">
 <resources>
  <object id="1" type="model"><mesh>
   <vertices><vertex x="0" y="0" z="0"/><vertex x="1" y="0" z="0"/><vertex x="0" y="1" z="0"/>
    <vertex x="0" y="0" z="1"/></vertices>
   <triangles><triangle v1="0" v2="2" v3="1"/><triangle v1="0" v2="1" v3="3"/><triangle v1="1" v2="2" v3="3"/>
    <triangle v1="0" v2="3" v3="2"/></triangles>
  </mesh></object>
  <object id="2" type="model"><components>
   <component objectid="1"/><component objectid="1" transform="1 0 0 0 1 0 0 0 1 3 0 0"/>
  </components></object>
 </resources>
 <build><item objectid="2"/><item objectid="1" transform="1 0 0 0 1 0 0 0 1 0 5 0"/></build>
</model>
"""


def test_a_3mf_places_its_components_and_build_items(tmp_path):
    import zipfile

    need("trimesh")
    path = tmp_path / "parts.3mf"
    with zipfile.ZipFile(path, "w") as z:
        z.writestr("[Content_Types].xml", '<?xml version="1.0"?><Types xmlns="http://schemas.openxmlformats.org/'
                   'package/2006/content-types"><Default Extension="model" ContentType="application/vnd.ms-'
                   'package.3dmanufacturing-3dmodel+xml"/></Types>')
        z.writestr("3D/3dmodel.model", MODEL_3MF)
    if os.environ.get("CI", "").lower() == "true":  # CI reads them; a user's machine may say what to install
        need("lxml")
        need("networkx")
    try:
        import lxml  # noqa: F401
        import networkx  # noqa: F401
    except ImportError as exc:  # the io extra's packages missing: one line that says what to install
        with pytest.raises(ImportError, match=rf"parts.3mf: reading .3mf files needs {exc.name}: pip install"):
            tm.load(str(path))
        return
    meshes = tm.load(str(path))
    # the component object's two parts and the plain build item: three tetrahedra, each where placed
    offsets = sorted(tuple(np.round(m.transform[:3, 3] if m.transform is not None else [0, 0, 0], 6))
                     for m in meshes)
    assert offsets == [(0, 0, 0), (0, 5, 0), (3, 0, 0)]


TETRAHEDRON_3MF = ('<mesh><vertices><vertex x="0" y="0" z="0"/><vertex x="1" y="0" z="0"/><vertex x="0" y="1" z="0"/>'
                   '<vertex x="0" y="0" z="1"/></vertices><triangles><triangle v1="0" v2="2" v3="1"/>'
                   '<triangle v1="0" v2="1" v3="3"/><triangle v1="1" v2="2" v3="3"/><triangle v1="0" v2="3" v3="2"/>'
                   '</triangles></mesh>')
CUBE_3MF = ("<mesh><vertices>" + "".join(f'<vertex x="{x}" y="{y}" z="{z}"/>' for x in (0, 2) for y in (0, 2)
                                         for z in (0, 2))
            + "</vertices><triangles>" + "".join(
                f'<triangle v1="{a}" v2="{b}" v3="{c}"/><triangle v1="{a}" v2="{c}" v3="{d}"/>'
                for a, b, c, d in [(0, 1, 3, 2), (4, 6, 7, 5), (0, 4, 5, 1), (2, 3, 7, 6), (0, 2, 6, 4), (1, 5, 7, 3)])
            + "</triangles></mesh>")
CORE_NS = "http://schemas.microsoft.com/3dmanufacturing/core/2015/02"
PRODUCTION_NS = "http://schemas.microsoft.com/3dmanufacturing/production/2015/06"


def production_3mf(path, items: int = 17, component_object: str = "2") -> str:
    """A 3MF of the production extension: a root object (id 1, as the part's first object) of
    two components that name objects 1 (a tetrahedron) and 2 (a cube, raised by 5) of another
    model part, /3D/Objects/part.model, placed by ``items`` build items 10 apart along x."""
    import zipfile

    part = (f'<?xml version="1.0" encoding="UTF-8"?><model unit="millimeter" xmlns="{CORE_NS}" '
            f'xmlns:p="{PRODUCTION_NS}"><resources><object id="1" type="model" p:UUID="a1">{TETRAHEDRON_3MF}</object>'
            f'<object id="2" type="model" p:UUID="a2">{CUBE_3MF}</object></resources></model>')
    build = "".join(f'<item objectid="1" transform="1 0 0 0 1 0 0 0 1 {10 * k} 0 0" p:UUID="b{k}"/>'
                    for k in range(items))
    root = (f'<?xml version="1.0" encoding="UTF-8"?><model unit="millimeter" xmlns="{CORE_NS}" '
            f'xmlns:p="{PRODUCTION_NS}" requiredextensions="p"><resources><object id="1" type="model" p:UUID="c1">'
            '<components><component p:path="/3D/Objects/part.model" objectid="1" p:UUID="d1"/>'
            f'<component p:path="/3D/Objects/part.model" objectid="{component_object}" '
            'transform="1 0 0 0 1 0 0 0 1 0 0 5" p:UUID="d2"/>'
            f'</components></object></resources><build p:UUID="e1">{build}</build></model>')
    rels = "http://schemas.openxmlformats.org/package/2006/relationships"
    kind = "http://schemas.microsoft.com/3dmanufacturing/2013/01/3dmodel"
    with zipfile.ZipFile(path, "w") as z:
        z.writestr("[Content_Types].xml", '<?xml version="1.0"?><Types xmlns="http://schemas.openxmlformats.org/'
                   'package/2006/content-types"><Default Extension="rels" ContentType="application/vnd.'
                   'openxmlformats-package.relationships+xml"/><Default Extension="model" ContentType='
                   '"application/vnd.ms-package.3dmanufacturing-3dmodel+xml"/></Types>')
        z.writestr("_rels/.rels", f'<?xml version="1.0"?><Relationships xmlns="{rels}"><Relationship '
                   f'Target="/3D/3dmodel.model" Id="r0" Type="{kind}"/></Relationships>')
        z.writestr("3D/_rels/3dmodel.model.rels", f'<?xml version="1.0"?><Relationships xmlns="{rels}">'
                   f'<Relationship Target="/3D/Objects/part.model" Id="r1" Type="{kind}"/></Relationships>')
        z.writestr("3D/3dmodel.model", root)
        z.writestr("3D/Objects/part.model", part)
    return str(path)


def test_a_3mf_of_the_production_extension_places_its_parts(tmp_path):
    need("trimesh")
    meshes = tm.load(production_3mf(tmp_path / "production.3mf"))
    # each of the 17 build items places both components, each with its own object of the part
    placed = sorted((len(m.faces), tuple(np.round(m.transform[:3, 3], 6))) for m in meshes)
    assert placed == sorted([(4, (10.0 * k, 0.0, 0.0)) for k in range(17)]
                            + [(12, (10.0 * k, 0.0, 5.0)) for k in range(17)])
    tetrahedra = [m for m in meshes if len(m.faces) == 4]
    assert all(m.vertices is tetrahedra[0].vertices for m in tetrahedra)  # one geometry, placed 17 times
    assert {m.up for m in meshes} == {"z"}


def test_a_3mf_naming_an_object_its_part_lacks_is_refused_in_one_line(tmp_path):
    need("trimesh")
    path = production_3mf(tmp_path / "missing.3mf", items=2, component_object="7")
    with pytest.raises(ValueError) as caught:
        tm.load(path)
    assert str(caught.value) == (f"{path}: component 2 of object 1 (/3D/3dmodel.model) names object 7 of "
                                 "/3D/Objects/part.model, which it does not define")


def test_a_polygon_far_from_flat_keeps_its_fan(tmp_path):
    need("trimesh")
    path = tmp_path / "bent.obj"  # a square with a corner lifted far out of its plane (as trimesh's polygonfaces.obj)
    path.write_text("v -1 0 1\nv 1 0 1\nv 1 0 -1\nv -1 0 -1\nv 0 1 -1\nf 1 2 3 4 5\n")
    (mesh,) = tm.load(str(path))
    assert mesh.faces.tolist() == [[0, 1, 2], [0, 2, 3], [0, 3, 4]]


@pytest.mark.parametrize("text", [
    "v 0 0 0\nv 9 9 9\nv 1 0 0\nv 0 1 0\nv 1 1 0\nf 1 3 4\nf 5 4 3\n",  # a vertex no face names
    "# made by hand\r\nv 0 0 0\r\nv 1e0 0 0\r\nv 0 1.00000000000000001 0\r\nf 1 2 3\r\nf 1 2 3",  # CRLF, no end
])
def test_an_obj_of_positions_and_triangles_reads_as_trimesh_reads_it(tmp_path, text):
    trimesh = need("trimesh")
    path = tmp_path / "plain.obj"
    path.write_bytes(text.encode())
    (mesh,) = tm.load(str(path))  # read once, by the checks' scan
    ref = trimesh.load(str(path), process=False, maintain_order=True)
    assert mesh.vertices.dtype == np.float64 and mesh.faces.dtype == np.int64
    assert np.array_equal(mesh.vertices, ref.vertices) and np.array_equal(mesh.faces, ref.faces)
    assert mesh.name == "" and mesh.normals == "auto" and not carries_colour(mesh)


def test_the_meshes_of_the_tests_read_as_trimesh_reads_them():
    trimesh = need("trimesh")
    folder = os.path.join(os.path.dirname(__file__), "data", "meshes")
    for name in ("cow.obj", "teapot.obj", "fandisk.obj"):  # positions and triangles alone
        (mesh,) = tm.load(os.path.join(folder, name))
        ref = trimesh.load(os.path.join(folder, name), process=False, maintain_order=True)
        assert np.array_equal(mesh.vertices, ref.vertices) and np.array_equal(mesh.faces, ref.faces), name


def test_a_sparse_accessor_replaces_the_values_it_names():
    need("trimesh")
    path = os.path.join(os.path.dirname(__file__), "data", "corpus", "khronos", "SimpleSparseAccessor.gltf")
    (mesh,) = tm.load(path)  # a strip of 14 vertices, three of them raised by the sparse accessor
    assert mesh.vertices[[8, 10, 12]].tolist() == [[1, 2, 0], [3, 3, 0], [5, 4, 0]]
    assert mesh.vertices.max(axis=0).tolist() == [6, 4, 0]  # the accessor's own max

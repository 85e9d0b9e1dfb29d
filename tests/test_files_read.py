"""Files that trimesh reads wrongly, half-reads or reads without a word: OBJ negative indices,
faces naming texture coordinates or normals the file lacks, missing MTL, texture and buffer
files, warnings raised while reading, archives and compressed files, colours that are not numbers
and meshes without area. Each is written here, at run time, into tmp_path.
"""

from __future__ import annotations

import gzip
import json
import os
import struct
import tarfile
import warnings
import zipfile

import numpy as np
import pytest

import toonmesh as tm
from conftest import need
from toonmesh.files import _archives

QUAD = "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\n"


def read(path):
    """(meshes, the warnings' texts) of tm.load(path)."""
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        meshes = tm.load(str(path))
    return meshes, [str(w.message) for w in caught]


def write(path, text):
    path.write_bytes(text.encode() if isinstance(text, str) else text)
    return str(path)


def triangle_ply(path, properties, values, comment=""):
    """An ASCII PLY of one triangle whose vertices carry the float ``properties`` with
    ``values`` (a row per vertex), and a header ``comment``."""
    head = ["ply", "format ascii 1.0"] + ([f"comment {comment}"] if comment else []) + ["element vertex 3"]
    head += [f"property float {name}" for name in ["x", "y", "z"] + properties]
    head += ["element face 1", "property list uchar int vertex_indices", "end_header"]
    rows = [" ".join(str(float(x)) for x in [*p, *v]) for p, v in zip([[0, 0, 0], [1, 0, 0], [0, 1, 0]], values)]
    return write(path, "\n".join(head + rows + ["3 0 1 2"]) + "\n")


def glb(path, V, F, colors=None, uri=None):
    """A one-triangle-list glTF by hand: float positions, uint32 indices and optional float
    COLOR_0, in a GLB or (with ``uri``) a .gltf whose buffer is the file ``uri``, not written."""
    V, F = np.asarray(V, np.float32), np.asarray(F, np.uint32).ravel()
    blobs, attributes = [V.tobytes(), F.tobytes()], {"POSITION": 0}
    accessors = [{"bufferView": 0, "componentType": 5126, "count": len(V), "type": "VEC3",
                  "min": V.min(0).tolist(), "max": V.max(0).tolist()},
                 {"bufferView": 1, "componentType": 5125, "count": len(F), "type": "SCALAR"}]
    if colors is not None:
        C = np.asarray(colors, np.float32)
        blobs.append(C.tobytes())
        attributes["COLOR_0"] = 2
        accessors.append({"bufferView": 2, "componentType": 5126, "count": len(C), "type": f"VEC{C.shape[1]}"})
    views, offset = [], 0
    for b in blobs:
        views.append({"buffer": 0, "byteOffset": offset, "byteLength": len(b)})
        offset += len(b)
    binary = b"".join(blobs)
    doc = {"asset": {"version": "2.0"}, "scene": 0, "scenes": [{"nodes": [0]}], "nodes": [{"mesh": 0}],
           "meshes": [{"primitives": [{"attributes": attributes, "indices": 1}]}], "accessors": accessors,
           "bufferViews": views, "buffers": [{"byteLength": len(binary)}]}
    if uri is not None:
        doc["buffers"][0]["uri"] = uri
        path.write_text(json.dumps(doc))
        return str(path), binary
    text = json.dumps(doc).encode()
    text += b" " * (-len(text) % 4)
    binary += b"\0" * (-len(binary) % 4)
    body = struct.pack("<II", len(text), 0x4E4F534A) + text + struct.pack("<II", len(binary), 0x004E4942) + binary
    path.write_bytes(b"glTF" + struct.pack("<II", 2, 12 + len(body)) + body)
    return str(path), binary


def image(path, rgb=(200, 30, 30)):
    Image = need("PIL.Image")
    Image.new("RGB", (4, 4), rgb).save(str(path))


# ------------------------------------------------------------------------------------------------
# OBJ indices


def test_obj_negative_indices_count_back_from_the_entries_before_the_face(tmp_path):
    need("trimesh")
    # each face counts back from what is listed before it (trimesh counts from the file's end)
    text = ("v 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0 0\nvt 1 0\nvt 0 1\nvn 0 0 1\nf -3/-3/-1 -2/-2/-1 -1/-1/-1\n"
            "v 0 0 1\nv 1 0 1\nv 0 1 1\nvt 0.5 0.5\nvt 1 1\nvt 0 0.5\nf -3/-3 -2/-2 -1/-1\nf -6//-1 -5//-1 -4//-1\n")
    (m,), said = read(write(tmp_path / "neg.obj", text))
    assert said == []
    corners = m.vertices[m.faces]
    np.testing.assert_array_equal(corners[0], [[0, 0, 0], [1, 0, 0], [0, 1, 0]])
    np.testing.assert_array_equal(corners[1], [[0, 0, 1], [1, 0, 1], [0, 1, 1]])
    np.testing.assert_array_equal(corners[2], corners[0])
    # the same file with positive indices reads the same
    positive = ("v 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0 0\nvt 1 0\nvt 0 1\nvn 0 0 1\nf 1/1/1 2/2/1 3/3/1\n"
                "v 0 0 1\nv 1 0 1\nv 0 1 1\nvt 0.5 0.5\nvt 1 1\nvt 0 0.5\nf 4/4 5/5 6/6\nf 1//1 2//1 3//1\n")
    (p,), _ = read(write(tmp_path / "pos.obj", positive))
    np.testing.assert_array_equal(p.vertices[p.faces], corners)
    # past the entries before the face: still refused, naming the line
    with pytest.raises(ValueError, match=r"bad\.obj: line 4: face index -4 points past the 3 vertices"):
        tm.load(write(tmp_path / "bad.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf -1 -2 -4\n"))


@pytest.mark.parametrize("kind, faces, first, named", [
    ("vt", "vt 0 0\nvt 1 0\nf 1/1 2/2 3/2\nf 1/1 3/5 4/9\nf 1/1 2/7 3/1\n", 8, "texture coordinate 5, of 2 listed"),
    ("vt", "vt 0 0\nf 1/1 2/1 3/1\nf 1/-4 3/1 4/1\nf 1/3 3/1 4/1\n", 7, "texture coordinate -4, of 1 listed"),
    ("vn", "f 1//1 2//1 3//1\nf 1//1 3//1 4//1\n", 5, "normal 1, of 0 listed"),
    ("vn", "vn 0 0 1\nf 1/1/1 2/1/1 3/1/1\nvt 0 0\nf 1/1/1 3/1/1 4/1/2\n", 8, "normal 2, of 1 listed"),
])
def test_faces_naming_missing_uvs_or_normals_keep_their_positions_with_one_warning(tmp_path, kind, faces, first,
                                                                                   named):
    need("trimesh")
    (m,), said = read(write(tmp_path / "m.obj", QUAD + faces))
    assert len(said) == 1 and f"m.obj: line {first}: a face names {named}" in said[0], said
    assert "positions kept" in said[0]
    # every face, at the positions it names
    corners = [[int(c.split("/")[0]) - 1 for c in line.split()[1:]] for line in faces.splitlines() if line[0] == "f"]
    quad = np.array([[0, 0, 0], [1, 0, 0], [1, 1, 0], [0, 1, 0]], np.float64)
    np.testing.assert_array_equal(m.vertices[m.faces], quad[corners])


def test_the_first_face_past_the_file_s_entries_is_the_line_named(tmp_path):
    """The face with the largest index is not the first that points past the entries."""
    text = QUAD + "f 1 2 3\nf 1 2 6\nf 1 2 40\n"
    with pytest.raises(ValueError, match=r"m\.obj: line 6: face index 6 points past the 4 vertices in the file"):
        tm.load(write(tmp_path / "m.obj", text))


# ------------------------------------------------------------------------------------------------
# Files a file names


def test_a_missing_mtl_or_texture_is_named_with_the_path_tried(tmp_path):
    need("trimesh")
    textured = QUAD + "vt 0 0\nvt 1 0\nvt 1 1\nusemtl red\nf 1/1 2/2 3/3\n"
    path = write(tmp_path / "nomtl.obj", "mtllib gone.mtl\n" + textured)
    _, said = read(path)
    assert said == [f"{path}: MTL file {tmp_path / 'gone.mtl'} not found: its materials (colours, textures) are "
                    "not drawn"]
    write(tmp_path / "m.mtl", "newmtl red\nKd 1 0 0\nmap_Kd textures/red.png\n")
    path = write(tmp_path / "notex.obj", "mtllib m.mtl\n" + textured)
    (m,), said = read(path)
    assert said == [f"{path}: texture of material 'red' {tmp_path / 'textures/red.png'} not found: not drawn"]
    assert "texture" not in m.colors
    (tmp_path / "textures").mkdir()
    (tmp_path / "textures" / "red.png").write_bytes(b"not an image")
    _, said = read(path)
    assert len(said) == 1 and "red.png cannot be read as an image" in said[0]
    image(tmp_path / "textures" / "red.png")
    (m,), said = read(path)
    assert said == [] and "texture" in m.colors
    # a PLY's texture (comment TextureFile) and a glTF's image file
    path = triangle_ply(tmp_path / "skin.ply", ["s", "t"], [[0, 0], [1, 0], [0, 1]], "TextureFile skin.png")
    _, said = read(path)
    assert said == [f"{path}: texture {tmp_path / 'skin.png'} not found: not drawn"]
    path, binary = glb(tmp_path / "pic.gltf", [[0, 0, 0], [1, 0, 0], [0, 1, 0]], [[0, 1, 2]], uri="pic.bin")
    (tmp_path / "pic.bin").write_bytes(binary)
    doc = json.loads((tmp_path / "pic.gltf").read_text())
    doc["images"] = [{"uri": "maps/albedo.png"}]
    (tmp_path / "pic.gltf").write_text(json.dumps(doc))
    _, said = read(path)
    assert said == [f"{path}: image 0 {tmp_path / 'maps/albedo.png'} not found: not drawn"]


def test_a_gltf_without_its_buffer_file_names_the_path_tried(tmp_path):
    need("trimesh")
    path, binary = glb(tmp_path / "TestScene.gltf", [[0, 0, 0], [1, 0, 0], [0, 1, 0]], [[0, 1, 2]], uri="TestScene.bin")
    with pytest.raises(ValueError) as e:
        tm.load(path)
    assert str(e.value) == f"{path}: buffer 0 is read from {tmp_path / 'TestScene.bin'}, which is not there"
    (tmp_path / "TestScene.bin").write_bytes(binary[:-4])
    with pytest.raises(ValueError, match=r"TestScene\.gltf: buffer 0 \(.*TestScene\.bin\) holds 44 bytes but the glTF "
                                         r"claims 48: truncated"):
        tm.load(path)
    (tmp_path / "TestScene.bin").write_bytes(binary)
    (m,), said = read(path)
    assert said == [] and len(m.faces) == 1
    # a name written with percent-escapes (as URIs are) is found as the file it names
    os.rename(tmp_path / "TestScene.bin", tmp_path / "Test Scene.bin")
    doc = json.loads((tmp_path / "TestScene.gltf").read_text())
    doc["buffers"][0]["uri"] = "Test%20Scene.bin"
    (tmp_path / "TestScene.gltf").write_text(json.dumps(doc))
    (m,), said = read(path)
    assert said == [] and len(m.faces) == 1


# ------------------------------------------------------------------------------------------------
# Warnings


def test_warnings_raised_while_reading_carry_the_file_name(tmp_path, monkeypatch, caplog):
    trimesh = need("trimesh")
    real = trimesh.load

    def noisy(*args, **kwargs):  # as trimesh does on some files (NumPy's nanmedian over unused vertices)
        warnings.warn("All-NaN slice encountered", RuntimeWarning)
        trimesh.util.log.warning("id 1 included but not defined!")
        return real(*args, **kwargs)

    monkeypatch.setattr(trimesh, "load", noisy)
    path = write(tmp_path / "line.obj", "v 0 0 0\nv 1 0 0\nv 2 0 0\nf 1 2 3\n")
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        tm.load(path)
    # toonmesh's own warning names the file; NumPy's and trimesh's noise never reaches the user
    assert [(str(w.message), w.category) for w in caught] == [
        (f"{path}: the mesh has no area (1 faces, their corners in a line or at one point): nothing to draw",
         UserWarning)]
    assert caught[0].filename == __file__  # shown where the caller loads the file
    assert not [r for r in caplog.records if r.name.startswith("trimesh")]
    monkeypatch.undo()
    flat = trimesh.Scene()
    flat.add_geometry(trimesh.Trimesh([[0, 0, 0], [1, 0, 0], [2, 0, 0]], [[0, 1, 2]], process=False), geom_name="flat")
    with pytest.warns(UserWarning, match="scene: mesh 'flat' has no area"):  # a scene's warnings name it too
        tm.render(flat, width=8, height=8)


# ------------------------------------------------------------------------------------------------
# Archives and compressed files


def test_zip_tar_and_compressed_files_are_read_like_the_plain_ones(tmp_path):
    trimesh = need("trimesh")
    box = trimesh.creation.box()
    box.export(str(tmp_path / "box.stl"))
    plain = tm.load(str(tmp_path / "box.stl"))
    assert len(plain[0].vertices) == 8  # an STL's corners merged
    stl = (tmp_path / "box.stl").read_bytes()
    with zipfile.ZipFile(tmp_path / "box.zip", "w") as z:
        z.writestr("parts/box.stl", stl)
        z.writestr("readme.txt", "not a mesh")
    (tmp_path / "box.stl.gz").write_bytes(gzip.compress(stl))
    with tarfile.open(tmp_path / "box.tar.gz", "w:gz") as t:
        t.add(str(tmp_path / "box.stl"), "box.stl")
    for name in ("box.zip", "box.stl.gz", "box.tar.gz"):
        (m,), said = read(tmp_path / name)
        assert said == [], name
        np.testing.assert_array_equal(m.vertices, plain[0].vertices)
        np.testing.assert_array_equal(m.faces, plain[0].faces)
    # an OBJ with its MTL and texture in a zip: the texture is found beside it
    image(tmp_path / "red.png")
    with zipfile.ZipFile(tmp_path / "textured.zip", "w") as z:
        z.writestr("m/t.obj", "mtllib t.mtl\n" + QUAD + "vt 0 0\nvt 1 0\nvt 1 1\nusemtl red\nf 1/1 2/2 3/3\n")
        z.writestr("m/t.mtl", "newmtl red\nmap_Kd red.png\n")
        z.write(tmp_path / "red.png", "m/red.png")
        z.writestr("../outside.obj", QUAD + "f 1 2 3\n")  # a name leaving the folder: not unpacked
    (m,), said = read(tmp_path / "textured.zip")
    assert said == [] and "texture" in m.colors
    # what goes wrong inside names the archive and the file in it
    with zipfile.ZipFile(tmp_path / "broken.zip", "w") as z:
        z.writestr("a/cut.obj", QUAD + "f 1 2 3\nf 1 3")
    with pytest.raises(ValueError, match=r"broken\.zip:a/cut\.obj: line 6: a face needs 3 or more corners"):
        tm.load(str(tmp_path / "broken.zip"))
    with zipfile.ZipFile(tmp_path / "none.zip", "w") as z:
        z.writestr("notes.txt", "hello")
    with pytest.raises(ValueError, match=r"none\.zip: no mesh file inside \(it holds notes\.txt\)"):
        tm.load(str(tmp_path / "none.zip"))
    (tmp_path / "bad.zip").write_bytes(b"PK not really")
    with pytest.raises(ValueError, match=r"bad\.zip: cannot unpack"):
        tm.load(str(tmp_path / "bad.zip"))


def test_an_archive_unpacking_to_more_than_the_limit_is_refused(tmp_path, monkeypatch):
    need("trimesh")
    monkeypatch.setattr(_archives, "MAX_UNPACKED", 1000)
    (tmp_path / "big.obj.gz").write_bytes(gzip.compress(b"# " + b"x" * 5000 + b"\n" + QUAD.encode()))
    with pytest.raises(ValueError, match=r"big\.obj\.gz: unpacks to more than 1,000 bytes"):
        tm.load(str(tmp_path / "big.obj.gz"))


# ------------------------------------------------------------------------------------------------
# Colours that are not numbers, meshes without area


def test_colours_that_are_not_numbers_are_named(tmp_path):
    need("trimesh")
    path = write(tmp_path / "c.obj", "v 0 0 0 1 0 0\nv 1 0 0 nan nan nan\nv 0 1 0 0 0 1\nf 1 2 3\n")
    (m,), said = read(path)
    assert said == [f"{path}: line 2: vertex 2's colour is not a number (nan nan nan): drawn black"]
    path = triangle_ply(tmp_path / "c.ply", ["red", "green", "blue"], [[1, 0, 0], [0, 1, 0], [np.nan, 0, 1]])
    _, said = read(path)
    assert said == [f"{path}: 1 vertex colours are not numbers (the first of vertex 3): drawn black"]
    path, _ = glb(tmp_path / "c.glb", [[0, 0, 0], [1, 0, 0], [0, 1, 0]], [[0, 1, 2]],
                  colors=[[1, 0, 0, 1], [np.nan, 0, 0, 1], [0, 0, 1, np.nan]])
    _, said = read(path)
    assert said == [f"{path}: mesh 0 primitive 0: 2 vertex colours are not numbers (the first of vertex 2): "
                    "drawn black"]
    write(tmp_path / "k.mtl", "newmtl paint\nKd nan 0.5 0.5\n")
    path = write(tmp_path / "k.obj", "mtllib k.mtl\nusemtl paint\n" + QUAD + "f 1 2 3\n")
    _, said = read(path)
    assert said == [f"{path}: {tmp_path / 'k.mtl'}: material 'paint': Kd nan 0.5 0.5 is not a colour: drawn black"]


def test_a_mesh_without_area_is_named(tmp_path):
    need("trimesh")
    path = write(tmp_path / "line.obj", "v 0 0 0\nv 1 1 1\nv 2 2 2\nv 5 5 5\nf 1 2 3\nf 2 3 4\n")
    _, said = read(path)
    assert said == [f"{path}: the mesh has no area (2 faces, their corners in a line or at one point): nothing to draw"]
    path = write(tmp_path / "tiny.obj", "v 0 0 0\nv 1e-9 0 0\nv 0 1e-9 0\nf 1 2 3\n")  # small, not flat: drawn
    assert read(path)[1] == []

"""Files others wrote that cannot be read: each refused in one line naming the file and what is
wrong (never a traceback, never a Python or NumPy message), in ``tm.load`` and on the command
line; and what is read says nothing that is not toonmesh's, naming the file."""

from __future__ import annotations

import base64
import json
import struct
import warnings

import numpy as np
import pytest

import toonmesh as tm
from conftest import need
from test_cli import in_process, one_line_error

#: Words of Python's and NumPy's own messages, which must never reach the user.
INTERNALS = ("object has no attribute", "dictionary update sequence", "list index out of range", "KeyError",
             "TypeError", "NoneType", "All-NaN slice", "invalid value encountered", "Traceback", "is not subscriptable")


def gltf_doc() -> dict:
    """A minimal glTF 2.0 document: one triangle, its buffer inside as base64."""
    positions = np.array([[0, 0, 0], [1, 0, 0], [0, 1, 0]], np.float32).tobytes()
    return {
        "asset": {"version": "2.0"}, "scene": 0, "scenes": [{"nodes": [0]}], "nodes": [{"mesh": 0}],
        "meshes": [{"primitives": [{"attributes": {"POSITION": 0}}]}],
        "accessors": [{"bufferView": 0, "componentType": 5126, "count": 3, "type": "VEC3",
                       "min": [0, 0, 0], "max": [1, 1, 0]}],
        "bufferViews": [{"buffer": 0, "byteLength": len(positions)}],
        "buffers": [{"byteLength": len(positions),
                     "uri": "data:application/octet-stream;base64," + base64.b64encode(positions).decode()}],
    }


def write_gltf(path, doc) -> str:
    path.write_text(json.dumps(doc))
    return str(path)


def refused(path: str, *words: str) -> str:
    """The one-line message ``tm.load`` refuses ``path`` with; it names the file and ``words``."""
    need("trimesh")
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        with pytest.raises(ValueError) as info:
            tm.load(path)
    text = str(info.value)
    assert "\n" not in text and text.startswith(path), text
    for w in words:
        assert w in text, text
    assert not any(i in text for i in INTERNALS), text
    assert not caught, [str(w.message) for w in caught]
    return text


def test_a_good_gltf_reads(tmp_path):
    need("trimesh")
    (mesh,) = tm.load(write_gltf(tmp_path / "ok.gltf", gltf_doc()))
    assert mesh.faces.shape == (1, 3)


@pytest.mark.parametrize("change, words", [
    (lambda d: d["meshes"][0].update(primitives="triangles"), "meshes[0].primitives: expected an array, got a string"),
    (lambda d: d.update(meshes={"a": d["meshes"][0]}), "meshes: expected an array, got an object"),
    (lambda d: d["meshes"][0]["primitives"][0].update(attributes=[0]),
     "meshes[0].primitives[0].attributes: expected an object, got an array"),
    (lambda d: d["meshes"][0]["primitives"][0]["attributes"].update(POSITION="0"),
     "meshes[0].primitives[0].attributes.POSITION: expected an index (an integer 0 or more), got a string"),
    (lambda d: d["nodes"][0].update(mesh=4), "nodes[0].mesh: index 4 names no entry of 'meshes' (it has 1)"),
    (lambda d: d["nodes"][0].update(matrix=[1, 0, 0]), "nodes[0].matrix: expected 16 numbers, got 3"),
    (lambda d: d["accessors"].__setitem__(0, "positions"), "accessors[0]: expected an object, got a string"),
])
def test_a_gltf_of_the_wrong_shape_names_the_json_path(tmp_path, change, words):
    doc = gltf_doc()
    change(doc)
    refused(write_gltf(tmp_path / "odd.gltf", doc), words)


def test_a_glb_of_the_wrong_shape_names_the_json_path(tmp_path):
    doc = gltf_doc()
    doc["meshes"][0]["primitives"] = "triangles"
    body = json.dumps(doc).encode().ljust(4 * ((len(json.dumps(doc)) + 3) // 4))
    glb = tmp_path / "odd.glb"
    glb.write_bytes(b"glTF" + struct.pack("<II", 2, 12 + 8 + len(body)) + struct.pack("<II", len(body), 0x4E4F534A)
                    + body)
    refused(str(glb), "meshes[0].primitives: expected an array, got a string")


def png_bytes() -> bytes:
    from toonmesh import _core

    return bytes(_core.encode_png_rgba(np.zeros((2, 2, 4), np.uint8)))


@pytest.mark.parametrize("name, content, words", [
    ("image.stl", "png", "not an STL file: it starts like a PNG image"),
    ("notes.stl", b"hello there\nnothing here\n", "not an STL file: it starts like text ('hello there')"),
    ("image.obj", "png", "not an OBJ file: it starts like a PNG image"),
    ("page.obj", b"<!DOCTYPE html><html></html>\n", "not an OBJ file: it starts like an HTML page"),
    ("image.ply", "png", "not a PLY file: it starts like a PNG image"),
    ("archive.off", b"PK\x03\x04" + bytes(40), "not an OFF file: it starts like a zip archive"),
    ("mesh.gltf", "png", "not a glTF file: it starts like a PNG image"),
    ("mesh.glb", b"ply\nformat ascii 1.0\n", "not a GLB file: it starts like a PLY file"),
    ("empty.stl", b"", "the file is empty"),
    ("empty.obj", b"", "the file is empty"),
    ("blank.gltf", b"  \n\n", "the file is empty (4 blank bytes)"),
])
def test_a_file_not_of_its_suffixs_format_says_what_it_looks_like(tmp_path, name, content, words):
    path = tmp_path / name
    path.write_bytes(png_bytes() if content == "png" else content)
    refused(str(path), words)


def test_the_command_line_says_the_same_in_one_line(tmp_path, capsys):
    need("trimesh")
    doc = gltf_doc()
    doc["meshes"][0]["primitives"] = "triangles"
    odd = write_gltf(tmp_path / "odd.gltf", doc)
    image = tmp_path / "image.stl"
    image.write_bytes(png_bytes())
    for path, words in ((odd, "meshes[0].primitives: expected an array, got a string"),
                        (str(image), "not an STL file: it starts like a PNG image")):
        for command in (["render", path, "-o", str(tmp_path / "x.png")], ["smooth", path, str(tmp_path / "y.obj")],
                        ["edges", path, "-o", str(tmp_path / "z.svg")]):
            line = one_line_error(in_process(capsys, *command, check=False), path, words)
            assert not any(i in line for i in INTERNALS), line


def test_the_renderers_warnings_on_a_files_mesh_name_the_file(tmp_path):
    need("trimesh")
    sheet = tmp_path / "sheet.obj"  # a square stored double-sided: the renderer draws each pair once
    sheet.write_text("v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nf 1 2 3\nf 1 3 4\nf 3 2 1\nf 4 3 1\n")
    with pytest.warns(UserWarning) as caught:
        tm.render(str(sheet), width=16, height=16)
    (back,) = [str(w.message) for w in caught if "back to back" in str(w.message)]
    assert back.startswith(f"{sheet}: 2 of the 4 faces lie back to back"), back

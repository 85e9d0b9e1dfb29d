"""Files from other projects' test suites (tests/data/corpus, their sources and licences in its
README.md): each is drawn, or refused in one line naming the file; no traceback, no Python or
NumPy words, no warning that does not name the file, nothing from trimesh's log."""

from __future__ import annotations

import logging
import os
import warnings
from pathlib import Path

import pytest

import toonmesh as tm
from conftest import need
from test_files_errors import INTERNALS

CORPUS = Path(__file__).resolve().parent / "data" / "corpus"
#: Files that name others (read with them), not read on their own.
BESIDE = (".bin", ".mtl", ".md", ".png", ".jpg")

#: What each file gives: (meshes, faces) drawn, (meshes, faces, points, line segments) for a
#: file with points or lines, or the words of its refusal.
EXPECTED = {
    "7_8ths_cube.stl": (1, 24), "BoxInterleaved.glb": (1, 12), "Mesh_PrimitiveMode_04.gltf": (1, 2),
    "box.obj": (2, 12), "comments.off": (1, 12), "cube.OBJ": (1, 12), "cube.glb": (1, 12),
    "cube_blender_uv.ply": (1, 12), "cube_compressed.obj": (1, 12), "cubevc.glb": (1, 48), "cubevt.obj": (1, 12),
    "empty.obj": "no triangles in the file", "empty.ply": "no triangles in the file",
    "empty.stl": "no triangles in the file", "face_in_group_name.obj": (0, 0, 1, 0),
    "featuretype.3MF": (1, 2208), "jacked.obj": (1, 12), "joined_tetrahedra.obj": (1, 8), "metadata.ply": (1, 2),
    "multi.ply": (1, 2), "nancolor.obj": (1, 12), "negative_indices.obj": (1, 12), "nested.glb": (3, 36),
    "no_indices_3storybuilding.glb": (3, 72), "not_convex.obj": (1, 96),
    "notenoughindices.obj": "line 9: a face needs 3 or more corners, got 2",
    "obj_points.obj": (0, 0, 8, 0), "obj_wireframe.obj": (0, 0, 0, 12), "plane.ply": (1, 2),
    "ply_points_bin.ply": (0, 0, 8, 0), "points_ascii.ply": (0, 0, 5, 0), "points_bin.ply": (0, 0, 5, 0),
    "points_emptyface.ply": (0, 0, 1024, 0), "points_agisoft.xyz": (0, 0, 100, 0),
    "points_cloudcompare.xyz": (0, 0, 101, 0),
    "polygonfaces.obj": (1, 3), "pyramids.3mf": (12, 3276), "rgb_cube_with_primitives.gltf": (3, 12),
    "singlevn.obj": (1, 2), "soup.stl": (1, 100), "stl_empty_bin.stl": "no triangles in the file",
    "testplate.glb": (1, 264), "tet.ply": (1, 4), "textured_tetrahedron.obj": (1, 4), "two_objects.obj": (1, 16),
    "unit_cube.STL": (1, 12), "wallhole.obj": (1, 66), "whitespace.off": (1, 12),
    # khronos/: glTF sample assets (cameras, morph targets and animations named as not drawn)
    "Cameras.gltf": (1, 2), "SimpleMeshes.gltf": (2, 2), "SimpleMorph.gltf": (1, 1),
    "SimpleSparseAccessor.gltf": (1, 12), "TriangleWithoutIndices.gltf": (1, 1),
    # every primitive mode: triangles, a strip and a fan; points; lines, a line loop and a strip
    "MeshPrimitiveModes.gltf": (3, 6 + 4 + 6, 7, 6 + 7 + 6),
    # pdal/: point clouds from PDAL's tests
    "text_extradim.ply": (0, 0, 1, 0), "simple_binary.ply": (0, 0, 3, 0),
}

FILES = sorted(p for p in CORPUS.rglob("*") if p.is_file() and not p.name.endswith(BESIDE))


def test_the_corpus_is_held_whole():
    assert sorted(p.name for p in FILES) == sorted(EXPECTED)


@pytest.mark.parametrize("path", FILES, ids=[p.name for p in FILES])
def test_each_file_is_drawn_or_refused_in_one_line(path, caplog):
    need("trimesh")
    expected = EXPECTED[path.name]
    if path.suffix.lower() == ".3mf":
        if os.environ.get("CI", "").lower() == "true":  # CI reads them; a user's machine may say what to install
            need("lxml")
            need("networkx")
        try:
            import lxml  # noqa: F401
            import networkx  # noqa: F401
        except ImportError as exc:
            expected = f"reading .3mf files needs {exc.name}: pip install 'toonmesh[io]'"
    caplog.set_level(logging.DEBUG)
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        try:
            items = tm.load(str(path))
            meshes = [m for m in items if isinstance(m, tm.Mesh)]
            got = (len(meshes), sum(len(m.faces) for m in meshes))
            if len(meshes) < len(items):
                got += (sum(len(p) for p in items if isinstance(p, tm.Points)),
                        sum(len(s) for s in items if isinstance(s, tm.Lines)))
        except (ValueError, ImportError) as exc:
            got = str(exc)
            assert "\n" not in got and got.startswith(f"{path}: ") and not any(i in got for i in INTERNALS), got
            got = got[len(f"{path}: "):]
    if isinstance(expected, str):
        assert isinstance(got, str) and got.startswith(expected), got
    else:
        assert got == expected
    assert all(str(w.message).startswith(str(path)) for w in caught), [str(w.message) for w in caught]
    assert not [r for r in caplog.records if r.name.startswith("trimesh") and r.levelno >= logging.WARNING]

"""The meshes shipped in ``toonmesh.data``: each is the repository's test copy, read the same way,
and the package stays small (the shipped meshes other than the bunny: a few hundred KB)."""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest

import toonmesh.data as data

ROOT = Path(__file__).resolve().parent.parent
#: bytes the shipped meshes besides the bunny may take in the wheel
EXTRA_BUDGET = 300_000


@pytest.mark.parametrize("name, vertices, faces", [("fandisk", 6475, 12946), ("cow", 2903, 5804)])
def test_a_shipped_mesh_is_the_test_meshes_copy(name, vertices, faces):
    V, F = getattr(data, name)()
    assert V.shape == (vertices, 3) and V.dtype == np.float64
    assert F.shape == (faces, 3) and F.dtype == np.int64
    assert F.min() == 0 and F.max() == vertices - 1
    V2, F2 = data.load_obj(ROOT / "tests" / "data" / "meshes" / f"{name}.obj")
    np.testing.assert_array_equal(V, V2)
    np.testing.assert_array_equal(F, F2)


def test_the_shipped_meshes_besides_the_bunny_stay_small():
    folder = Path(data.__file__).parent
    extra = {p.name: p.stat().st_size for p in folder.iterdir()
             if p.is_file() and p.suffix not in (".py", ".pyc", ".md") and p.name != "bunny.obj"}
    assert {"fandisk.obj.gz", "cow.obj.gz"} <= set(extra), extra
    assert sum(extra.values()) < EXTRA_BUDGET, extra
    readme = (folder / "README.md").read_text()
    assert all(name in readme for name in extra), "every shipped file is described, with its source"

"""Snapshot tests with ``toon_snapshot``.

The pytest fixture ``toon_snapshot`` holds a render to a reference image kept beside the test.
This script writes a small test file, runs pytest on it with ``--toon-update`` (which writes the
reference), changes the material and runs it again: the test fails, and the fixture leaves the
actual image and a difference image beside the reference. The strip shows the three: the
reference, the actual and the difference.
"""

import subprocess
import sys
from pathlib import Path

import numpy as np
from PIL import Image

from toonmesh.figures import panels

TEST = """
import toonmesh as tm

COLOUR = "{colour}"


def test_bunny(toon_snapshot):
    V, F = tm.shapes.icosphere(3, noise=0.02, seed=1)
    material = tm.Material.bands(COLOUR)
    r = tm.render(V, F, material=material, outlines="mesh", width=160, height=160)
    toon_snapshot(r)
"""


folder = Path("snapshot_tests")
folder.mkdir(exist_ok=True)
(folder / "test_look.py").write_text(TEST.format(colour="#f08a3c"))
pytest = [
    sys.executable,
    "-m",
    "pytest",
    "-q",
    "-p",
    "no:cacheprovider",
    "-p",
    "toonmesh.pytest_plugin",
    str(folder),
]
subprocess.run(
    pytest + ["--toon-update"], check=True
)  # writes __snapshots__/test_bunny.png
(folder / "test_look.py").write_text(
    TEST.format(colour="#3c8af0")
)  # a change of look ...
failed = subprocess.run(
    pytest, capture_output=True, text=True
)  # ... fails the test, naming the difference
assert failed.returncode == 1, failed.stdout
print(failed.stdout.splitlines()[-1])
shots = folder / "__snapshots__"
print(sorted(p.name for p in shots.iterdir()))
names = {
    "test_bunny.png": "reference",
    "test_bunny.actual.png": "actual",
    "test_bunny.diff.png": "difference",
}
strip = [np.asarray(Image.open(shots / name).convert("RGB")) for name in names]
Image.fromarray(panels(strip, list(names.values()))).save("snapshot.png")

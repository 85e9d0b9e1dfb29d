"""A frame reads back its own images, not the last frame's, on both backends: on GL (Mesa's
llvmpipe) a copy recorded after the passes that draw a pooled texture could read the texture
as the previous frame of the same size left it (the depth and the hidden-line test of a new
process's second frame were the first frame's about 1 time in 4). Each run is a fresh process,
where it showed."""

from __future__ import annotations

import json
import subprocess
import sys

import pytest

RUNS = 12
SCRIPT = """
import json, numpy as np, toonmesh as tm
kw = dict(outlines="mesh", outputs=("outline", "lines", "depth"), width=200, height=200, backend=BACKEND)
first = tm.render(*tm.shapes.torus(), **kw)
V = np.array([[0, 0, 0], [1, 0, 0], [1, 1, 0], [0, 1, 0], [0, 1, -1], [0, 0, -1]], float)
plates = [tm.Mesh(V, np.array([[0, 1, 2], [0, 2, 3]])), tm.Mesh(V, np.array([[0, 3, 4], [0, 4, 5]]))]
second = tm.render(plates, camera=tm.Camera.look_at(eye=(-2, 2, 2), target=(0.3, 0.5, -0.3)), **kw)
alone = tm.render(plates, camera=tm.Camera.look_at(eye=(-2, 2, 2), target=(0.3, 0.5, -0.3)), **kw)
print(json.dumps({"first": int(np.isfinite(first.depth).sum()), "second": int(np.isfinite(second.depth).sum()),
                  "again": int(np.isfinite(alone.depth).sum()), "lines": len(second.lines),
                  "lines_again": len(alone.lines)}))
"""


@pytest.mark.parametrize("backend", ["vulkan", "gl"])
def test_a_frame_reads_back_its_own_depth_and_lines_after_a_frame_of_the_same_size(backend):
    for run in range(RUNS):
        out = subprocess.run([sys.executable, "-c", SCRIPT.replace("BACKEND", repr(backend))],
                             capture_output=True, text=True, timeout=120)
        assert out.returncode == 0, out.stderr
        got = json.loads(out.stdout.strip().splitlines()[-1])
        assert got["first"] != got["again"], got  # the two scenes cover different pixels
        assert got["second"] == got["again"], (run, got)
        assert got["lines"] == got["lines_again"], (run, got)

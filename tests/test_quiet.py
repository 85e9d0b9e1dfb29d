"""A successful render prints nothing on stderr, even without a runtime directory (containers,
CI, cron), where Mesa's Wayland probe used to print two 'error:' lines."""

from __future__ import annotations

import os
import subprocess
import sys

SCRIPT = """
import os, toonmesh as tm
V, F = tm.shapes.icosphere(2)
for backend in ("vulkan", "gl"):
    try:
        tm.render(V, F, width=16, height=16, backend=backend)
    except tm.GpuUnavailableError:
        pass  # a machine without this backend: nothing to print either
print(os.environ.get("XDG_RUNTIME_DIR", ""))
"""


def _run(env):
    return subprocess.run([sys.executable, "-c", SCRIPT], env=env, capture_output=True, text=True, timeout=120)


def test_render_without_runtime_dir_has_an_empty_stderr():
    env = {k: v for k, v in os.environ.items() if k != "XDG_RUNTIME_DIR"}
    r = _run(env)
    assert r.returncode == 0 and r.stderr == "", r.stderr
    private = r.stdout.strip()
    if sys.platform.startswith("linux"):
        assert os.path.basename(private).startswith("toonmesh-runtime-")
        assert not os.path.exists(private)  # removed at exit


def test_a_valid_runtime_dir_is_left_alone(tmp_path):
    os.chmod(tmp_path, 0o700)
    r = _run(dict(os.environ, XDG_RUNTIME_DIR=str(tmp_path)))
    assert r.returncode == 0 and r.stderr == "", r.stderr
    assert r.stdout.strip() == str(tmp_path)

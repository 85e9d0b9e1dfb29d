"""Rendering after fork(): a child renders with a fresh GPU context (Vulkan) or refuses at once
(GL, whose EGL state does not survive a fork); it never hangs. Each case runs in its own
process, with a timeout as the guard against a hang."""

from __future__ import annotations

import subprocess
import sys
import textwrap

import pytest

COMMON = """
import multiprocessing, os, sys, time
import numpy as np
import toonmesh as tm
from toonmesh import _core

V, F = _core.icosphere(3, 0.0, 0)

def image(backend=None):
    return tm.render(V, F, width=24, height=24, backend=backend).color

# runs `work` in a forked child (which always exits), then prints its exit status
def in_child(work):
    pid = os.fork()
    if pid == 0:
        code = 1
        try:
            work()
            code = 0
        finally:
            os._exit(code)
    _, status = os.waitpid(pid, 0)
    print("status", status)
"""


def run(code: str) -> str:
    out = subprocess.run([sys.executable, "-c", COMMON + textwrap.dedent(code)], capture_output=True, text=True, timeout=120)
    assert out.returncode == 0, out.stdout + out.stderr
    return out.stdout


def test_a_forked_child_renders_with_a_fresh_context():
    out = run("""
        parent = image("vulkan")
        r = tm.Renderer("vulkan")
        mesh = r.add_mesh(V, F)

        def child():
            same = np.array_equal(image("vulkan"), parent)
            try:
                r.render(mesh)
                old = "rendered"
            except tm.GpuError as e:
                old = "refused: " + str(e)
            print("child", same, old, flush=True)

        in_child(child)
    """)
    assert "child True refused: this renderer was made before the process forked" in out
    assert "status 0" in out


def test_gl_in_a_forked_child_refuses_at_once_and_auto_uses_vulkan():
    out = run("""
        parent = image("gl")

        def child():
            t = time.perf_counter()
            try:
                image("gl")
                print("gl rendered")
            except tm.GpuError as e:
                print("gl refused", "spawn" in str(e), time.perf_counter() - t < 5.0)
            print("auto", tm.gpu_info()["backend"], image().shape, flush=True)

        in_child(child)
    """)
    assert "gl refused True True" in out
    assert "auto vulkan (24, 24, 4)" in out and "status 0" in out


def _pool_case(method: str) -> str:
    return f"""
        def work(seed):
            return image("vulkan")[..., 0].sum() + seed

        if __name__ == "__main__":
            expected = [image("vulkan")[..., 0].sum() + s for s in range(4)]
            with multiprocessing.get_context("{method}").Pool(2) as pool:
                got = pool.map(work, range(4))
            print("pool", got == expected)
    """


@pytest.mark.parametrize("method", ["fork", "spawn"])
def test_a_multiprocessing_pool_renders(method, tmp_path):
    # spawn needs an importable main module: write the script to a file
    script = tmp_path / "pool_case.py"
    script.write_text(COMMON + textwrap.dedent(_pool_case(method)))
    out = subprocess.run([sys.executable, str(script)], capture_output=True, text=True, timeout=180)
    assert out.returncode == 0, out.stdout + out.stderr
    assert "pool True" in out.stdout

"""The type stubs of the compiled core match what it really exports."""

from __future__ import annotations

import importlib.util
import subprocess
import sys
from pathlib import Path
from typing import get_type_hints

from conftest import need

# What stubtest cannot see as the stub says it (each entry says why).
ROOT = Path(__file__).resolve().parent.parent
ALLOWLIST = ROOT / "scripts" / "stubtest-allowlist.txt"


def test_core_stubs_match_the_extension():
    need("mypy")
    r = subprocess.run(
        [sys.executable, "-m", "mypy.stubtest", "toonmesh._core", "--allowlist", str(ALLOWLIST)],
        capture_output=True,
        text=True,
    )
    assert r.returncode == 0, r.stdout + r.stderr


def test_the_testing_helpers_type_check_as_a_users_tests_see_them(tmp_path):
    """toonmesh.testing and the pytest plugin are typed (py.typed): mypy --strict finds nothing."""
    need("mypy")
    package = Path(__file__).resolve().parent.parent / "python" / "toonmesh"
    r = subprocess.run(
        [sys.executable, "-m", "mypy", "--strict", "--follow-imports=silent", "--cache-dir", str(tmp_path),
         str(package / "testing" / "__init__.py"), str(package / "pytest_plugin.py")],
        capture_output=True,
        text=True,
        cwd=package.parent,
    )
    assert r.returncode == 0, r.stdout + r.stderr


def test_the_smoothing_typeddicts_are_the_cores_description():
    """smooth.py's generated block (a TypedDict of each method's keywords) is what scripts/stubs.py
    writes from the core's description now."""
    spec = importlib.util.spec_from_file_location("stubs", ROOT / "scripts" / "stubs.py")
    stubs = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(stubs)
    assert (ROOT / "python" / "toonmesh" / "smooth.py").read_text() == stubs.smooth_module(), "run `make stubs`"
    import toonmesh.smooth as smooth

    for method, described in smooth._DESCRIBED.items():
        hints = get_type_hints(getattr(smooth, method.capitalize() + "Options"))  # its own and the shared ones
        assert set(hints) == {k["name"] for k in described["keywords"]} | {"pinned"}, method


def test_type_checkers_see_each_methods_own_keywords(tmp_path):
    """mypy reads the keywords through `Unpack[...Options]`: a keyword of the right type passes,
    a wrong type or another method's keyword is an error."""
    need("mypy")
    user = tmp_path / "user.py"
    user.write_text(
        "import numpy as np\n"
        "import toonmesh as tm\n"
        "V, F = np.zeros((3, 3)), np.array([[0, 1, 2]])\n"
        "tm.smooth.taubin(V, F, iterations=3, lamb=0.5, mu=-0.5, preset='trimesh', weld=True)\n"
        "tm.smooth.taubin(V, F, mu='x')\n"
        "tm.smooth.laplacian(V, F, mu=-0.5)\n"
        "tm.smooth.guided(V, F, sigma_r=0.3, pinned=[0])\n"
    )
    r = subprocess.run(
        [sys.executable, "-m", "mypy", "--follow-imports=silent", "--cache-dir", str(tmp_path / "cache"), str(user)],
        capture_output=True,
        text=True,
        cwd=ROOT / "python",
    )
    errors = [line for line in r.stdout.splitlines() if ": error:" in line]
    assert [line.split(":")[1] for line in errors] == ["5", "6"], r.stdout

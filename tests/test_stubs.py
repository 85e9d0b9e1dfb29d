"""The type stubs of the compiled core match what it really exports."""

from __future__ import annotations

import subprocess
import sys
from pathlib import Path

from conftest import need

# What stubtest cannot see as the stub says it (each entry says why).
ALLOWLIST = Path(__file__).resolve().parent.parent / "scripts" / "stubtest-allowlist.txt"


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

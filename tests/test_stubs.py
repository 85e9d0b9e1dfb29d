"""The type stubs of the compiled core match what it really exports."""

from __future__ import annotations

import subprocess
import sys

from conftest import need


def test_core_stubs_match_the_extension():
    need("mypy")
    r = subprocess.run(
        [sys.executable, "-m", "mypy.stubtest", "toonmesh._core"],
        capture_output=True,
        text=True,
    )
    assert r.returncode == 0, r.stdout + r.stderr

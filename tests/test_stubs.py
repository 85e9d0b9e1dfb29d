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

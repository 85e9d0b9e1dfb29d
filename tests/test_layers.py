"""The Rust core's module graph: no import cycle, no arrow from a lower layer to a higher one
(scripts/layers.py holds the layers and how an arrow is read)."""

from __future__ import annotations

import subprocess
import sys
from pathlib import Path

SCRIPT = Path(__file__).resolve().parent.parent / "scripts" / "layers.py"


def test_layers_point_down():
    r = subprocess.run([sys.executable, str(SCRIPT)], capture_output=True, text=True)
    assert "import cycles: 0" in r.stdout, r.stdout
    assert "arrows from a lower layer to a higher one: 0" in r.stdout, r.stdout
    assert "modules in no layer" not in r.stdout, r.stdout
    assert r.returncode == 0, r.stdout + r.stderr

"""The command line entry points run as the README says."""

from __future__ import annotations

import subprocess
import sys

import numpy as np


def test_smooth_command_writes_a_smoothed_mesh(tmp_path):
    out = tmp_path / "smoothed.obj"
    r = subprocess.run(
        [sys.executable, "-m", "toonmesh", "smooth", "--subdivisions", "3", "--out", str(out)],
        capture_output=True, text=True, check=True,
    )
    assert "radius spread" in r.stdout
    V = np.array([list(map(float, l.split()[1:])) for l in out.read_text().splitlines() if l.startswith("v ")])
    assert V.shape == (642, 3)
    r_out = np.linalg.norm(V, axis=1)
    assert r_out.std() < 0.01  # the noisy input's spread is about 0.017


def test_bench_quick_smoke_lists_the_suites():
    r = subprocess.run([sys.executable, "-m", "toonmesh.bench", "--help"], capture_output=True, text=True, check=True)
    assert "smooth" in r.stdout


def test_bench_thread_scaling_table_restores_the_thread_count():
    import toonmesh as tm
    from toonmesh.bench.smooth import scaling_table

    before = tm.get_num_threads()
    text = scaling_table("10k", 1)
    assert tm.get_num_threads() == before
    rows = [l for l in text.splitlines() if l.startswith("| ") and "threads" not in l]
    assert len(rows) >= 4  # one row per job at 1 thread at least
    assert rows[0].split("|")[2].strip() == "1"
    assert all(float(r.split("|")[3]) > 0 for r in rows)
    assert "1.00x" in rows[0]


def test_bench_refuses_unknown_options_before_running_anything():
    r = subprocess.run([sys.executable, "-m", "toonmesh.bench", "smooth", "--quik"], capture_output=True, text=True,
                       timeout=60)
    assert r.returncode == 2
    assert "unrecognised arguments: --quik" in r.stderr
    assert r.stdout == ""

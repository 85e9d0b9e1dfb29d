"""Smoothing benchmark: toonmesh side by side with trimesh and pymeshlab, in one run.

    python -m toonmesh.bench smooth [--quick] [--repeat N]

Meshes are seeded noisy icospheres of 10,242 / 163,842 / 655,362 vertices. Every time is the
median of ``repeat`` runs after a warm-up. toonmesh's time is the whole call: input checks,
adjacency build, smoothing and output. trimesh's is ``filter_*`` on a fresh ``Trimesh`` (its
operator build included); pymeshlab's is the filter on a loaded ``MeshSet`` (conversion in and
out is reported separately). Ratios are peer time / toonmesh time: above 1 means toonmesh is
faster.
"""

from __future__ import annotations

import importlib
import subprocess
import sys
import time
from typing import Any, Callable, Dict, List, Optional, Sequence

import numpy as np

import toonmesh as tm
from toonmesh import _core
from toonmesh.bench._timing import median_time, table

SIZES = {"10k": 5, "164k": 7, "655k": 8}


def _optional(name: str) -> Any:
    try:
        return importlib.import_module(name)
    except ImportError:
        return None


def _fresh_trimesh(trimesh: Any, V: np.ndarray, F: np.ndarray) -> Callable[[], Any]:
    return lambda: trimesh.Trimesh(V.copy(), F.copy(), process=False)


def _time_peer(make: Callable[[], Any], run: Callable[[Any], Any], repeat: int) -> float:
    """Median of run(make()) with make() outside the timer."""
    times = []
    for _ in range(repeat):
        obj = make()
        t0 = time.perf_counter()
        run(obj)
        times.append(time.perf_counter() - t0)
    return float(np.median(times))


def speed_table(sizes: Sequence[str], repeat: int, quick: bool = False) -> str:
    """Each toonmesh call next to the peer filters it is compared with.

    Rows with a preset compute the same numbers as the peer beside them (same formula, same
    number of passes), so they are like-for-like. Rows without one are the clean behaviour:
    clean Taubin does a shrink and an inflate pass per iteration (20 passes for 10 iterations)
    where trimesh's ``filter_taubin`` counts passes (10).
    """
    trimesh = _optional("trimesh")
    pymeshlab = _optional("pymeshlab")
    rows: List[List[Any]] = []
    for size in sizes:
        V, F = _core.icosphere(SIZES[size], 0.02, 1)
        lap, tau, hc = tm.smooth.laplacian, tm.smooth.taubin, tm.smooth.hc
        jobs: List[tuple] = [
            ("uniform Laplacian", lambda: lap(V, F), ["trimesh lap", "pymeshlab uniform"]),
            ("uniform Laplacian, preset trimesh", lambda: lap(V, F, preset="trimesh", volume_constraint=False),
             ["trimesh lap"]),
            ("cotangent Laplacian", lambda: lap(V, F, weights="cotangent"), ["pymeshlab cotangent"]),
            ("cotangent Laplacian, preset pymeshlab",
             lambda: lap(V, F, weights="cotangent", iterations=10, preset="pymeshlab"), ["pymeshlab cotangent"]),
            ("Taubin (20 passes)", lambda: tau(V, F), ["trimesh taubin", "pymeshlab taubin"]),
            ("Taubin, preset trimesh (10 passes)", lambda: tau(V, F, preset="trimesh"), ["trimesh taubin"]),
            ("Taubin, preset pymeshlab", lambda: tau(V, F, iterations=10, preset="pymeshlab"), ["pymeshlab taubin"]),
            ("HC", lambda: hc(V, F), ["trimesh hc", "pymeshlab hc"]),
            ("HC, preset trimesh", lambda: hc(V, F, preset="trimesh"), ["trimesh hc"]),
            ("HC, preset pymeshlab", lambda: hc(V, F, iterations=10, preset="pymeshlab"), ["pymeshlab hc"]),
            ("implicit (10 steps)", lambda: tm.smooth.implicit(V, F, step=0.5, iterations=10), ["trimesh implicit"]),
        ]
        peers: Dict[str, tuple] = {}
        if trimesh is not None:
            sm = trimesh.smoothing
            mk = _fresh_trimesh(trimesh, V, F)
            peers["trimesh lap"] = ("trimesh filter_laplacian (no volume constraint)", mk,
                                    lambda m: sm.filter_laplacian(m, volume_constraint=False))
            peers["trimesh taubin"] = ("trimesh filter_taubin", mk, lambda m: sm.filter_taubin(m))
            peers["trimesh hc"] = ("trimesh filter_humphrey", mk, lambda m: sm.filter_humphrey(m))
            # trimesh's direct solve takes a minute at 164k and far longer beyond.
            if SIZES[size] <= (5 if quick else 7):
                peers["trimesh implicit"] = ("trimesh filter_laplacian implicit", mk,
                                             lambda m: sm.filter_laplacian(m, implicit_time_integration=True,
                                                                           volume_constraint=False))
        if pymeshlab is not None:
            def ml() -> Any:
                ms = pymeshlab.MeshSet()
                ms.add_mesh(pymeshlab.Mesh(V, F))
                return ms
            peers["pymeshlab uniform"] = ("pymeshlab Laplacian uniform (10 steps)", ml,
                                          lambda ms: ms.apply_coord_laplacian_smoothing(stepsmoothnum=10, cotangentweight=False))
            peers["pymeshlab cotangent"] = ("pymeshlab Laplacian cotangent (10 steps)", ml,
                                            lambda ms: ms.apply_coord_laplacian_smoothing(stepsmoothnum=10, cotangentweight=True))
            peers["pymeshlab taubin"] = ("pymeshlab Taubin (10 steps)", ml,
                                         lambda ms: ms.apply_coord_taubin_smoothing(stepsmoothnum=10))
            peers["pymeshlab hc"] = ("pymeshlab HC (10 calls)", ml,
                                     lambda ms: [ms.apply_coord_hc_laplacian_smoothing() for _ in range(10)])
        peer_times: Dict[str, float] = {}
        for name, fn, wanted in jobs:
            t_ours = median_time(fn, repeat=repeat)
            rows.append([size, name, f"{t_ours * 1e3:.1f}", "", "", ""])
            for key in wanted:
                if key not in peers:
                    continue
                peer_name, make, run = peers[key]
                if key not in peer_times:  # each peer is timed once per mesh
                    peer_times[key] = _time_peer(make, run, 1 if "implicit" in key else repeat)
                t_peer = peer_times[key]
                rows.append([size, "", "", peer_name, f"{t_peer * 1e3:.1f}", f"{t_peer / t_ours:.1f}x"])
    return table(["mesh", "toonmesh (10 iterations)", "ms", "peer", "peer ms", "ratio"], rows,
                 "Speed, median wall time")


_MEMORY_JOB = r"""
import sys, numpy as np
from toonmesh import _core
V, F = _core.icosphere({sub}, 0.02, 1)
def rss(key):
    for line in open('/proc/self/status'):
        if line.startswith(key):
            return int(line.split()[1]) * 1024
{setup}
base = rss('VmRSS:')
{job}
print(rss('VmHWM:') - base)
"""


def memory_table(size: str) -> str:
    jobs = {
        "toonmesh uniform Laplacian": ("import toonmesh as tm", "tm.smooth.laplacian(V, F)"),
        "trimesh filter_laplacian (no volume constraint)": (
            "import trimesh\nm = trimesh.Trimesh(V.copy(), F.copy(), process=False)",
            "trimesh.smoothing.filter_laplacian(m, volume_constraint=False)",
        ),
    }
    rows = []
    for name, (setup, job) in jobs.items():
        if name.startswith("trimesh") and _optional("trimesh") is None:
            continue
        code = _MEMORY_JOB.format(sub=SIZES[size], setup=setup, job=job)
        out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, check=True)
        rows.append([name, f"{int(out.stdout.strip()) / 2**20:.0f}"])
    return table(["job (" + size + ", 10 iterations)", "peak extra memory (MiB)"], rows, "Peak memory above the loaded mesh")


def bandwidth_table(size: str, repeat: int) -> str:
    V, F = _core.icosphere(SIZES[size], 0.02, 1)
    rows = []
    big = np.ones(64 * 2**20 // 8)  # 64 MiB
    dst = np.empty_like(big)
    t_copy = median_time(lambda: np.copyto(dst, big), repeat=max(5, repeat))
    copy_bw = 2 * big.nbytes / t_copy
    n_iter = 50
    for dtype in (np.float32, np.float64):
        X = V.astype(dtype)
        # The difference of two runs cancels the one-time work (input checks, adjacency).
        t0 = median_time(lambda: tm.smooth.laplacian(X, F, iterations=1), repeat=repeat)
        t1 = median_time(lambda: tm.smooth.laplacian(X, F, iterations=1 + n_iter), repeat=repeat)
        per_iter = (t1 - t0) / n_iter
        slots = 2 * (len(F) * 3 // 2)  # each undirected edge of a closed mesh, seen from both ends
        item = np.dtype(dtype).itemsize
        # Per iteration: read offsets and neighbour lists, read positions, write new positions.
        nbytes = 4 * (len(V) + 1) + 4 * slots + 2 * 3 * item * len(V)
        bw = nbytes / per_iter
        rows.append([np.dtype(dtype).name, f"{per_iter * 1e3:.2f}", f"{bw / 1e9:.1f}", f"{copy_bw / 1e9:.1f}",
                     f"{copy_bw / bw:.2f}x"])
    return table(["dtype", "ms / iteration", "achieved GB/s", "np.copyto GB/s", "copy / achieved"], rows,
                 f"Uniform Laplacian memory bandwidth ({size})")


def scaling_table(size: str, repeat: int) -> str:
    """toonmesh's time against its thread count (1, 2, 4, ... up to the default).

    The peers run on one core, so the ratios in the speed table grow with the cores toonmesh
    is given; this shows by how much on the machine at hand.
    """
    V, F = _core.icosphere(SIZES[size], 0.02, 1)
    jobs = [
        ("uniform Laplacian", lambda: tm.smooth.laplacian(V, F)),
        ("cotangent Laplacian", lambda: tm.smooth.laplacian(V, F, weights="cotangent")),
        ("Taubin", lambda: tm.smooth.taubin(V, F)),
        ("HC", lambda: tm.smooth.hc(V, F)),
    ]
    default = tm.get_num_threads()
    counts = sorted({1, default} | {2**k for k in range(1, 8) if 2**k < default})
    rows = []
    try:
        for name, fn in jobs:
            base = None
            for n in counts:
                tm.set_num_threads(n)
                t = median_time(fn, repeat=repeat)
                base = t if base is None else base
                rows.append([name if n == counts[0] else "", n, f"{t * 1e3:.1f}", f"{base / t:.2f}x"])
    finally:
        tm.set_num_threads(default)
    return table(["toonmesh (10 iterations)", "threads", "ms", "speed-up over 1 thread"], rows,
                 f"Thread scaling ({size})")


def accuracy_table(repeat: int, quick: bool) -> str:
    """Error to the true sphere against time, per method, precision and iteration count."""
    V, F = _core.icosphere(5 if quick else 6, 0.0, 0)  # quick: 10,242 vertices, else 40,962
    rng = np.random.default_rng(5)
    noisy = V * (1.0 + 0.02 * rng.standard_normal(len(V)))[:, None]
    def err(X: np.ndarray) -> float:
        return float(np.sqrt(np.mean((np.linalg.norm(X.astype(np.float64), axis=1) - 1.0) ** 2)))
    methods = {
        "Laplacian uniform": lambda X, n: tm.smooth.laplacian(X, F, iterations=n),
        "Laplacian cotangent": lambda X, n: tm.smooth.laplacian(X, F, iterations=n, weights="cotangent"),
        "Taubin": lambda X, n: tm.smooth.taubin(X, F, iterations=n),
        "HC": lambda X, n: tm.smooth.hc(X, F, iterations=n),
        "implicit (step 1 per iteration)": lambda X, n: tm.smooth.implicit(X, F, iterations=n, step=1.0),
    }
    iters = (1, 10) if quick else (1, 3, 10, 30)
    rows = [["(input)", "", "", "", f"{err(noisy):.2e}"]]
    for name, fn in methods.items():
        for dtype in (np.float32, np.float64):
            X = noisy.astype(dtype)
            for n in iters:
                t = median_time(lambda: fn(X, n), repeat=repeat)
                rows.append([name, np.dtype(dtype).name, n, f"{t * 1e3:.1f}", f"{err(fn(X, n)):.2e}"])
    return table(["method", "dtype", "iterations", "ms", "RMS radius error"], rows,
                 f"What accuracy costs: noisy unit sphere ({len(V)} vertices, 2% noise)")


def accuracy(quick: bool = False, repeat: int = 3, extra: Sequence[str] = ()) -> None:
    """Only the table of error against time (``--accuracy``)."""
    print(accuracy_table(1 if quick else repeat, quick))


def main(quick: bool = False, repeat: int = 3, extra: Sequence[str] = ()) -> None:
    sizes = ["10k", "164k"] if quick else list(SIZES)
    reps = 1 if quick else repeat
    print(f"toonmesh {tm.__version__}, {tm.get_num_threads()} threads")
    print(speed_table(sizes, reps, quick))
    print(memory_table(sizes[-1]))
    print(bandwidth_table(sizes[-1], reps))
    print(scaling_table(sizes[-1], reps))
    print(accuracy_table(reps, quick))

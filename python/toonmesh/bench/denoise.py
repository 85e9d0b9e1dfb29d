"""Feature-preserving smoothing benchmark: bilateral and guided normal filtering side by side
with Taubin and pymeshlab's two-step smoothing (``apply_coord_two_steps_smoothing``), all with
their defaults, in one run.

    python -m toonmesh.bench denoise [--quick] [--repeat N] [--accuracy]

Parts are the generated noisy CAD parts of :mod:`toonmesh.bench.parts` (box, fandisk-like,
cylinder, and the harder sphere with V-grooves and twelve-sided prism), and, in a table of
their own, the held-out parts of :mod:`toonmesh.bench.held_out` (irregular meshes that no
default was tuned on: a sharp sphere, a twelve-sided prism with fanned caps, a chamfered box, a
fandisk-like extrusion) at the paper's noise levels (Gaussian 0.1-0.7, impulsive). Error is the mean angle, in degrees, between the result's face normals and the clean
part's. Every time is the median of ``repeat`` runs after a warm-up: toonmesh's is the whole
call, pymeshlab's the filter on a loaded ``MeshSet`` (conversion in and out not counted).
Ratios are pymeshlab's time / toonmesh's time: above 1 means toonmesh is faster.
"""

from __future__ import annotations

import importlib
from typing import Any, Callable, Dict, List, Optional, Sequence

import numpy as np

import toonmesh as tm
from toonmesh.bench import held_out, parts
from toonmesh.bench._timing import median_time, table

NOISE_CASES = [("gaussian", 0.2), ("gaussian", 0.4), ("gaussian", 0.7), ("impulsive", 1.0)]
HELD_OUT_NOISE_CASES = [("gaussian", 0.1), ("gaussian", 0.3), ("gaussian", 0.5), ("gaussian", 0.7),
                        ("impulsive", 1.0)]
SPEED_SIZES = {"20k": 20000, "500k": 500000}


def _pymeshlab() -> Any:
    try:
        return importlib.import_module("pymeshlab")
    except ImportError:
        return None


def two_step(pymeshlab: Any, V: np.ndarray, F: np.ndarray) -> Callable[[], np.ndarray]:
    """pymeshlab's two-step smoothing with its defaults, as a call that times only the filter
    (the MeshSet is loaded outside the timer) and returns the positions."""
    state: Dict[str, Any] = {}

    def load() -> None:
        ms = pymeshlab.MeshSet()
        ms.add_mesh(pymeshlab.Mesh(V, F))
        state["ms"] = ms

    def run() -> np.ndarray:
        if "ms" not in state:
            load()
        ms = state.pop("ms")
        ms.apply_coord_two_steps_smoothing()
        return ms.current_mesh().vertex_matrix()

    run.load = load  # type: ignore[attr-defined]
    return run


def _time_two_step(run: Callable[[], np.ndarray], repeat: int) -> float:
    times = []
    import time

    run()  # warm-up
    for _ in range(max(1, repeat)):
        run.load()  # type: ignore[attr-defined]
        t0 = time.perf_counter()
        run()
        times.append(time.perf_counter() - t0)
    return float(np.median(times))


def methods(F: np.ndarray) -> Dict[str, Callable[[np.ndarray], np.ndarray]]:
    return {
        "Taubin": lambda X: tm.smooth.taubin(X, F),
        "bilateral": lambda X: tm.smooth.bilateral(X, F),
        "guided": lambda X: tm.smooth.guided(X, F),
    }


def error_table(faces: int, repeat: int) -> str:
    """Error and time per part, noise and method."""
    pml = _pymeshlab()
    rows: List[List[Any]] = []
    for name in parts.PARTS + parts.HARD_PARTS:
        V, F = parts.part(name, faces)
        for kind, level in NOISE_CASES:
            N = parts.noisy(V, F, level, kind, seed=1)
            row: List[Any] = [name, f"{kind} {level}", f"{parts.normal_error(N, F, V):.1f}"]
            cells: Dict[str, Optional[str]] = {}
            if pml is not None:
                run = two_step(pml, N, F)
                t = _time_two_step(run, repeat)
                cells["two-step"] = f"{parts.normal_error(run(), F, V):.1f} / {t * 1e3:.0f} ms"
            else:
                cells["two-step"] = "not installed"
            for m, fn in methods(F).items():
                t = median_time(lambda: fn(N), repeat=repeat)
                cells[m] = f"{parts.normal_error(fn(N), F, V):.1f} / {t * 1e3:.0f} ms"
            rows.append(row + [cells["Taubin"], cells["two-step"], cells["bilateral"], cells["guided"]])
    return table(
        ["part", "noise (x mean edge)", "noisy", "Taubin", "pymeshlab two-step", "bilateral", "guided"],
        rows,
        f"Mean face-normal error (degrees) / time, {len(F):,} faces, defaults",
    )


def held_out_table(faces: int, repeat: int) -> str:
    """Error and time of the normal filters per held-out part and noise."""
    rows: List[List[Any]] = []
    for name in held_out.HELD_OUT:
        V, F = held_out.part(name, faces)
        for kind, level in HELD_OUT_NOISE_CASES:
            N = parts.noisy(V, F, level, kind, seed=1)
            row: List[Any] = [name, f"{len(F):,}", f"{kind} {level}", f"{parts.normal_error(N, F, V):.1f}"]
            for fn in (tm.smooth.bilateral, tm.smooth.guided):
                t = median_time(lambda: fn(N, F), repeat=repeat)
                row.append(f"{parts.normal_error(fn(N, F), F, V):.1f} / {t * 1e3:.0f} ms")
            rows.append(row)
    return table(["part", "faces", "noise (x mean edge)", "noisy", "bilateral", "guided"], rows,
                 "Held-out irregular parts: mean face-normal error (degrees) / time, defaults")


def speed_table(sizes: Sequence[str], repeat: int) -> str:
    """Time at each size, and pymeshlab's time over toonmesh's."""
    pml = _pymeshlab()
    rows: List[List[Any]] = []
    for size in sizes:
        V, F = parts.part("fandisk", SPEED_SIZES[size])
        N = parts.noisy(V, F, 0.4, seed=1)
        t_pml = _time_two_step(two_step(pml, N, F), repeat) if pml is not None else None
        for m, fn in methods(F).items():
            t = median_time(lambda: fn(N), repeat=repeat)
            ratio = f"{t_pml / t:.2f}x" if t_pml is not None else "not installed"
            rows.append([f"{len(F):,}", m, f"{t * 1e3:.0f} ms",
                         f"{t_pml * 1e3:.0f} ms" if t_pml is not None else "not installed", ratio])
    return table(["faces", "toonmesh", "time", "pymeshlab two-step", "ratio (pymeshlab / toonmesh)"], rows,
                 f"Speed: fandisk-like part, Gaussian noise 0.4, {tm.get_num_threads()} threads")


def knobs_table(repeat: int, quick: bool) -> str:
    """Error against time for each knob, one changed at a time from the defaults."""
    V, F = parts.part("fandisk", 20000)
    rows: List[List[Any]] = []
    for kind, level in ([("gaussian", 0.4)] if quick else [("gaussian", 0.4), ("gaussian", 0.7)]):
        N = parts.noisy(V, F, level, kind, seed=1)
        settings: List[Dict[str, Any]] = [{}]
        settings += [{"iterations": n} for n in (5, 10, 40)]
        settings += [{"vertex_iterations": n} for n in (5, 10, 40)]
        settings += [{"sigma_r": s} for s in (0.2, 0.35, 0.5)]
        settings += [{"sigma_s": s} for s in (0.5, 2.0)]
        for method in ("bilateral", "guided"):
            fn = getattr(tm.smooth, method)
            for kw in settings:
                t = median_time(lambda: fn(N, F, **kw), repeat=repeat)
                label = ", ".join(f"{k}={v}" for k, v in kw.items()) or "defaults"
                rows.append([f"{kind} {level}", method, label, f"{t * 1e3:.0f} ms",
                             f"{parts.normal_error(fn(N, F, **kw), F, V):.2f}"])
    return table(["noise", "method", "setting", "time", "error (degrees)"], rows,
                 f"What the knobs do: fandisk-like part, {len(F):,} faces")


def accuracy(quick: bool = False, repeat: int = 3, extra: Sequence[str] = ()) -> None:
    """Only the tables of error against time (``--accuracy``)."""
    reps = 1 if quick else repeat
    print(error_table(5000 if quick else 20000, reps))
    print(held_out_table(5000 if quick else 20000, reps))
    print(knobs_table(reps, quick))


def main(quick: bool = False, repeat: int = 3, extra: Sequence[str] = ()) -> None:
    reps = 1 if quick else repeat
    print(f"toonmesh {tm.__version__}, {tm.get_num_threads()} threads")
    print(error_table(5000 if quick else 20000, reps))
    print(held_out_table(5000 if quick else 20000, reps))
    print(speed_table(["20k"] if quick else list(SPEED_SIZES), reps))
    print(knobs_table(reps, quick))

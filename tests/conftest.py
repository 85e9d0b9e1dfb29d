"""Shared test helpers: mesh loading, peer imports and scale-relative comparisons."""

from __future__ import annotations

import os
from pathlib import Path
from typing import Any, Tuple

import numpy as np
import pytest

from toonmesh.testing import need_peer

MESHES = Path(__file__).parent / "data" / "meshes"


def need(module: str) -> Any:
    """Imports an optional peer library: skipped on a user's machine without it, but a hard
    failure in CI, where every peer must be installed (toonmesh.testing.need_peer)."""
    return need_peer(module)


def chromium() -> str:
    """Debian's Chromium for the browser tests: skipped on a user's machine without it, a hard
    failure in CI (scripts/system-deps.sh --test installs it)."""
    import shutil

    path = shutil.which("chromium") or shutil.which("chromium-browser")
    if path is None:
        if os.environ.get("CI", "").lower() == "true":
            raise RuntimeError("chromium is not installed: run scripts/system-deps.sh --test as root")
        pytest.skip("chromium is not installed (scripts/system-deps.sh --test installs it)")
    return path


# The toon_snapshot fixture and --toon-update: toonmesh's plugin, named here for a build whose
# metadata predates its entry point (named as its module, so this is a no-op where it is loaded).
pytest_plugins = ["toonmesh.pytest_plugin"]


def load_mesh(name: str) -> Tuple[np.ndarray, np.ndarray]:
    """(V float64, F int64) of a test mesh, exactly as stored (no merging, no cleanup)."""
    trimesh = need("trimesh")
    m = trimesh.load(MESHES / f"{name}.obj", process=False, force="mesh")
    return np.asarray(m.vertices, dtype=np.float64), np.asarray(m.faces, dtype=np.int64)


def diagonal(V: np.ndarray) -> float:
    return float(np.linalg.norm(V.max(axis=0) - V.min(axis=0)))


def rel_err(a: np.ndarray, b: np.ndarray, V: np.ndarray) -> float:
    """Largest coordinate difference relative to the bounding-box diagonal of V."""
    return float(np.abs(np.asarray(a, np.float64) - np.asarray(b, np.float64)).max() / diagonal(V))


def ticks_during(call: Any) -> Tuple[float, int]:
    """Runs `call` while another Python thread ticks every millisecond: the call's seconds and
    how many ticks fell inside it (none if the call held the GIL throughout)."""
    import threading
    import time

    ticks = []
    stop = threading.Event()

    def ticker() -> None:
        while not stop.is_set():
            ticks.append(time.perf_counter())
            time.sleep(0.001)

    t = threading.Thread(target=ticker)
    t.start()
    try:
        t0 = time.perf_counter()
        call()
        t1 = time.perf_counter()
    finally:
        stop.set()
        t.join()
    return t1 - t0, len([x for x in ticks if t0 < x < t1])


def long_tests() -> bool:
    """TOONMESH_LONG_TESTS=1 asks for the long soak and many property examples; CI runs a
    bounded, deterministic number."""
    return os.environ.get("TOONMESH_LONG_TESTS", "") == "1"


try:
    from hypothesis import HealthCheck, settings

    # "ci" (the default): few examples, derandomized, so every run checks the same cases.
    settings.register_profile(
        "ci", max_examples=30, derandomize=True, deadline=None, suppress_health_check=[HealthCheck.too_slow]
    )
    settings.register_profile(
        "long", max_examples=1000, deadline=None, suppress_health_check=[HealthCheck.too_slow]
    )
    settings.load_profile("long" if long_tests() else "ci")
except ImportError:  # the property tests say so themselves (and fail in CI)
    pass


# ------------------------------------------------------------------------------------------------
# Render backends: each test parametrized with `backend` runs on each backend this machine has.
# One that cannot open a device is skipped, with the reason, on a user's machine, and fails the
# run in CI, where both must work. The summary at the end says which ran and which did not.

RENDER_BACKENDS = ("vulkan", "gl")
_BACKEND_STATE: dict = {}


def backend_problem(backend: str) -> "str | None":
    """Why `backend` cannot render here (None when it can), probed once."""
    if backend not in _BACKEND_STATE:
        import toonmesh as tm

        try:
            info = tm.gpu_info(backend)
            _BACKEND_STATE[backend] = (None, f"{info['name']} ({info['driver']} {info['driver_info']})".strip())
        except tm.GpuUnavailableError as exc:
            _BACKEND_STATE[backend] = (str(exc).split(". ")[0], None)
    return _BACKEND_STATE[backend][0]


def need_backend(backend: str) -> None:
    """Skips the test when ``backend`` cannot render here (fails it in CI)."""
    problem = backend_problem(backend)
    if problem is None:
        return
    if os.environ.get("CI", "").lower() == "true":
        pytest.fail(f"the {backend} backend must work in CI: {problem}")
    pytest.skip(f"the {backend} backend is not available here: {problem}")


@pytest.fixture(autouse=True)
def _render_backend_available(request: Any) -> None:
    backend = getattr(getattr(request.node, "callspec", None), "params", {}).get("backend")
    if backend in RENDER_BACKENDS:
        need_backend(backend)


def pytest_terminal_summary(terminalreporter: Any) -> None:
    if not _BACKEND_STATE:
        return
    terminalreporter.section("render backends")
    for backend in RENDER_BACKENDS:
        if backend in _BACKEND_STATE:
            problem, adapter = _BACKEND_STATE[backend]
            terminalreporter.write_line(f"{backend}: " + (f"ran on {adapter}" if problem is None else f"SKIPPED: {problem}"))


# What a view shows on screen against the exact frame of the same view, and screenshots taken
# mid-drag (the browser tests; the viewer_browser benchmark reads the screen with the same).
from toonmesh.bench._screen import centre, press_and_move  # noqa: E402,F401
from toonmesh.bench._screen import pixels as screen_pixels  # noqa: E402,F401
from toonmesh.bench._screen import screenshot_mid_drag  # noqa: E402,F401
from toonmesh.bench._screen import shares as screen_shares  # noqa: E402,F401

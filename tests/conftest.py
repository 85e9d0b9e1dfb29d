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


# ------------------------------------------------------------------------------------------------
# What a view shows on screen, against the exact frame of the same view (the browser tests).


def screen_pixels(png: bytes) -> np.ndarray:
    """A screenshot (PNG bytes, Playwright's ``locator.screenshot()``) as (H, W, 3) int16."""
    import io

    from PIL import Image

    return np.asarray(Image.open(io.BytesIO(png)).convert("RGB")).astype(np.int16)


def covered_pixels(picture: np.ndarray, background: np.ndarray) -> int:
    """The pixels of ``picture`` that differ from ``background`` (an RGB colour) by more than 24
    levels in a channel: the model, not the empty view."""
    return int((np.abs(picture[..., :3].astype(np.int16) - background[:3].astype(np.int16)).max(-1) > 24).sum())


def ink_pixels(picture: np.ndarray) -> int:
    """The dark pixels of ``picture`` (every channel below 100): the ink (the default bands stay lighter)."""
    return int((picture[..., :3].max(-1) < 100).sum())


def screen_shares(shot: np.ndarray, exact: np.ndarray) -> "tuple[float, float]":
    """What a screenshot of a view shows against the exact frame of the same view: its covered
    pixels and its ink pixels, each as a share of the exact frame's. The background is the
    commonest colour along the exact frame's edges (a screenshot may take in a border's row)."""
    edges = np.concatenate([exact[0], exact[-1], exact[:, 0], exact[:, -1]])[:, :3].astype(np.int16)
    colours, counts = np.unique(edges, axis=0, return_counts=True)
    background = colours[counts.argmax()]
    return (covered_pixels(shot, background) / max(covered_pixels(exact, background), 1),
            ink_pixels(shot) / max(ink_pixels(exact), 1))


def screenshot_mid_drag(page: Any, locator: Any, target: str, x: float, y: float) -> bytes:
    """A screenshot of ``locator`` while a drag goes on: with the mouse held down at (x, y) on
    the element that ``target`` (a CSS selector) selects, the page moves the pointer a pixel
    right and back every 40 ms until the screenshot is taken, so that the view never settles
    however long the screenshot takes, and ends where it was."""
    page.evaluate("""([target, x, y]) => {
      const el = document.querySelector(target);
      const move = (to) => el.dispatchEvent(new PointerEvent('pointermove', { pointerId: 1, pointerType: 'mouse',
        isPrimary: true, clientX: to, clientY: y, buttons: 1, bubbles: true, cancelable: true }));
      let k = 0;
      window.__wiggle = { stop: () => { clearInterval(t); if (k % 2 === 1) move(x); } };
      const t = setInterval(() => move(x + (k++ % 2 === 0 ? 1 : 0)), 40);
    }""", [target, x, y])
    try:
        return locator.screenshot()
    finally:
        page.evaluate("() => window.__wiggle.stop()")

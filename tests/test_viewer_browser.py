"""toonmesh.Viewer in a real browser: a JupyterLab server and headless Chromium (Debian's
``chromium``, installed by scripts/system-deps.sh) driven through Playwright.

The test opens a notebook that shows a viewer of the bunny, runs it, drags across the frame
and checks that the picture changed, that the kernel sent new frames (the frame numbers come
from the kernel), that the frames drawn while dragging were smaller than the last one, which is
full size, and that the kernel's viewer agrees (a cell run afterwards reads its render count);
then turns the wheel and checks that the bunny grew, and switches the outlines off with the
on-screen controls and checks that the ink went.
With TOONMESH_SCREENSHOT=1 it also writes the screenshot the viewer's page shows (docs/viewer.png).
"""

from __future__ import annotations

import io
import json
import os
import shutil
import socket
import subprocess
import sys
import time
import urllib.request
from pathlib import Path

import numpy as np
import pytest

from conftest import need

ROOT = Path(__file__).resolve().parent.parent
SCREENSHOT = ROOT / "docs" / "viewer.png"

CELLS = [
    "import toonmesh as tm\n"
    "from toonmesh.data import bunny\n"
    "\n"
    "V, F = bunny()\n"
    "blue = tm.Material.bands('#4f8fd8')\n"
    "v = tm.Viewer(V, F, material=blue, outlines='mesh', width=480, height=360, controls=True)\n"
    "v",
    "print('renders', v.render_count, 'camera eye', v.camera.eye)",
]


def _notebook(path: Path) -> None:
    cells = [{"cell_type": "code", "metadata": {}, "source": s, "outputs": [], "execution_count": None} for s in CELLS]
    nb = {
        "cells": cells,
        "metadata": {"kernelspec": {"name": "python3", "display_name": "Python 3", "language": "python"}},
        "nbformat": 4,
        "nbformat_minor": 5,
    }
    path.write_text(json.dumps(nb), encoding="utf-8")


def _free_port() -> int:
    with socket.socket() as s:
        s.bind(("127.0.0.1", 0))
        return int(s.getsockname()[1])


def _chromium() -> str:
    path = shutil.which("chromium") or shutil.which("chromium-browser")
    if path is None:
        if os.environ.get("CI", "").lower() == "true":
            raise RuntimeError("chromium is not installed: run scripts/system-deps.sh as root")
        pytest.skip("chromium is not installed (scripts/system-deps.sh installs it)")
    return path


@pytest.fixture
def jupyter_lab(tmp_path):
    """A token-less JupyterLab server on a free port, serving tmp_path/work; yields its URL."""
    need("jupyterlab")
    need("anywidget")
    work = tmp_path / "work"
    work.mkdir()
    _notebook(work / "viewer.ipynb")
    port = _free_port()
    # the user's own Jupyter settings, kernels and workspaces stay out of it: the kernel is this Python
    env = dict(os.environ, JUPYTER_CONFIG_DIR=str(tmp_path / "config"), JUPYTER_DATA_DIR=str(tmp_path / "data"),
               JUPYTER_RUNTIME_DIR=str(tmp_path / "runtime"), JUPYTERLAB_WORKSPACES_DIR=str(tmp_path / "workspaces"),
               JUPYTER_PLATFORM_DIRS="1")
    log = open(tmp_path / "server.log", "wb")
    server = subprocess.Popen(
        [sys.executable, "-m", "jupyterlab", "--no-browser", "--ip=127.0.0.1", f"--port={port}",
         "--ServerApp.token=", "--ServerApp.password=", "--ServerApp.disable_check_xsrf=True",
         f"--ServerApp.root_dir={work}", "--LabApp.news_url=", "--LabApp.check_for_updates_class=jupyterlab.NeverCheckForUpdate",
         "--allow-root"],
        cwd=work, env=env, stdout=log, stderr=subprocess.STDOUT,
    )
    url = f"http://127.0.0.1:{port}"
    try:
        deadline = time.monotonic() + 30
        while True:
            try:
                urllib.request.urlopen(f"{url}/api/status", timeout=1).read()
                break
            except OSError:
                if server.poll() is not None or time.monotonic() > deadline:
                    log.close()
                    raise RuntimeError("jupyter lab did not start:\n" + (tmp_path / "server.log").read_text(errors="replace"))
                time.sleep(0.25)
        yield url
    finally:
        server.terminate()
        try:
            server.wait(timeout=10)
        except subprocess.TimeoutExpired:
            server.kill()
        log.close()


def _pixels(png: bytes) -> np.ndarray:
    from PIL import Image

    return np.asarray(Image.open(io.BytesIO(png)).convert("RGB")).astype(np.int16)


def test_dragging_the_viewer_in_chromium_orbits_the_view(jupyter_lab, tmp_path):
    chromium = _chromium()
    need("PIL")
    sync_api = need("playwright.sync_api")
    with sync_api.sync_playwright() as p:
        browser = p.chromium.launch(executable_path=chromium, args=["--no-sandbox"])
        try:
            page = browser.new_page(viewport={"width": 1500, "height": 900})
            page.goto(f"{jupyter_lab}/lab/tree/viewer.ipynb")
            page.wait_for_selector(".jp-Notebook .jp-Cell", timeout=30_000)
            # the kernel connected and idle (the status bar says "Python 3 (ipykernel) | Idle")
            page.get_by_text("| Idle").wait_for(timeout=30_000)
            cells = page.locator(".jp-Notebook .jp-Cell")
            cells.first.locator(".jp-InputPrompt").click()
            page.keyboard.press("Shift+Enter")  # runs the cell that shows the viewer
            viewer = page.locator(".toonmesh-viewer[data-frame]")
            viewer.wait_for(timeout=30_000)
            img = viewer.locator("img")
            page.wait_for_function("document.querySelector('.toonmesh-viewer img').naturalWidth > 0")
            page.evaluate("""() => {
                const img = document.querySelector('.toonmesh-viewer img');
                window.__sizes = [];
                img.addEventListener('load', () => window.__sizes.push(img.naturalWidth));
            }""")
            first_frame = int(viewer.get_attribute("data-frame"))
            before = _pixels(img.screenshot())

            box = img.bounding_box()
            x, y = box["x"] + box["width"] / 2, box["y"] + box["height"] / 2
            page.mouse.move(x, y)
            page.mouse.down()
            for i in range(1, 13):
                page.mouse.move(x + 12 * i, y + 3 * i)
                page.wait_for_timeout(30)
            page.mouse.up()
            # The full-size frame follows the release; wait until it has been shown.
            page.wait_for_function(
                "(n) => { const r = document.querySelector('.toonmesh-viewer');"
                " return +r.dataset.frame >= n && r.querySelector('img').naturalWidth === 480"
                " && (window.__sizes.at(-1) === 480); }",
                arg=first_frame + 2, timeout=20_000,
            )
            page.wait_for_timeout(300)
            last_frame = int(viewer.get_attribute("data-frame"))
            after = _pixels(img.screenshot())
            sizes = page.evaluate("window.__sizes")
            if os.environ.get("TOONMESH_SCREENSHOT") == "1":  # the viewer page's picture: after the drag
                cells.first.screenshot(path=str(SCREENSHOT))

            # the wheel turned away from the user zooms in: the bunny covers more of the frame
            page.mouse.move(x, y)
            page.mouse.wheel(0, -200)
            page.wait_for_function(
                "(n) => { const r = document.querySelector('.toonmesh-viewer');"
                " return +r.dataset.frame > n && window.__sizes.at(-1) === 480; }",
                arg=last_frame, timeout=20_000,
            )
            page.wait_for_timeout(300)
            zoomed = _pixels(img.screenshot())

            # a control: outlines off re-renders (the frame has fewer dark pixels)
            before_switch = int(viewer.get_attribute("data-frame"))
            page.locator(".toonmesh-outlines-kind select").select_option("none")  # the outlines' kind
            page.wait_for_function(
                "(n) => +document.querySelector('.toonmesh-viewer').dataset.frame > n", arg=before_switch, timeout=20_000)
            page.wait_for_timeout(300)
            no_outlines = _pixels(img.screenshot())

            # the kernel's own count, read by the notebook's second cell (run after the drag)
            cell = cells.nth(1)
            cell.locator(".jp-InputPrompt").click()
            page.keyboard.press("Shift+Enter")
            printed = cell.locator(".jp-OutputArea-output", has_text="renders")
            printed.wait_for(timeout=20_000)
            kernel_renders = int(printed.inner_text().split()[1])
        except Exception:
            page.screenshot(path=str(tmp_path / "failure.png"))
            raise
        finally:
            browser.close()

    assert before.shape == after.shape and abs(before.shape[0] - 360) <= 1 and abs(before.shape[1] - 480) <= 1
    changed = np.abs(before - after).max(axis=2) > 24
    assert changed.mean() > 0.02, f"only {changed.mean():.1%} of the pixels changed"
    assert last_frame >= first_frame + 2, (first_frame, last_frame)
    assert sizes and max(sizes) == 480 and min(sizes) < 480, sizes  # drafts while dragging, then full size
    assert kernel_renders >= last_frame

    def covered(picture):  # pixels that are not the white background
        return float((picture.min(axis=2) < 200).mean())

    assert covered(zoomed) > 1.2 * covered(after), (covered(after), covered(zoomed))

    def inked(picture):  # near-black pixels: outlines and the darkest band
        return float((picture.max(axis=2) < 40).mean())

    assert inked(no_outlines) < 0.9 * inked(zoomed), (inked(zoomed), inked(no_outlines))

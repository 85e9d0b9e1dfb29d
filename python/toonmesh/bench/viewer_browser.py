"""The viewer in a browser while the user drags: JupyterLab and headless Chromium (Playwright), the
bunny at 512x512 with ink (outlines "both"), a 2-second drag with mouse events at 60 Hz.

    python -m toonmesh.bench viewer_browser [--quick]

Rows, measured in one run:

- the viewer's drafts drawn in the browser (WebGL2, toonmesh's own shaders in GLSL ES 3.00);
- the same viewer with the kernel drawing the drafts (how the viewer drew them before);
- a plain banded WebGL2 program drawing the same mesh on the same page's browser, written here
  as the yardstick (the most a program of this browser can draw), its draws paced as the
  viewer's (one per animation frame with a move).

Each row: the frames shown per second during the drag, the share of the plain program's rate, the
median delay from a pointer event to the frame that shows it (the drafts and the plain program),
and the time from the release to the exact frame (the viewer). Headless Chromium draws WebGL2
through SwiftShader on the CPU: on a machine with a GPU the browser draws at the display's rate.

A frame counts only where it reached the screen. The page counts a frame of the viewer only
while it is shown as the user sees it (``viewer_browser_watch.js``: a draft's canvas visible and
laid out over the view at its full size; a kernel's frame in the opaque image at full size), and
after the timed drag a second drag checks what the screen shows: a screenshot of the view taken
with the pointer held and moving, against a screenshot of the exact frame of the same view (for
the plain program, its still frame after the release). Where that screenshot shows less than 80%
of the covered pixels, the row's frames did not reach the screen: its rate is 0. The table gives
that share ("on screen") and the frames counted by the viewer but not shown ("not shown").
"""

from __future__ import annotations

import base64
import shutil
import statistics
import tempfile
import time
from pathlib import Path
from typing import Any, Dict, List, Optional, Sequence

import numpy as np

from toonmesh.bench._screen import pixels, press_and_move, screenshot_mid_drag, script, shares
from toonmesh.bench._timing import table

SIZE = 512
DRAG_SECONDS, HZ = 2.0, 60
ON_SCREEN = 0.8  # the least share of the exact frame's covered pixels a mid-drag screenshot shows

CELL = (
    "import toonmesh as tm\n"
    "from toonmesh.data import bunny\n"
    "V, F = bunny()\n"
    "class KernelDrafts(tm.Viewer):\n"
    "    _browser_drafts = False\n"
    f"v = tm.Viewer(V, F, outlines='both', width={SIZE}, height={SIZE})\n"
    f"k = KernelDrafts(V, F, outlines='both', width={SIZE}, height={SIZE})\n"
    "display(v, k)"
)

def _plain_arguments(V: np.ndarray, F: np.ndarray) -> List[Any]:
    """The yardstick's mesh: centred and scaled into the unit sphere, smooth normals, base64."""
    P = (V - (V.min(0) + V.max(0)) / 2).astype(np.float32)
    P /= np.linalg.norm(P, axis=1).max()
    N = np.zeros_like(P)
    tri = P[F]
    fn = np.cross(tri[:, 1] - tri[:, 0], tri[:, 2] - tri[:, 0])
    for k in range(3):
        np.add.at(N, F[:, k], fn)
    N /= np.maximum(np.linalg.norm(N, axis=1, keepdims=True), 1e-12)
    b64 = lambda a: base64.b64encode(np.ascontiguousarray(a).tobytes()).decode("ascii")  # noqa: E731
    return [SIZE, b64(P), b64(N.astype(np.float32)), b64(F.astype(np.uint32))]


def _drag(page: Any, x: float, y: float) -> float:
    """A drag of DRAG_SECONDS from (x, y) with a mouse event every 1/HZ s, to the right and a
    little down; returns the page's time at the first move (ms)."""
    page.mouse.move(x, y)
    page.mouse.down()
    start = page.evaluate("performance.now()")
    t0 = time.perf_counter()
    count = int(DRAG_SECONDS * HZ)
    for i in range(1, count + 1):
        wait = t0 + i / HZ - time.perf_counter()
        if wait > 0:
            time.sleep(wait)
        page.mouse.move(x + 150 * np.sin(np.pi * i / count), y + 20 * i / count)
    page.mouse.up()
    return float(start)


def _rate(shown: List[float], start: float) -> float:
    during = [t for t in shown if start <= t <= start + DRAG_SECONDS * 1000]
    return len(during) / DRAG_SECONDS


_EXACT_AFTER = script("viewer_browser_exact_after.js")


def _on_screen(page: Any, view: Any, target: str, index: int, x: float, y: float, still: Any) -> float:
    """What the screen shows of a drag on ``view`` (a locator) from (x, y) on ``target`` (its
    ``index``-th match): a screenshot with the pointer held and moving, as a share of the covered
    pixels of a screenshot of the same view once it is still (``still()`` waits for it: the pointer
    still held)."""
    press_and_move(page, x, y, 8, 5, pause_ms=20)
    moving = pixels(screenshot_mid_drag(page, view, target, x + 40, y, index))
    still()
    exact = pixels(view.screenshot())
    page.mouse.up()
    return shares(moving, exact)[0]


def _viewer_row(page: Any, i: int) -> Dict[str, Optional[float]]:
    root = page.locator(".toonmesh-viewer").nth(i)
    root.scroll_into_view_if_needed()
    img = root.locator("img")
    box = img.bounding_box()
    page.evaluate(script("viewer_browser_watch.js"), i)
    start = _drag(page, box["x"] + box["width"] / 2 - 75, box["y"] + box["height"] / 2)
    page.wait_for_function("window.__watch.exact !== null", timeout=30_000)
    w = page.evaluate("window.__watch")
    delays = root.evaluate("r => r.toonmeshEventDelays || []")
    scale = root.get_attribute("data-draft-scale")

    def still() -> None:  # the exact frame of the view where the pointer stopped
        page.wait_for_function(_EXACT_AFTER, arg=[i, int(root.get_attribute("data-frames-shown"))], timeout=30_000)

    screen = _on_screen(page, img, ".toonmesh-viewer img", i, box["x"] + box["width"] / 2 - 20,
                        box["y"] + box["height"] / 2, still)
    page.wait_for_function(_EXACT_AFTER, arg=[i, -1], timeout=30_000)
    return {"fps": _rate(w["shown"], start) if screen >= ON_SCREEN else 0.0, "hidden": w["hidden"],
            "delay": statistics.median(delays) if delays else None, "exact": w["exact"] - w["up"],
            "scale": None if scale is None else float(scale), "screen": screen}


def _plain_row(page: Any, V: np.ndarray, F: np.ndarray) -> Dict[str, Optional[float]]:
    page.evaluate(script("viewer_browser_plain.js"), _plain_arguments(V, F))
    page.wait_for_timeout(500)
    start = _drag(page, SIZE / 2 - 75, SIZE / 2)
    w = page.evaluate("window.__watch")
    screen = _on_screen(page, page.locator(".bench-plain"), ".bench-plain", 0, SIZE / 2 - 20, SIZE / 2,
                        lambda: page.wait_for_timeout(300))
    return {"fps": _rate(w["shown"], start) if screen >= ON_SCREEN else 0.0, "hidden": 0,
            "delay": statistics.median(w["delays"]), "exact": None, "scale": 1.0, "screen": screen}


def main(quick: bool = False, repeat: int = 3, extra: Sequence[str] = ()) -> None:
    from playwright.sync_api import sync_playwright

    from toonmesh.bench._lab import jupyter_lab, open_notebook, write_notebook
    from toonmesh.data import bunny

    chromium = shutil.which("chromium") or shutil.which("chromium-browser")
    if chromium is None:
        raise RuntimeError("the viewer_browser benchmark needs Chromium (scripts/system-deps.sh --test)")
    V, F = bunny()
    rows: List[Sequence[Any]] = []
    with tempfile.TemporaryDirectory() as tmp, jupyter_lab(Path(tmp)) as url, sync_playwright() as p:
        write_notebook(Path(tmp) / "work" / "bench.ipynb", [CELL])
        browser = p.chromium.launch(executable_path=chromium, args=["--no-sandbox"])
        try:
            page = browser.new_page(viewport={"width": 1400, "height": 1300})
            cells = open_notebook(page, url, "bench.ipynb")
            cells.first.locator(".jp-InputPrompt").click()
            page.keyboard.press("Shift+Enter")
            page.wait_for_function("document.querySelectorAll('.toonmesh-viewer[data-frame]').length === 2 && "
                                   "document.querySelector('.toonmesh-viewer').dataset.draft === 'webgl'",
                                   timeout=60_000)
            page.wait_for_timeout(1000)
            browser_drafts = _viewer_row(page, 0)
            page.wait_for_timeout(500)
            kernel_drafts = _viewer_row(page, 1)
            plain_row = _plain_row(page, V, F)
        finally:
            browser.close()
    base = plain_row["fps"] or float("nan")
    fmt = lambda x, unit="": "-" if x is None else f"{x:.0f}{unit}"  # noqa: E731
    for label, r in (("viewer, drafts in the browser (WebGL2)", browser_drafts),
                     ("viewer, drafts by the kernel", kernel_drafts),
                     ("plain banded WebGL2 program", plain_row)):
        size = "-" if r["scale"] is None else f"{round(SIZE * r['scale'])}"
        rows.append((label, size, round(r["fps"] or 0.0, 1), f"{100 * (r['fps'] or 0.0) / base:.0f}%",
                     f"{100 * (r['screen'] or 0.0):.0f}%", r["hidden"], fmt(r["delay"], " ms"), fmt(r["exact"], " ms")))
    title = (f"The viewer during a {DRAG_SECONDS:g} s drag at {HZ} Hz: the bunny ({len(F):,} faces) at "
             f"{SIZE}x{SIZE} with ink, JupyterLab in headless Chromium")
    print(table(("view", "drawn at", "fps", "of plain", "on screen", "not shown", "event to frame (median)",
                 "release to exact"), rows, title))
    ratio = (browser_drafts["fps"] or 0.0) / max(kernel_drafts["fps"] or 0.0, 1e-9)
    print(f"browser drafts / kernel drafts: {ratio:.1f}x")


if __name__ == "__main__":
    main()

"""toonmesh.Viewer's size in a real browser (JupyterLab, headless Chromium through Playwright) on a
narrow window of a 2x screen: a viewer made without a width fits the cell's width (nothing
clipped, the toolbar on screen), its frames are rendered at the screen's pixel ratio (an image of
twice the pixels shown at the view's size: sharp) and its drafts too; ``v.code()`` reproduces the
frame; the view follows the window when it widens, fills the screen in full screen and comes
back after.
"""

from __future__ import annotations

import pytest

from conftest import centre, chromium, need, press_and_move
from test_viewer_browser import _run_cell, _wait_exact_after, notebook_server
from toonmesh.bench._lab import open_notebook

HEIGHT = 240

CELLS = [
    "import numpy as np\n"
    "import toonmesh as tm\n"
    "from toonmesh.data import bunny\n"
    "V, F = bunny()\n"
    f"v = tm.Viewer(V, F, outlines='both', height={HEIGHT})\n"
    "v",
    "print('size', v.width, v.height, v.pixel_ratio, *v.frame.shape[:2])",
    "scope = {'V': V, 'F': F}\n"
    "exec(v.code(), scope)\n"
    "print('same', bool(np.array_equal(scope['r'].color, v.frame)))",
    "print('size', v.width, v.height, v.pixel_ratio, *v.frame.shape[:2])",
]


@pytest.fixture
def jupyter_lab(tmp_path):
    with notebook_server(tmp_path, "size.ipynb", CELLS) as url:
        yield url


# The view's size as shown: the image's CSS size, its pixels, the root's and the cell's edges.
_SHOWN = """() => {
  const root = document.querySelector('.toonmesh-viewer'), img = root.querySelector('img');
  const cell = root.closest('.jp-OutputArea-output').getBoundingClientRect(), r = root.getBoundingClientRect();
  const bar = root.querySelector('.toonmesh-toolbar').getBoundingClientRect();
  return { css: [img.clientWidth, img.clientHeight], pixels: [img.naturalWidth, img.naturalHeight],
           left: r.left, right: r.right, cellLeft: cell.left, cellRight: cell.right, barRight: bar.right,
           window: window.innerWidth, ratio: window.devicePixelRatio };
}"""

_SHARP = "() => { const i = document.querySelector('.toonmesh-viewer img');" \
         " return i.clientWidth > 0 && i.naturalWidth === 2 * i.clientWidth && i.naturalHeight === 2 * i.clientHeight; }"


def test_a_viewer_fits_the_cell_at_the_screens_pixel_ratio(jupyter_lab, tmp_path):
    executable = chromium()
    sync_api = need("playwright.sync_api")
    with sync_api.sync_playwright() as p:
        browser = p.chromium.launch(executable_path=executable, args=["--no-sandbox"])
        try:
            page = browser.new_page(viewport={"width": 760, "height": 900}, device_scale_factor=2)
            cells = open_notebook(page, jupyter_lab, "size.ipynb")
            cells.first.locator(".jp-InputPrompt").click()
            page.keyboard.press("Shift+Enter")
            viewer = page.locator(".toonmesh-viewer[data-frame]")
            viewer.wait_for(timeout=30_000)
            page.wait_for_function(_SHARP, timeout=30_000)  # the frame re-rendered at the cell's width, 2x
            _wait_exact_after(page, 0)
            narrow = page.evaluate(_SHOWN)
            kernel = _run_cell(page, cells, 1, "size").split()[1:]
            same = _run_cell(page, cells, 2, "same").split()[1]

            # a drag: the drafts are drawn at the screen's ratio times the draft scale
            img = viewer.locator("img")
            img.scroll_into_view_if_needed()
            shown = int(viewer.get_attribute("data-frames-shown"))
            press_and_move(page, *centre(img), 7, 10)
            draft = viewer.evaluate("r => { const p = r.toonmeshDraft.pixels();"
                                    " return [p.width, p.height, +r.dataset.draftScale, r.dataset.draft]; }")
            page.mouse.up()
            _wait_exact_after(page, shown)

            # the window widens: the view follows the cell
            page.set_viewport_size({"width": 1100, "height": 900})
            page.wait_for_function(
                f"() => {{ const i = document.querySelector('.toonmesh-viewer img');"
                f" return i.clientWidth > {narrow['css'][0] + 200} && i.naturalWidth === 2 * i.clientWidth; }}",
                timeout=30_000)
            _wait_exact_after(page, 0)
            wide = page.evaluate(_SHOWN)

            # full screen fills the screen, and the view comes back after
            viewer.locator(".toonmesh-fullscreen").click()
            page.wait_for_function(
                "() => { const i = document.querySelector('.toonmesh-viewer img');"
                " return i.clientWidth >= window.innerWidth - 4 && i.naturalWidth === 2 * i.clientWidth; }",
                timeout=30_000)
            full = page.evaluate(_SHOWN)
            viewer.locator(".toonmesh-fullscreen").click()
            page.wait_for_function(
                f"() => {{ const i = document.querySelector('.toonmesh-viewer img');"
                f" return document.fullscreenElement === null && i.clientWidth === {wide['css'][0]}"
                f" && i.clientHeight === {HEIGHT} && i.naturalWidth === 2 * i.clientWidth; }}",
                timeout=30_000)
            back = _run_cell(page, cells, 3, "size").split()[1:]
        except Exception:
            page.screenshot(path=str(tmp_path / "failure.png"))
            raise
        finally:
            browser.close()

    # narrow: the view fills the cell's width and no more (the toolbar on screen), 2x pixels
    assert narrow["ratio"] == 2
    assert narrow["right"] <= narrow["cellRight"] + 1 and narrow["barRight"] <= narrow["window"], narrow
    assert narrow["right"] - narrow["left"] >= 0.95 * (narrow["cellRight"] - narrow["cellLeft"]), narrow
    assert narrow["css"][1] == HEIGHT and narrow["pixels"] == [2 * narrow["css"][0], 2 * HEIGHT], narrow
    width = narrow["css"][0]
    assert kernel == [str(width), str(HEIGHT), "2.0", str(2 * HEIGHT), str(2 * width)], (kernel, narrow)
    assert same == "True"
    # the drafts: drawn here, at the ratio times the draft scale
    assert draft[3] == "webgl" and 0 < draft[2] < 1, draft
    assert abs(draft[0] - 2 * width * draft[2]) <= 1 and abs(draft[1] - 2 * HEIGHT * draft[2]) <= 1, (draft, width)
    # wider: the cell's new width, still 2x
    assert wide["right"] <= wide["cellRight"] + 1 and wide["css"][0] > width + 200, wide
    # full screen: the screen, 2x; and back
    assert full["css"][0] >= full["window"] - 4 and full["pixels"][0] == 2 * full["css"][0], full
    assert back[:3] == [str(wide["css"][0]), str(HEIGHT), "2.0"], (back, wide)

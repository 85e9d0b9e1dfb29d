"""toonmesh.Viewer in JupyterLab (headless Chromium, as tests/test_viewer_browser.py): a view shown
from a function lives while its output is on the page and is freed when the output is cleared or
its cell runs again; Escape and a click on another cell give the notebook its keys back; the
controls sit in collapsible sections, only the material's open, and the column is far shorter
than the flat list it was (2,372 px for this viewer's settings); a threshold's handle dragged
past its neighbour stops at it and the view shows the new bands."""

from __future__ import annotations


import numpy as np

from conftest import centre, chromium, need, press_and_move
from conftest import screen_pixels as _pixels
from test_viewer_browser import notebook_server, _run_cell
from toonmesh.bench._lab import open_notebook

CELLS = [
    "import gc, weakref\n"
    "import toonmesh as tm\n"
    "from IPython.display import display\n"
    "from toonmesh.data import bunny\n"
    "\n"
    "V, F = bunny()\n"
    "refs = globals().get('refs', [])  # kept across runs of this cell\n"
    "def show():  # nothing refers to the viewer once this returns but its view on the page\n"
    "    v = tm.Viewer(V, F, material=tm.Material.hatching(), outlines='both', width=400, height=300, controls=True)\n"
    "    refs.append(weakref.ref(v))\n"
    "    display(v)\n"
    "show()",
    "gc.collect()\n"
    "checks = globals().get('checks', 0) + 1\n"
    "print('alive', sum(r() is not None for r in refs), 'of', len(refs), 'check', checks)",
    "print('another cell')",
]
# The controls column's full height (px) for the viewer above as a flat list, before sections.
FLAT_HEIGHT = 2372


_checks = [0]


def _alive(page, cells) -> str:
    """The kernel's count of live viewers after a collection ('alive N of M')."""
    _checks[0] += 1
    return " ".join(_run_cell(page, cells, 1, f"check {_checks[0]}").split()[:4])


def _alive_becomes(page, cells, want: str) -> str:
    """Runs the counting cell until it says ``want`` (a removed view tells the kernel shortly after)."""
    got = ""
    for _ in range(10):
        page.wait_for_timeout(700)
        got = _alive(page, cells)
        if got == want:
            break
    return got


def test_a_shown_view_lives_while_on_the_page_and_gives_keys_back(tmp_path):
    executable = chromium()
    need("PIL")
    sync_api = need("playwright.sync_api")
    with notebook_server(tmp_path, "life.ipynb", CELLS) as url, sync_api.sync_playwright() as p:
        browser = p.chromium.launch(executable_path=executable, args=["--no-sandbox"])
        page = browser.new_page(viewport={"width": 1500, "height": 1000})
        try:
            cells = open_notebook(page, url, "life.ipynb")
            cells.first.locator(".jp-InputPrompt").click()
            page.keyboard.press("Shift+Enter")
            viewer = page.locator(".toonmesh-viewer[data-frame]")
            viewer.wait_for(timeout=60_000)
            img = viewer.locator("img")
            page.wait_for_function("document.querySelector('.toonmesh-viewer img').naturalWidth > 0")
            alive_shown = _alive(page, cells)  # collected: the page's view holds it

            # it keeps drawing: a drag gives a new exact frame of the turned bunny
            page.wait_for_timeout(500)
            before = _pixels(img.screenshot())
            shown = int(viewer.get_attribute("data-frames-shown"))
            img.scroll_into_view_if_needed()
            press_and_move(page, *centre(img), 8, 12, 2)
            page.mouse.up()
            page.wait_for_function(
                "(n) => { const r = document.querySelector('.toonmesh-viewer');"
                " return +r.dataset.framesShown > n && r.dataset.exact === '1' && r.dataset.busy === '0'; }",
                arg=shown, timeout=30_000)
            page.wait_for_timeout(300)
            after = _pixels(img.screenshot())

            # the controls: sections, the material's open; the column's full height
            sections = page.locator(".toonmesh-section").evaluate_all(  # open: its controls are visible
                "ss => ss.map(s => [s.className.match(/toonmesh-section-(\\w+)/)[1],"
                " [...s.querySelectorAll('input, select')].some(e => e.getBoundingClientRect().height > 0)])")
            column = page.locator(".toonmesh-controls")
            height = column.evaluate("c => { const m = c.style.maxHeight; c.style.maxHeight = 'none';"
                                     " const h = c.scrollHeight; c.style.maxHeight = m; return h; }")
            column.screenshot(path=str(tmp_path / "controls.png"))

            # the first threshold's handle dragged to the far right, past the second: it stops at it
            # (the readouts say so), and the view shows the new bands
            readouts = [page.locator(f".toonmesh-material-thresholds-{i} .widget-readout") for i in range(4)]
            thresholds_before = [r.inner_text() for r in readouts]
            handle = page.locator(".toonmesh-material-thresholds-0 .noUi-handle")
            track = page.locator(".toonmesh-material-thresholds-0 .noUi-target").bounding_box()
            handle.scroll_into_view_if_needed()
            hb = handle.bounding_box()
            shown = int(viewer.get_attribute("data-frames-shown"))
            before_bands = _pixels(img.screenshot())
            page.mouse.move(hb["x"] + hb["width"] / 2, hb["y"] + hb["height"] / 2)
            page.mouse.down()
            page.mouse.move(track["x"] + track["width"] + 40, hb["y"] + hb["height"] / 2, steps=8)
            page.mouse.up()
            page.wait_for_function(
                "(n) => { const r = document.querySelector('.toonmesh-viewer');"
                " return +r.dataset.framesShown > n && r.dataset.exact === '1' && r.dataset.busy === '0'; }",
                arg=shown, timeout=30_000)
            page.wait_for_timeout(500)
            thresholds_after = [r.inner_text() for r in readouts]
            after_bands = _pixels(img.screenshot())

            # keys: Escape leaves the view, and the notebook's command mode takes "b" (a cell below)
            count = cells.count()
            img.click()
            focused = page.evaluate("document.querySelector('.toonmesh-viewer').contains(document.activeElement)")
            page.keyboard.press("b")  # the view's: no cell added
            page.wait_for_timeout(300)
            count_in_view = cells.count()
            page.keyboard.press("Escape")
            left = not page.evaluate("document.querySelector('.toonmesh-viewer').contains(document.activeElement)")
            page.keyboard.press("b")
            page.wait_for_timeout(500)
            count_after_escape = cells.count()
            page.keyboard.press("z")  # undo the cell added (command mode)
            page.wait_for_timeout(300)
            # a click on another cell does too
            img.click()
            cells.nth(2).locator(".jp-InputPrompt").click()
            left_by_click = not page.evaluate("document.querySelector('.toonmesh-viewer').contains(document.activeElement)")
            before_b = cells.count()
            page.keyboard.press("b")
            page.wait_for_timeout(500)
            count_after_click = cells.count() - before_b
            page.keyboard.press("z")
            page.wait_for_timeout(300)

            # clearing the output frees the viewer
            cells.first.locator(".jp-InputPrompt").click(button="right")
            page.get_by_text("Clear Cell Output", exact=True).first.click()
            page.wait_for_function("document.querySelectorAll('.toonmesh-viewer').length === 0", timeout=10_000)
            alive_cleared = _alive_becomes(page, cells, "alive 0 of 1")

            # a re-run cell frees the viewer it showed before
            cells.first.locator(".jp-InputPrompt").click()
            page.keyboard.press("Control+Enter")
            page.locator(".toonmesh-viewer[data-frame]").wait_for(timeout=60_000)
            page.keyboard.press("Control+Enter")  # once more: the first one's output is replaced
            page.wait_for_function("document.querySelectorAll('.toonmesh-viewer[data-frame]').length === 1", timeout=60_000)
            alive_rerun = _alive_becomes(page, cells, "alive 1 of 3")
        except Exception:
            page.screenshot(path=str(tmp_path / "failure.png"))
            raise
        finally:
            browser.close()

    assert alive_shown == "alive 1 of 1", alive_shown
    assert before.shape == after.shape
    changed = np.abs(before - after).max(axis=2) > 24
    assert changed.mean() > 0.02, f"only {changed.mean():.1%} of the pixels changed"
    covered = (after.min(axis=2) < 200).mean()  # the bunny, not a blank or broken view
    assert covered > 0.1, covered

    names = [name for name, _ in sections]
    assert names[0] == "material" and {"light", "outlines", "camera", "options"} <= set(names), names
    assert [is_open for _, is_open in sections] == [True] + [False] * (len(sections) - 1), sections
    assert height < FLAT_HEIGHT / 2, height
    assert thresholds_before == ["0.20", "0.50", "0.70", "0.90"], thresholds_before
    assert thresholds_after == ["0.49", "0.50", "0.70", "0.90"], thresholds_after  # stopped a step short
    assert (np.abs(before_bands - after_bands).max(axis=2) > 24).mean() > 0.01  # the bands moved
    assert (after_bands.min(axis=2) < 200).mean() > 0.1  # and the bunny is still drawn
    print("controls column", height, "px; as a flat list", FLAT_HEIGHT, "px")

    assert focused and count_in_view == count, (focused, count_in_view, count)
    assert left and count_after_escape == count + 1, (left, count_after_escape, count)
    assert left_by_click and count_after_click == 1, (left_by_click, count_after_click)
    assert alive_cleared == "alive 0 of 1", alive_cleared
    assert alive_rerun == "alive 1 of 3", alive_rerun

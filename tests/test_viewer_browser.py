"""toonmesh.Viewer in a real browser: a JupyterLab server and headless Chromium (Debian's
``chromium``, installed by scripts/system-deps.sh) driven through Playwright.

The test opens a notebook that shows a viewer of the bunny (ink of both kinds; its renders
slowed down by 0.2 s, so that pointer moves come faster than frames), runs it and checks the view's habits: the
context menu is suppressed, the wheel does nothing before the view has focus. It drags across
the frame and checks that the picture changed, that the kernel sent new frames (the frame
numbers come from the kernel), that the frames drawn while dragging were drafts drawn in the
browser by WebGL2 (every frame from the kernel is full size; the tooltip says that the drafts
draw everything the exact frame does, the mesh-space lines included), that the view was marked as a draft then exact, and busy meanwhile;
that the browser sent a view only once the last was answered (the kernel counts the views that
came early: none) and merged the moves meanwhile (fewer views than moves), losing none (the
kernel's camera is the whole drag's). Then it turns the wheel and checks that the bunny grew,
opens the outlines' section of the on-screen controls, switches the outlines off there and
checks that the ink went, presses
the toolbar's +x and home buttons and checks the kernel's camera, downloads the screenshot and
compares it with the kernel's frame, goes full screen and back, turns the view with the
auto-rotate button and stops it (the exact frame shows the turned view), loses the WebGL context
(the kernel draws the drafts) and gets it back, sends a frame made for an old
view and checks that it is dropped, and closes the viewer: the view and its controls go, and
using it raises an error that says it is closed.
The toolbar's triad turns with the drag (its screenshot changes); the projection toggle shows an
orthographic frame that differs from the perspective one, and toggled back the perspective one
again; a triad label views from its axis. A second viewer, of two bunnies, lists its parts:
unticking one removes its pixels from the frame (and from the draft drawn here).
What the screen shows is judged by screenshots of the view against the exact frame of the same
view (covered and ink pixels): mid-drag (the pointer held; the exact frame then follows with it
still held), while the view turns, and mid-drag once the lost context is back.
With TOONMESH_SCREENSHOT=1 it also writes the screenshot the viewer's page shows (docs/viewer.png:
the viewer and its controls after the drag and the wheel turn).
"""

from __future__ import annotations

import contextlib
import os
import re
from pathlib import Path
from typing import Iterator, List

import numpy as np
import pytest

from conftest import centre, chromium, need, press_and_move, screen_shares, screenshot_mid_drag
from conftest import screen_pixels as _pixels
from toonmesh.bench._lab import open_notebook

ROOT = Path(__file__).resolve().parent.parent
SCREENSHOT = ROOT / "docs" / "viewer.png"

# the drag: DRAG_STEPS pointer moves of (DRAG_DX, DRAG_DY) pixels each
DRAG_STEPS, DRAG_DX, DRAG_DY = 12, 12, 3

CELLS = [
    "import time\n"
    "import numpy as np\n"
    "import toonmesh as tm\n"
    "from toonmesh.data import bunny\n"
    "\n"
    "V, F = bunny()\n"
    "blue = tm.Material.bands('#4f8fd8')\n"
    "v = tm.Viewer(V, F, material=blue, outlines='both', width=480, height=360, controls=True)\n"
    "_show = v._show\n"
    "def slow(draft):  # frames slower than the pointer's moves\n"
    "    time.sleep(0.2)\n"
    "    return _show(draft)\n"
    "v._show = slow\n"
    "v",
    # after the drag: the kernel's counts, and its camera against the whole drag at once
    "del v._show\n"
    "same = tm.Viewer(V, F, material=blue, outlines='both', width=480, height=360)\n"
    f"same.orbit({DRAG_STEPS * DRAG_DX}, {DRAG_STEPS * DRAG_DY})\n"
    "off = float(np.abs(np.subtract(v.camera.eye, same.camera.eye)).max())\n"
    "same.close()\n"
    "print('renders', v.render_count, 'views', v._shared.views, 'early', v._shared.early, 'off', off)",
    "d = np.subtract(v.camera.eye, v.camera.target)\n"
    "print('direction', *(d / np.linalg.norm(d)).round(6))",
    "np.save('frame.npy', v.frame)\n"
    "print('home', bool(np.allclose(v.camera.eye, v._home.eye) and np.allclose(v.camera.target, v._home.target)))",
    "v.widget.show_frame(v.widget._frame, v.widget._format, 10**6, 480, 360, view_id=0)\n"
    "print('stale sent')",
    "v.close()\n"
    "try:\n"
    "    v.orbit(5, 0)\n"
    "except Exception as e:\n"
    "    print('error', type(e).__name__, e)",
    # a scene of two parts: an orange bunny and a blue one beside it
    "shifted = np.eye(4)\n"
    "shifted[0, 3] = 0.17\n"
    "w = tm.Viewer([tm.Mesh(V, F, name='bunny'), tm.Mesh(V, F, name='twin', transform=shifted, material=blue)],\n"
    "              outlines='mesh', width=480, height=300)\n"
    "w",
]


@contextlib.contextmanager
def notebook_server(tmp_path: Path, name: str, cells: List[str]) -> Iterator[str]:
    """A token-less JupyterLab server on a free port, serving tmp_path/work with the notebook
    ``name`` of ``cells``; yields its URL."""
    need("jupyterlab")
    need("anywidget")
    from toonmesh.bench._lab import jupyter_lab, write_notebook

    (tmp_path / "work").mkdir()
    write_notebook(tmp_path / "work" / name, cells)
    with jupyter_lab(tmp_path) as url:
        yield url


@pytest.fixture
def jupyter_lab(tmp_path):
    with notebook_server(tmp_path, "viewer.ipynb", CELLS) as url:
        yield url


def _run_cell(page, cells, i: int, text: str, timeout: int = 30_000) -> str:
    """Runs cell ``i`` and returns the text of its output that contains ``text``."""
    cell = cells.nth(i)
    cell.locator(".jp-InputPrompt").click()
    page.keyboard.press("Shift+Enter")
    printed = cell.locator(".jp-OutputArea-output", has_text=text)
    printed.wait_for(timeout=timeout)
    return printed.inner_text()


def _wait_exact_after(page, frames_shown: int, timeout: int = 20_000) -> None:
    """Waits until a full-size frame is shown after ``frames_shown`` frames, and nothing is on its way."""
    page.wait_for_function(
        "(n) => { const r = document.querySelector('.toonmesh-viewer');"
        " return +r.dataset.framesShown > n && r.dataset.exact === '1' && r.dataset.busy === '0'; }",
        arg=frames_shown, timeout=timeout)


def test_the_viewer_in_chromium(jupyter_lab, tmp_path):
    executable = chromium()
    need("PIL")
    sync_api = need("playwright.sync_api")
    work = tmp_path / "work"
    with sync_api.sync_playwright() as p:
        browser = p.chromium.launch(executable_path=executable, args=["--no-sandbox"])
        try:
            page = browser.new_page(viewport={"width": 1500, "height": 900}, accept_downloads=True)
            cells = open_notebook(page, jupyter_lab, "viewer.ipynb")
            cells.first.locator(".jp-InputPrompt").click()
            page.keyboard.press("Shift+Enter")  # runs the cell that shows the viewer
            viewer = page.locator(".toonmesh-viewer[data-frame]")
            viewer.wait_for(timeout=30_000)
            img = viewer.locator("img")
            page.wait_for_function("document.querySelector('.toonmesh-viewer img').naturalWidth > 0")
            page.evaluate("""() => {
                const root = document.querySelector('.toonmesh-viewer');
                const img = root.querySelector('img');
                window.__sizes = [];
                window.__exact = [];
                window.__busy = [];
                img.addEventListener('load', () => window.__sizes.push(img.naturalWidth));
                new MutationObserver(() => {
                    if (window.__exact.at(-1) !== root.dataset.exact) window.__exact.push(root.dataset.exact);
                    if (window.__busy.at(-1) !== root.dataset.busy) window.__busy.push(root.dataset.busy);
                }).observe(root, { attributes: true });
            }""")
            first = {k: viewer.get_attribute(f"data-{k}") for k in ("frame", "frames-shown", "exact", "busy")}
            toolbar = {
                "home": viewer.locator(".toonmesh-home").count(),
                "axes": viewer.locator(".toonmesh-axis").evaluate_all("bs => bs.map(b => b.dataset.axis)"),
                "screenshot": viewer.locator(".toonmesh-screenshot").count(),
                "fullscreen": viewer.locator(".toonmesh-fullscreen").count(),
                "spin": viewer.locator(".toonmesh-spin").count(),
                "projection": viewer.locator(".toonmesh-projection").get_attribute("data-projection"),
                "parts": viewer.locator(".toonmesh-parts-button").is_visible(),  # one part: no list
                "suppress": viewer.get_attribute("data-jp-suppress-context-menu"),
                "tabindex": viewer.get_attribute("tabindex"),
            }
            # the context menu is suppressed on the view (right-drag pans), the browser's and JupyterLab's
            menu_prevented = img.evaluate(
                "img => !img.dispatchEvent(new MouseEvent('contextmenu', { bubbles: true, cancelable: true, button: 2 }))")
            before = _pixels(img.screenshot())
            x, y = centre(img)
            shown = int(viewer.get_attribute("data-frames-shown"))
            page.mouse.click(x, y, button="right")  # a pan of no length: the full-size frame again
            _wait_exact_after(page, shown)
            jupyter_menus = page.locator(".lm-Menu").count()
            page.keyboard.press("Escape")

            # before the view has focus, the wheel is the notebook's: no view is sent, no frame comes
            page.evaluate("document.activeElement && document.activeElement.blur()")
            shown, sent = int(viewer.get_attribute("data-frames-shown")), int(viewer.get_attribute("data-views-sent"))
            page.mouse.move(x, y)
            page.mouse.wheel(0, -200)
            page.wait_for_timeout(800)
            unfocused_frames = int(viewer.get_attribute("data-frames-shown")) - shown
            unfocused_views = int(viewer.get_attribute("data-views-sent")) - sent

            first_frame = int(viewer.get_attribute("data-frame"))
            shown = int(viewer.get_attribute("data-frames-shown"))
            triad_before = _pixels(viewer.locator(".toonmesh-triad").screenshot())
            page.mouse.move(x, y)
            page.mouse.down()
            for i in range(1, DRAG_STEPS + 1):
                page.mouse.move(x + DRAG_DX * i, y + DRAG_DY * i)
                page.wait_for_timeout(30)
                if i == DRAG_STEPS // 2:
                    # what the screen shows mid-drag (the pointer held; a draft: the kernel's frame
                    # is not shown until the pointer stops), then, the pointer still held, the
                    # exact frame of the same view
                    mid_drag = _pixels(screenshot_mid_drag(page, img, ".toonmesh-viewer img", x + DRAG_DX * i,
                                                           y + DRAG_DY * i))
                    mid_marks = (viewer.get_attribute("data-exact"), viewer.get_attribute("data-draft-scale"))
                    _wait_exact_after(page, int(viewer.get_attribute("data-frames-shown")))
                    held = _pixels(img.screenshot())
            page.mouse.up()
            # The full-size frame follows the release; wait until it has been shown.
            _wait_exact_after(page, shown)
            page.wait_for_function("window.__sizes.at(-1) === 480", timeout=20_000)
            focused = page.evaluate("document.activeElement === document.querySelector('.toonmesh-viewer')")
            last_frame = int(viewer.get_attribute("data-frame"))
            views_sent = int(viewer.get_attribute("data-views-sent"))
            after = _pixels(img.screenshot())
            triad_after = _pixels(viewer.locator(".toonmesh-triad").screenshot())
            sizes = page.evaluate("window.__sizes")
            draft_mode, title = viewer.get_attribute("data-draft"), viewer.get_attribute("title")
            # the last draft: not blank (its pixels vary), drawn smaller than the view while moving
            drawn_here = viewer.evaluate(
                "r => { const p = r.toonmeshDraft.pixels(); let lo = 255, hi = 0;"
                " for (let i = 0; i < p.data.length; i += 4) { lo = Math.min(lo, p.data[i]); hi = Math.max(hi, p.data[i]); }"
                " return p.width < 480 && hi - lo > 100 && +r.dataset.draftScale < 1; }")
            exact_marks, busy_marks = page.evaluate("[window.__exact, window.__busy]")
            counts = _run_cell(page, cells, 1, "renders").split()
            kernel_renders, kernel_views, early, off = int(counts[1]), int(counts[3]), int(counts[5]), float(counts[7])

            # once the view has focus (a click: running the cell took it), the wheel turned away
            # from the user zooms in
            shown = int(viewer.get_attribute("data-frames-shown"))
            img.scroll_into_view_if_needed()  # the output of the cell run moved it
            x, y = centre(img)
            page.mouse.click(x, y)
            _wait_exact_after(page, shown)
            shown = int(viewer.get_attribute("data-frames-shown"))
            page.mouse.wheel(0, -200)
            _wait_exact_after(page, shown)
            page.wait_for_timeout(300)
            zoomed = _pixels(img.screenshot())
            stats = viewer.locator(".toonmesh-stats").inner_text()
            if os.environ.get("TOONMESH_SCREENSHOT") == "1":  # the viewer page's picture: after the drag and zoom
                cells.first.locator(".jp-OutputArea").screenshot(path=str(SCREENSHOT))

            # a control: outlines off re-renders (the frame has fewer dark pixels)
            shown = int(viewer.get_attribute("data-frames-shown"))
            page.locator(".toonmesh-section-outlines").get_by_text("outlines", exact=True).click()  # its section, closed at first
            page.locator(".toonmesh-outlines-kind select").select_option("none")  # the outlines' kind
            page.wait_for_function(
                "(n) => +document.querySelector('.toonmesh-viewer').dataset.framesShown > n", arg=shown, timeout=20_000)
            page.wait_for_timeout(300)
            no_outlines = _pixels(img.screenshot())

            # the toolbar: the view from +x, then home (the first view)
            shown = int(viewer.get_attribute("data-frames-shown"))
            viewer.locator(".toonmesh-axis[data-axis='+x']").click()
            _wait_exact_after(page, shown)
            direction = [float(t) for t in _run_cell(page, cells, 2, "direction").split()[1:]]
            shown = int(viewer.get_attribute("data-frames-shown"))
            viewer.locator(".toonmesh-home").click()
            _wait_exact_after(page, shown)
            home = _run_cell(page, cells, 3, "home").split()[1]
            perspective = _pixels(img.screenshot())
            with page.expect_download() as download:
                viewer.locator(".toonmesh-screenshot").click()
            download.value.save_as(str(tmp_path / "screenshot.png"))

            # the projection toggle: orthographic, then perspective again; a triad label: the view from +z
            shown = int(viewer.get_attribute("data-frames-shown"))
            viewer.locator(".toonmesh-projection").click()
            _wait_exact_after(page, shown)
            page.wait_for_timeout(300)
            orthographic = _pixels(img.screenshot())
            toggled = viewer.locator(".toonmesh-projection").get_attribute("data-projection")
            shown = int(viewer.get_attribute("data-frames-shown"))
            viewer.locator(".toonmesh-projection").click()
            _wait_exact_after(page, shown)
            page.wait_for_timeout(300)
            perspective_again = _pixels(img.screenshot())
            shown = int(viewer.get_attribute("data-frames-shown"))
            viewer.locator(".toonmesh-triad-z .toonmesh-triad-label").click()
            _wait_exact_after(page, shown)
            page.wait_for_timeout(300)
            from_z = _pixels(img.screenshot())
            triad_z = _pixels(viewer.locator(".toonmesh-triad").screenshot())

            viewer.locator(".toonmesh-fullscreen").click()
            page.wait_for_function("document.fullscreenElement === document.querySelector('.toonmesh-viewer')",
                                   timeout=5_000)
            viewer.locator(".toonmesh-fullscreen").click()
            page.wait_for_function("document.fullscreenElement === null", timeout=5_000)

            # auto-rotate: the view turns (drafts drawn here) until the button is pressed again,
            # then the exact frame of where it turned to
            before_spin = _pixels(img.screenshot())
            shown = int(viewer.get_attribute("data-frames-shown"))
            viewer.locator(".toonmesh-spin").click()
            page.wait_for_function("(n) => +document.querySelector('.toonmesh-viewer').dataset.framesShown > n + 5",
                                   arg=shown, timeout=20_000)
            spin_shot = _pixels(img.screenshot())  # what the screen shows while it turns: a draft
            spin_exact_mark = viewer.get_attribute("data-exact")
            spinning = viewer.get_attribute("data-spinning")
            viewer.locator(".toonmesh-spin").click()
            shown = int(viewer.get_attribute("data-frames-shown"))
            _wait_exact_after(page, shown)
            page.wait_for_timeout(300)
            after_spin = _pixels(img.screenshot())
            stopped = viewer.get_attribute("data-spinning")

            # a lost WebGL context: the kernel draws the drafts until the browser gives it back; then
            # the drafts are drawn here again and reach the screen
            viewer.evaluate("r => { window.__lose = r.toonmeshDraft.gl.getExtension('WEBGL_lose_context');"
                            " window.__lose.loseContext(); }")
            page.wait_for_function("document.querySelector('.toonmesh-viewer').dataset.draft === 'kernel'",
                                   timeout=10_000)
            lost_title = viewer.get_attribute("title")
            page.evaluate("window.__lose.restoreContext()")
            page.wait_for_function("document.querySelector('.toonmesh-viewer').dataset.draft === 'webgl'",
                                   timeout=10_000)
            img.scroll_into_view_if_needed()
            x, y = centre(img)
            press_and_move(page, x, y, 4, -10)
            restored_shot = _pixels(screenshot_mid_drag(page, img, ".toonmesh-viewer img", x - 40, y))
            restored_mark = viewer.get_attribute("data-exact")
            shown = int(viewer.get_attribute("data-frames-shown"))
            page.mouse.up()
            _wait_exact_after(page, shown)
            restored_shares = screen_shares(restored_shot, _pixels(img.screenshot()))

            # a frame made for an older view than the one shown is dropped
            shown = int(viewer.get_attribute("data-frames-shown"))
            _run_cell(page, cells, 4, "stale sent")
            page.wait_for_function("+document.querySelector('.toonmesh-viewer').dataset.dropped >= 1", timeout=10_000)
            stale_shown = int(viewer.get_attribute("data-frames-shown")) - shown

            # close(): the view and its controls leave the notebook; using it says it is closed
            closed_error = _run_cell(page, cells, 5, "error")
            page.wait_for_function("document.querySelectorAll('.toonmesh-viewer').length === 0", timeout=10_000)
            controls_left = page.locator(".toonmesh-outlines-kind").count()

            # the parts list of a scene of two bunnies: unticking the blue one removes its pixels
            cells.nth(6).locator(".jp-InputPrompt").click()
            page.keyboard.press("Shift+Enter")
            scene = page.locator(".toonmesh-viewer[data-frame]")
            scene.wait_for(timeout=30_000)
            page.wait_for_function("document.querySelector('.toonmesh-viewer img').naturalWidth > 0")
            _wait_exact_after(page, 0)
            both = _pixels(scene.locator("img").screenshot())
            scene.locator(".toonmesh-parts-button").click()
            names = scene.locator(".toonmesh-parts label").all_inner_texts()
            shown = int(scene.get_attribute("data-frames-shown"))
            scene.locator(".toonmesh-parts input[data-part='1']").uncheck()
            _wait_exact_after(page, shown)
            scene.locator(".toonmesh-parts-button").click()  # the list closed, off the picture
            page.wait_for_timeout(300)
            one = _pixels(scene.locator("img").screenshot())
            # a drag: the draft drawn here leaves the blue bunny out too
            shown = int(scene.get_attribute("data-frames-shown"))
            press_and_move(page, *centre(scene.locator("img")), 5, 4)
            draft_blue = scene.evaluate(
                "r => { const p = r.toonmeshDraft.pixels(); let n = 0, m = 0;"
                " for (let i = 0; i < p.data.length; i += 4) { if (p.data[i + 2] > p.data[i] + 60) n++;"
                " if (p.data[i] > p.data[i + 2] + 60) m++; } return [n, m]; }")
            page.mouse.up()
            _wait_exact_after(page, shown)
        except Exception:
            page.screenshot(path=str(tmp_path / "failure.png"))
            raise
        finally:
            browser.close()

    assert first["exact"] == "1" and first["busy"] == "0" and int(first["frames-shown"]) >= 1, first
    assert toolbar == {"home": 1, "axes": ["+x", "-x", "+y", "-y", "+z", "-z"], "screenshot": 1, "fullscreen": 1,
                       "spin": 1, "projection": "perspective", "parts": False, "suppress": "", "tabindex": "0"}, toolbar
    assert spinning == "1" and stopped == "0", (spinning, stopped)
    # the screen showed the turning view's drafts: the model as the exact frame of the view it
    # stopped at (a few degrees on) shows it (the outlines are off by then: no ink to compare)
    spin_shares = screen_shares(spin_shot, after_spin)
    assert spin_exact_mark == "0" and spin_shares[0] >= 0.8, (spin_exact_mark, spin_shares)
    assert (np.abs(before_spin - after_spin).max(axis=2) > 24).mean() > 0.02  # it turned
    assert menu_prevented and jupyter_menus == 0, (menu_prevented, jupyter_menus)
    assert unfocused_frames == 0 and unfocused_views == 0, (unfocused_frames, unfocused_views)

    assert before.shape == after.shape and abs(before.shape[0] - 360) <= 1 and abs(before.shape[1] - 480) <= 1
    changed = np.abs(before - after).max(axis=2) > 24
    assert changed.mean() > 0.02, f"only {changed.mean():.1%} of the pixels changed"
    assert last_frame >= first_frame + 1, (first_frame, last_frame)  # the exact frame after the drafts
    # the drafts were drawn in the browser by WebGL2 (no kernel drafts: every kernel frame is full
    # size), drawing everything the exact frame does (the mesh-space lines included)
    assert draft_mode == "webgl" and drawn_here, (draft_mode, drawn_here, title)
    # mid-drag the screen showed a draft (smaller than the view) with the model and its ink as
    # the exact frame of the same view shows them
    mid_shares = screen_shares(mid_drag, held)
    assert mid_marks[0] == "0" and float(mid_marks[1]) < 1, mid_marks
    assert mid_shares[0] >= 0.8 and mid_shares[1] >= 0.5, mid_shares
    assert "WebGL2" in title and "the draft draws everything the exact frame does" in title, title
    assert sizes and set(sizes) == {480}, sizes
    assert "0" in exact_marks and exact_marks[-1] == "1", exact_marks  # a draft shown, then the exact frame
    assert "1" in busy_marks and busy_marks[-1] == "0", busy_marks
    assert focused
    # flow control: one view in flight at a time, the moves merged meanwhile, none lost
    assert early == 0, early
    assert kernel_views == views_sent and 1 <= views_sent < DRAG_STEPS, (kernel_views, views_sent)
    assert off < 1e-9, off
    assert kernel_renders >= last_frame

    def covered(picture):  # pixels that are not the white background
        return float((picture.min(axis=2) < 200).mean())

    assert covered(zoomed) > 1.2 * covered(after), (covered(after), covered(zoomed))
    assert re.fullmatch(r"\d+ fps \u00b7 \d+ ms", stats), stats

    def inked(picture):  # near-black pixels: outlines and the darkest band
        return float((picture.max(axis=2) < 40).mean())

    assert inked(no_outlines) < 0.9 * inked(zoomed), (inked(zoomed), inked(no_outlines))

    assert direction[0] > 0.999, direction  # the eye on the +x side
    assert home == "True"
    shot = np.asarray(__import__("PIL.Image", fromlist=["Image"]).open(tmp_path / "screenshot.png"))
    np.testing.assert_array_equal(shot, np.load(work / "frame.npy"))  # the kernel's exact frame, as it is

    assert "the WebGL context was lost" in lost_title, lost_title
    assert restored_mark == "0" and restored_shares[0] >= 0.8, (restored_mark, restored_shares)
    assert stale_shown == 0, stale_shown
    assert "ViewerClosedError" in closed_error and "closed" in closed_error.split("ViewerClosedError", 1)[1], closed_error
    assert controls_left == 0

    def moved(a, b):  # the share of pixels that changed (inside: a screenshot's edge rows may catch the toolbar's)
        return float((np.abs(a - b)[2:-2, 2:-2].max(axis=2) > 24).mean())

    # the triad turned with the drag, and again to the view from +z
    assert triad_before.shape == triad_after.shape and moved(triad_before, triad_after) > 0.02
    assert moved(triad_after, triad_z) > 0.02
    # the orthographic frame is another picture of the same framing; toggled back, the perspective one
    assert toggled == "orthographic"
    assert moved(perspective, orthographic) > 0.02, moved(perspective, orthographic)
    assert moved(perspective, perspective_again) < 0.002, moved(perspective, perspective_again)
    assert moved(perspective_again, from_z) > 0.02

    def blue(picture):  # the blue bunny's pixels
        return float((picture[..., 2] > picture[..., 0] + 60).mean())

    def orange(picture):
        return float((picture[..., 0] > picture[..., 2] + 60).mean())

    assert [n.strip() for n in names] == ["bunny", "twin"], names
    assert blue(both) > 0.1 and orange(both) > 0.1, (blue(both), orange(both))
    assert blue(one) < 0.001 and orange(one) > 0.1, (blue(one), orange(one))
    assert draft_blue[0] == 0 and draft_blue[1] > 1000, draft_blue

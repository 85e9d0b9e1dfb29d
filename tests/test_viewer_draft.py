"""The viewer's drafts drawn in the browser: toonmesh's own WGSL translated to GLSL ES 3.00 by the
core (``Renderer._draft``), drawn by WebGL2 in headless Chromium (SwiftShader) from the page
:meth:`toonmesh.Viewer.to_html` writes.

The page is opened in Chromium: its shaders compile and link there (the check of the translated
GLSL that counts), it draws (the canvas is not blank) and a drag makes it draw more frames. A
draft and the exact frame of the same view (``tm.render`` with the viewer's camera) agree on at
least 95% of the covered pixels within 8 levels, for the plain bunny, a coloured one, a
textured one and two bunnies (each its own draw and material), with Vulkan and GL kernels (shading without ink: the draft's ink is image-space
only). The draft's image-space ink is drawn (dark pixels where the exact frame has its edges),
the page shows the draft's pixels as they are (a screenshot of the canvas), and what the draft
leaves to the exact frame is named in the page's tooltip. The draft draws the mesh-space lines
and the hatching as the exact frame does: with ``outlines="mesh"``, ``"both"`` and a hatched
material, at least 95% of the covered pixels within 8 levels and at least 70% of the exact
frame's ink within a pixel of the draft's. A draft at a quarter of the size draws
the core's coarse copy of the mesh (a tenth of its faces) and keeps the picture: within 8
levels of the exact frame at that size, up to a pixel, on at least 93% of the covered pixels.
Screenshots of the page show the model and its ink during a drag (the pointer held) and after
it, and the page draws again once a lost WebGL context is given back.
"""

from __future__ import annotations

import io

import numpy as np
import pytest

import toonmesh as tm
from conftest import (RENDER_BACKENDS, centre, chromium, need, press_and_move, screen_pixels, screen_shares,
                      screenshot_mid_drag)
from toonmesh.data import bunny

SIZE = (320, 240)


def _scene(kind: str):
    V, F = bunny()
    if kind == "plain":
        return tm.Mesh(V, F)
    if kind == "two meshes":  # each with its own draw: one placed, one coloured by its material
        moved = np.array([[1, 0, 0, 0.12], [0, 1, 0, 0], [0, 0, 1, 0], [0, 0, 0, 1]], float)
        return [tm.Mesh(V, F), tm.Mesh(V, F, transform=moved, material=tm.Material.bands("#4f8fd8"))]
    lo, hi = V.min(axis=0), V.max(axis=0)
    t = (V - lo) / (hi - lo)
    if kind == "coloured":
        return tm.Mesh(V, F, vertex_colors=np.c_[t, np.ones(len(V))].astype(np.float32))
    checker = (np.indices((8, 8)).sum(axis=0) % 2).astype(np.uint8)
    texture = np.stack([checker * 200 + 40, 120 + checker * 60, 255 - checker * 180, np.full_like(checker, 255)], -1)
    return tm.Mesh(V, F, uv=t[:, :2].astype(np.float32), texture=texture.astype(np.uint8), texture_filter="nearest")


@pytest.fixture(scope="module")
def browser():
    executable = chromium()
    sync_api = need("playwright.sync_api")
    with sync_api.sync_playwright() as p:
        b = p.chromium.launch(executable_path=executable, args=["--no-sandbox"])
        try:
            yield b
        finally:
            b.close()


def _open(browser, path):
    page = browser.new_page()
    errors = []
    page.on("pageerror", lambda e: errors.append(str(e)))
    page.goto(path.as_uri())
    page.wait_for_function("() => { const r = document.querySelector('.toonmesh-viewer');"
                           " return +r.dataset.framesShown > 0 || r.dataset.error; }", timeout=60_000)
    error = page.evaluate("document.querySelector('.toonmesh-viewer').dataset.error")
    assert error is None and not errors, (error, errors)
    return page


def _draft(page, camera=None) -> np.ndarray:
    """The page's draft of ``camera`` (the viewer's camera state; None: as it is), (H, W, 4) uint8."""
    p = page.evaluate("(c) => { window.toonmeshDraft.draw(c); const p = window.toonmeshDraft.pixels();"
                      " return [p.width, p.height, Array.from(p.data)]; }", camera)
    return np.asarray(p[2], np.uint8).reshape(p[1], p[0], 4)


def _agreement(draft: np.ndarray, exact: np.ndarray, reach: int = 0) -> float:
    """The share of the pixels covered in either image (not the background, the corner's colour)
    whose channels differ by at most 8 levels from the exact frame's pixel (or, with ``reach``,
    from one of those within that many pixels)."""
    bg = exact[0, 0, :3].astype(int)
    covered = (np.abs(exact[..., :3] - bg).max(-1) > 0) | (np.abs(draft[..., :3] - bg).max(-1) > 0)
    d, e = draft[..., :3].astype(int), exact[..., :3].astype(int)
    h, w = e.shape[:2]
    near = np.pad(e, ((reach, reach), (reach, reach), (0, 0)), mode="edge")
    steps = range(-reach, reach + 1)
    diff = np.min([np.abs(d - near[reach + y:reach + y + h, reach + x:reach + x + w]).max(-1)
                   for y in steps for x in steps], axis=0)
    return float((diff[covered] <= 8).mean())


@pytest.mark.parametrize("backend", RENDER_BACKENDS)
@pytest.mark.parametrize("kind", ["plain", "coloured", "textured", "two meshes"])
def test_a_draft_agrees_with_the_exact_frame_of_the_same_view(browser, tmp_path, backend, kind):
    mesh = _scene(kind)
    v = tm.Viewer(mesh, backend=backend, width=SIZE[0], height=SIZE[1])
    try:
        v.orbit(70, -25)  # not the first view: the page's camera follows the viewer's
        v.to_html(tmp_path / "page.html")
        page = _open(browser, tmp_path / "page.html")
        draft = _draft(page, v._camera_state())
        exact = tm.render(mesh, camera=v.camera, width=SIZE[0], height=SIZE[1], backend=backend).color
        title = page.evaluate("document.querySelector('.toonmesh-viewer').title")
        page.close()
    finally:
        v.close()
    assert draft.shape == exact.shape
    covered = float((np.abs(exact[..., :3].astype(int) - 255).max(-1) > 0).mean())
    assert covered > 0.1, covered  # the bunny is in the view
    share = _agreement(draft, exact)
    assert share >= 0.95, f"{share:.1%} of the covered pixels agree within 8 levels"
    assert "WebGL2" in title and "the draft draws everything" in title, title


def _quarter_draft(browser, tmp_path, **options):
    """A bunny viewer's page with ``options``: its draft at a quarter of the size (H, W, 4), the
    faces that draft drew and those of the full-size draft, and the viewer's camera."""
    V, F = bunny()
    v = tm.Viewer(V, F, width=SIZE[0], height=SIZE[1], **options)
    try:
        v.to_html(tmp_path / "page.html")
        camera, view = v._camera_state(), v.camera
    finally:
        v.close()
    page = _open(browser, tmp_path / "page.html")
    w, h = SIZE[0] // 4, SIZE[1] // 4
    drawn = "([c, w, h, r]) => { const d = window.toonmeshDraft.renderer; d.draw(c, w, h, r); return d.drawnFaces(); }"
    full = page.evaluate(drawn, [camera, *SIZE, 1])
    small = page.evaluate(drawn, [camera, w, h, 0.25])
    pixels = page.evaluate("Array.from(window.toonmeshDraft.renderer.pixels().data)")
    page.close()
    return np.asarray(pixels, np.uint8).reshape(h, w, 4), small, full, view


def test_a_small_draft_draws_a_coarse_copy_that_keeps_the_picture(browser, tmp_path):
    V, F = bunny()
    draft, small, full, view = _quarter_draft(browser, tmp_path)
    exact = tm.render(V, F, camera=view, width=draft.shape[1], height=draft.shape[0]).color
    # a quarter of the size: far fewer faces (about two a pixel), the same picture at that size
    # up to band borders and edges moved by a pixel (the copy's vertices are its clusters' means)
    assert full == len(F) and small < 0.25 * len(F), (small, full, len(F))
    share = _agreement(draft, exact, reach=1)
    print(f"quarter-size draft: {small} faces, {share:.1%} of the covered pixels within 8 levels up to a pixel,"
          f" {_agreement(draft, exact):.1%} without")
    assert share >= 0.93, f"{share:.1%} of the covered pixels agree within 8 levels and a pixel"


def test_a_small_draft_keeps_its_ink_visible(browser, tmp_path):
    draft, _, _, _ = _quarter_draft(browser, tmp_path, outlines="image")
    rgb = draft[..., :3].astype(int)
    covered = np.abs(rgb - 255).max(-1) > 0
    inside = np.roll(covered, 1, 0) & np.roll(covered, -1, 0) & np.roll(covered, 1, 1) & np.roll(covered, -1, 1)
    outline = int((covered & ~inside).sum())  # the pixels along the silhouette
    dark = int((rgb.max(-1) < 110).sum())  # ink (the bands stay lighter: no ink, none is this dark)
    # the ink a quarter as many pixels wide would be a faint fringe; at least the default line's
    # width in the draft's pixels, it is a line along the silhouette and the creases
    assert dark >= outline, (dark, outline)


def test_a_small_draft_draws_the_smooth_contours_of_its_coarse_copy(browser, tmp_path):
    V, F = bunny()
    draft, _, _, view = _quarter_draft(browser, tmp_path, outlines="mesh")
    h, w = draft.shape[:2]
    exact = tm.render(V, F, outlines="mesh", camera=view, width=w, height=h).color
    # the copy's contours where its surface is: the lines where the exact frame's are, none
    # hidden by the copy's surface (its vertices are its clusters' means)
    found, own = _ink_found(draft, exact), _ink_found(exact, draft)
    assert _ink(exact).sum() > 100, _ink(exact).sum()
    assert found >= 0.7 and own >= 0.7, (found, own)


def test_a_small_drafts_dither_cells_keep_their_size_on_screen(browser, tmp_path):
    V, F = bunny()
    material = tm.Material.bands("#d0a070", dither=tm.Dither("bayer4", scale=4.0))
    draft, _, _, view = _quarter_draft(browser, tmp_path, material=material)
    h, w = draft.shape[:2]
    # a quarter-size draft is the frame at a quarter of the pixel ratio: cells a quarter as many
    # pixels wide, as large on screen (not the cells of the full-size frame, four times as large)
    same = _agreement(draft, tm.render(V, F, material=material, camera=view, width=w, height=h, pixel_ratio=0.25).color)
    other = _agreement(draft, tm.render(V, F, material=material, camera=view, width=w, height=h).color)
    assert same > other + 0.05, (same, other)


def _page_of(browser, tmp_path, name, **options):
    """The page of a bunny viewer with ``options``, opened; and the viewer's exact frame and camera."""
    V, F = bunny()
    v = tm.Viewer(V, F, width=SIZE[0], height=SIZE[1], **options)
    path = tmp_path / f"{name}.html"
    try:
        assert v.to_html(path) == str(path)
        exact, camera = v.frame, v._camera_state()
    finally:
        v.close()
    text = path.read_text(encoding="utf-8")
    assert "http://" not in text and "https://" not in text and "src=" not in text  # all inlined
    return _open(browser, path), exact, camera


def test_the_draft_draws_the_image_space_ink_as_the_exact_frame_does(browser, tmp_path):
    page, exact, camera = _page_of(browser, tmp_path, "image", outlines="image")
    draft = _draft(page, camera)
    # what the page shows is the draft's pixels, as they are
    need("PIL")
    from PIL import Image

    shown = np.asarray(Image.open(io.BytesIO(page.locator("canvas").screenshot())).convert("RGB"))
    np.testing.assert_array_equal(shown, draft[..., :3])
    page.close()
    dark_draft = draft[..., :3].max(-1) < 100
    dark_exact = exact[..., :3].max(-1) < 100
    assert dark_exact.sum() > 500, dark_exact.sum()
    assert (dark_draft & dark_exact).sum() > 0.8 * max(dark_draft.sum(), dark_exact.sum())
    assert _agreement(draft, exact) >= 0.95


def test_the_page_draws_orbits_and_names_what_the_draft_leaves_out(browser, tmp_path):
    page, exact, camera = _page_of(browser, tmp_path, "both", outlines="both", msaa=4)
    root = page.locator(".toonmesh-viewer")
    assert root.get_attribute("data-exact") == "0"
    title = root.get_attribute("title")
    # the lines and the image-space ink are drawn, the multisampling left out
    assert title.endswith("left to the exact frame: multisampling"), title
    first = _draft(page, camera)
    assert first[..., :3].min() < 150 and first[..., :3].max() > 200, "the canvas is blank"
    # a synthetic drag: more frames, another picture
    shown = int(root.get_attribute("data-frames-shown"))
    press_and_move(page, *centre(page.locator("canvas")), 10, 8, 2, pause_ms=20)
    page.mouse.up()
    page.wait_for_function("(n) => +document.querySelector('.toonmesh-viewer').dataset.framesShown >= n + 3",
                           arg=shown, timeout=20_000)
    moved = _draft(page)
    assert (np.abs(moved.astype(int) - first.astype(int)).max(-1) > 24).mean() > 0.02
    page.close()


def test_the_page_shows_the_model_on_screen_during_and_after_a_drag(browser, tmp_path):
    page, exact, _ = _page_of(browser, tmp_path, "screen", outlines="image")
    canvas = page.locator("canvas")
    loaded = screen_shares(screen_pixels(canvas.screenshot()), exact)
    x, y = centre(canvas)
    page.mouse.move(x, y)
    page.mouse.down()
    during = []
    for i in range(1, 13):  # the pointer held: a screenshot after every fourth move
        page.mouse.move(x + 6 * i, y + 2 * i)
        page.wait_for_timeout(30)
        if i % 4 == 0:
            shot = screen_pixels(screenshot_mid_drag(page, canvas, "canvas", x + 6 * i, y + 2 * i))
            # a draft of the moving view (smaller than the view), shown at the view's size
            small = page.evaluate("window.toonmeshDraft.renderer.pixels().width") < SIZE[0]
            during.append((screen_shares(shot, exact), small, shot.shape[:2]))
    page.mouse.up()
    page.wait_for_timeout(500)  # settled: the full-size draft
    full = page.evaluate("window.toonmeshDraft.renderer.pixels().width") == SIZE[0]
    after = screen_shares(screen_pixels(canvas.screenshot()), exact)
    page.close()
    assert full
    figures = {"loaded": loaded, "during": [d[0] for d in during], "after": after}  # (covered, ink) shares
    assert loaded[0] >= 0.95, figures
    for shares, small, shape in during:
        assert small and shape == (SIZE[1], SIZE[0]), (small, shape)
    # the view turned by a few degrees: most of the model and its ink in every screenshot
    assert all(c >= 0.6 and i >= 0.3 for c, i in figures["during"] + [after]), figures


def test_the_page_draws_again_once_a_lost_webgl_context_is_restored(browser, tmp_path):
    page, exact, _ = _page_of(browser, tmp_path, "lost", outlines="image")
    root, canvas = page.locator(".toonmesh-viewer"), page.locator("canvas")
    page.evaluate("window.__lose = window.toonmeshDraft.renderer.gl.getExtension('WEBGL_lose_context');"
                  " window.__lose.loseContext()")
    page.wait_for_function("document.querySelector('.toonmesh-viewer').dataset.error !== undefined", timeout=10_000)
    lost = (root.get_attribute("data-error"), root.get_attribute("title"))
    shown = int(root.get_attribute("data-frames-shown"))
    page.evaluate("window.__lose.restoreContext()")
    page.wait_for_function("(n) => { const r = document.querySelector('.toonmesh-viewer');"
                           " return r.dataset.error === undefined && +r.dataset.framesShown > n; }", arg=shown,
                           timeout=10_000)
    page.wait_for_timeout(200)
    shares = screen_shares(screen_pixels(canvas.screenshot()), exact)
    title = root.get_attribute("title")
    page.close()
    assert lost[0] == "the WebGL context was lost" and lost[1].startswith("WebGL2 drafts failed"), lost
    assert "drafts drawn in WebGL2" in title, title
    assert shares[0] >= 0.95 and shares[1] >= 0.9, shares  # the renderer made again: the view as before


def _ink(img: np.ndarray) -> np.ndarray:
    """The dark pixels: ink (lines, hatching strokes), the shading's bands all being lighter."""
    return img[..., :3].max(-1) < 100


def _ink_found(draft: np.ndarray, exact: np.ndarray, reach: int = 1) -> float:
    """The share of the exact frame's ink within ``reach`` pixels of the draft's ink."""
    d = np.pad(_ink(draft), reach)
    h, w = draft.shape[:2]
    steps = range(-reach, reach + 1)
    near = np.any([d[reach + y:reach + y + h, reach + x:reach + x + w] for y in steps for x in steps], axis=0)
    e = _ink(exact)
    return float((e & near).sum() / max(e.sum(), 1))


# The drafts decide visibility by the depth rule (per pixel, in WebGL): the frame they are held to
# uses it too; the exact rule's frame differs from it only where lines run along the rim
# (test_the_exact_rule_s_frame_differs_from_the_draft_s_only_along_the_rim).
INKED = {
    "mesh lines": {"outlines": tm.Outlines("mesh", visibility="depth")},
    "face edges": {"outlines": tm.Outlines("mesh", contours="faces", visibility="depth")},  # the face-edge rule
    "hatched": {"material": tm.Material.hatching("#d08050")},
    "both": {"outlines": tm.Outlines("both", visibility="depth")},
}


def test_the_exact_rule_s_frame_differs_from_the_draft_s_only_along_the_rim():
    # a scan's face-edge silhouettes zig-zag in and out of sight along the rim: the depth rule
    # shows the bits just behind it, the exact rule does not; elsewhere the two frames agree
    V, F = bunny()
    kw = dict(camera=tm.Camera.fit((0.35, 0.3, 1.0)), width=SIZE[0], height=SIZE[1])
    for rule in ({}, {"contours": "faces"}):
        depth = tm.render(V, F, outlines=tm.Outlines("mesh", visibility="depth", **rule), **kw).color
        exact = tm.render(V, F, outlines=tm.Outlines("mesh", **rule), **kw).color
        assert _agreement(exact, depth) >= 0.93, rule
        assert _agreement(exact, depth, reach=1) >= 0.97, rule


@pytest.mark.parametrize("kind", list(INKED))
def test_a_draft_draws_the_lines_and_the_hatching_as_the_exact_frame_does(browser, tmp_path, kind):
    options = INKED[kind]
    V, F = bunny()
    v = tm.Viewer(V, F, width=SIZE[0], height=SIZE[1], **options)
    try:
        v.orbit(70, -25)
        v.to_html(tmp_path / "page.html")
        camera = v._camera_state()
        exact = tm.render(V, F, camera=v.camera, width=SIZE[0], height=SIZE[1], **options).color
    finally:
        v.close()
    page = _open(browser, tmp_path / "page.html")
    draft = _draft(page, camera)
    title = page.locator(".toonmesh-viewer").get_attribute("title")
    page.close()
    assert "the draft draws everything the exact frame does" in title, title
    share, found = _agreement(draft, exact), _ink_found(draft, exact)
    print(f"{kind}: {share:.1%} of the covered pixels within 8 levels, {found:.1%} of the ink found")
    assert _ink(exact).sum() > 1000, _ink(exact).sum()  # ink to find
    assert share >= 0.95, f"{share:.1%} of the covered pixels agree within 8 levels"
    assert found >= 0.70, f"{found:.1%} of the exact frame's ink within a pixel of the draft's"
    # and the draft draws no ink of its own where the exact frame has none
    assert _ink_found(exact, draft) >= 0.70


def test_to_html_refuses_a_path_that_is_not_one():
    V, F = bunny()
    v = tm.Viewer(V, F, width=64, height=64)
    try:
        with pytest.raises(TypeError, match="path"):
            v.to_html(3)  # type: ignore[arg-type]
    finally:
        v.close()
    with pytest.raises(tm.ViewerClosedError):
        v.to_html("x.html")


@pytest.mark.parametrize("options, left", [
    ({"material": tm.Material.hatching("#d08050")}, None),
    ({"material": tm.Material.hatching("#d08050", mode="triplanar")}, None),
    ({"lights": [tm.Light.directional((-1, -1, -1), shadows=True)]}, "shadows"),
    ({"material": tm.Material.bands("#d08050", rim=tm.Rim(), dither="bayer4")}, None),
    ({"supersample": 2}, "supersampling"),
])
def test_effects_compile_in_the_browser_and_those_it_cannot_draw_are_named(browser, tmp_path, options, left):
    page, exact, camera = _page_of(browser, tmp_path, "effects", **options)  # its programs compiled and linked
    title = page.locator(".toonmesh-viewer").get_attribute("title")
    draft = _draft(page, camera)
    page.close()
    if left is None:  # per-pixel effects the draft draws as the exact frame does
        assert "the draft draws everything" in title, title
        assert _agreement(draft, exact) >= 0.95
    else:
        assert f"left to the exact frame: {left}" in title, title


@pytest.mark.parametrize("options", [
    {"camera": tm.Camera.fit(orthographic=True)},
    {"outlines": tm.Outlines("image", image_rule="paper")},  # the ink read from the geometry target
    {"transform": [[0, 0, 2, 0.5], [0, 2, 0, 0], [-2, 0, 0, 1], [0, 0, 0, 1]]},
    {"lights": [tm.Light.point((0.3, 0.3, 0.3), space="world"), tm.Light.directional((1, 0, -1))]},
], ids=["orthographic", "paper-rule", "transform", "world-lights"])
def test_the_camera_the_placement_and_the_lights_follow_the_view_as_in_the_kernel(browser, tmp_path, options):
    V, F = bunny()
    v = tm.Viewer(V, F, width=SIZE[0], height=SIZE[1], **options)
    try:
        v.orbit(40, 10)
        v.to_html(tmp_path / "page.html")
        camera = v._camera_state()
        given = {k: x for k, x in options.items() if k != "camera"}
        exact = tm.render(V, F, camera=v.camera, width=SIZE[0], height=SIZE[1], **given).color
    finally:
        v.close()
    page = _open(browser, tmp_path / "page.html")
    draft = _draft(page, camera)
    page.close()
    assert _agreement(draft, exact) >= 0.95


def test_a_shader_the_browser_refuses_is_said_in_the_tooltip(browser, tmp_path):
    import json

    from toonmesh.viewer._draft import page as draft_page

    V, F = bunny()
    v = tm.Viewer(V, F, width=64, height=64)
    try:
        spec, blob = v._draft()
        camera = v._camera_state()
    finally:
        v.close()
    broken = json.loads(spec)
    broken["programs"][0]["fragment"]["source"] += "\nthis is not GLSL\n"
    path = tmp_path / "broken.html"
    path.write_text(draft_page(json.dumps(broken), blob, camera, {"drag_scale": 0.5}, (64, 64), "t"), encoding="utf-8")
    page = browser.new_page()
    page.goto(path.as_uri())
    page.wait_for_function("document.querySelector('.toonmesh-viewer').dataset.error !== undefined", timeout=30_000)
    title = page.locator(".toonmesh-viewer").get_attribute("title")
    page.close()
    assert title.startswith("WebGL2 drafts failed: shade") and "fragment" in title, title


def _two_fingers(page, spread: float, shift: float) -> None:
    """Two touch pointers on the canvas's centre, 40 px apart, moved apart by ``spread`` px each
    and both by ``shift`` px to the right, in ten steps, then lifted."""
    page.evaluate("""([spread, shift]) => {
      const c = document.querySelector('canvas'), r = c.getBoundingClientRect();
      const cx = r.left + r.width / 2, cy = r.top + r.height / 2;
      const ev = (type, id, x) => c.dispatchEvent(new PointerEvent(type, { pointerId: id, clientX: x, clientY: cy,
        pointerType: 'touch', isPrimary: id === 1, bubbles: true, cancelable: true }));
      ev('pointerdown', 1, cx - 20); ev('pointerdown', 2, cx + 20);
      let a = cx - 20, b = cx + 20;
      for (let i = 1; i <= 10; i++) {
        a += shift / 10 - spread / 10; b += shift / 10 + spread / 10;
        ev('pointermove', 1, a); ev('pointermove', 2, b);
      }
      ev('pointerup', 1, a); ev('pointerup', 2, b);
    }""", [spread, shift])


def _covered(img: np.ndarray) -> np.ndarray:
    bg = img[0, 0, :3].astype(int)
    return np.abs(img[..., :3].astype(int) - bg).max(-1) > 0


def test_two_fingers_pinch_to_zoom_and_move_together_to_pan(browser, tmp_path):
    page, _, _ = _page_of(browser, tmp_path, "fingers")
    first = _covered(_draft(page))
    _two_fingers(page, spread=40.0, shift=0.0)  # apart: nearer
    nearer = _covered(_draft(page))
    assert nearer.sum() > 1.3 * first.sum(), (first.sum(), nearer.sum())
    _two_fingers(page, spread=-20.0, shift=0.0)  # together: farther
    farther = _covered(_draft(page))
    assert farther.sum() < 0.9 * nearer.sum(), (nearer.sum(), farther.sum())
    _two_fingers(page, spread=0.0, shift=40.0)  # both to the right: the model follows
    moved = _covered(_draft(page))
    x = np.arange(SIZE[0])
    centre = lambda m: float((m * x).sum() / m.sum())  # noqa: E731
    assert 25 < centre(moved) - centre(farther) < 55, (centre(farther), centre(moved))
    assert abs(moved.sum() - farther.sum()) < 0.1 * farther.sum()  # a pan, not a zoom
    page.close()


def test_the_wheel_zooms_toward_the_cursor_as_the_kernels_viewer_does(browser, tmp_path):
    V, F = bunny()
    v = tm.Viewer(V, F, width=SIZE[0], height=SIZE[1])
    path = tmp_path / "wheel.html"
    v.to_html(path)
    page = _open(browser, path)
    box = page.locator("canvas").bounding_box()
    offset = (70, -40)  # right of and above the centre
    page.mouse.move(box["x"] + box["width"] / 2 + offset[0], box["y"] + box["height"] / 2 + offset[1])
    page.mouse.wheel(0, -300)
    page.wait_for_timeout(200)
    drafted = page.evaluate("window.toonmeshDraft.camera()")
    page.close()
    # the kernel's viewer, given the same wheel turn at the same cursor
    v._step({"event": "zoom", "dx": 0, "dy": -300, "x": offset[0], "y": offset[1]})
    kernel = v._camera_state()
    v.close()
    for k in ("eye", "target"):
        assert np.allclose(drafted[k], kernel[k], rtol=1e-6, atol=1e-6 * np.abs(kernel["eye"]).max()), (k, drafted, kernel)


@pytest.mark.parametrize("orthographic", [False, True])
def test_a_zoom_toward_the_cursor_keeps_the_point_under_it(orthographic):
    V, F = bunny()
    camera = tm.Camera.orthographic((0.3, 0.4, 1.0), height=0.3) if orthographic else None
    v = tm.Viewer(V, F, width=SIZE[0], height=SIZE[1], camera=camera)
    before = v._camera_state()

    def under(state, x, y):
        """The point at the target's depth under pixel offset (x, y), and the basis and pixel size."""
        eye, target, up = (np.asarray(state[k], float) for k in ("eye", "target", "up"))
        f = (target - eye) / np.linalg.norm(target - eye)
        right = np.cross(f, up)
        right /= np.linalg.norm(right)
        true_up = np.cross(right, f)
        size = (state["height"] if state["orthographic"]
                else 2 * np.linalg.norm(target - eye) * np.tan(np.radians(state["fov_y"]) / 2)) / SIZE[1]
        return target + (x * right - y * true_up) * size, right, true_up, size, target

    point = under(before, 90, 35)[0]
    v._step({"event": "zoom", "dx": 0, "dy": -400, "x": 90, "y": 35})
    after = v._camera_state()
    _, right, true_up, size, target = under(after, 0, 0)
    assert size < under(before, 0, 0)[3] * 0.8  # nearer
    seen = ((point - target) @ right / size, -(point - target) @ true_up / size)
    assert np.allclose(seen, (90, 35), atol=1e-6), seen
    v.close()


def test_a_draft_blends_glass_over_what_it_covers_and_leaves_the_exact_layers_and_line_items_to_the_frame(
        browser, tmp_path):
    """A pawn in a glass case: the draft shows the pawn through the glass (blended by the glass's
    opacity over it, as the exact frame composites it), and names what it leaves out: the exact
    compositing of the layers in depth order, and the scene's own lines."""
    from toonmesh.bench.lines import slab

    pawn = tm.Mesh(*tm.shapes.pawn(), material=tm.Material.bands("#f08a4b"))
    case = tm.Mesh(*slab((-0.7, -0.1, -0.7), (0.7, 1.2, 0.7)), material=tm.Material.bands("#9fd3ff", opacity=0.3))
    scenes = {"glass": [pawn, case], "opaque": [pawn, tm.Mesh(case.vertices, case.faces, material=tm.Material.bands("#9fd3ff"))],
              "lines": [pawn, tm.Lines([[-0.7, -0.1, 0.8], [0.7, 1.2, 0.8]], width=3.0)]}
    drafts, exacts, titles = {}, {}, {}
    for name, scene in scenes.items():
        v = tm.Viewer(scene, width=SIZE[0], height=SIZE[1])
        try:
            v.orbit(30, -20)
            v.to_html(tmp_path / f"{name}.html")
            exacts[name] = v.frame.copy()
            page = _open(browser, tmp_path / f"{name}.html")
            drafts[name] = _draft(page, v._camera_state())
            titles[name] = page.locator(".toonmesh-viewer").get_attribute("title")
            page.close()
        finally:
            v.close()
    assert "exact transparency" in titles["glass"] and "exact transparency" not in titles["opaque"], titles
    assert "the scene's own lines (tm.Lines)" in titles["lines"], titles["lines"]
    # the pawn shows through: orange (red well above blue) where the exact frame shows it
    # through the glass, in the draft too; the opaque case hides it
    def orange(img):
        c = img[..., :3].astype(int)
        return (c[..., 0] - c[..., 2]) > 40
    seen = orange(exacts["glass"])
    assert seen.sum() > 500, seen.sum()
    assert orange(drafts["glass"])[seen].mean() > 0.9
    assert orange(drafts["opaque"]).sum() < 0.05 * seen.sum()
    share = _agreement(drafts["glass"], exacts["glass"], reach=1)
    assert share >= 0.95, f"{share:.1%} of the covered pixels agree within 8 levels (or one pixel away)"


def test_a_draft_draws_a_point_cloud_s_splats_as_the_exact_frame_does(browser, tmp_path):
    rng = np.random.default_rng(3)
    P = rng.normal(size=(20_000, 3))
    P /= np.linalg.norm(P, axis=1, keepdims=True)
    v = tm.Viewer(tm.Points(P), width=SIZE[0], height=SIZE[1])
    try:
        v.orbit(30, -20)
        v.to_html(tmp_path / "points.html")
        exact = v.frame.copy()
        page = _open(browser, tmp_path / "points.html")
        draft = _draft(page, v._camera_state())
        page.close()
    finally:
        v.close()
    covered = _covered(exact)
    assert covered.mean() > 0.2, covered.mean()  # the sphere fills the view
    share = _agreement(draft, exact, reach=1)
    assert share >= 0.97, f"{share:.1%} of the covered pixels agree within 8 levels (or one pixel away)"

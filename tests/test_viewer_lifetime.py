"""toonmesh.Viewer's lifetime, scene input and extras, in plain Python (no browser): a viewer
dropped or closed frees its render thread, meshes and widgets; a closed one says so when used;
it reads files, scenes and lists as tm.render does and shows what tm.render shows (textured
meshes not tinted by the default material); the browser's numbered views; home and the views
from each axis; turntables."""

from __future__ import annotations

import ctypes
import gc
import threading
import time
import weakref

import numpy as np
import pytest

from conftest import need

import toonmesh as tm
from toonmesh.data import bunny

SIZE = 128
# The yellow a textured GLB's texture has (its texels, sRGB), and the blue of its stripes.
YELLOW, BLUE = (219, 184, 0), (40, 120, 220)


@pytest.fixture(scope="module")
def mesh():
    return bunny()


def _rss_mb() -> float:
    """The process's resident memory (MB), once the C allocator has handed back the free memory
    it caches (glibc keeps freed blocks in per-thread arenas, the render threads' among them: a
    count that moved by tens of MB from run to run with nothing kept alive)."""
    try:
        ctypes.CDLL("libc.so.6").malloc_trim(0)
    except (OSError, AttributeError):  # not glibc: the count as it is
        pass
    with open("/proc/self/status") as f:
        for line in f:
            if line.startswith("VmRSS:"):
                return int(line.split()[1]) / 1024
    raise RuntimeError("no VmRSS in /proc/self/status")


def _views(mesh, count: int, controls: bool) -> "weakref.ref[tm.Viewer]":
    """Makes ``count`` viewers as re-running a cell would (each dragged once), dropping each;
    returns a weak reference to the last."""
    ref = None
    for _ in range(count):
        v = tm.Viewer(*mesh, outlines="mesh", width=SIZE, height=SIZE, controls=controls)
        v._on_event({"event": "view", "id": 1, "steps": [{"event": "orbit", "dx": 5, "dy": 1}], "exact": False})
        assert v._wait()
        ref = weakref.ref(v)
        del v
    assert ref is not None
    return ref


@pytest.mark.parametrize("controls", [False, True])
def test_ten_dropped_viewers_leave_threads_meshes_widgets_and_memory_as_they_were(mesh, controls):
    need("anywidget")
    if controls:
        need("ipywidgets")
    from ipywidgets.widgets.widget import _instances

    renderer = tm.rendering._render.shared_renderer(None)
    _views(mesh, 2, controls)  # first-use allocations (pipelines, caches) out of the count
    gc.collect()
    threads, meshes, widgets, rss = threading.active_count(), renderer._engine.mesh_count, len(_instances), _rss_mb()
    last = _views(mesh, 10, controls)
    gc.collect()
    time.sleep(0.2)
    assert last() is None  # nothing keeps a dropped viewer alive (widget callbacks and the thread hold it weakly)
    assert threading.active_count() == threads
    assert renderer._engine.mesh_count == meshes
    assert len(_instances) == widgets  # the frame's widget, the controls and their layouts closed
    grown = _rss_mb() - rss
    assert grown < 20, f"RSS grew by {grown:.1f} MB over 10 viewers"


def test_ten_kept_viewers_of_one_mesh_share_its_upload_as_re_runs_kept_in_out_do(mesh):
    """A cell that ends in a bare ``v``, run again and again, keeps every viewer alive in
    IPython's ``Out``: viewers of the same meshes (the same contents, as a file read again
    gives) share one upload, freed with the last of them."""
    need("anywidget")
    renderer = tm.rendering._render.shared_renderer(None)
    first = tm.Viewer(*mesh, outlines="mesh", width=512, height=512)  # first-use allocations out of the count
    gc.collect()
    threads, meshes, rss = threading.active_count(), renderer._engine.mesh_count, _rss_mb()
    V, F = mesh
    kept = [tm.Viewer(V.copy(), F.copy(), outlines="mesh", width=512, height=512) for _ in range(10)]
    gc.collect()
    time.sleep(0.2)
    assert renderer._engine.mesh_count == meshes  # the first viewer's upload, shared
    assert threading.active_count() == threads
    grown = _rss_mb() - rss
    assert grown < 20, f"RSS grew by {grown:.1f} MB over 10 kept viewers"
    # another mesh is an upload of its own; the shared one goes with the last viewer holding it
    other = tm.Viewer(V * 2.0, F, width=64, height=64)
    assert renderer._engine.mesh_count == meshes + 1
    first.close()
    kept[0].close()
    assert renderer._engine.mesh_count == meshes + 1
    del first, kept
    gc.collect()
    assert renderer._engine.mesh_count == meshes
    other.close()
    assert renderer._engine.mesh_count == meshes - 1


def test_a_closed_viewer_frees_everything_and_says_it_is_closed_when_used(mesh, tmp_path):
    need("anywidget")
    need("ipywidgets")
    renderer = tm.Renderer()
    v = tm.Viewer(*mesh, renderer=renderer, width=64, height=64, controls=True)
    widget, panel = v.widget, v._controls
    v._on_event({"event": "orbit", "dx": 3, "dy": 0})
    assert renderer._engine.mesh_count == 1
    v.close()
    assert v.closed and renderer._engine.mesh_count == 0
    assert widget.comm is None and panel.widget.comm is None  # the front end is gone: the frame and the controls
    assert all(c.comm is None for c in panel.widgets.values())
    assert v._shared.worker is None or not v._shared.worker.is_alive() or v._wait(5)
    for use in (lambda: v.orbit(1, 0), lambda: v.pan(1, 0), lambda: v.zoom(2), v.reframe, v.home,
                lambda: v.view_from("+x"), lambda: setattr(v, "outlines", "both"), lambda: v.set(width=32),
                lambda: setattr(v, "camera", tm.Camera.fit()), v.snapshot,
                lambda: v.turntable(tmp_path / "t.gif", seconds=1, fps=2)):
        with pytest.raises(tm.ViewerClosedError, match="closed"):
            use()
    count = v.render_count
    v._on_event({"event": "view", "id": 9, "steps": [{"event": "orbit", "dx": 3, "dy": 0}], "exact": True})
    assert v._wait() and v.render_count == count  # a late browser message renders nothing
    assert "closed" in repr(v)
    v.close()  # twice: nothing more to do


def _textured_glb(path) -> str:
    """An icosphere with a yellow texture striped blue, as a GLB (trimesh writes it)."""
    trimesh = need("trimesh")
    Image = need("PIL.Image")
    m = trimesh.creation.icosphere(3)
    uv = np.c_[0.5 + 0.5 * np.arctan2(m.vertices[:, 1], m.vertices[:, 0]) / np.pi, 0.5 + 0.5 * m.vertices[:, 2]]
    texture = np.zeros((16, 16, 3), np.uint8)
    texture[...] = YELLOW
    texture[::4] = BLUE
    m.visual = trimesh.visual.TextureVisuals(
        uv=uv, material=trimesh.visual.material.PBRMaterial(baseColorTexture=Image.fromarray(texture)))
    m.export(str(path))
    return str(path)


def _median(color: np.ndarray) -> np.ndarray:
    """The median colour of the pixels that are not the white background."""
    rgb = color[..., :3].reshape(-1, 3).astype(int)
    return np.median(rgb[rgb.min(axis=1) < 250], axis=0)


def test_a_textured_file_looks_as_tm_render_draws_it_given_as_a_path_a_scene_or_a_list(tmp_path):
    need("anywidget")
    trimesh = need("trimesh")
    path = _textured_glb(tmp_path / "textured.glb")
    reference = tm.render(path, width=SIZE, height=SIZE).color
    v = tm.Viewer(path, width=SIZE, height=SIZE)
    assert np.abs(_median(v.frame) - _median(reference)).max() <= 10, (_median(v.frame), _median(reference))
    assert _median(v.frame)[2] < 80  # yellow, not the default material's orange over it, nor grey
    np.testing.assert_array_equal(v.frame, reference)  # the same fitted view and the same look
    for given, name in ((trimesh.load(path), "scene"), (tm.load(path), "meshes")):
        other = tm.Viewer(given, width=SIZE, height=SIZE)
        np.testing.assert_array_equal(other.frame, reference)
        assert f"tm.render(\n    {name},\n" in other.code()
        other.close()

    v.orbit(30, -10)
    v.zoom(1.2)
    code = v.code()
    assert f"tm.render(\n    {path!r},\n" in code
    scope: dict = {}
    exec(code, scope)
    np.testing.assert_array_equal(scope["r"].color, v.frame)

    # a material given is drawn as tm.render draws it: under the texture's colours
    v.material = tm.Material.bands("#4f8fd8")
    scope = {}
    exec(v.code(), scope)
    np.testing.assert_array_equal(scope["r"].color, v.frame)
    assert np.abs(_median(v.frame) - _median(reference)).max() > 10
    v.material = None  # back to the default: white under the texture again
    exec(v.code(), scope)
    np.testing.assert_array_equal(scope["r"].color, v.frame)
    v.close()


def test_the_browsers_numbered_views_are_answered_with_frames_that_carry_their_number(mesh):
    need("anywidget")
    v = tm.Viewer(*mesh, width=SIZE, height=SIZE)
    w = v.widget
    answers = w._answers
    v._on_event({"event": "view", "id": 4, "exact": False,
                 "steps": [{"event": "orbit", "dx": 20, "dy": 0}, {"event": "orbit", "dx": 20, "dy": 5}]})
    assert v._wait()
    assert (w._view_id, w._exact, w._answers) == (4, False, answers + 1)
    assert v.frame.shape == (SIZE // 2, SIZE // 2, 4)  # a draft
    same = tm.Viewer(*mesh, width=SIZE, height=SIZE)
    same.orbit(40, 5)  # the steps, all of them
    np.testing.assert_allclose(v.camera.eye, same.camera.eye, atol=1e-12)
    v._on_event({"event": "view", "id": 5, "steps": [], "exact": True})
    assert v._wait()
    assert (w._view_id, w._exact) == (5, True) and v.frame.shape == (SIZE, SIZE, 4)
    np.testing.assert_array_equal(v.frame, same.frame)
    v._on_event({"event": "view", "id": 6, "steps": [{"event": "spin"}], "exact": True})  # answered with an error
    assert w._view_id == 6 and "spin" in w._error
    v._on_event({"event": "view", "id": 7, "steps": [{"event": "home"}], "exact": True})
    assert v._wait()
    assert w._view_id == 7 and w._error == ""
    np.testing.assert_allclose(v.camera.eye, tm.Viewer(*mesh, width=SIZE, height=SIZE).camera.eye, atol=1e-12)
    assert v._shared.views == 4 and v._shared.early == 0  # each came after the last was answered
    same.close()
    v.close()


def test_home_and_the_views_from_each_axis(mesh):
    need("anywidget")
    v = tm.Viewer(*mesh, width=SIZE, height=SIZE)
    first = v.camera
    for axis in ("+x", "-x", "+z", "-z"):
        v.view_from(axis)
        d = np.subtract(v.camera.eye, v.camera.target)
        d /= np.linalg.norm(d)
        expected = np.zeros(3)
        expected["xyz".index(axis[1])] = 1 if axis[0] == "+" else -1
        np.testing.assert_allclose(d, expected, atol=1e-9)
    v.view_from("+y")  # from the up axis: a degree short of the pole, as orbiting stops
    d = np.subtract(v.camera.eye, v.camera.target)
    assert np.degrees(np.arccos(d[1] / np.linalg.norm(d))) == pytest.approx(1.0)
    v.orbit(10, 0)  # and orbiting from there turns about up as before
    v.home()
    assert v.camera == first
    with pytest.raises(ValueError, match="axis"):
        v.view_from("x")
    with pytest.raises(TypeError, match="axis"):
        v.view_from(0)
    v.close()


def test_a_turntable_is_written_as_a_gif_or_an_mp4_with_one_frame_per_view(mesh, tmp_path):
    need("anywidget")
    Image = need("PIL.Image")
    v = tm.Viewer(*mesh, outlines="mesh", width=96, height=64)
    before = v.camera
    path = v.turntable(tmp_path / "turn.gif", seconds=1.5, fps=8)
    with Image.open(path) as gif:
        assert gif.n_frames == 12 and gif.size == (96, 64)
        gif.seek(0)
        first = np.asarray(gif.convert("RGB")).astype(int)
    assert np.abs(first - v.frame[..., :3]).mean() < 8  # it starts at the current view (GIF's palette aside)
    assert v.camera == before  # the view stays as it was
    imageio_ffmpeg = need("imageio_ffmpeg")
    mp4 = v.turntable(tmp_path / "turn.mp4", seconds=1, fps=10)
    frames, _ = imageio_ffmpeg.count_frames_and_secs(mp4)
    assert frames == 10
    with pytest.raises(ValueError, match="path"):
        v.turntable(tmp_path / "turn.avi")
    with pytest.raises(ValueError, match="fps"):
        v.turntable(tmp_path / "turn.gif", fps=0)
    with pytest.raises(TypeError, match="fps"):
        v.turntable(tmp_path / "turn.gif", fps=2.5)
    with pytest.raises(ValueError, match="seconds"):
        v.turntable(tmp_path / "turn.gif", seconds=-1)
    v.width = 95
    with pytest.raises(ValueError, match="even"):
        v.turntable(tmp_path / "odd.mp4")
    v.close()


def test_a_viewer_lives_while_a_view_of_it_is_on_the_page(mesh):
    """The page holds a viewer nothing else refers to (``display(tm.Viewer(...))`` in a function)
    while a view of it is drawn: the widget's views say when they are drawn and removed."""
    need("anywidget")
    renderer = tm.Renderer()
    v = tm.Viewer(*mesh, renderer=renderer, width=64, height=64)
    widget, ref = v.widget, weakref.ref(v)

    def message(event: str, view: str) -> None:  # as the front end sends it
        widget._handle_custom_msg({"event": event, "view": view}, [])

    message("shown", "a")
    message("shown", "b")  # the same viewer in two outputs
    del v
    gc.collect()
    assert ref() is not None and renderer._engine.mesh_count == 1
    ref().orbit(10, 0)  # still drawing
    message("gone", "a")
    gc.collect()
    assert ref() is not None  # one view left
    message("gone", "b")
    gc.collect()
    assert ref() is None and renderer._engine.mesh_count == 0 and widget.comm is None  # freed with its last view

    # close() lets go at once, views or not; a late message holds nothing
    v = tm.Viewer(*mesh, renderer=renderer, width=64, height=64)
    widget, ref = v.widget, weakref.ref(v)
    message("shown", "c")
    v.close()
    del v
    gc.collect()
    assert ref() is None and renderer._engine.mesh_count == 0


def test_a_viewer_displayed_in_a_kernel_is_held_until_its_first_view_comes(mesh, monkeypatch):
    """Between display() and the front end drawing the view, nothing else may refer to the
    viewer: the kernel holds it meanwhile; where no view ever comes (no front end), only for
    a while."""
    need("anywidget")
    import toonmesh.viewer._viewer as tv

    monkeypatch.setattr(tv, "_in_kernel", lambda: True)
    renderer = tm.Renderer()
    v = tm.Viewer(*mesh, renderer=renderer, width=64, height=64)
    widget, ref = v.widget, weakref.ref(v)
    v._repr_mimebundle_()  # display(v)
    del v
    gc.collect()
    assert ref() is not None  # waiting for its view
    widget._handle_custom_msg({"event": "shown", "view": "a"}, [])
    widget._handle_custom_msg({"event": "gone", "view": "a"}, [])
    gc.collect()
    assert ref() is None and renderer._engine.mesh_count == 0

    # displayed where no view comes: let go once the wait is over (at the next display)
    monkeypatch.setattr(tv, "_FIRST_VIEW_S", 0.0)
    v = tm.Viewer(*mesh, renderer=renderer, width=64, height=64)
    ref = weakref.ref(v)
    v.widget._repr_mimebundle_()  # display(v.widget) holds it too
    del v
    gc.collect()
    assert ref() is not None
    time.sleep(0.01)
    other = tm.Viewer(*mesh, renderer=renderer, width=64, height=64)
    other._repr_mimebundle_()
    gc.collect()
    assert ref() is None
    other.close()

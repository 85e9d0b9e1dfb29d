"""toonmesh.Viewer's kernel side: camera moves, flow control, settings, code() and display.

The front end's events are fed to the viewer as the widget would hand them over
(``Viewer._on_event``); the browser itself is tested in test_viewer_browser.py.
"""

from __future__ import annotations

import numpy as np
import pytest

from conftest import need

import toonmesh as tm
from toonmesh.data import bunny

SIZE = 160


@pytest.fixture(scope="module")
def mesh():
    return bunny()


@pytest.fixture
def viewer(mesh):
    need("anywidget")
    v = tm.Viewer(*mesh, outlines="mesh", width=SIZE, height=SIZE)
    yield v
    v.close()


def _distance(v):
    c = v.camera
    return float(np.linalg.norm(np.subtract(c.eye, c.target)))


def test_a_hundred_quick_drag_events_render_a_few_frames_and_end_on_the_final_view(viewer, mesh):
    before = viewer.render_count
    for _ in range(100):
        viewer._on_event({"event": "orbit", "dx": 2, "dy": 0.5})
    assert viewer._wait()
    drafts = viewer.render_count - before
    assert 1 <= drafts <= 5, f"{drafts} renders for 100 events"
    assert viewer.frame.shape == (SIZE // 2, SIZE // 2, 4)  # drawn at drag_scale while dragging

    viewer._on_event({"event": "settle"})  # the pointer stopped
    assert viewer._wait()
    assert viewer.frame.shape == (SIZE, SIZE, 4)

    same = tm.Viewer(*mesh, outlines="mesh", width=SIZE, height=SIZE)
    same.orbit(200, 50)  # the whole drag at once
    np.testing.assert_allclose(viewer.camera.eye, same.camera.eye, rtol=0, atol=1e-12)
    np.testing.assert_array_equal(viewer.frame, same.frame)
    same.close()


def test_drag_scale_can_be_changed_and_reaches_the_browser(viewer):
    need("anywidget")
    viewer.drag_scale = 0.25
    assert viewer.drag_scale == 0.25 and viewer.widget._moves["drag_scale"] == 0.25
    viewer._on_event({"event": "orbit", "dx": 2, "dy": 0.5})
    assert viewer._wait()
    assert viewer.frame.shape == (SIZE // 4, SIZE // 4, 4)  # a kernel draft at the new scale
    with pytest.raises(ValueError, match="drag_scale"):
        viewer.drag_scale = 0
    assert viewer.drag_scale == 0.25
    viewer.drag_scale = 0.5


def test_orbit_turns_about_the_target_and_half_a_turn_per_frame_height(viewer):
    c0 = viewer.camera
    frame0 = viewer.frame.copy()
    count = viewer.render_count
    viewer.orbit(SIZE, 0)  # a drag across the frame's height: half way round about up
    c1 = viewer.camera
    assert viewer.render_count == count + 1 and viewer.frame.shape == (SIZE, SIZE, 4)
    assert not np.array_equal(frame0, viewer.frame)
    np.testing.assert_allclose(c1.target, c0.target)
    offset0, offset1 = np.subtract(c0.eye, c0.target), np.subtract(c1.eye, c1.target)
    np.testing.assert_allclose(offset1[[0, 2]], -offset0[[0, 2]], atol=1e-12)  # mirrored about the up axis
    assert offset1[1] == pytest.approx(offset0[1])

    viewer.orbit(0, 10 * SIZE)  # dragging down shows the top; tilting stops short of the pole instead of flipping over
    offset2 = np.subtract(viewer.camera.eye, viewer.camera.target)
    cos_to_up = offset2[1] / np.linalg.norm(offset2)
    assert 0.999 < cos_to_up < 1.0
    assert np.linalg.norm(offset2) == pytest.approx(np.linalg.norm(offset0))


def test_zoom_and_pan(viewer):
    d0 = _distance(viewer)
    viewer.zoom(2)
    assert _distance(viewer) == pytest.approx(d0 / 2)
    c0 = viewer.camera
    viewer.pan(30, -10)
    c1 = viewer.camera
    step = np.subtract(c1.eye, c0.eye)
    np.testing.assert_allclose(np.subtract(c1.target, c0.target), step, atol=1e-12)
    assert np.linalg.norm(step) > 0
    assert abs(np.dot(step, np.subtract(c0.target, c0.eye))) < 1e-9 * np.linalg.norm(step) * d0  # across the view

    viewer._on_event({"event": "frame"})  # double-click: framed again from the same side
    assert viewer._wait()
    assert _distance(viewer) == pytest.approx(d0, rel=1e-6)


def test_wheel_events_zoom(viewer):
    d0 = _distance(viewer)
    viewer._on_event({"event": "zoom", "dx": 0, "dy": -300})  # wheel turned away from the user
    assert viewer._wait()
    assert _distance(viewer) < 0.8 * d0


def test_setting_a_render_setting_re_renders(viewer):
    count, frame = viewer.render_count, viewer.frame.copy()
    viewer.outlines = "both"
    assert viewer.render_count == count + 1
    assert viewer.outlines.kind == "both"
    viewer.outlines = None
    assert viewer.render_count == count + 2 and not np.array_equal(frame, viewer.frame)
    viewer.width = 96
    assert viewer.frame.shape == (SIZE, 96, 4)
    viewer.material = tm.Material.bands("#3060c0", thresholds=[0.3, 0.6], values=[0.2, 0.6, 1.0])
    assert viewer.material.thresholds == pytest.approx([0.3, 0.6])
    with pytest.raises(ValueError, match="thresholds"):
        viewer.material = tm.Material.bands(thresholds=[0.5], values=[1.0])


def test_code_reproduces_the_frame(viewer, mesh):
    V, F = mesh
    viewer.orbit(25, -12)
    viewer.zoom(1.3)
    viewer.lights = [tm.Light.directional((1, -1, -1), shadows=True)]
    viewer.material = tm.Material.bands("#4f8fd8", thresholds=[0.25, 0.6], values=[0.3, 0.7, 1.0])
    viewer.background = "#eeeeee"
    code = viewer.code()
    assert "tm.render(\n    V, F,\n" in code and "tm._core" not in code
    scope = {"V": V, "F": F}
    exec(code, scope)
    np.testing.assert_array_equal(scope["r"].color, viewer.frame)


def test_camera_can_be_read_and_set(viewer):
    viewer.camera = tm.Camera.look_at((0.0, 0.3, 0.5), (0.0, 0.1, 0.0), fov_y=40)
    c = viewer.camera
    assert c.eye == pytest.approx((0.0, 0.3, 0.5)) and c.fov_y == 40
    viewer.camera = tm.Camera.fit((1, 0, 0))  # fitted by the core, then held as eye and target
    eye = np.subtract(viewer.camera.eye, viewer.camera.target)
    assert eye[0] > 0 and abs(eye[1]) < 1e-9 * abs(eye[0]) and abs(eye[2]) < 1e-9 * abs(eye[0])


def test_orthographic_views_zoom_by_their_height(mesh):
    need("anywidget")
    v = tm.Viewer(*mesh, camera=tm.Camera.fit(orthographic=True), width=64, height=64)
    h0 = v.camera.height
    v.zoom(2)
    assert v.camera.projection == "orthographic" and v.camera.height == pytest.approx(h0 / 2)
    v.close()


def test_snapshot_renders_the_view_at_any_size_and_outputs(viewer):
    r = viewer.snapshot(width=80, height=60, outputs=("color", "depth"))
    assert r.color.shape == (60, 80, 4) and r.depth.shape == (60, 80)
    full = viewer.snapshot()
    np.testing.assert_array_equal(full.color, viewer.frame)


def test_the_saved_notebook_keeps_a_still_frame(viewer):
    bundle, metadata = viewer._repr_mimebundle_()
    assert bundle["image/png"].startswith(b"\x89PNG")
    assert metadata["image/png"] == {"width": SIZE, "height": SIZE}  # shown at the view's size
    assert "application/vnd.jupyter.widget-view+json" in bundle
    assert viewer.widget._frame_id >= 1 and len(viewer.widget._frame) > 0


def test_without_a_widget_front_end_the_viewer_says_how_to_get_one(mesh, monkeypatch):
    import toonmesh.viewer._viewer as tv

    monkeypatch.setattr(tv, "_make_widget", lambda viewer: None)  # as without anywidget
    v = tm.Viewer(*mesh, width=64, height=64)
    bundle, _ = v._repr_mimebundle_()
    assert set(bundle) == {"image/png", "text/plain"}
    assert "toonmesh[notebook]" in bundle["text/plain"]
    v.orbit(10, 0)  # still works from Python
    assert v.frame.shape == (64, 64, 4)
    v.close()


def test_controls_change_the_render_settings(mesh):
    need("ipywidgets")
    need("anywidget")
    v = tm.Viewer(*mesh, outlines="mesh", width=64, height=64, controls=True)
    controls = v._controls.widgets  # every control by the field it sets (tests/test_viewer_controls.py drives them all)
    count = v.render_count
    controls["outlines.silhouette.width"].value = 3.0
    assert v.outlines.styles["silhouette"].width == 3.0 and v.render_count == count + 1
    controls["outlines.crease_angle"].value = 60
    assert v.outlines.crease_angle == 60
    controls["material.thresholds[0]"].value = 0.1
    assert v.material.thresholds[0] == pytest.approx(0.1)
    controls["light.shadows"].value = True
    assert v.lights[0].shadows is not None
    controls["outlines.kind"].value = "none"
    assert v.outlines is None
    v.close()


def test_bad_arguments_are_named(viewer, mesh):
    with pytest.raises(TypeError, match="dx"):
        viewer.orbit("a", 0)
    with pytest.raises(ValueError, match="factor"):
        viewer.zoom(0)
    with pytest.raises(ValueError, match="image_format"):
        tm.Viewer(*mesh, image_format="gif")
    with pytest.raises(ValueError, match="drag_scale"):
        tm.Viewer(*mesh, drag_scale=2)
    with pytest.raises(TypeError, match="outputs"):
        tm.Viewer(*mesh, outputs=("depth",))
    with pytest.raises(ValueError, match="width"):
        viewer.width = 0


def test_the_viewer_benchmark_reports_frame_times(capsys):
    need("anywidget")
    from toonmesh.bench import viewer as bench

    bench.main(quick=True)
    rows = [line for line in capsys.readouterr().out.splitlines() if line.startswith("| orbit") or line.startswith("| frame while")]
    assert len(rows) == 3
    for row in rows:
        fps = float(row.strip(" |").split("|")[-1])
        assert fps > 0


def test_a_scene_of_several_meshes_and_its_code(mesh):
    need("anywidget")
    V, F = mesh
    left = tm.Mesh(V, F, material=tm.Material.bands("#d05050"), transform=np.eye(4))
    shifted = np.eye(4)
    shifted[0, 3] = 0.2
    right = tm.Mesh(V, F, material=tm.Material.lambert("#50a050"), transform=shifted)
    v = tm.Viewer([left, right], width=96, height=64)
    # the view turns about the point of its axis nearest the scene's centre (the fit centres the
    # scene's image, so the axis passes near the centre, not through it)
    eye, target = np.array(v.camera.eye), np.array(v.camera.target)
    center = (V.min(axis=0) + V.max(axis=0) + [0.2, 0.0, 0.0]) / 2
    axis = (target - eye) / np.linalg.norm(target - eye)
    assert np.allclose(target, eye + axis * np.dot(center - eye, axis), atol=1e-9)
    assert np.linalg.norm(target - center) < 0.1 * np.linalg.norm(V.max(axis=0) - V.min(axis=0))
    v.orbit(10, 5)
    assert np.allclose(v.camera.target, target)  # orbiting keeps the target
    code = v.code()
    assert "tm.render(\n    meshes,\n" in code
    scope = {"meshes": [left, right]}
    exec(code, scope)
    np.testing.assert_array_equal(scope["r"].color, v.frame)
    v.close()


def test_close_frees_only_the_meshes_the_viewer_uploaded(mesh):
    need("anywidget")
    renderer = tm.Renderer()
    mine = renderer.add_mesh(*mesh)
    v = tm.Viewer([tm.Mesh(mine), tm.Mesh(*mesh)], renderer=renderer, width=48, height=48)
    assert renderer._engine.mesh_count == 2
    v.close()
    assert renderer._engine.mesh_count == 1
    assert renderer.render(mine, width=16, height=16).color.shape == (16, 16, 4)


def _report(v, view_id, **size):
    """The browser's size report, as the widget sends it (a view of one ``size`` step)."""
    v._on_event({"event": "view", "id": view_id, "exact": True,
                 "steps": [{"event": "size", "width": None, "ratio": None, "full": None, **size}]})
    assert v._wait()


def test_a_view_without_a_width_fits_the_cell_at_the_screens_pixel_ratio(mesh):
    need("anywidget")
    V, F = mesh
    v = tm.Viewer(V, F, outlines="mesh", height=90)
    assert (v.width, v.height, v.pixel_ratio) == (512, 90, 1.0)  # until the browser says
    assert v.widget._layout == {"fit": True, "follow_screen": True, "ratio": 1.0}
    _report(v, 1, width=150, ratio=2)
    assert (v.width, v.height, v.pixel_ratio) == (150, 90, 2.0)
    assert v.frame.shape == (180, 300, 4)  # the frame in output pixels; shown at 150 x 90
    assert v.widget._size == [150, 90] and v.widget._layout["ratio"] == 2.0
    assert v.options.width == 300 and v.options.pixel_ratio == 2.0 and "at 2x" in repr(v)
    # the still frame a saved notebook keeps: the 2x PNG, shown at the view's size
    bundle, metadata = v._repr_mimebundle_()
    assert metadata["image/png"] == {"width": 150, "height": 90} and bundle["image/png"][16:24] == bytes(
        [0, 0, 1, 44, 0, 0, 0, 180])  # the PNG's IHDR: 300 x 180
    # code() reproduces the frame, at its size and ratio
    code = v.code()
    assert "width=300" in code and "height=180" in code and "pixel_ratio=2.0" in code
    scope = {"V": V, "F": F}
    exec(code, scope)
    np.testing.assert_array_equal(scope["r"].color, v.frame)
    # a drag is in layout pixels: across the view's height, half a turn, at any pixel ratio
    up = np.asarray(v.camera.up, np.float64) / np.linalg.norm(v.camera.up)

    def level():  # the eye's offset from the target, across up
        d = np.subtract(v.camera.eye, v.camera.target)
        return d - np.dot(d, up) * up

    before = level()
    v.orbit(90, 0)
    np.testing.assert_allclose(level(), -before, atol=1e-9 * np.linalg.norm(before))
    # full screen fills the screen while it lasts
    _report(v, 2, width=150, ratio=2, full=[400, 300])
    assert (v.width, v.height) == (400, 300) and v.frame.shape == (600, 800, 4)
    _report(v, 3, width=160, ratio=2)
    assert (v.width, v.height) == (160, 90)
    v.close()


def test_a_given_width_and_ratio_stay_and_none_follows_again(mesh):
    need("anywidget")
    v = tm.Viewer(*mesh, width=70, height=50, pixel_ratio=1)
    assert v.widget._layout == {"fit": False, "follow_screen": False, "ratio": 1.0}
    _report(v, 1, width=200, ratio=2)  # a cell and screen it does not follow
    assert (v.width, v.pixel_ratio) == (70, 1.0) and v.frame.shape == (50, 70, 4)
    v.width = None  # fits the cell it was told of
    v.pixel_ratio = None
    assert (v.width, v.pixel_ratio) == (200, 2.0) and v.frame.shape == (100, 400, 4)
    v.set(width=40, pixel_ratio=1.5)
    assert v.frame.shape == (75, 60, 4)
    for bad, error in [(dict(width=0), ValueError), (dict(width=1.5), TypeError), (dict(pixel_ratio=9), ValueError),
                       (dict(pixel_ratio="2"), TypeError), (dict(height=-1), ValueError)]:
        with pytest.raises(error, match=next(iter(bad))):
            v.set(**bad)
    assert v.frame.shape == (75, 60, 4)
    # a size the device cannot render is refused, and the viewer keeps what it had
    with pytest.raises(ValueError, match="width"):
        v.set(width=9000, pixel_ratio=4, outlines="mesh")
    assert (v.width, v.pixel_ratio, v.outlines, v.options.width) == (40, 1.5, None, 60)
    # a report the viewer cannot read is answered with an error, and nothing changes
    count = v.render_count
    _report(v, 2, width="wide")
    assert "width" in v.widget._error and v.render_count == count and v.frame.shape == (75, 60, 4)
    v.close()


def test_the_projection_switches_keeping_the_framing_and_its_frames_are_tm_renders(mesh):
    need("anywidget")
    V, F = mesh
    v = tm.Viewer(V, F, outlines="mesh", width=SIZE, height=SIZE)
    v.orbit(30, -10)
    perspective = v.camera
    before = v.frame.copy()
    assert v.projection == "perspective"
    v.projection = "orthographic"
    camera = v.camera
    assert camera.projection == "orthographic" and v.projection == "orthographic"
    # the target's plane shows the height the perspective view saw there
    assert camera.height == pytest.approx(2 * _distance(v) * np.tan(np.radians(perspective.fov_y) / 2), rel=1e-12)
    np.testing.assert_array_equal(camera.eye, perspective.eye)
    np.testing.assert_array_equal(v.frame, tm.render(V, F, outlines="mesh", width=SIZE, height=SIZE, camera=camera).color)
    assert (np.abs(v.frame.astype(int) - before).max(axis=2) > 24).mean() > 0.02  # another picture
    scope = {"V": V, "F": F}
    exec(v.code(), scope)
    assert "tm.Camera.orthographic(" in v.code()
    np.testing.assert_array_equal(scope["r"].color, v.frame)
    v.zoom(2)  # an orthographic zoom halves the height; back, the eye comes as near as that frames
    v._on_event({"event": "projection", "projection": "perspective"})  # the toolbar's toggle
    assert v._wait()
    assert v.projection == "perspective" and v.camera.fov_y == perspective.fov_y
    assert _distance(v) == pytest.approx(float(np.linalg.norm(np.subtract(perspective.eye, perspective.target))) / 2)
    np.testing.assert_array_equal(v.frame, tm.render(V, F, outlines="mesh", width=SIZE, height=SIZE, camera=v.camera).color)
    v.projection = "perspective"  # no change
    with pytest.raises(ValueError, match="projection: expected 'perspective' or 'orthographic', got 'iso'"):
        v.projection = "iso"
    with pytest.raises(TypeError, match="projection: .* got bool"):
        v.projection = True
    assert v.projection == "perspective"
    v.close()


def test_parts_are_shown_and_hidden_and_the_frames_are_tm_renders_of_the_parts_shown(mesh):
    need("anywidget")
    V, F = mesh
    shifted = np.eye(4)
    shifted[0, 3] = 0.2
    left = tm.Mesh(V, F, name="left", material=tm.Material.bands("#d05050"))
    right = tm.Mesh(V, F, transform=shifted, material=tm.Material.bands("#50a050"))
    meshes = [left, right, left]
    v = tm.Viewer(meshes, width=96, height=64)
    assert v.parts == ("left", "part 2", "left (2)")
    assert v.widget._parts == {"names": list(v.parts), "visible": [True, True, True]}
    v.visible = {"part 2": False, 2: False}
    assert v.visible == {"left": True, "part 2": False, "left (2)": False}
    assert v.widget._parts["visible"] == [True, False, False]
    np.testing.assert_array_equal(v.frame, tm.render([left], width=96, height=64, camera=v.camera).color)
    code = v.code()
    assert "[meshes[i] for i in (0,)]" in code
    scope = {"meshes": meshes}
    exec(code, scope)
    np.testing.assert_array_equal(scope["r"].color, v.frame)
    np.testing.assert_array_equal(v.snapshot().color, v.frame)
    # the toolbar's list: one part's box
    v._on_event({"event": "view", "id": 1, "steps": [{"event": "part", "part": 1, "visible": True}], "exact": True})
    assert v._wait()
    assert v.visible == {"left": True, "part 2": True, "left (2)": False}
    np.testing.assert_array_equal(v.frame, tm.render([left, right], width=96, height=64, camera=v.camera).color)
    # the draft the browser draws from leaves the hidden parts out too: the core's draft of the parts shown
    spec = __import__("json").loads(v.widget._draft_spec)
    assert len(spec["meshes"]) == 2
    v.visible = {0: False, 1: False}  # nothing shown: the background, and code() says so
    assert (v.frame == v.frame[0, 0]).all()
    assert "tm.render(\n    None,\n" in v.code()
    with pytest.raises(TypeError, match="visible: expected a dict"):
        v.visible = ["left"]
    with pytest.raises(ValueError, match="visible: no part named 'wheel'"):
        v.visible = {"wheel": False}
    with pytest.raises(ValueError, match="visible: part 3 is out of range"):
        v.visible = {3: False}
    with pytest.raises(TypeError, match=r"visible\['left'\]: expected True or False, got int"):
        v.visible = {"left": 1}
    v.close()


def test_the_parts_of_a_scene_are_its_geometries_and_code_reads_them_as_tm_render_does(mesh):
    need("anywidget")
    trimesh = need("trimesh")
    V, F = mesh
    scene = trimesh.Scene()
    for i, name in enumerate(("body", "wheel")):
        shifted = np.eye(4)
        shifted[0, 3] = 0.2 * i
        scene.add_geometry(trimesh.Trimesh(V, F, process=False), geom_name=name, transform=shifted)
    v = tm.Viewer(scene, width=96, height=64)
    assert v.parts == ("body", "wheel")
    whole = v.frame.copy()
    v.visible = {"wheel": False}
    assert (v.frame != whole).any()
    code = v.code()
    assert "[m for i, m in enumerate(tm.load(scene)) if i in (0,)]" in code
    scope = {"scene": scene}
    exec(code, scope)
    np.testing.assert_array_equal(scope["r"].color, v.frame)
    v.close()


@pytest.mark.parametrize("orthographic", [False, True])
def test_a_fitted_camera_shows_what_tm_render_shows_and_so_do_the_axis_views(mesh, orthographic):
    need("anywidget")
    V, F = mesh
    fit = tm.Camera.fit(orthographic=orthographic)
    v = tm.Viewer(V, F, camera=fit, width=120, height=90)
    # the fit's own height for an orthographic view (not the camera's default, a tenth of the size)
    np.testing.assert_array_equal(v.frame, tm.render(V, F, camera=fit, width=120, height=90).color)
    v.view_from("+z")
    view = tm.render(V, F, camera=tm.Camera.fit((0, 0, 1), orthographic=orthographic), width=120, height=90).color
    covered = lambda frame: float((frame[..., :3].min(-1) < 200).mean())  # noqa: E731
    assert covered(v.frame) == pytest.approx(covered(view), abs=0.01), (covered(v.frame), covered(view))
    v.close()


def test_the_parts_of_a_file_are_its_geometries_by_name_and_code_reads_the_file(mesh, tmp_path):
    need("anywidget")
    trimesh = need("trimesh")
    V, F = mesh
    scene = trimesh.Scene()
    scene.add_geometry(trimesh.Trimesh(V, F, process=False), geom_name="ears")
    scene.add_geometry(trimesh.Trimesh(V + [0.2, 0.0, 0.0], F, process=False), geom_name="tail")
    path = str(tmp_path / "two.glb")
    scene.export(path)
    v = tm.Viewer(path, width=96, height=64)
    assert sorted(v.parts) == ["ears", "tail"] and list(v.parts) == [m.name for m in tm.load(path)]
    v.visible = {"tail": False}
    code = v.code()
    assert f"tm.load({path!r})" in code
    scope = {}
    exec(code, scope)
    np.testing.assert_array_equal(scope["r"].color, v.frame)
    kept = [m for m in tm.load(path) if m.name == "ears"]
    np.testing.assert_array_equal(tm.render(kept, width=96, height=64, camera=v.camera).color, v.frame)
    v.close()

"""toonmesh.Viewer's on-screen controls (``controls=True``), driven from Python without a browser:
every control shown changes exactly one field of the viewer's settings, a change from Python
shows in the controls, band thresholds cannot cross, and a refused value snaps back with a note
beside the controls (never an error over the frame).

Frames are small (48 pixels), so the hundreds of renders a sweep makes stay cheap."""

from __future__ import annotations

from typing import Any, List

import numpy as np
import pytest

from conftest import need

import toonmesh as tm
from toonmesh.data import bunny

SIZE = 48


@pytest.fixture(scope="module")
def mesh():
    return bunny()


def _viewer(mesh: Any, **options: Any) -> Any:
    need("ipywidgets")
    need("anywidget")
    return tm.Viewer(*mesh, width=SIZE, height=SIZE, controls=True, **options)


def _is_settings(value: Any) -> bool:
    return hasattr(type(value), "describe")


def _changes(a: Any, b: Any, path: str = "") -> List[str]:
    """The fields that differ between two settings objects, as paths (``.lights[0].direction``),
    compared field by field through the classes' descriptions."""
    if _is_settings(a) and type(a) is type(b):
        out: List[str] = []
        for field in type(a).describe()["fields"]:
            name = field["name"]
            out += _changes(getattr(a, name), getattr(b, name), f"{path}.{name}")
        return out
    if isinstance(a, list) and isinstance(b, list) and len(a) == len(b) and any(map(_is_settings, a)):
        return [p for i, (x, y) in enumerate(zip(a, b)) for p in _changes(x, y, f"{path}[{i}]")]
    return [] if a == b else [path]


def _candidates(widget: Any) -> List[Any]:
    """Other values to try: the other state, the next choices, points between the value and the
    slider's ends, then the ends."""
    value = widget.value
    if isinstance(value, bool):
        return [not value]
    if hasattr(widget, "options"):
        options = list(widget.options)
        i = options.index(value)
        return options[i + 1:] + options[:i]
    if isinstance(value, str):  # a colour
        return ["#3366cc" if value != "#3366cc" else "#cc6633"]
    lo, hi = widget.min, widget.max
    out = [(value + lo) / 2, (value + hi) / 2, lo, hi]
    if isinstance(value, int):
        out = [round(x) for x in out]
    return [x for x in dict.fromkeys(out) if x != value]


def _sweep(v: Any) -> dict:
    """Drives every control shown, once each (controls that a change shows are driven too):
    each value tried is either taken, changing exactly one field of the settings, or refused,
    changing nothing, the control snapping back and a note saying why. Returns the widgets'
    keys with the field each changed (None where every value tried was refused)."""
    panel = v._controls
    keys = {id(widget): key for key, widget in panel.widgets.items()}
    done: dict = {}
    while True:
        # from the last control up: a switch comes after its own controls, which are driven
        # before it may turn them off
        shown = [(c, leaf) for c in reversed(panel.controls()) for leaf in c.leaves()]
        todo = [(c, leaf) for c, leaf in shown if keys[id(leaf)] not in done]
        if not todo:
            return done
        control, widget = todo[0]
        key = keys[id(widget)]
        done[key] = None
        for value in _candidates(widget):
            before, old, renders = v.options, widget.value, v.render_count
            widget.value = value
            after = v.options
            changed = _changes(before, after)
            assert v.widget._error == "", (key, value, v.widget._error)
            if changed:
                assert len(changed) == 1, (key, value, changed)
                field = changed[0].rsplit(".", 1)[-1]
                # its own field; the outlines' kind to or from "none" sets the outlines themselves
                off = "none" in (value, old)
                assert field == control.name or (off and key == "outlines.kind" and changed[0] == ".outlines"), (key, changed)
                assert v.render_count == renders + 1, key
                assert panel.note.value == "", (key, panel.note.value)
                done[key] = changed[0]
                break
            assert widget.value == old, (key, value, widget.value, old)  # snapped back
            assert panel.note.value, (key, value)


STARTS = {
    "bands": dict(outlines="mesh"),
    "hatching": dict(material=tm.Material.hatching(), outlines=tm.Outlines("both", curvature_smoothing=2.0),
                     lights=[tm.Light.key(), tm.Light.directional((0, -1, 0))]),
    "thresholded_phong": dict(material=tm.Material.thresholded_phong("#4080c0"), outlines="image"),
    "phong, a point light": dict(material=tm.Material.phong(), lights=[tm.Light.point((0.5, 0.5, 0.5))]),
    "dithered bands, no outlines": dict(material=tm.Material.bands(dither="bayer4")),
}


@pytest.mark.parametrize("start", list(STARTS))
def test_every_control_changes_exactly_one_field(mesh, start):
    v = _viewer(mesh, **STARTS[start])
    try:
        changed = _sweep(v)
    finally:
        v.close()
    refused = {key for key, field in changed.items() if field is None}
    # a material that dithers needs per-pixel shading: that switch is the one value refused
    assert refused <= {"material.per_vertex"}, refused
    assert len(changed) >= 20


def test_the_controls_show_the_fields_the_settings_have(mesh):
    v = _viewer(mesh)
    panel = v._controls
    shown = {c.key for c in panel.controls()}
    assert "material.thresholds" in shown and "material.spacing" not in shown and "material.shininess" not in shown
    assert "outlines.crease_angle" not in shown and panel.widgets["outlines.kind"].value == "none"
    v.material = tm.Material.hatching()
    shown = {c.key for c in panel.controls()}
    assert {"material.spacing", "material.ink", "material.mode"} <= shown
    assert panel.widgets["material.spacing"].value == tm.Material.hatching().spacing
    v.set(material=tm.Material.phong(), outlines="mesh")
    shown = {c.key for c in panel.controls()}
    assert "material.shininess" in shown and "material.thresholds" not in shown and "material.spacing" not in shown
    v.close()


def test_outlines_set_from_python_show_in_the_dropdown(mesh):
    v = _viewer(mesh)
    panel = v._controls
    v.outlines = "mesh"
    assert panel.widgets["outlines.kind"].value == "mesh"
    assert panel.widgets["outlines.crease_angle"].value == v.outlines.crease_angle
    v.outlines = tm.Outlines("both", width=3.0, crease_angle=50)
    assert panel.widgets["outlines.kind"].value == "both"
    assert panel.widgets["outlines.silhouette.width"].value == 3.0
    assert panel.widgets["outlines.crease_angle"].value == 50
    v.outlines = None
    assert panel.widgets["outlines.kind"].value == "none"
    assert "outlines.crease_angle" not in {c.key for c in panel.controls()}
    v.close()


def test_outlines_switched_off_and_on_again_come_back_as_they_were(mesh):
    v = _viewer(mesh, outlines=tm.Outlines("mesh", width=2.5))
    panel = v._controls
    panel.widgets["outlines.crease_angle"].value = 60
    kept = v.outlines
    panel.widgets["outlines.kind"].value = "none"
    assert v.outlines is None
    panel.widgets["outlines.kind"].value = "image"
    assert v.outlines == kept.replace(kind="image")
    v.close()


def test_a_band_slider_keeps_a_hatching_material(mesh):
    v = _viewer(mesh)
    hatching = tm.Material.hatching(ink="#203040", spacing=9.0)
    v.material = hatching
    v._controls.widgets["material.thresholds[0]"].value = 0.1
    assert v.material == hatching.replace(thresholds=[0.1, *hatching.thresholds[1:]])
    assert v.material.hatch_style is not None and v.material.spacing == 9.0
    v.close()


def test_band_sliders_cannot_cross(mesh):
    v = _viewer(mesh, material=tm.Material.bands(thresholds=[0.2, 0.5, 0.7, 0.9]))
    panel = v._controls
    sliders = [panel.widgets[f"material.thresholds[{i}]"] for i in range(4)]
    bounds = [(s.min, s.max) for s in sliders]
    assert set(bounds) == {(0.0, 1.0)}, bounds  # one fixed range: a 0.70 handle never sits left of a 0.55 one
    sliders[0].value = 0.95  # past its neighbour: the handle stops a step short of it
    assert v.material.thresholds[0] == pytest.approx(0.5 - sliders[0].step)
    sliders[3].value = 0.1
    assert v.material.thresholds[3] == pytest.approx(0.7 + sliders[3].step)
    sliders[1].value = 0.6  # between its neighbours: taken as it is
    thresholds = v.material.thresholds
    assert thresholds == pytest.approx([0.49, 0.6, 0.7, 0.71]), thresholds
    assert all(x < y for x, y in zip(thresholds, thresholds[1:])), thresholds
    assert [s.value for s in sliders] == pytest.approx(thresholds)
    assert [(s.min, s.max) for s in sliders] == bounds  # the ranges stayed put
    assert panel.note.value == "" and v.widget._error == ""
    # the render is valid: the frame shown is tm.render's of these settings
    np.testing.assert_array_equal(v.frame, tm.render(*mesh, **{k: getattr(v.options, k) for k in (
        "material", "camera", "width", "height", "lights", "outlines")}).color)
    v.close()


def test_a_refused_value_snaps_back_with_a_note_beside_the_controls(mesh):
    v = _viewer(mesh)
    panel = v._controls
    msaa = panel.widgets["render.msaa"]
    msaa.value = 2  # the core takes 1 or 4 (it refuses 2 when it renders)
    assert v.options.msaa == 1 and msaa.value == 1
    assert "msaa" in panel.note.value and v.widget._error == ""
    np.testing.assert_array_equal(v.frame, v.snapshot().color)  # the frame shown is of the settings kept
    msaa.value = 4  # the note goes with the next change that is taken
    assert v.options.msaa == 4 and panel.note.value == ""
    v.close()


def test_the_controls_start_from_the_current_settings(mesh):
    v = _viewer(mesh, outlines=tm.Outlines("mesh", width=2.0, crease_angle=45), camera=tm.Camera.fit(fov_y=50))
    panel = v._controls
    assert panel.widgets["outlines.crease_angle"].value == 45
    assert panel.widgets["outlines.silhouette.width"].value == 2.0
    assert panel.widgets["camera.fov_y"].value == 50
    v.camera = tm.Camera.look_at((0, 0.2, 0.6), (0, 0.1, 0), fov_y=30)
    assert panel.widgets["camera.fov_y"].value == 30
    v.close()


def test_the_controls_are_in_sections_laid_out_by_the_settings_description(mesh):
    v = _viewer(mesh, outlines="mesh")
    panel = v._controls
    titles = list(panel.accordions)
    # a section per settings object among the render options (the lights: the first), then the rest
    fields = tm.RenderOptions.describe()["fields"]
    own = [f["name"].removesuffix("s") if f["kind"] == "lights" else f["name"] for f in fields if f["kind"] in ("setting", "lights")]
    assert titles == [*own, "options"], titles
    assert [a.selected_index for a in panel.accordions.values()] == [0] + [None] * (len(titles) - 1)  # the material's open
    section_of = {id(c): title for title, (_, controls) in zip(titles, panel.sections) for c in controls}
    assert section_of[id(next(c for c in panel.controls() if c.key == "outlines.crease_angle"))] == "outlines"
    assert section_of[id(next(c for c in panel.controls() if c.key == "render.msaa"))] == "options"
    # the paper, off, turns on by its switch in its own section
    panel.widgets["paper"].value = True
    assert v.options.paper == tm.Paper() and "paper.strength" in {c.key for c in panel.controls()}
    v.close()


def test_v_controls_is_the_column_to_place_anywhere(mesh):
    need("ipywidgets")
    need("anywidget")
    import ipywidgets

    v = _viewer(mesh)
    assert isinstance(v.controls, ipywidgets.VBox) and v.controls is v._controls.column
    assert v._controls.widget.children == (v.widget, v.controls)  # shown beside the frame
    plain = tm.Viewer(*mesh, width=SIZE, height=SIZE)
    column = plain.controls  # made on first read; displaying the viewer still shows the frame alone
    assert column is plain.controls and plain._controls.widget is column
    bundle, _ = plain._repr_mimebundle_()
    assert bundle["application/vnd.jupyter.widget-view+json"]["model_id"] == plain.widget.model_id
    plain.controls  # it drives the viewer as the column beside the frame does
    plain._controls.widgets["material.thresholds[0]"].value = 0.1
    assert plain.material.thresholds[0] == pytest.approx(0.1)
    plain.close()
    v.close()
    assert column.comm is None and v.controls.comm is None  # closed with the viewer

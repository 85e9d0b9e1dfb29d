"""On-screen controls of :class:`toonmesh.Viewer` (``controls=True``): a column beside the frame
with a section per setting the viewer shows (material, the first light, outlines, the camera's
field of view, and the render options), each made from the core's description of the setting's
class (see _field_controls). A change from Python (``v.material = ...``, ``v.set(...)``)
refreshes the controls; a control changes only its field, so ``code()`` sees it. A value the
core refuses leaves the settings as they were: the control snaps back and a note above the
controls says why. Sliders update when released, so dragging one never queues renders.
Imported only where ipywidgets is installed."""

from __future__ import annotations

import html
import weakref
from typing import TYPE_CHECKING, Any, Callable, List, Tuple

import ipywidgets as w  # type: ignore[import-untyped]

from toonmesh._core import Camera, Light, Material, Outlines, RenderOptions
from toonmesh.viewer._field_controls import Control, Panel, Source, controls_for

if TYPE_CHECKING:
    from toonmesh.viewer._viewer import Viewer

# The render options that have a section of their own, and the view's size and pixel ratio,
# which follow the cell and the screen or are set from Python (``v.width = 640``): a slider
# would resize the view under the pointer.
_OWN_SECTIONS = ("material", "lights", "outlines", "camera")
_FRAME_SIZE = ("width", "height", "pixel_ratio")
# The column is as high as the frame (scrolling beyond), but never shorter than this.
_MIN_HEIGHT = 360


class ControlPanel(Panel):
    """The viewer's frame with the column of controls beside it (``widget``, an HBox); every
    control's widget by key in ``widgets`` (``"material.thresholds[0]"``, ``"outlines.kind"``).
    It holds the viewer through a weak reference (the widgets live in ipywidgets' registry until
    closed), so the viewer is freed once nothing else refers to it."""

    def __init__(self, viewer: "Viewer"):
        super().__init__()
        viewer = weakref.proxy(viewer)
        self.viewer = viewer
        self.note = w.HTML("")
        material = Source.whole(lambda: viewer.material, lambda m: viewer.set(material=m))
        light = Source.whole(self._light, self._set_light)
        outlines = Source.whole(lambda: viewer.outlines, lambda o: viewer.set(outlines=o))
        camera = Source.whole(lambda: viewer.camera, lambda c: setattr(viewer, "camera", c))
        render = Source(lambda: viewer.options, lambda name, value: viewer.set(**{name: value}))
        rendering = [f["name"] for f in RenderOptions.describe()["fields"] if f["name"] not in _OWN_SECTIONS + _FRAME_SIZE]
        self.sections: List[Tuple[Any, List[Control]]] = [
            (_heading("material", Material), controls_for(self, material, Material, "material")),
            (_heading("light", Light), controls_for(self, light, Light, "light", directions=("direction",))),
            (_heading("outlines", Outlines), controls_for(self, outlines, Outlines, "outlines",
                                                          whole=lambda o: viewer.set(outlines=o))),
            (_heading("camera", Camera), controls_for(self, camera, Camera, "camera", only=("fov_y",))),
            (_heading("render", RenderOptions), controls_for(self, render, RenderOptions, "render", only=rendering)),
        ]
        rows: List[Any] = [self.note]
        for heading, controls in self.sections:
            rows += [heading, *(c.box for c in controls)]
        self.column = w.VBox(rows, layout=w.Layout(overflow="auto", flex="0 0 auto"))
        self.widget = w.HBox([viewer.widget, self.column]) if viewer.widget is not None else self.column
        self.refresh()

    def close(self) -> None:
        """Closes the column, the box around it and every control (they leave the notebook)."""
        seen = set()
        stack = [self.widget, self.column, self.note, *self.widgets.values()]
        while stack:
            widget = stack.pop()
            if id(widget) in seen:
                continue
            seen.add(id(widget))
            stack.extend(getattr(widget, "children", ()) or ())
            stack.extend(v for v in (getattr(widget, n, None) for n in widget.keys) if isinstance(v, w.Widget))  # layout, style
            widget.close()

    def _light(self) -> Any:
        lights = self.viewer.lights
        return lights[0] if lights else None

    def _set_light(self, light: Light) -> None:
        self.viewer.set(lights=[light, *self.viewer.lights[1:]])

    def controls(self) -> List[Control]:
        """Every control shown now, its own controls after it (a light's Shadows' under the switch)."""
        out: List[Control] = []

        def walk(controls: List[Control]) -> None:
            for c in controls:
                if c.box.layout.display != "none":
                    out.append(c)
                    walk(c.children())

        for _, controls in self.sections:
            walk(controls)
        return out

    def refresh(self) -> None:
        """Shows the viewer's current settings (and only the controls of fields they have)."""
        self.syncing = True
        try:
            for heading, controls in self.sections:
                for c in controls:
                    c.refresh()
                heading.layout.display = None if any(c.box.layout.display != "none" for c in controls) else "none"
            self.column.layout.max_height = f"{max(self.viewer.height, _MIN_HEIGHT)}px"
        finally:
            self.syncing = False

    def apply(self, change: Callable[[], None]) -> None:
        """Runs a control's change; where it fails, the settings go back to what they were and the
        note says why (never over the frame), and the controls show the settings again."""
        before = self.viewer.options
        try:
            change()
        except Exception as exc:  # a refused value: the control snaps back
            self._restore(before)
            self.note.value = f"<span style='color:#a00'>{html.escape(f'{type(exc).__name__}: {exc}')}</span>"
        else:
            self.note.value = ""
        self.refresh()

    def _restore(self, before: RenderOptions) -> None:
        """Puts back the settings a failed change left changed (the core refuses most values
        before anything changes; a render can still fail after)."""
        now = self.viewer.options
        changed = {f["name"]: getattr(before, f["name"]) for f in RenderOptions.describe()["fields"]
                   if getattr(before, f["name"]) != getattr(now, f["name"])}
        if changed:
            self.viewer.set(**changed)


def _heading(title: str, cls: Any) -> Any:
    return w.HTML(f"<b>{html.escape(title)}</b>", tooltip=cls.describe()["help"])

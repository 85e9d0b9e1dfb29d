"""On-screen controls of :class:`toonmesh.Viewer` (``controls=True``, or ``v.controls`` to place
them yourself): a column of collapsible sections, one per settings object among the render
options (the material, the first light, the outlines, the camera's field of view, the paper)
and one for the other render options, each section made from the core's description of the
setting's class (see _field_controls); only the material's is open at first. A change from
Python (``v.material = ...``, ``v.set(...)``) refreshes the controls; a control changes only its
field, so ``code()`` sees it. A value the core refuses leaves the settings as they were: the
control snaps back and a note above the controls says why. Sliders update when released, so
dragging one never queues renders. Imported only where ipywidgets is installed."""

from __future__ import annotations

import functools
import html
import weakref
from typing import Any, Callable, Dict, List, Optional, Protocol, Sequence, Tuple

import ipywidgets as w  # type: ignore[import-untyped]

from toonmesh import _core
from toonmesh._core import Camera, Light, RenderOptions
from toonmesh.viewer._field_controls import Control, Panel, Source, control_for, controls_for


class Viewed(Protocol):
    """What the controls use of the viewer they set (a :class:`toonmesh.Viewer`): named here so
    that this module needs nothing of the viewer's, which imports it."""

    @property
    def widget(self) -> Any: ...

    @property
    def options(self) -> RenderOptions: ...

    @property
    def lights(self) -> Sequence[Light]: ...

    @property
    def height(self) -> int: ...

    @property
    def set(self) -> Callable[..., None]: ...  # set(**render_keywords)

# The view's size and pixel ratio follow the cell and the screen or are set from Python
# (``v.width = 640``): a slider would resize the view under the pointer.
_FRAME_SIZE = ("width", "height", "pixel_ratio")
# The camera's fields the viewer's view keeps as it moves (its eye, target and up come from the
# pointer; a fitted camera's margin and turn, and near and far, are not kept).
_CAMERA_FIELDS = ("fov_y",)
# The section of the render options that are no settings object of their own, and the key its
# controls are registered under (``render.msaa``).
_OPTIONS_TITLE, _OPTIONS_KEY = "options", "render"
# The column is as high as the frame (scrolling beyond), but never shorter than this.
_MIN_HEIGHT = 360
_SECTION_WIDTH = "370px"


class ControlPanel(Panel):
    """The column of controls (``column``, a VBox of collapsible sections) and, where ``beside``,
    the viewer's frame with the column beside it (``widget``, an HBox; else ``widget`` is the
    column); every control's widget by key in ``widgets`` (``"material.thresholds[0]"``,
    ``"outlines.kind"``), each section's by its title in ``accordions``. It holds the viewer
    through a weak reference (the widgets live in ipywidgets' registry until closed), so the
    viewer is freed once nothing else refers to it."""

    def __init__(self, viewer: Viewed, beside: bool = True):
        super().__init__()
        viewer = weakref.proxy(viewer)
        self.viewer = viewer
        self.beside = beside
        self.note = w.HTML("")
        self.sections: List[Tuple[Any, List[Control]]] = []
        self.accordions: Dict[str, Any] = {}
        for title, cls, controls in self._sections():
            # (no tooltip: on an Accordion or a box it breaks the view in JupyterLab; each control has its own)
            section = w.Accordion([_group([c.box for c in controls])], titles=(title,),
                                  selected_index=0 if not self.sections else None,  # the first (the material's) open
                                  layout=w.Layout(width=_SECTION_WIDTH, flex="0 0 auto"))
            section.add_class("toonmesh-section")
            section.add_class("toonmesh-section-" + title)
            self.accordions[title] = section
            self.sections.append((section, controls))
        rows: List[Any] = [self.note, *(section for section, _ in self.sections)]
        self.column = w.VBox(rows, layout=w.Layout(overflow="auto", flex="0 0 auto"))
        self.column.add_class("toonmesh-controls")
        self.widget = w.HBox([viewer.widget, self.column]) if beside and viewer.widget is not None else self.column
        self.refresh()

    def _sections(self) -> List[Tuple[str, Any, List[Control]]]:
        """The sections as the render options' description lays them out: a settings object
        (a field naming its class; the lights: the first) has a section of its own, titled by
        its field, with a control per field of its class; an optional one turns off by its
        choice's "none" where the render options take a choice for the whole setting (the
        outlines' kind: ``outlines="mesh"``), else by a switch (the paper); the other options
        share the last section."""
        viewer = self.viewer
        render = Source(lambda: viewer.options, lambda name, value: viewer.set(**{name: value}))
        out: List[Tuple[str, Any, List[Control]]] = []
        others: List[str] = []
        for field in RenderOptions.describe()["fields"]:
            name, kind = field["name"], field["kind"]
            if kind == "lights":  # a Light or a list: the first light's controls
                light = Source.whole(self._light, self._set_light)
                out.append((name.removesuffix("s"), Light,
                            controls_for(self, light, Light, name.removesuffix("s"), directions=("direction",))))
            elif kind == "setting":
                cls = getattr(_core, field["class"])
                read = functools.partial(_option, viewer, name)
                write = functools.partial(_set_option, viewer, name)
                source = Source.whole(read, write)
                if field["optional"] and not _named_by_choice(name, cls):
                    switch = control_for(self, render, field, name)
                    out.append((name, cls, [switch] if switch is not None else []))
                else:
                    whole = write if field["optional"] else None
                    only = _CAMERA_FIELDS if cls is Camera else None
                    out.append((name, cls, controls_for(self, source, cls, name, only=only, whole=whole)))
            elif name not in _FRAME_SIZE:
                others.append(name)
        out.append((_OPTIONS_TITLE, RenderOptions, controls_for(self, render, RenderOptions, _OPTIONS_KEY, only=others)))
        return out

    def close(self) -> None:
        """Closes the column, the box around it and every control (they leave the notebook)."""
        seen = set()
        stack = [self.widget, self.column, self.note, *self.accordions.values(), *self.widgets.values()]
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
            for section, controls in self.sections:
                for c in controls:
                    c.refresh()
                section.layout.display = None if any(c.box.layout.display != "none" for c in controls) else "none"
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


def _option(viewer: Any, name: str) -> Any:
    return getattr(viewer.options, name)


def _set_option(viewer: Any, name: str, value: Any) -> None:
    viewer.set(**{name: value})


def _named_by_choice(name: str, cls: Any) -> bool:
    """Whether the render options take the first choice of ``cls``'s fields for the whole
    setting ``name`` (``outlines="mesh"``): the core's check is the rule."""
    choice = next((f for f in cls.describe()["fields"] if f["kind"] == "choice" and not f["fixed"]), None)
    if choice is None:
        return False
    try:
        RenderOptions(**{name: choice["choices"][0]})
        return True
    except (TypeError, ValueError):
        return False


def _group(children: List[Any]) -> Any:
    return w.VBox(children, layout=w.Layout(flex="0 0 auto"))

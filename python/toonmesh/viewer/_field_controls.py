"""On-screen controls made from the core's description of a settings class: one control per
described field, its widget chosen by the field's kind (bool: a checkbox; int, float: a slider
between the described bounds; choice: a dropdown; color: a colour picker; floats: a slider per
entry; a LineStyle, or an optional setting such as a light's Shadows: a checkbox with the
setting's own controls under it). A control shows the current object's value, is hidden where
the object lacks the field (hatch spacing on a plain bands material), and changes only its
field, through ``replace`` on the current object, so nothing else of the object is lost.

The controls know nothing of the viewer: a :class:`Source` reads and changes the object, and a
:class:`Panel` runs each change and refreshes every control afterwards. Imported only where
ipywidgets is installed."""

from __future__ import annotations

import functools
import math
import re
from typing import Any, Callable, Dict, List, Optional, Sequence, Tuple

import ipywidgets as w  # type: ignore[import-untyped]

from toonmesh import _core

Field = Dict[str, Any]

# The core gives lists (bands' thresholds and tones) no bounds: both are fractions of light, so
# their sliders span 0 to 1, widened to hold the current entries.
_LIST_RANGE = (0.0, 1.0)
# A direction is shown as where it comes from: azimuth about y (from +z toward +x) and
# elevation toward +y, in degrees; the elevation stops short of the poles, where azimuth is lost.
_AZIMUTH = (-180.0, 180.0)
_ELEVATION = (-89.0, 89.0)
_STYLE = {"description_width": "110px"}
_WIDTH = "330px"


def is_settings(value: Any) -> bool:
    """Whether ``value`` is one of the core's settings objects (it describes its class)."""
    return hasattr(type(value), "describe")


def label(name: str) -> str:
    return name.replace("_", " ")


class Source:
    """Where a settings object lives: ``read()`` gives the current one (None where there is none:
    outlines off, a material without hatching's LineStyle...); ``put(name, value)`` changes one of
    its fields, raising what the core raises for a refused value."""

    def __init__(self, read: Callable[[], Any], put: Callable[[str, Any], None]):
        self.read = read
        self.put = put

    @classmethod
    def whole(cls, read: Callable[[], Any], write: Callable[[Any], None]) -> "Source":
        """An object written back whole (``viewer.material = m``), changed through ``replace``."""
        return cls(read, lambda name, value: write(read().replace(**{name: value})))

    def inner(self, name: str) -> "Source":
        """The settings object in this one's field ``name`` (a light's Shadows, an outline
        kind's LineStyle); None where that field holds none."""

        def read() -> Any:
            outer = self.read()
            value = None if outer is None else getattr(outer, name)
            return value if is_settings(value) else None

        return Source(read, lambda field, value: self.put(name, read().replace(**{field: value})))


class Panel:
    """What the controls report to: every widget by its key (``material.thresholds[0]``), the
    change runner (a refused value shows a note and the controls snap back) and the flag that
    says the controls are being set from the settings, not by the user."""

    syncing = False

    def __init__(self) -> None:
        self.widgets: Dict[str, Any] = {}

    def register(self, key: str, widget: Any) -> None:
        widget.add_class("toonmesh-" + re.sub(r"[^a-z0-9]+", "-", key.lower()).strip("-"))
        self.widgets[key] = widget

    def unregister(self, key: str) -> None:
        self.widgets.pop(key, None)

    def apply(self, change: Callable[[], None]) -> None:
        raise NotImplementedError


class Control:
    """A widget (or a few) bound to one described field of the object that ``source`` reads."""

    def __init__(self, panel: Panel, source: Source, field: Field, key: str):
        self.panel = panel
        self.source = source
        self.field = field
        self.name: str = field["name"]
        self.key = key
        self.box: Any = None  # what is shown or hidden

    def current(self) -> Any:
        obj = self.source.read()
        return None if obj is None else getattr(obj, self.name)

    def present(self) -> bool:
        """Whether the current object has this field (a field its variant lacks reads None)."""
        return self.current() is not None

    def refresh(self) -> None:
        shown = self.present()
        self.box.layout.display = None if shown else "none"
        if shown:
            self.show(self.current())

    def show(self, value: Any) -> None:
        raise NotImplementedError

    def change(self, value: Any) -> None:
        if not self.panel.syncing:
            self.panel.apply(lambda: self.source.put(self.name, value))

    def watch(self, widget: Any, on_value: Callable[[Any], None]) -> None:
        widget.observe(lambda event: None if self.panel.syncing else on_value(event["new"]), names="value")

    def own(self, widget: Any, on_value: Optional[Callable[[Any], None]] = None) -> Any:
        """`widget` as this control's, under its key, calling `on_value` (by default
        :meth:`change`) when the user sets it."""
        self.panel.register(self.key, widget)
        self.watch(widget, on_value or self.change)
        return widget

    def children(self) -> List["Control"]:
        """The controls of the setting inside this field (a light's Shadows'), if any."""
        return []

    def leaves(self) -> List[Any]:
        """The widgets a user sets (a slider, or a slider per entry of a list)."""
        return [self.box]


def _step(lo: float, hi: float) -> float:
    """A slider's step: a power of ten giving at least a hundred steps."""
    return 10.0 ** math.floor(math.log10((hi - lo) / 100.0)) if hi > lo else 1.0


def _slider(kind: str, description: str, lo: float, hi: float, tooltip: str) -> Any:
    common = dict(description=description, continuous_update=False, style=_STYLE, layout=w.Layout(width=_WIDTH), tooltip=tooltip)
    if kind == "int":
        return w.IntSlider(min=int(lo), max=int(hi), **common)
    step = _step(lo, hi)
    return w.FloatSlider(min=lo, max=hi, step=step, readout_format=f".{max(0, -math.floor(math.log10(step)))}f", **common)


def _group(children: List[Any], margin: str = "0") -> Any:
    """A column of widgets that keeps its height in a scrolling column (a flex item would
    shrink to nothing there)."""
    return w.VBox(children, layout=w.Layout(flex="0 0 auto", margin=margin))


def _place(slider: Any, value: Any, lo: float, hi: float) -> None:
    """Sets a slider's range and value at once; the range widens to hold a value outside it
    (the description's ``slider`` is what a control spans; its rule, ``min`` and ``max``, may
    be wider or unbounded)."""
    with slider.hold_trait_notifications():
        slider.min = min(lo, value)
        slider.max = max(hi, value)
        slider.value = value


class Toggle(Control):
    def __init__(self, *args: Any):
        super().__init__(*args)
        self.box = self.own(w.Checkbox(description=label(self.name), style=_STYLE, tooltip=self.field["help"]))

    def show(self, value: Any) -> None:
        self.box.value = bool(value)


class Slider(Control):
    def __init__(self, *args: Any):
        super().__init__(*args)
        self.box = self.own(_slider(self.field["kind"], label(self.name), *self.field["slider"], self.field["help"]))

    def show(self, value: Any) -> None:
        _place(self.box, value, *self.field["slider"])


class Choice(Control):
    """A dropdown of the field's choices; with ``whole`` (an optional setting's first choice,
    such as the outlines' kind) it offers "none" too, which sets the whole setting to None, and
    a choice made from "none" brings back the setting as it was, with that choice."""

    OFF = "none"

    def __init__(self, panel: Panel, source: Source, field: Field, key: str, whole: Optional[Callable[[Any], None]] = None):
        super().__init__(panel, source, field, key)
        self.whole = whole
        self.last: Any = None  # the setting before it was set to None
        options = ([self.OFF] if whole is not None else []) + list(field["choices"])
        self.box = self.own(w.Dropdown(options=options, description=label(self.name), style=_STYLE,
                                       layout=w.Layout(width=_WIDTH), tooltip=field["help"]), self.choose)

    def present(self) -> bool:
        return self.whole is not None or super().present()

    def refresh(self) -> None:
        obj = self.source.read()
        if obj is not None:
            self.last = obj
        super().refresh()

    def show(self, value: Any) -> None:
        self.box.value = self.OFF if value is None else value

    def choose(self, value: str) -> None:
        whole = self.whole
        if whole is None or self.source.read() is not None and value != self.OFF:
            self.change(value)
        elif value == self.OFF:
            self.panel.apply(lambda: whole(None))
        else:  # from "none": the setting as it was, else as the core makes it from the choice
            last = self.last
            self.panel.apply(lambda: whole(value if last is None else last.replace(**{self.name: value})))


class Color(Control):
    def __init__(self, *args: Any):
        super().__init__(*args)
        self.box = self.own(w.ColorPicker(description=label(self.name), style=_STYLE, tooltip=self.field["help"]))

    def show(self, value: Any) -> None:
        self.box.value = "#" + "".join(f"{round(min(max(float(c), 0.0), 1.0) * 255):02x}" for c in value[:3])


class Sliders(Control):
    """A list of numbers, a slider per entry, each over the same fixed range. Where the core
    keeps the list strictly increasing (bands' thresholds), a handle moved past its neighbour
    stops a step short of it, so the handles keep their order and their ranges stay put."""

    def __init__(self, *args: Any):
        super().__init__(*args)
        self.box = _group([])
        self.sliders: List[Any] = []
        self.increasing: Optional[bool] = None  # asked of the core once the list has two entries

    def _entry_key(self, i: int) -> str:
        return f"{self.key}[{i}]"

    def _build(self, count: int) -> None:
        for i in range(len(self.sliders)):
            self.panel.unregister(self._entry_key(i))
        singular = label(self.name).removesuffix("s")
        self.sliders = [_slider("float", f"{singular} {i + 1}", *_LIST_RANGE, self.field["help"]) for i in range(count)]
        for i, s in enumerate(self.sliders):
            self.panel.register(self._entry_key(i), s)
            self.watch(s, functools.partial(self.move, i))
        self.box.children = self.sliders

    def _must_increase(self, values: Sequence[float]) -> bool:
        """Whether the core refuses two equal neighbours in this list (its check is the rule)."""
        if self.increasing is None and len(values) >= 2:
            try:
                self.source.read().replace(**{self.name: [values[0], *values[:1], *values[2:]]})
                self.increasing = False
            except ValueError:
                self.increasing = True
        return bool(self.increasing)

    def show(self, value: Any) -> None:
        values = [float(v) for v in value]
        if len(values) != len(self.sliders):
            self._build(len(values))
        lo, hi = _LIST_RANGE
        for s, v in zip(self.sliders, values):
            _place(s, v, min(lo, *values), max(hi, *values))  # one range for all, holding every entry

    def leaves(self) -> List[Any]:
        return list(self.sliders)

    def move(self, i: int, value: float) -> None:
        values = [float(v) for v in self.current()]
        if self._must_increase(values):  # stopped a step short of a neighbour it passed
            step = self.sliders[i].step
            if i > 0:
                value = max(value, values[i - 1] + step)
            if i + 1 < len(values):
                value = min(value, values[i + 1] - step)
        values[i] = value
        self.change(values)


class Direction(Control):
    """A direction as where it comes from: azimuth and elevation sliders."""

    def __init__(self, *args: Any):
        super().__init__(*args)
        tip = self.field["help"] + " (shown as where it comes from)"
        self.azimuth = _slider("float", "azimuth", *_AZIMUTH, tip)
        self.elevation = _slider("float", "elevation", *_ELEVATION, tip)
        self.box = _group([self.azimuth, self.elevation])
        for part, s in (("azimuth", self.azimuth), ("elevation", self.elevation)):
            self.panel.register(f"{self.key}.{part}", s)
            self.watch(s, lambda _: self.change(_toward(self.azimuth.value, self.elevation.value)))

    def leaves(self) -> List[Any]:
        return [self.azimuth, self.elevation]

    def show(self, value: Any) -> None:
        azimuth, elevation = _angles(tuple(-x for x in value))
        _place(self.azimuth, azimuth, *_AZIMUTH)
        _place(self.elevation, min(max(elevation, _ELEVATION[0]), _ELEVATION[1]), *_ELEVATION)


def _angles(direction: Any) -> Tuple[float, float]:
    """Azimuth and elevation of a direction, in degrees."""
    x, y, z = direction
    n = math.sqrt(x * x + y * y + z * z) or 1.0
    return math.degrees(math.atan2(x, z)), math.degrees(math.asin(max(-1.0, min(1.0, y / n))))


def _toward(azimuth: float, elevation: float) -> Tuple[float, float, float]:
    """The direction of travel of something coming from ``azimuth``, ``elevation``."""
    a, e = math.radians(azimuth), math.radians(elevation)
    return (-math.cos(e) * math.sin(a), -math.sin(e), -math.cos(e) * math.cos(a))


class Switch(Control):
    """A setting inside the object that may be off: an optional setting (a light's Shadows, a
    material's Dither: off is None, on is the class's default) or a line kind's style (off is
    False, on is True: the common style). Its own fields' controls sit under the checkbox."""

    def __init__(self, panel: Panel, source: Source, field: Field, key: str, cls: Any, on: Any, off: Any):
        super().__init__(panel, source, field, key)
        self.on, self.off = on, off
        self.check = self.own(w.Checkbox(description=label(self.name), style=_STYLE, tooltip=field["help"]),
                              lambda value: self.change(self.on() if value else self.off))
        self.inner = controls_for(panel, source.inner(self.name), cls, key)
        self.box = _group([self.check, _group([c.box for c in self.inner], margin="0 0 0 24px")])

    def present(self) -> bool:
        """Where the field is on, or the core would take it on (no shadows for a point light, no
        suggestive contours among edges found in the image)."""
        obj = self.source.read()
        if obj is None:
            return False
        if is_settings(getattr(obj, self.name)):
            return True
        try:
            obj.replace(**{self.name: self.on()})
            return True
        except (TypeError, ValueError):
            return False

    def show(self, value: Any) -> None:
        self.check.value = is_settings(value)
        for c in self.inner:
            c.refresh()

    def children(self) -> List[Control]:
        return self.inner

    def leaves(self) -> List[Any]:
        return [self.check]


def control_for(panel: Panel, source: Source, field: Field, key: str, directions: Sequence[str] = ()) -> Optional[Control]:
    """The control of one described field, or None for a kind with no control here (a table,
    a matrix, a point...); ``directions`` names the vec3 fields that are directions."""
    kind = field["kind"]
    if field["fixed"]:
        return None
    if kind == "bool":
        return Toggle(panel, source, field, key)
    if kind in ("int", "float"):
        return Slider(panel, source, field, key)
    if kind == "choice":
        return Choice(panel, source, field, key)
    if kind == "color":
        return Color(panel, source, field, key)
    if kind == "floats":
        return Sliders(panel, source, field, key)
    if kind == "vec3" and field["name"] in directions:
        return Direction(panel, source, field, key)
    if kind == "style":  # a line kind: False (not drawn), True (the common style) or a LineStyle
        return Switch(panel, source, field, key, _core.LineStyle, lambda: True, False)
    if kind == "setting" and field["optional"]:
        cls = getattr(_core, field["class"])
        return Switch(panel, source, field, key, cls, cls, None)
    return None


def controls_for(panel: Panel, source: Source, cls: Any, key: str, only: Optional[Sequence[str]] = None,
                 directions: Sequence[str] = (), whole: Optional[Callable[[Any], None]] = None) -> List[Control]:
    """The controls of the described fields of ``cls`` (of those in ``only``, where given), in
    the description's order. ``whole`` writes the whole setting where it may be None (outlines
    off): its first choice then offers "none" too (see :class:`Choice`)."""
    out: List[Control] = []
    for field in cls.describe()["fields"]:
        if only is not None and field["name"] not in only:
            continue
        name = f"{key}.{field['name']}"
        if whole is not None and field["kind"] == "choice" and not field["fixed"]:
            control: Optional[Control] = Choice(panel, source, field, name, whole)
            whole = None
        else:
            control = control_for(panel, source, field, name, directions)
        if control is not None:
            out.append(control)
    return out

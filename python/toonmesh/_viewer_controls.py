"""On-screen controls of :class:`toonmesh.Viewer` (``controls=True``): ipywidgets sliders and
switches beside the frame, each setting the viewer's render settings (so ``code()`` sees them).
Sliders update when released, so dragging one never queues renders."""

from __future__ import annotations

import math
from typing import TYPE_CHECKING, Any, List, Optional

from toonmesh._render import Light, Material, Outlines

if TYPE_CHECKING:
    from toonmesh.viewer import Viewer


def _angles(direction: Any) -> "tuple[float, float]":
    """Azimuth (about y, from +z toward +x) and elevation (toward +y) of a direction, in degrees.
    The sliders show where the light comes from: the opposite of its direction of travel."""
    x, y, z = direction
    n = math.sqrt(x * x + y * y + z * z) or 1.0
    return math.degrees(math.atan2(x, z)), math.degrees(math.asin(max(-1.0, min(1.0, y / n))))


def _direction(azimuth: float, elevation: float) -> "tuple[float, float, float]":
    a, e = math.radians(azimuth), math.radians(elevation)
    return (math.cos(e) * math.sin(a), math.sin(e), math.cos(e) * math.cos(a))


def control_panel(viewer: "Viewer") -> Any:
    """The viewer's widget with a column of controls beside it (an ``ipywidgets.HBox``)."""
    import ipywidgets as w  # type: ignore[import-untyped]

    rows: List[Any] = []
    style = {"description_width": "110px"}
    layout = w.Layout(width="330px")

    def slider(description: str, value: float, lo: float, hi: float, step: float) -> Any:
        return w.FloatSlider(value=value, min=lo, max=hi, step=step, description=description,
                             continuous_update=False, style=style, layout=layout)

    def guarded(change: Any) -> None:
        try:
            change()
        except (TypeError, ValueError) as exc:  # shown over the frame rather than lost in a log
            if viewer.widget is not None:
                viewer.widget.show_error(f"{type(exc).__name__}: {exc}")

    light: Optional[Light] = viewer.lights[0] if viewer.lights else None
    if light is not None and light.direction is not None:  # a directional light
        az, el = _angles(tuple(-x for x in light.direction))
        azimuth = slider("light azimuth", az, -180, 180, 1)
        elevation = slider("light elevation", el, -89, 89, 1)
        shadows = w.Checkbox(value=light.shadows is not None, description="shadows", style=style)

        def relight(_: Any = None) -> None:
            first = viewer.lights[0]
            toward = _direction(azimuth.value, elevation.value)
            lit = Light.directional(tuple(-x for x in toward), color=first.color,
                                    intensity=first.intensity, space=first.space,
                                    shadows=(first.shadows or True) if shadows.value else None)
            guarded(lambda: setattr(viewer, "lights", [lit, *viewer.lights[1:]]))

        for c in (azimuth, elevation, shadows):
            c.observe(relight, names="value")
        rows += [azimuth, elevation, shadows]

    material: Material = viewer.material
    if material.model == "bands" and material.hatch_style is None and material.thresholds:
        thresholds = [slider(f"band {i + 1}", t, 0, 1, 0.01) for i, t in enumerate(material.thresholds)]

        def rethreshold(_: Any = None) -> None:
            m = viewer.material
            guarded(lambda: setattr(viewer, "material", Material.bands(
                m.diffuse, thresholds=[s.value for s in thresholds], values=m.values, per_vertex=m.per_vertex, dither=m.dither)))

        for s in thresholds:
            s.observe(rethreshold, names="value")
        rows += thresholds

    current = viewer.outlines
    first_style = next((s for s in current.styles.values() if s is not None), None) if current is not None else None
    kind = w.Dropdown(options=["none", "mesh", "image", "both"], value=current.kind if current is not None else "none",
                      description="outlines", style=style, layout=layout)
    crease = slider("crease angle", current.crease_angle if current is not None else 30.0, 0, 180, 1)
    width = slider("outline width", first_style.width if first_style is not None else 1.5, 0.5, 8, 0.25)

    def reoutline(_: Any = None) -> None:
        if kind.value == "none":
            guarded(lambda: setattr(viewer, "outlines", None))
            return
        color = first_style.color if first_style is not None else (0.0, 0.0, 0.0)
        guarded(lambda: setattr(viewer, "outlines", Outlines(kind.value, color=color, width=width.value, crease_angle=crease.value)))

    for c in (kind, crease, width):
        c.observe(reoutline, names="value")
    rows += [kind, crease, width]
    return w.HBox([viewer.widget, w.VBox(rows)]) if viewer.widget is not None else w.VBox(rows)

"""The size of a :class:`toonmesh.Viewer`'s view: its width and height in layout pixels (CSS
pixels: what the page lays out and the pointer moves in), given or fitted to the notebook cell's
width, and the pixel ratio its frames are rendered at (given, or the screen's device pixel ratio
as the browser reports it). A frame is the view's size times the ratio, in output pixels, with
the lengths the settings give in pixels scaled by the same ratio (``RenderOptions.pixel_ratio``),
so a 2x screen shows the same picture, sharper. Full screen fills the screen while it lasts."""

from __future__ import annotations

import math
from typing import Any, Dict, Optional, Tuple

from toonmesh.arguments._checks import integer, number
from toonmesh._core import RenderOptions
from toonmesh.arguments._described import default, described

# The view's size when none is given, until the browser says how wide the cell is.
DEFAULT_WIDTH = int(default(RenderOptions, "", "width"))
DEFAULT_HEIGHT = int(default(RenderOptions, "", "height"))
# A cell narrower than this keeps this width (a view too small to drag in helps no one).
MIN_FITTED_WIDTH = 64

#: The viewer's keywords that size its view, each a field of ``Layout`` of the same name.
KEYWORDS = ("width", "height", "pixel_ratio")


def checked(name: str, value: Any) -> Any:
    """A layout keyword's value (``KEYWORDS``) within the core's bounds for the render option of
    the same name (None: fitted, the default or followed, as ``Layout`` says)."""
    if value is None:
        return None
    bounds = described(RenderOptions, name)
    if name == "pixel_ratio":
        return number(name, value, bounds["min"], bounds["max"])
    return integer(name, value, bounds["min"], bounds["max"])


class Layout:
    """The view's size and pixel ratio: ``width`` None fits the cell's width (``cell_width``,
    reported by the browser); ``height`` None is the default; ``pixel_ratio`` None follows the
    screen's (``screen_ratio``); ``full`` the screen's size while the view is full screen (None
    otherwise)."""

    def __init__(self, width: Optional[int] = None, height: Optional[int] = None,
                 pixel_ratio: Optional[float] = None):
        self.width = width
        self.height = height
        self.pixel_ratio = pixel_ratio
        self.cell_width: Optional[int] = None
        self.screen_ratio = 1.0
        self.full: Optional[Tuple[int, int]] = None

    def view_size(self) -> Tuple[int, int]:
        """The view's width and height in layout pixels, as shown now."""
        if self.full is not None:
            return self.full
        width = self.width if self.width is not None else (self.cell_width or DEFAULT_WIDTH)
        return width, DEFAULT_HEIGHT if self.height is None else self.height

    def ratio(self) -> float:
        """Output pixels per layout pixel, as rendered now."""
        return self.pixel_ratio if self.pixel_ratio is not None else self.screen_ratio

    def frame(self) -> Dict[str, Any]:
        """The render options of a frame of the view: ``width``, ``height`` (output pixels) and
        ``pixel_ratio``."""
        ratio = self.ratio()
        w, h = self.view_size()
        return {"width": max(1, round(w * ratio)), "height": max(1, round(h * ratio)), "pixel_ratio": ratio}

    def reported(self, step: Dict[str, Any]) -> None:
        """The browser's report (the toolbar's ``size`` step): ``width``, the cell's width in
        layout pixels; ``ratio``, the screen's device pixel ratio; ``full``, the screen's
        [width, height] while the view is full screen, else None."""
        width = step.get("width")
        if width is not None:
            self.cell_width = max(MIN_FITTED_WIDTH, _whole("width", width))
        ratio = step.get("ratio")
        if ratio is not None:
            self.screen_ratio = checked("pixel_ratio", ratio)
        full = step.get("full")
        if full is None:
            self.full = None
        else:
            if not isinstance(full, (list, tuple)) or len(full) != 2:
                raise ValueError(f"full: expected [width, height] in pixels, got {full!r}")
            self.full = (max(MIN_FITTED_WIDTH, _whole("full", full[0])), max(MIN_FITTED_WIDTH, _whole("full", full[1])))

    def state(self) -> Dict[str, Any]:
        """What the browser needs to know: whether it reports the cell's width (``fit``) and the
        screen's ratio (``follow_screen``), and the ratio the frames are rendered at."""
        return {"fit": self.width is None, "follow_screen": self.pixel_ratio is None, "ratio": self.ratio()}


def _whole(name: str, value: Any) -> int:
    """A size the browser reported: a finite number of pixels, rounded down."""
    if isinstance(value, bool) or not isinstance(value, (int, float)) or not math.isfinite(value) or value < 0:
        raise ValueError(f"{name}: expected a size in pixels, got {value!r}")
    return int(min(value, 1 << 16))

"""The viewer's browser code: the ``.js`` and ``.css`` files beside this module, joined in order
into the widget's ESM and the standalone page's script. The files are plain scripts (functions and
constants, no imports), so that one list says what each front end loads: the camera's moves and
gestures (``moves.js``) and the draft renderer (``draft.js``) are written once for both."""

from __future__ import annotations

from importlib import resources
from typing import Sequence

#: The widget's ESM (``widget.js`` ends in its ``export default``).
WIDGET = ("moves.js", "draft.js", "triad.js", "widget.js")
#: The widget's styles (anywidget's ``_css``).
WIDGET_CSS = "widget.css"
#: The standalone page's module script (:meth:`toonmesh.Viewer.to_html`).
PAGE = ("moves.js", "draft.js", "page.js")


def text(name: str) -> str:
    """One of the viewer's files, by name."""
    return resources.files(__package__).joinpath(name).read_text(encoding="utf-8")


def script(names: Sequence[str]) -> str:
    """The files ``names`` joined in order, each under a comment naming it."""
    return "\n".join(f"// ---- {n}\n{text(n)}" for n in names)

"""The browser side of :class:`toonmesh.Viewer`: an anywidget that draws drafts while the pointer
moves (WebGL2, the core's draft: ``toonmesh.viewer._draft``), shows the frames the kernel sends,
sends pointer events and toolbar clicks back, and paces them to the kernel's answers. Imported
only where anywidget is installed."""

from __future__ import annotations

import weakref
from typing import Any, Callable, Dict, Optional, Union

import anywidget
import traitlets

from toonmesh.viewer._assets import WIDGET, WIDGET_CSS, script, text

class ViewerWidget(anywidget.AnyWidget):  # type: ignore[misc]
    """The widget a :class:`toonmesh.Viewer` displays: its last frame (PNG or JPEG bytes), the
    frame's size on screen, its number, the number of the browser's view it was made for, whether
    it is the full-size frame, and a count of the answers sent (frames and errors)."""

    _esm = script(WIDGET)
    _css = text(WIDGET_CSS)
    _frame = traitlets.Bytes(b"").tag(sync=True)
    _format = traitlets.Unicode("png").tag(sync=True)
    _frame_id = traitlets.Int(0).tag(sync=True)
    _view_id = traitlets.Int(0).tag(sync=True)
    _exact = traitlets.Bool(True).tag(sync=True)
    _size = traitlets.List([512, 512]).tag(sync=True)
    _layout = traitlets.Dict({"fit": False, "follow_screen": False, "ratio": 1.0}).tag(sync=True)
    _error = traitlets.Unicode("").tag(sync=True)
    _answers = traitlets.Int(0).tag(sync=True)
    _camera = traitlets.Dict({}).tag(sync=True)
    _draft_spec = traitlets.Unicode("").tag(sync=True)
    _draft_data = traitlets.Bytes(b"").tag(sync=True)
    _moves = traitlets.Dict({}).tag(sync=True)
    # the scene's parts for the toolbar's list: {"names": [...], "visible": [True or False, ...]}
    _parts = traitlets.Dict({"names": list[str](), "visible": list[bool]()}).tag(sync=True)

    _on_display: Optional["weakref.WeakMethod[Callable[[], None]]"] = None

    def attach(self, on_event: "Union[weakref.WeakMethod[Callable[[Dict[str, Any]], None]], Callable[[Dict[str, Any]], None]]",
               on_display: "Optional[weakref.WeakMethod[Callable[[], None]]]" = None) -> None:
        """Sends the front end's messages (dicts, see ``Viewer._on_event``) to ``on_event``: a
        callable, or a ``weakref.WeakMethod`` (the widget then does not keep its viewer alive;
        messages after the viewer is gone are dropped); calls ``on_display`` (weakly) when the
        widget itself is displayed (``display(v.widget)``), as the viewer is when it is."""
        def handle(_widget: Any, content: Dict[str, Any], _buffers: Any) -> None:
            target: Optional[Callable[[Dict[str, Any]], None]] = on_event() if isinstance(on_event, weakref.WeakMethod) else on_event
            if target is not None:
                target(content)

        self.on_msg(handle)
        self._on_display = on_display

    def _repr_mimebundle_(self, **kwargs: Any) -> Any:
        displayed = self._on_display() if self._on_display is not None else None
        if displayed is not None:
            displayed()
        return super()._repr_mimebundle_(**kwargs)

    def show_frame(self, data: bytes, image_format: str, frame_id: int, width: int, height: int,
                   view_id: int = 0, exact: bool = True, camera: Optional[Dict[str, Any]] = None,
                   layout: Optional[Dict[str, Any]] = None) -> None:
        """Sends a frame: encoded bytes shown at ``width`` x ``height`` CSS pixels, made for the
        browser's view ``view_id`` (the browser drops it if it shows a later view's frame);
        ``exact``: the full-size frame (False: a draft drawn while the pointer moves);
        ``camera``: the view it shows, as the browser's draft renderer moves it; ``layout``:
        whether the browser reports the cell's width (``fit``) and the screen's pixel ratio
        (``follow_screen``), and the ratio the frames are rendered at (``ratio``)."""
        with self.hold_sync():
            if camera is not None:
                self._camera = camera
            if layout is not None:
                self._layout = layout
            self._frame = data
            self._format = image_format
            self._frame_id = frame_id
            self._view_id = view_id
            self._exact = bool(exact)
            self._size = [width, height]
            self._error = ""
            self._answers += 1

    def show_draft(self, spec: str, data: bytes, moves: Dict[str, float]) -> None:
        """Sends the core's draft (its JSON and bytes; ``toonmesh.viewer._draft``) and the
        constants of the viewer's moves, for the browser to draw drafts itself."""
        with self.hold_sync():
            self._draft_data = data
            self._moves = moves
            self._draft_spec = spec

    def show_error(self, message: str, view_id: int = 0) -> None:
        """Shows a render's error over the frame, answering the browser's view ``view_id``."""
        with self.hold_sync():
            self._error = message
            self._view_id = max(self._view_id, view_id)
            self._answers += 1

    def close(self) -> None:
        """Closes the widget (its views leave the notebook) and its layout widget."""
        layout = self.layout
        super().close()
        if layout is not None:
            layout.close()

"""The browser side of :class:`toonmesh.Viewer`: an anywidget that shows the frames the kernel
sends and sends pointer events back. Imported only where anywidget is installed."""

from __future__ import annotations

from typing import Any, Callable, Dict

import anywidget
import traitlets

_ESM = r"""
// Shows the kernel's frames in an <img>; sends drags, wheel turns and double-clicks as events.
// Events are merged per animation frame, and "settle" (render full size) follows once the
// pointer has stopped for SETTLE_MS or is released.
const SETTLE_MS = 150;

function render({ model, el }) {
  const root = document.createElement("div");
  root.className = "toonmesh-viewer";
  root.style.cssText = "position: relative; display: inline-block; line-height: 0";
  const img = document.createElement("img");
  img.draggable = false;
  img.alt = "toonmesh viewer";
  img.style.cssText = "cursor: grab; touch-action: none; user-select: none; display: block";
  const note = document.createElement("div");
  note.style.cssText = "position: absolute; left: 4px; bottom: 4px; font: 12px sans-serif; line-height: 1.2; color: #a00";
  root.append(img, note);
  el.appendChild(root);

  let url = null;
  function show() {
    const data = model.get("_frame");
    if (!data || data.byteLength === 0) return;
    const blob = new Blob([data], { type: "image/" + model.get("_format") });
    const next = URL.createObjectURL(blob);
    const previous = url;
    url = next;
    img.src = next;
    if (previous) setTimeout(() => URL.revokeObjectURL(previous), 1000);
    const [w, h] = model.get("_size");
    img.style.width = w + "px";
    img.style.height = h + "px";
    root.dataset.frame = String(model.get("_frame_id"));
    note.textContent = model.get("_error");
  }
  model.on("change:_frame", show);
  model.on("change:_error", () => { note.textContent = model.get("_error"); });
  show();

  let drag = null;
  let pending = null;
  let scheduled = false;
  let settleTimer = null;
  function flush() {
    scheduled = false;
    if (pending) { model.send(pending); pending = null; }
  }
  function queue(event, dx, dy) {
    if (pending && pending.event !== event) flush();
    if (!pending) pending = { event, dx: 0, dy: 0 };
    pending.dx += dx;
    pending.dy += dy;
    if (!scheduled) { scheduled = true; requestAnimationFrame(flush); }
    clearTimeout(settleTimer);
    settleTimer = setTimeout(settle, SETTLE_MS);
  }
  function settle() {
    clearTimeout(settleTimer);
    flush();
    model.send({ event: "settle" });
  }
  function down(e) {
    drag = { x: e.clientX, y: e.clientY, event: (e.shiftKey || e.button === 2) ? "pan" : "orbit" };
    img.setPointerCapture(e.pointerId);
    img.style.cursor = "grabbing";
    e.preventDefault();
  }
  function move(e) {
    if (!drag) return;
    const dx = e.clientX - drag.x, dy = e.clientY - drag.y;
    drag.x = e.clientX; drag.y = e.clientY;
    if (dx || dy) queue(drag.event, dx, dy);
  }
  function up(e) {
    if (!drag) return;
    drag = null;
    img.style.cursor = "grab";
    settle();
  }
  function wheel(e) { e.preventDefault(); queue("zoom", 0, e.deltaY); }
  function dblclick(e) { e.preventDefault(); model.send({ event: "frame" }); }
  function menu(e) { e.preventDefault(); }
  img.addEventListener("pointerdown", down);
  img.addEventListener("pointermove", move);
  img.addEventListener("pointerup", up);
  img.addEventListener("pointercancel", up);
  img.addEventListener("wheel", wheel, { passive: false });
  img.addEventListener("dblclick", dblclick);
  img.addEventListener("contextmenu", menu);
  return () => {
    clearTimeout(settleTimer);
    if (url) URL.revokeObjectURL(url);
  };
}

export default { render };
"""


class ViewerWidget(anywidget.AnyWidget):  # type: ignore[misc]
    """The widget a :class:`toonmesh.Viewer` displays: its last frame (PNG or JPEG bytes), the
    frame's size on screen and its number."""

    _esm = _ESM
    _frame = traitlets.Bytes(b"").tag(sync=True)
    _format = traitlets.Unicode("png").tag(sync=True)
    _frame_id = traitlets.Int(0).tag(sync=True)
    _size = traitlets.List([512, 512]).tag(sync=True)
    _error = traitlets.Unicode("").tag(sync=True)

    def attach(self, on_event: Callable[[Dict[str, Any]], None]) -> None:
        """Sends the front end's events (dicts with ``event``, ``dx``, ``dy``) to ``on_event``."""
        self.on_msg(lambda _widget, content, _buffers: on_event(content))

    def show_frame(self, data: bytes, image_format: str, frame_id: int, width: int, height: int) -> None:
        """Sends a frame: encoded bytes shown at ``width`` x ``height`` CSS pixels."""
        with self.hold_sync():
            self._frame = data
            self._format = image_format
            self._frame_id = frame_id
            self._size = [width, height]
            self._error = ""

    def show_error(self, message: str) -> None:
        """Shows a render's error over the frame."""
        self._error = message

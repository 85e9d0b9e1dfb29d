"""The draft renderer of :class:`toonmesh.Viewer`: what the browser needs to draw a view itself in
WebGL2 while the pointer moves (the core's draft: GLSL ES 3.00 translated from toonmesh's own
WGSL, the uniform bytes and their layout, the meshes as uploaded; ``Renderer._draft``), the
script that draws it (``_draft.js``: WebGL calls and camera plumbing only), and a standalone page
that orbits a scene with it (:meth:`toonmesh.Viewer.to_html`)."""

from __future__ import annotations

import base64
import html
import json
from importlib import resources
from typing import Any, Dict, Tuple

#: The page's own controller: orbit, pan and zoom with the viewer's moves, one draft a frame.
_PAGE_JS = r"""
const data = JSON.parse(document.getElementById("toonmesh-data").textContent);
const blob = Uint8Array.from(atob(document.getElementById("toonmesh-blob").textContent), (c) => c.charCodeAt(0)).buffer;
const root = document.querySelector(".toonmesh-viewer");
const canvas = root.querySelector("canvas");
const [width, height] = data.size;
canvas.style.width = width + "px"; canvas.style.height = height + "px";
const home = draftCamera(data.camera);
let cam = draftCamera(home), draft = null, wanted = false, moving = false, settle = null;
const pacer = draftPacer(data.moves.drag_scale);
try {
  draft = createDraft(canvas, JSON.parse(data.spec), blob);
  root.title = "drag to orbit, shift-drag to pan, wheel or pinch to zoom, two fingers to pan, double-click for the first view; "
    + "drafts drawn in WebGL2 from toonmesh's shaders; " + draftNote(draft.leftToExact);
} catch (e) {
  root.dataset.error = String(e.message || e);
  root.title = "WebGL2 drafts failed: " + root.dataset.error;
}
// while the view moves, drafts at the viewer's drag_scale of the size; full size once it stops
function frame() {
  wanted = false;
  if (!draft) return;
  // at the screen's pixel ratio (sharp on a 2x screen), smaller while moving
  const r = (window.devicePixelRatio || 1) * (moving ? pacer.scale() : 1);
  draft.draw(cam, Math.max(1, Math.round(width * r)), Math.max(1, Math.round(height * r)), r);
  pacer.shown(performance.now(), moving);
  root.dataset.framesShown = String(+root.dataset.framesShown + 1);
}
function ask() { if (!wanted) { wanted = true; requestAnimationFrame(frame); } }
function moved() {
  moving = true;
  ask();
  clearTimeout(settle);
  settle = setTimeout(() => { moving = false; ask(); }, 150);
}
draftGestures(canvas, () => data.moves, (step) => { draftStep(cam, step, height, data.moves); moved(); }, () => {}, () => {});
canvas.addEventListener("wheel", (e) => {  // toward the cursor, as the viewer zooms
  e.preventDefault();
  draftStep(cam, { event: "zoom", dx: 0, dy: e.deltaY, ...draftCursor(e, canvas) }, height, data.moves);
  moved();
}, { passive: false });
canvas.addEventListener("dblclick", () => { cam = draftCamera(home); ask(); });
canvas.addEventListener("contextmenu", (e) => e.preventDefault());
// for tests and measurements: draw a view (the viewer's camera state) at full size, read it back
window.toonmeshDraft = { draw: (c) => { if (c) cam = draftCamera(c); moving = false; frame(); },
                         pixels: () => draft && draft.pixels(), camera: () => draftCamera(cam), renderer: draft };
frame();
"""


def draft_js() -> str:
    """The draft renderer's script (``_draft.js``)."""
    return resources.files("toonmesh").joinpath("_draft.js").read_text(encoding="utf-8")


def page(spec: str, blob: bytes, camera: Dict[str, Any], moves: Dict[str, float], size: Tuple[int, int],
         title: str) -> str:
    """A standalone HTML page that orbits the draft ``spec`` (the core's JSON) with its bytes
    ``blob`` from ``camera`` (see :func:`camera_state`): everything inlined, nothing fetched."""
    data = json.dumps({"spec": spec, "camera": camera, "moves": moves, "size": list(size)})
    # JSON inside <script>: "</" would end the element
    data = data.replace("</", "<\\/")
    script = (draft_js() + _PAGE_JS).replace("</script", "<\\/script")
    return (
        "<!DOCTYPE html>\n<html><head><meta charset=\"utf-8\">"
        f"<title>{html.escape(title)}</title>"
        "<style>body { margin: 16px; font: 13px sans-serif } canvas { display: block; cursor: grab;"
        " touch-action: none } .toonmesh-viewer { display: inline-block; border: 1px solid #c8c8c8 }</style>"
        "</head><body>\n"
        "<div class=\"toonmesh-viewer\" data-frames-shown=\"0\" data-exact=\"0\"><canvas></canvas></div>\n"
        f"<script type=\"application/json\" id=\"toonmesh-data\">{data}</script>\n"
        f"<script type=\"text/plain\" id=\"toonmesh-blob\">{base64.b64encode(blob).decode('ascii')}</script>\n"
        f"<script type=\"module\">\n{script}\n</script>\n"
        "</body></html>\n"
    )

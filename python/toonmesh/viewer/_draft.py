"""The draft renderer of :class:`toonmesh.Viewer`: what the browser needs to draw a view itself in
WebGL2 while the pointer moves (the core's draft: GLSL ES 3.00 translated from toonmesh's own
WGSL, the uniform bytes and their layout, the meshes as uploaded; ``Renderer._draft``), the
scripts that draw it (``draft.js``: WebGL calls and camera plumbing only; ``moves.js``; ``page.js``), and a standalone page
that orbits a scene with it (:meth:`toonmesh.Viewer.to_html`)."""

from __future__ import annotations

import base64
import html
import json
import re
from typing import Any, Dict, Tuple

from toonmesh.viewer._assets import PAGE, script, text


def page(spec: str, blob: bytes, camera: Dict[str, Any], moves: Dict[str, float], size: Tuple[int, int],
         title: str) -> str:
    """A standalone HTML page that orbits the draft ``spec`` (the core's JSON) with its bytes
    ``blob`` from ``camera`` (see :func:`camera_state`): everything inlined, nothing fetched."""
    data = json.dumps({"spec": spec, "camera": camera, "moves": moves, "size": list(size)})
    # inside <script>: "</" would end the element
    parts = {
        "@TITLE@": html.escape(title),
        "@STYLE@": text("page.css"),
        "@DATA@": data.replace("</", "<\\/"),
        "@BLOB@": base64.b64encode(blob).decode("ascii"),
        "@SCRIPT@": script(PAGE).replace("</script", "<\\/script"),
    }
    return re.sub("|".join(parts), lambda m: parts[m.group(0)], text("page.html"))

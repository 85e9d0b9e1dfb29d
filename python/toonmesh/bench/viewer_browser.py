"""The viewer in a browser while the user drags: JupyterLab and headless Chromium (Playwright), the
bunny at 512x512 with ink (outlines "both"), a 2-second drag with mouse events at 60 Hz.

    python -m toonmesh.bench viewer_browser [--quick]

Rows, measured in one run:

- the viewer's drafts drawn in the browser (WebGL2, toonmesh's own shaders in GLSL ES 3.00);
- the same viewer with the kernel drawing the drafts (how the viewer drew them before);
- a plain banded WebGL2 program drawing the same mesh on the same page's browser, written here
  as the yardstick (the most a program of this browser can draw), its draws paced as the
  viewer's (one per animation frame with a move).

Each row: the frames shown per second during the drag, the share of the plain program's rate, the
median delay from a pointer event to the frame that shows it (the drafts and the plain program),
and the time from the release to the exact frame (the viewer). Headless Chromium draws WebGL2
through SwiftShader on the CPU: on a machine with a GPU the browser draws at the display's rate.
"""

from __future__ import annotations

import base64
import shutil
import statistics
import tempfile
import time
from pathlib import Path
from typing import Any, Dict, List, Optional, Sequence

import numpy as np

from toonmesh.bench._timing import table

SIZE = 512
DRAG_SECONDS, HZ = 2.0, 60

CELL = (
    "import toonmesh as tm\n"
    "from toonmesh.data import bunny\n"
    "V, F = bunny()\n"
    "class KernelDrafts(tm.Viewer):\n"
    "    _browser_drafts = False\n"
    f"v = tm.Viewer(V, F, outlines='both', width={SIZE}, height={SIZE})\n"
    f"k = KernelDrafts(V, F, outlines='both', width={SIZE}, height={SIZE})\n"
    "display(v, k)"
)

# Records, in the page, when each frame is shown and when the pointer is released and the exact
# frame follows (the viewers' data-frames-shown and data-exact).
_WATCH = """(i) => {
  const root = document.querySelectorAll('.toonmesh-viewer')[i];
  const w = window.__watch = { shown: [], up: null, exact: null };
  new MutationObserver(() => {
    const n = +root.dataset.framesShown, now = performance.now();
    if (n !== w.last) { w.last = n; w.shown.push(now); }
    if (w.up !== null && w.exact === null && root.dataset.exact === '1' && root.dataset.busy === '0') w.exact = now;
  }).observe(root, { attributes: true });
  root.addEventListener('pointerup', () => { w.up = performance.now(); }, true);
}"""

# The yardstick: the mesh drawn by a banded program written here, on a canvas over the viewers'
# page (the same page, so that the browser composites as much for each), one draw per animation
# frame with a move, counted as the viewer counts its frames.
_PLAIN = """([size, positions, normals, faces]) => {
const canvas = document.createElement('canvas');
canvas.width = canvas.height = size;
canvas.style.cssText = `position: fixed; left: 0; top: 0; z-index: 10000; width: ${size}px; height: ${size}px`;
document.body.appendChild(canvas);
const gl = canvas.getContext('webgl2', { antialias: false });
const bytes = (s) => Uint8Array.from(atob(s), (c) => c.charCodeAt(0)).buffer;
const P = new Float32Array(bytes(positions)), N = new Float32Array(bytes(normals));
const I = new Uint32Array(bytes(faces));
const vs = `#version 300 es
layout(location = 0) in vec3 p; layout(location = 1) in vec3 n;
uniform mat4 mvp; uniform mat3 nm; out vec3 vn;
void main() { vn = nm * n; gl_Position = mvp * vec4(p, 1.0); }`;
const fs = `#version 300 es
precision highp float; in vec3 vn; out vec4 color;
void main() {
  float d = max(dot(normalize(vn), normalize(vec3(0.3, 0.5, 1.0))), 0.0);
  float b = d > 0.7 ? 1.0 : d > 0.3 ? 0.7 : 0.4;
  color = vec4(vec3(0.95, 0.55, 0.25) * b, 1.0);
}`;
function sh(t, s) { const x = gl.createShader(t); gl.shaderSource(x, s); gl.compileShader(x); return x; }
const prog = gl.createProgram();
gl.attachShader(prog, sh(gl.VERTEX_SHADER, vs)); gl.attachShader(prog, sh(gl.FRAGMENT_SHADER, fs));
gl.linkProgram(prog); gl.useProgram(prog);
for (const [loc, data] of [[0, P], [1, N]]) {
  gl.bindBuffer(gl.ARRAY_BUFFER, gl.createBuffer()); gl.bufferData(gl.ARRAY_BUFFER, data, gl.STATIC_DRAW);
  gl.enableVertexAttribArray(loc); gl.vertexAttribPointer(loc, 3, gl.FLOAT, false, 0, 0);
}
gl.bindBuffer(gl.ELEMENT_ARRAY_BUFFER, gl.createBuffer()); gl.bufferData(gl.ELEMENT_ARRAY_BUFFER, I, gl.STATIC_DRAW);
gl.enable(gl.DEPTH_TEST);
let yaw = 0, pitch = 0.3, wanted = false, lastEvent = 0;
const w = window.__watch = { shown: [], delays: [] };
function draw() {
  wanted = false;
  const cy = Math.cos(yaw), sy = Math.sin(yaw), cp = Math.cos(pitch), sp = Math.sin(pitch);
  const r = [cy, sy * sp, -sy * cp, 0, cp, sp, sy, -cy * sp, cy * cp];  // column-major rotation
  // perspective (GL's depth) of the mesh 3 units in front of the eye, turned by r
  const f = 1 / Math.tan(0.35), n = 1, far = 5, A = (far + n) / (n - far), B = 2 * far * n / (n - far);
  const mvp = new Float32Array(16);
  for (let c = 0; c < 3; c++) {
    mvp[c * 4] = f * r[c * 3]; mvp[c * 4 + 1] = f * r[c * 3 + 1];
    mvp[c * 4 + 2] = A * r[c * 3 + 2]; mvp[c * 4 + 3] = -r[c * 3 + 2];
  }
  mvp[14] = -3 * A + B; mvp[15] = 3;
  gl.uniformMatrix4fv(gl.getUniformLocation(prog, 'mvp'), false, mvp);
  gl.uniformMatrix3fv(gl.getUniformLocation(prog, 'nm'), false, new Float32Array(r));
  gl.clearColor(1, 1, 1, 1); gl.clear(gl.COLOR_BUFFER_BIT | gl.DEPTH_BUFFER_BIT);
  gl.drawElements(gl.TRIANGLES, I.length, gl.UNSIGNED_INT, 0);
  const now = performance.now();
  w.shown.push(now);
  if (lastEvent) { const since = lastEvent; lastEvent = 0; requestAnimationFrame(() => w.delays.push(performance.now() - since)); }
}
let drag = null;
canvas.addEventListener('pointerdown', (e) => { drag = [e.clientX, e.clientY]; canvas.setPointerCapture(e.pointerId); });
canvas.addEventListener('pointermove', (e) => {
  if (!drag) return;
  yaw += (e.clientX - drag[0]) * Math.PI / size; pitch += (e.clientY - drag[1]) * Math.PI / size;
  drag = [e.clientX, e.clientY];
  if (!lastEvent) lastEvent = e.timeStamp;
  if (!wanted) { wanted = true; requestAnimationFrame(draw); }
});
canvas.addEventListener('pointerup', () => { drag = null; });
draw();
}
"""


def _plain_arguments(V: np.ndarray, F: np.ndarray) -> List[Any]:
    """The yardstick's mesh: centred and scaled into the unit sphere, smooth normals, base64."""
    P = (V - (V.min(0) + V.max(0)) / 2).astype(np.float32)
    P /= np.linalg.norm(P, axis=1).max()
    N = np.zeros_like(P)
    tri = P[F]
    fn = np.cross(tri[:, 1] - tri[:, 0], tri[:, 2] - tri[:, 0])
    for k in range(3):
        np.add.at(N, F[:, k], fn)
    N /= np.maximum(np.linalg.norm(N, axis=1, keepdims=True), 1e-12)
    b64 = lambda a: base64.b64encode(np.ascontiguousarray(a).tobytes()).decode("ascii")  # noqa: E731
    return [SIZE, b64(P), b64(N.astype(np.float32)), b64(F.astype(np.uint32))]


def _drag(page: Any, x: float, y: float) -> float:
    """A drag of DRAG_SECONDS from (x, y) with a mouse event every 1/HZ s, to the right and a
    little down; returns the page's time at the first move (ms)."""
    page.mouse.move(x, y)
    page.mouse.down()
    start = page.evaluate("performance.now()")
    t0 = time.perf_counter()
    count = int(DRAG_SECONDS * HZ)
    for i in range(1, count + 1):
        wait = t0 + i / HZ - time.perf_counter()
        if wait > 0:
            time.sleep(wait)
        page.mouse.move(x + 150 * np.sin(np.pi * i / count), y + 20 * i / count)
    page.mouse.up()
    return float(start)


def _rate(shown: List[float], start: float) -> float:
    during = [t for t in shown if start <= t <= start + DRAG_SECONDS * 1000]
    return len(during) / DRAG_SECONDS


def _viewer_row(page: Any, i: int) -> Dict[str, Optional[float]]:
    root = page.locator(".toonmesh-viewer").nth(i)
    root.scroll_into_view_if_needed()
    box = root.locator("img").bounding_box()
    page.evaluate(_WATCH, i)
    start = _drag(page, box["x"] + box["width"] / 2 - 75, box["y"] + box["height"] / 2)
    page.wait_for_function("window.__watch.exact !== null", timeout=30_000)
    w = page.evaluate("window.__watch")
    delays = root.evaluate("r => r.toonmeshEventDelays || []")
    scale = root.get_attribute("data-draft-scale")
    return {"fps": _rate(w["shown"], start), "delay": statistics.median(delays) if delays else None,
            "exact": w["exact"] - w["up"], "scale": None if scale is None else float(scale)}


def main(quick: bool = False, repeat: int = 3, extra: Sequence[str] = ()) -> None:
    from playwright.sync_api import sync_playwright

    from toonmesh.bench._lab import jupyter_lab, open_notebook, write_notebook
    from toonmesh.data import bunny

    chromium = shutil.which("chromium") or shutil.which("chromium-browser")
    if chromium is None:
        raise RuntimeError("the viewer_browser benchmark needs Chromium (scripts/system-deps.sh --test)")
    V, F = bunny()
    rows: List[Sequence[Any]] = []
    with tempfile.TemporaryDirectory() as tmp, jupyter_lab(Path(tmp)) as url, sync_playwright() as p:
        write_notebook(Path(tmp) / "work" / "bench.ipynb", [CELL])
        browser = p.chromium.launch(executable_path=chromium, args=["--no-sandbox"])
        try:
            page = browser.new_page(viewport={"width": 1400, "height": 1300})
            cells = open_notebook(page, url, "bench.ipynb")
            cells.first.locator(".jp-InputPrompt").click()
            page.keyboard.press("Shift+Enter")
            page.wait_for_function("document.querySelectorAll('.toonmesh-viewer[data-frame]').length === 2 && "
                                   "document.querySelector('.toonmesh-viewer').dataset.draft === 'webgl'",
                                   timeout=60_000)
            page.wait_for_timeout(1000)
            browser_drafts = _viewer_row(page, 0)
            page.wait_for_timeout(500)
            kernel_drafts = _viewer_row(page, 1)
            page.evaluate(_PLAIN, _plain_arguments(V, F))
            page.wait_for_timeout(500)
            start = _drag(page, SIZE / 2 - 75, SIZE / 2)
            w = page.evaluate("window.__watch")
            plain_row = {"fps": _rate(w["shown"], start), "delay": statistics.median(w["delays"]), "exact": None,
                         "scale": 1.0}
        finally:
            browser.close()
    base = plain_row["fps"] or float("nan")
    fmt = lambda x, unit="": "-" if x is None else f"{x:.0f}{unit}"  # noqa: E731
    for label, r in (("viewer, drafts in the browser (WebGL2)", browser_drafts),
                     ("viewer, drafts by the kernel", kernel_drafts),
                     ("plain banded WebGL2 program", plain_row)):
        size = "-" if r["scale"] is None else f"{round(SIZE * r['scale'])}"
        rows.append((label, size, round(r["fps"] or 0.0, 1), f"{100 * (r['fps'] or 0.0) / base:.0f}%",
                     fmt(r["delay"], " ms"), fmt(r["exact"], " ms")))
    title = (f"The viewer during a {DRAG_SECONDS:g} s drag at {HZ} Hz: the bunny ({len(F):,} faces) at "
             f"{SIZE}x{SIZE} with ink, JupyterLab in headless Chromium")
    print(table(("view", "drawn at", "fps", "of plain", "event to frame (median)", "release to exact"), rows, title))
    ratio = (browser_drafts["fps"] or 0.0) / max(kernel_drafts["fps"] or 0.0, 1e-9)
    print(f"browser drafts / kernel drafts: {ratio:.1f}x")


if __name__ == "__main__":
    main()

// The standalone page's own controller (Viewer.to_html): orbit, pan and zoom with the viewer's
// moves, one draft a frame.
const data = JSON.parse(document.getElementById("toonmesh-data").textContent);
const blob = Uint8Array.from(atob(document.getElementById("toonmesh-blob").textContent), (c) => c.charCodeAt(0)).buffer;
const root = document.querySelector(".toonmesh-viewer");
const canvas = root.querySelector("canvas");
const [width, height] = data.size;
canvas.style.width = width + "px"; canvas.style.height = height + "px";
const home = draftCamera(data.camera);
let cam = draftCamera(home), draft = null, wanted = false, moving = false, settle = null;
const pacer = draftPacer(data.moves.drag_scale);
const TITLE = "drag to orbit, shift-drag to pan, wheel or pinch to zoom, two fingers to pan, double-click for the first view; ";
function failed(why) {
  draft = null;
  root.dataset.error = why;
  root.title = "WebGL2 drafts failed: " + why;
}
function load() {
  try {
    draft = createDraft(canvas, JSON.parse(data.spec), blob);
    delete root.dataset.error;
    root.title = TITLE + "drafts drawn in WebGL2 from toonmesh's shaders; " + draftNote(draft.leftToExact);
  } catch (e) {
    failed(String(e.message || e));
  }
  if (window.toonmeshDraft) window.toonmeshDraft.renderer = draft;
}
load();
// a lost WebGL context: nothing drawn until the browser gives it back, then the renderer anew
draftContextWatch(canvas, () => failed("the WebGL context was lost"), () => { load(); ask(); });
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

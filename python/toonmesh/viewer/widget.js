// Shows the kernel's frames in an <img> under a toolbar; sends drags, wheel turns, double-clicks
// and toolbar clicks as numbered views. Flow control: one view is in flight at a time; the
// moves made meanwhile are merged into the next one, sent when the kernel answers (a frame or an
// error carrying the view's number). A frame made for an older view than the one shown is
// dropped. "exact" (render full size) follows once the pointer has stopped for SETTLE_MS or is
// released. The root element's data-frames-shown counts the frames shown, data-exact is "1"
// while a full-size frame is shown ("0" for a draft), data-busy "1" while a full-size frame is
// on its way, data-dropped counts stale frames dropped, data-views-sent the views sent.
// While a WebGL2 draft renderer runs (draft.js: the core's shaders in GLSL ES), drags are drawn
// here, one draft per animation frame, and the moves go to the kernel only with the exact frame
// asked for when the pointer stops (data-draft "webgl"); otherwise (no WebGL2, a program that
// fails) the kernel draws the drafts as before (data-draft "kernel"), and the tooltip says why.
const SETTLE_MS = 150;
const SPIN_PX = 2;  // auto-rotate: a drag of this many pixels a frame
const ANSWER_TIMEOUT_MS = 10000;  // a view never answered (a kernel restarted) stops blocking
const AXES = ["+x", "-x", "+y", "-y", "+z", "-z"];
const BORDER = "1px solid #c8c8c8", FOCUSED = "1px solid #1a73e8";
// A removed view tells the kernel this much later, so that a view drawn again at once (a cell
// moved) is counted before the old one goes and the viewer is not let go in between.
const GONE_DELAY_MS = 500;

function render({ model, el }) {
  const root = document.createElement("div");
  root.className = "toonmesh-viewer";
  root.tabIndex = 0;  // focus: the wheel zooms only when the view has it
  root.setAttribute("data-jp-suppress-context-menu", "");  // JupyterLab's menu stays off the view
  root.setAttribute("data-lm-suppress-shortcuts", "");  // keys pressed here do not run notebook commands
  Object.assign(root.dataset, { framesShown: "0", exact: "0", busy: "0", dropped: "0", viewsSent: "0", draft: "kernel",
                                spinning: "0" });
  root.style.border = BORDER;  // the rest of the look: widget.css
  root.style.boxShadow = "none";
  const bar = document.createElement("div");
  bar.className = "toonmesh-toolbar";
  function button(cls, label, title, onclick) {
    const b = document.createElement("button");
    b.type = "button";
    b.className = "toonmesh-button " + cls;
    b.textContent = label;
    b.title = title;
    b.addEventListener("click", (e) => { e.preventDefault(); onclick(b); });
    bar.appendChild(b);
    return b;
  }
  const stage = document.createElement("div");
  stage.className = "toonmesh-stage";
  const img = document.createElement("img");
  img.draggable = false;
  img.alt = "toonmesh viewer";
  img.className = "toonmesh-frame";
  const note = document.createElement("div");
  note.className = "toonmesh-note";
  const busy = document.createElement("div");
  busy.className = "toonmesh-busy";
  busy.title = "the full-size frame is on its way";
  const canvas = document.createElement("canvas");
  canvas.className = "toonmesh-draft";
  // the orientation triad, turned with each draft and frame; a label views from its axis
  const triad = createTriad((axis) => add({ event: "axis", axis }, true));
  const partsPanel = document.createElement("div");
  partsPanel.className = "toonmesh-parts";
  stage.append(img, canvas, note, busy, triad.element, partsPanel);

  // -- drafts drawn here ----------------------------------------------------------------------
  let draft = null, cam = null, drawWanted = false, lastEvent = 0, pacer = null;
  const eventDelays = [];
  const KERNEL_DRAFTS = "drag: drafts rendered by the kernel";
  function loadDraft() {
    draft = null;
    const spec = model.get("_draft_spec");
    if (!spec) return;
    try {
      const parsed = JSON.parse(spec);
      if (parsed.error) throw new Error(parsed.error);
      const data = model.get("_draft_data");
      const blob = data.buffer.slice(data.byteOffset, data.byteOffset + data.byteLength);
      draft = createDraft(canvas, parsed, blob);
      pacer = null;
      root.dataset.draft = "webgl";
      root.title = "drag: drafts drawn here in WebGL2 from toonmesh's shaders; " + draftNote(draft.leftToExact);
    } catch (e) {
      draft = null;
      root.dataset.draft = "kernel";
      root.title = KERNEL_DRAFTS + " (WebGL2 drafts failed: " + (e.message || e) + ")";
    }
  }
  function drawDraft() {
    drawWanted = false;
    if (!draft || !cam) return;
    const [w, h] = model.get("_size");  // layout pixels
    canvas.style.width = w + "px";
    canvas.style.height = h + "px";
    if (!pacer) pacer = draftPacer(model.get("_moves").drag_scale);
    // drawn smaller while moving, as the kernel's drafts, at the kernel frames' pixel ratio
    const s = pacer.scale(), r = model.get("_layout").ratio * s;
    draft.draw(cam, Math.max(1, Math.round(w * r)), Math.max(1, Math.round(h * r)), r);
    pacer.shown(performance.now(), !!drag);
    canvas.style.visibility = "visible";
    img.style.opacity = "0";  // not composited under the draft (opacity keeps its pointer events)
    root.dataset.exact = "0";
    if (root.dataset.draftScale !== s.toFixed(3)) root.dataset.draftScale = s.toFixed(3);
    if (lastEvent) {  // the delay from the oldest move it shows to the next animation frame (on screen)
      const since = lastEvent;
      lastEvent = 0;
      requestAnimationFrame(() => {
        eventDelays.push(Math.round(performance.now() - since));
        if (eventDelays.length > 200) eventDelays.shift();
      });
    }
    shown();
  }
  function moveDraft(step) {
    if (!cam) cam = draftCamera(model.get("_camera"));
    draftStep(cam, step, model.get("_size")[1], model.get("_moves"));
    triad.update(cam);
    if (!drawWanted) { drawWanted = true; requestAnimationFrame(drawDraft); }
  }
  // the delays of the last 200 drafts (ms), read by the benchmark and tests
  Object.defineProperty(root, "toonmeshEventDelays", { get: () => eventDelays.slice() });
  Object.defineProperty(root, "toonmeshDraft", { get: () => draft });  // its pixels(), for tests
  model.on("change:_draft_spec", loadDraft);
  // a lost WebGL context: the kernel draws the drafts until the browser gives it back
  draftContextWatch(canvas, () => {
    draft = null;
    cam = null;  // the kernel's camera, where the next move starts
    canvas.style.visibility = "hidden";
    img.style.opacity = "1";
    root.dataset.draft = "kernel";
    root.title = KERNEL_DRAFTS + " (the WebGL context was lost)";
  }, loadDraft);
  model.on("change:_moves", () => { pacer = null; });  // a new drag_scale paces the next drafts
  loadDraft();

  // -- flow control ---------------------------------------------------------------------------
  let nextId = 1, inflight = 0, sentAt = 0, pending = null, scheduled = false, exactWanted = 0;
  let shownViewId = 0, lastAnswers = -1, latency = null, inflightTimer = null;
  function send() {
    scheduled = false;
    if (inflight || !pending || (draft && !pending.exact)) return;  // moves drawn here wait for the exact frame
    const id = Math.max(nextId, model.get("_view_id") + 1);
    nextId = id + 1;
    if (pending.exact) exactWanted = id;
    model.send({ event: "view", id, steps: pending.steps, exact: pending.exact });
    root.dataset.viewsSent = String(+root.dataset.viewsSent + 1);
    pending = null;
    inflight = id;
    sentAt = performance.now();
    clearTimeout(inflightTimer);
    inflightTimer = setTimeout(() => { inflight = 0; schedule(); }, ANSWER_TIMEOUT_MS);
  }
  function schedule() {
    if (draft && pending && !pending.exact) return;  // moves drawn here go with the exact frame
    if (!scheduled && pending && !inflight) { scheduled = true; requestAnimationFrame(send); }
  }
  function add(step, exact) {
    if (draft && step && "dx" in step) moveDraft(step);
    else if (step && step.event !== "size") { cam = null; stopSpin(); }  // home, an axis, framing: the kernel's camera follows
    if (!pending) pending = { steps: [], exact: false };
    if (step && step.event === "size") pending.steps = pending.steps.filter((s) => s.event !== "size");  // the newest size
    const last = pending.steps[pending.steps.length - 1];
    // consecutive moves of one kind merge (zooms only at one cursor: then they add up exactly)
    const same = step && last && last.event === step.event && "dx" in step && last.x === step.x && last.y === step.y;
    if (same) { last.dx += step.dx; last.dy += step.dy; }
    else if (step) pending.steps.push(step);
    pending.exact = exact;
    if (exact) setBusy(true);
    schedule();
  }
  function setBusy(on) {
    root.dataset.busy = on ? "1" : "0";
    busy.style.visibility = on ? "visible" : "hidden";
  }

  // -- frames ---------------------------------------------------------------------------------
  let url = null, exactFrame = null;
  const metas = new Map();
  const shownAt = [];
  let statsAt = 0;
  function answer() {
    const answers = model.get("_answers");
    if (answers === lastAnswers) return;
    lastAnswers = answers;
    const viewId = model.get("_view_id");
    if (inflight && viewId >= inflight) {
      latency = performance.now() - sentAt;
      inflight = 0;
      clearTimeout(inflightTimer);
      schedule();
    }
    note.textContent = model.get("_error");
    const data = model.get("_frame");
    if (model.get("_error") || !data || data.byteLength === 0) {
      if (exactWanted && viewId >= exactWanted && !(pending && pending.exact)) setBusy(false);
      return;
    }
    if (viewId < shownViewId) {  // made for an older view than the one shown: dropped
      root.dataset.dropped = String(+root.dataset.dropped + 1);
      return;
    }
    shownViewId = viewId;
    const format = model.get("_format");
    const blob = new Blob([data], { type: "image/" + format });
    const next = URL.createObjectURL(blob);
    const [w, h] = model.get("_size");
    metas.set(next, { id: model.get("_frame_id"), viewId, exact: model.get("_exact"), blob, format, camera: model.get("_camera") });
    img.src = next;
    img.style.width = w + "px";
    img.style.height = h + "px";
  }
  img.addEventListener("load", () => {
    const meta = metas.get(img.src);
    if (!meta) return;
    metas.delete(img.src);
    if (url && url !== img.src) URL.revokeObjectURL(url);
    url = img.src;
    for (const old of metas.keys()) { URL.revokeObjectURL(old); metas.delete(old); }  // superseded before shown
    root.dataset.frame = String(meta.id);
    root.dataset.exact = meta.exact ? "1" : "0";
    if (meta.camera && meta.camera.eye) triad.update(meta.camera);  // the camera of the frame shown
    canvas.style.visibility = "hidden";
    img.style.opacity = "1";
    if (meta.exact) {
      exactFrame = meta;
      if (meta.viewId >= exactWanted && !(pending && pending.exact)) setBusy(false);
      if (!pending && !drag) cam = draftCamera(meta.camera);  // the kernel's view, until the next move
    }
    shown();
  });
  function shown() {
    root.dataset.framesShown = String(+root.dataset.framesShown + 1);
    const now = performance.now();
    shownAt.push(now);
    while (shownAt.length && shownAt[0] < now - 1000) shownAt.shift();
    if (now - statsAt < 250) return;  // the readout four times a second
    statsAt = now;
    const text = shownAt.length + " fps" + (latency === null ? "" : " \u00b7 " + Math.round(latency) + " ms");
    if (stats.textContent !== text) stats.textContent = text;
  }
  model.on("change:_answers", answer);
  answer();

  // -- toolbar --------------------------------------------------------------------------------
  button("toonmesh-home", "\u2302", "home: the first view", () => add({ event: "home" }, true));
  for (const axis of AXES) {
    const b = button("toonmesh-axis", axis, "view from " + axis, () => add({ event: "axis", axis }, true));
    b.dataset.axis = axis;
  }
  // perspective / orthographic: the kernel switches the camera keeping the framing
  const projection = button("toonmesh-projection", "", "", () => {
    const ortho = !!model.get("_camera").orthographic;
    add({ event: "projection", projection: ortho ? "perspective" : "orthographic" }, true);
  });
  function showProjection() {
    const ortho = !!model.get("_camera").orthographic;
    projection.textContent = ortho ? "ortho" : "persp";
    projection.title = (ortho ? "orthographic" : "perspective") + " projection (click for "
      + (ortho ? "perspective" : "orthographic") + ")";
    projection.dataset.projection = ortho ? "orthographic" : "perspective";
  }
  // the parts list (a scene of several meshes): a checkbox a part shows or hides it
  const partsButton = button("toonmesh-parts-button", "parts \u25be", "show or hide the scene's parts", () => {
    partsPanel.classList.toggle("toonmesh-open");
    partsButton.classList.toggle("toonmesh-on", partsPanel.classList.contains("toonmesh-open"));
  });
  function showParts() {
    const { names, visible } = model.get("_parts");
    partsButton.style.display = names.length > 1 ? "" : "none";
    if (partsPanel.childElementCount !== names.length) {
      partsPanel.replaceChildren(...names.map((name, part) => {
        const label = document.createElement("label");
        const box = document.createElement("input");
        box.type = "checkbox";
        box.dataset.part = String(part);
        box.addEventListener("change", () => add({ event: "part", part, visible: box.checked }, true));
        label.append(box, " " + name);
        return label;
      }));
    }
    partsPanel.querySelectorAll("input").forEach((box, i) => { box.checked = !!visible[i]; });
  }
  model.on("change:_camera", showProjection);
  model.on("change:_parts", showParts);
  showProjection();
  showParts();
  if (model.get("_camera").eye) triad.update(model.get("_camera"));
  button("toonmesh-screenshot", "\u2913 PNG", "download the current full-size frame as PNG", screenshot);
  const full = button("toonmesh-fullscreen", "full", "full screen (again to leave)", () => {
    if (document.fullscreenElement === root) document.exitFullscreen();
    else if (root.requestFullscreen) root.requestFullscreen().catch(() => {});
  });
  // auto-rotate: the view turns about its up by SPIN_PX of a drag a frame, until clicked again,
  // dragged or sent elsewhere
  let spinning = false;
  const spinButton = button("toonmesh-spin", "\u27f3", "turn about the view's up (again to stop)", () => {
    if (spinning) stopSpin();
    else { spinning = true; root.dataset.spinning = "1"; spinButton.style.fontWeight = "bold"; requestAnimationFrame(spin); }
  });
  function spin() {
    if (!spinning) return;
    queue({ event: "orbit", dx: SPIN_PX, dy: 0 });
    requestAnimationFrame(spin);
  }
  function stopSpin() {
    if (!spinning) return;
    spinning = false;
    root.dataset.spinning = "0";
    spinButton.style.fontWeight = "";
  }
  const stats = document.createElement("span");
  stats.className = "toonmesh-stats";
  stats.title = "frames shown in the last second \u00b7 the last view's time to the kernel's answer";
  bar.appendChild(stats);
  function screenshot() {
    const f = exactFrame;
    if (!f) return;
    const save = (blob) => {
      const a = document.createElement("a");
      a.href = URL.createObjectURL(blob);
      a.download = "toonmesh-" + f.id + ".png";
      document.body.appendChild(a);
      a.click();
      a.remove();
      setTimeout(() => URL.revokeObjectURL(a.href), 10000);
    };
    if (f.format === "png") { save(f.blob); return; }  // the kernel's own PNG, byte for byte
    createImageBitmap(f.blob).then((bitmap) => {
      const canvas = document.createElement("canvas");
      canvas.width = bitmap.width;
      canvas.height = bitmap.height;
      canvas.getContext("2d").drawImage(bitmap, 0, 0);
      canvas.toBlob(save, "image/png");
    });
  }
  root.append(bar, stage);
  el.appendChild(root);

  // -- size -----------------------------------------------------------------------------------
  // The kernel renders the view at the cell's width (where no width was given: _layout.fit),
  // at the screen's pixel ratio (where none was given: _layout.follow_screen), and filling the
  // screen while full screen; this reports them when they change.
  let sizeTimer = null, sentSize = "", sentFull = false;
  function reportSize() {
    clearTimeout(sizeTimer);
    const layout = model.get("_layout"), [w, h] = model.get("_size");
    const isFull = document.fullscreenElement === root;
    const border = root.offsetWidth - root.clientWidth;  // the root's own border, both sides
    const full = isFull ? [Math.floor(window.innerWidth) - border, Math.floor(window.innerHeight - bar.offsetHeight) - border] : null;
    const available = Math.floor(el.getBoundingClientRect().width) - border;
    if (!isFull && available <= 0) return;  // not laid out (a hidden output)
    const width = layout.fit ? available : null;
    const ratio = layout.follow_screen ? (window.devicePixelRatio || 1) : null;
    const shown = full ? full[0] === w && full[1] === h : !sentFull && (width === null || width === w);
    const key = JSON.stringify([width, ratio, full]);
    if ((shown && (ratio === null || ratio === layout.ratio)) || key === sentSize) return;
    sentSize = key;
    sentFull = isFull;
    add({ event: "size", width, ratio, full }, true);
  }
  const laterSize = () => { clearTimeout(sizeTimer); sizeTimer = setTimeout(reportSize, 100); };
  function fitStyle() {  // a fitted view takes the row's free width (beside the controls too)
    const fit = model.get("_layout").fit;
    el.style.flex = fit ? "1 1 0" : "";
    el.style.minWidth = fit ? "0" : "";
  }
  const resizes = new ResizeObserver(laterSize);
  resizes.observe(el);
  window.addEventListener("resize", laterSize);  // a zoom changes the pixel ratio
  document.addEventListener("fullscreenchange", laterSize);
  model.on("change:_layout", () => { fitStyle(); laterSize(); });
  fitStyle();

  // -- pointer --------------------------------------------------------------------------------
  let drag = null, settleTimer = null;
  function queue(step) {  // a move; the exact frame follows once the moves stop
    add(step, false);
    clearTimeout(settleTimer);
    settleTimer = setTimeout(settle, SETTLE_MS);
  }
  function settle() { clearTimeout(settleTimer); add(null, true); }
  function down() {
    root.focus({ preventScroll: true });
    stopSpin();
    drag = true;
    img.style.cursor = "grabbing";
  }
  function step(s, e) {
    if (draft && !lastEvent) lastEvent = e.timeStamp;  // the oldest move the next draft shows
    queue(s);
  }
  function up() {
    drag = null;
    img.style.cursor = "grab";
    settle();
  }
  function wheel(e) {
    if (!root.contains(document.activeElement)) return;  // not focused: the notebook scrolls
    e.preventDefault();
    step({ event: "zoom", dx: 0, dy: e.deltaY, ...draftCursor(e, img) }, e);  // toward the cursor
  }
  function dblclick(e) { e.preventDefault(); add({ event: "frame" }, true); }
  function menu(e) { e.preventDefault(); }  // right-drag pans
  const focus = () => { root.style.border = FOCUSED; root.style.boxShadow = "0 0 0 1px #1a73e8"; };
  const blur = () => { root.style.border = BORDER; root.style.boxShadow = "none"; };
  // one pointer orbits (shift or the right button pans), two pinch to zoom and move to pan
  draftGestures(img, () => model.get("_moves"), step, down, up);
  stage.addEventListener("wheel", wheel, { passive: false });
  img.addEventListener("dblclick", dblclick);
  root.addEventListener("contextmenu", menu);
  root.addEventListener("focus", focus);
  root.addEventListener("blur", blur);
  // Escape gives the keys back to the page (in JupyterLab, command mode: the notebook's keys)
  function release() {
    if (!root.contains(document.activeElement)) return;
    let holder = root.parentElement;  // the nearest focusable element around the view (a cell)
    while (holder && !(holder.tabIndex >= 0 || holder.hasAttribute("tabindex"))) holder = holder.parentElement;
    if (holder) holder.focus({ preventScroll: true });
    else document.activeElement.blur();
  }
  root.addEventListener("keydown", (e) => { if (e.key === "Escape") { e.preventDefault(); release(); } });

  // the kernel holds the viewer while a view of it is on the page (a viewer displayed from a
  // function keeps drawing) and lets it go when the last is removed (output cleared, cell re-run)
  const viewToken = Math.random().toString(36).slice(2) + "-" + Date.now().toString(36);
  model.send({ event: "shown", view: viewToken });
  return () => {
    setTimeout(() => { try { model.send({ event: "gone", view: viewToken }); } catch (e) { /* the model closed */ } },
               GONE_DELAY_MS);
    resizes.disconnect();
    window.removeEventListener("resize", laterSize);
    document.removeEventListener("fullscreenchange", laterSize);
    clearTimeout(sizeTimer);
    clearTimeout(settleTimer);
    clearTimeout(inflightTimer);
    if (document.fullscreenElement === root) document.exitFullscreen();
    if (url) URL.revokeObjectURL(url);
    for (const old of metas.keys()) URL.revokeObjectURL(old);
  };
}

export default { render };

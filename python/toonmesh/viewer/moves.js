// The viewer's camera moves and pointer gestures, for the widget and the standalone page alike:
// the camera as toonmesh.viewer's _View holds it, moved as the kernel's viewer moves it (the
// constants come from the kernel: Viewer._moves).

// The camera a draft is drawn from: as toonmesh.viewer's _View holds it.
function draftCamera(c) {
  return { eye: c.eye.slice(), target: c.target.slice(), up: c.up.slice(), orthographic: !!c.orthographic,
           fov_y: c.fov_y, height: c.height };
}

const v3 = {
  sub: (a, b) => [a[0] - b[0], a[1] - b[1], a[2] - b[2]],
  add: (a, b) => [a[0] + b[0], a[1] + b[1], a[2] + b[2]],
  mul: (a, s) => [a[0] * s, a[1] * s, a[2] * s],
  dot: (a, b) => a[0] * b[0] + a[1] * b[1] + a[2] * b[2],
  cross: (a, b) => [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]],
  len: (a) => Math.hypot(a[0], a[1], a[2]),
  unit: (a) => { const n = Math.hypot(a[0], a[1], a[2]); return n > 0 ? [a[0] / n, a[1] / n, a[2] / n] : a; },
};

// `v` turned by `angle` about the unit `axis` (Rodrigues).
function draftRotate(v, axis, angle) {
  const c = Math.cos(angle), s = Math.sin(angle);
  return v3.add(v3.add(v3.mul(v, c), v3.mul(v3.cross(axis, v), s)), v3.mul(axis, v3.dot(axis, v) * (1 - c)));
}

// The viewer's moves, as toonmesh.viewer._View makes them (the constants come from the kernel).
function draftOrbit(cam, dx, dy, pixelsHigh, k) {
  const up = v3.unit(cam.up);
  const perPixel = k.orbit_per_height / pixelsHigh;
  const offset = draftRotate(v3.sub(cam.eye, cam.target), up, -dx * perPixel);
  const radius = v3.len(offset);
  const along = v3.dot(offset, up);
  let level = v3.sub(offset, v3.mul(up, along));
  if (v3.len(level) === 0) level = v3.cross(up, Math.abs(up[0]) < 0.9 ? [1, 0, 0] : [0, 0, 1]);
  let polar = Math.acos(Math.min(1, Math.max(-1, along / radius)));
  polar = Math.min(Math.PI - k.pole_margin, Math.max(k.pole_margin, polar - dy * perPixel));
  cam.eye = v3.add(cam.target, v3.mul(v3.add(v3.mul(up, Math.cos(polar)), v3.mul(v3.unit(level), Math.sin(polar))), radius));
}

function draftBasis(cam) {
  const f = v3.unit(v3.sub(cam.target, cam.eye));
  const s = v3.unit(v3.cross(f, v3.unit(cam.up)));
  return [f, s, v3.cross(s, f)];
}

function draftPan(cam, dx, dy, pixelsHigh) {
  const [, right, up] = draftBasis(cam);
  const perPixel = cam.orthographic ? cam.height / pixelsHigh
    : 2 * v3.len(v3.sub(cam.target, cam.eye)) * Math.tan(cam.fov_y * Math.PI / 360) / pixelsHigh;
  const step = v3.mul(v3.add(v3.mul(right, -dx), v3.mul(up, dy)), perPixel);
  cam.eye = v3.add(cam.eye, step);
  cam.target = v3.add(cam.target, step);
}

// A zoom toward the cursor at (x, y) pixels from the view's centre: the point under it at the
// target's depth stays under it (a pan after the zoom, as the kernel's viewer does).
function draftZoom(cam, wheel, x, y, pixelsHigh, k) {
  const factor = Math.min(k.max_zoom, Math.max(1 / k.max_zoom, Math.exp(-k.wheel_zoom * wheel)));
  if (cam.orthographic) cam.height /= factor;
  else cam.eye = v3.add(cam.target, v3.mul(v3.sub(cam.eye, cam.target), 1 / factor));
  if (x || y) draftPan(cam, -x * (factor - 1), -y * (factor - 1), pixelsHigh);
}

// The pointer event `e`'s offset from the centre of `el` in whole pixels (where a zoom goes
// toward: the kernel's viewer takes it so).
function draftCursor(e, el) {
  const r = el.getBoundingClientRect();
  return { x: Math.round(e.clientX - r.left - r.width / 2), y: Math.round(e.clientY - r.top - r.height / 2) };
}

// Pointer gestures on `el` as the viewer's steps ({event, dx, dy}, as `draftStep` and the
// kernel take them): one pointer drags (orbit; shift or the right button pans), two pointers
// pinch (a zoom, in the wheel's units: `k().wheel_zoom`) and move together (a pan of their
// midpoint). `on(step, e)` takes each step; `down(e)` and `up(e)` the first pointer down and the
// last one up. Lifting one finger of two ends the pinch; the other then does nothing.
function draftGestures(el, k, on, down, up) {
  const pointers = new Map();
  let drag = null, pinch = null;
  const pair = () => {
    const [a, b] = [...pointers.values()];
    return { d: Math.hypot(a.x - b.x, a.y - b.y), x: (a.x + b.x) / 2, y: (a.y + b.y) / 2 };
  };
  el.addEventListener("pointerdown", (e) => {
    pointers.set(e.pointerId, { x: e.clientX, y: e.clientY });
    try { el.setPointerCapture(e.pointerId); } catch (_) { /* a pointer already gone */ }
    e.preventDefault();
    if (pointers.size === 1) {
      drag = (e.shiftKey || e.button === 2) ? "pan" : "orbit";
      down(e);
    } else if (pointers.size === 2) {
      drag = null;
      pinch = pair();
    }
  });
  el.addEventListener("pointermove", (e) => {
    const p = pointers.get(e.pointerId);
    if (!p) return;
    const dx = e.clientX - p.x, dy = e.clientY - p.y;
    p.x = e.clientX; p.y = e.clientY;
    if (pinch && pointers.size === 2) {
      const now = pair(), wheel = k().wheel_zoom;
      if (wheel && pinch.d > 0 && now.d > 0 && now.d !== pinch.d) on({ event: "zoom", dx: 0, dy: -Math.log(now.d / pinch.d) / wheel }, e);
      if (now.x !== pinch.x || now.y !== pinch.y) on({ event: "pan", dx: now.x - pinch.x, dy: now.y - pinch.y }, e);
      pinch = now;
    } else if (drag && (dx || dy)) {
      on({ event: drag, dx, dy }, e);
    }
  });
  const lift = (e) => {
    if (!pointers.delete(e.pointerId)) return;
    drag = null;
    pinch = null;
    if (pointers.size === 0) up(e);
  };
  el.addEventListener("pointerup", lift);
  el.addEventListener("pointercancel", lift);
}

// A step as the kernel's viewer takes it ({event, dx, dy}).
function draftStep(cam, step, pixelsHigh, k) {
  if (step.event === "orbit") draftOrbit(cam, step.dx, step.dy, pixelsHigh, k);
  else if (step.event === "pan") draftPan(cam, step.dx, step.dy, pixelsHigh);
  else if (step.event === "zoom") draftZoom(cam, step.dy, step.x || 0, step.y || 0, pixelsHigh, k);
}

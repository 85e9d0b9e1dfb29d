// The viewer_browser benchmark's yardstick (an arrow function, evaluated by Playwright with the
// mesh as base64): the mesh drawn by a banded program written here, on a canvas over the
// viewers' page (the same page, so that the browser composites as much for each), one draw per
// animation frame with a move, counted as the viewer counts its frames (window.__watch).
([size, positions, normals, faces]) => {
const canvas = document.createElement('canvas');
canvas.className = 'bench-plain';
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

// Draft frames in WebGL2 from the core's own shaders (toonmesh's render::draft): the GLSL, the
// uniform bytes and where each field lies in them, and the meshes' buffers all come from the
// core. This file is plumbing only: GL calls, and the camera's matrices from its eye, target and
// up (as the kernel's viewer moves them). No shading rule is written here.

// Column-major 4x4 product a * b.
function mat4Mul(a, b) {
  const o = new Float64Array(16);
  for (let c = 0; c < 4; c++) for (let r = 0; r < 4; r++) {
    let x = 0;
    for (let i = 0; i < 4; i++) x += a[i * 4 + r] * b[c * 4 + i];
    o[c * 4 + r] = x;
  }
  return o;
}

// The inverse transpose of the 3x3 part of column-major `m`, in a 4x4 (column-major).
function normalMatrix(m) {
  const a = (r, c) => m[c * 4 + r];
  const c00 = a(1, 1) * a(2, 2) - a(1, 2) * a(2, 1), c01 = a(1, 2) * a(2, 0) - a(1, 0) * a(2, 2), c02 = a(1, 0) * a(2, 1) - a(1, 1) * a(2, 0);
  const c10 = a(0, 2) * a(2, 1) - a(0, 1) * a(2, 2), c11 = a(0, 0) * a(2, 2) - a(0, 2) * a(2, 0), c12 = a(0, 1) * a(2, 0) - a(0, 0) * a(2, 1);
  const c20 = a(0, 1) * a(1, 2) - a(0, 2) * a(1, 1), c21 = a(0, 2) * a(1, 0) - a(0, 0) * a(1, 2), c22 = a(0, 0) * a(1, 1) - a(0, 1) * a(1, 0);
  const det = a(0, 0) * c00 + a(0, 1) * c01 + a(0, 2) * c02;
  // inverse = cofactor^T / det, so its transpose = cofactor / det: entry (r, c) = c_rc / det
  const o = new Float64Array(16);
  const cof = [[c00, c01, c02], [c10, c11, c12], [c20, c21, c22]];
  for (let r = 0; r < 3; r++) for (let c = 0; c < 3; c++) o[c * 4 + r] = cof[r][c] / det;
  o[15] = 1;
  return o;
}

// World -> view (the eye at the origin looking down -z), column-major, and its rotation rows.
function lookAt(cam) {
  const [f, s, u] = draftBasis(cam);
  const e = cam.eye;
  const rows = [[s[0], s[1], s[2], -v3.dot(s, e)], [u[0], u[1], u[2], -v3.dot(u, e)],
                [-f[0], -f[1], -f[2], v3.dot(f, e)], [0, 0, 0, 1]];
  const m = new Float64Array(16);
  for (let r = 0; r < 4; r++) for (let c = 0; c < 4; c++) m[c * 4 + r] = rows[r][c];
  return m;
}

// View -> clip with depth in [0, 1] (the core's convention; the translated vertex stages map it
// to GL's), column-major.
function projection(cam, aspect, near, far, scale) {
  const m = new Float64Array(16);
  const [n, f] = [near / scale, far / scale];
  if (cam.orthographic) {
    const h = cam.height / 2 / scale;
    m[0] = 1 / (h * aspect); m[5] = 1 / h; m[10] = 1 / (n - f); m[14] = n / (n - f); m[15] = 1;
  } else {
    const t = 1 / Math.tan(cam.fov_y * Math.PI / 360);
    m[0] = t / aspect; m[5] = t; m[10] = f / (n - f); m[14] = n * (f / (n - f)); m[11] = -1;
  }
  return m;
}

// A draft renderer on `canvas` for the core's draft (`spec`, parsed JSON) and its bytes
// (`blob`, an ArrayBuffer). Throws where WebGL2 or a program fails.
function createDraft(canvas, spec, blob) {
  // the canvas only shows each draft (`pixels` reads the draft's own target): the browser need
  // not keep a copy of its drawing buffer
  const gl = canvas.getContext("webgl2", { antialias: false, depth: false, preserveDrawingBuffer: false });
  if (!gl) throw new Error("WebGL2 is not available");
  // An sRGB canvas takes the colour target's bytes by a blit; without one (older browsers) they
  // are read back and copied into a plain texture first (slower: the read waits for the draw).
  const srgbCanvas = typeof gl.drawingBufferStorage === "function";
  let canvasSize = null;
  const bytes = (span) => new Uint8Array(blob, span.offset, span.length);

  function shader(type, source, name) {
    const s = gl.createShader(type);
    gl.shaderSource(s, source);
    gl.compileShader(s);
    if (!gl.getShaderParameter(s, gl.COMPILE_STATUS)) throw new Error(name + ": " + gl.getShaderInfoLog(s));
    return s;
  }
  const programs = spec.programs.map((p) => {
    const prog = gl.createProgram();
    gl.attachShader(prog, shader(gl.VERTEX_SHADER, p.vertex.source, p.name + " (vertex)"));
    gl.attachShader(prog, shader(gl.FRAGMENT_SHADER, p.fragment.source, p.name + " (fragment)"));
    gl.linkProgram(prog);
    if (!gl.getProgramParameter(prog, gl.LINK_STATUS)) throw new Error(p.name + ": " + gl.getProgramInfoLog(prog));
    gl.useProgram(prog);
    for (const stage of [p.vertex, p.fragment]) {
      for (const b of stage.blocks) {
        const i = gl.getUniformBlockIndex(prog, b.name);
        if (i !== gl.INVALID_INDEX) gl.uniformBlockBinding(prog, i, b.group);  // a UBO binding per WGSL group
      }
      for (const t of stage.textures) {
        const loc = gl.getUniformLocation(prog, t.name);
        if (loc) gl.uniform1i(loc, t.group);  // a texture unit per WGSL group (one texture each)
      }
    }
    return prog;
  });

  const field = (fields, name) => {
    const f = fields.find((x) => x.name === name);
    if (!f) throw new Error("the draft has no uniform field " + name);
    return f;
  };
  const frameBytes = bytes(spec.frame).slice();
  const frameF32 = new Float32Array(frameBytes.buffer);
  const at = (name) => field(spec.frame_fields, name).offset / 4;
  const F = { proj: at("view.proj"), size: at("view.size"), footprint: at("view.footprint"), near: at("view.near") };
  const footprint = [frameF32[F.footprint], frameF32[F.footprint + 1]];
  // the widths in output pixels (the ink's), drawn as wide on screen at a smaller draft size
  const widths = spec.pixel_widths.map((offset) => [offset / 4, frameF32[offset / 4]]);
  // each light's position as an unturned view sees it
  const lights = spec.lights.map((l) => ({ world: l.world, at: l.position / 4,
    q: Array.from(frameF32.subarray(l.position / 4, l.position / 4 + 4)) }));
  const frameUbo = gl.createBuffer();
  gl.bindBuffer(gl.UNIFORM_BUFFER, frameUbo);
  gl.bufferData(gl.UNIFORM_BUFFER, frameBytes, gl.DYNAMIC_DRAW);
  const D = { modelView: field(spec.draw_fields, "mesh.model_view").offset / 4,
              normal: field(spec.draw_fields, "mesh.normal_matrix").offset / 4 };

  const wraps = { repeat: gl.REPEAT, clamp: gl.CLAMP_TO_EDGE, mirror: gl.MIRRORED_REPEAT };
  // the attributes of vertex buffer `vb` (the core's layout) from `data`, one record a vertex
  function attributes(vb, data) {
    const b = gl.createBuffer();
    gl.bindBuffer(gl.ARRAY_BUFFER, b);
    gl.bufferData(gl.ARRAY_BUFFER, data, gl.STATIC_DRAW);
    for (const a of vb.attributes) {
      gl.enableVertexAttribArray(a.location);
      if (a.integer) gl.vertexAttribIPointer(a.location, a.components, gl.UNSIGNED_INT, vb.stride, a.offset);
      else gl.vertexAttribPointer(a.location, a.components, gl.FLOAT, false, vb.stride, a.offset);
    }
  }
  // a vertex array of a mesh's buffers (its own or its coarse copy's: the same layouts)
  function vertexArray(m, own) {
    const vao = gl.createVertexArray();
    gl.bindVertexArray(vao);
    // by the stage part that reads each
    const buffers = Object.assign({ position: own.vertices, albedo: own.albedo }, own.derived || {});
    for (const vb of m.vertex_buffers) attributes(vb, bytes(buffers[vb.buffer]));
    if (own.indices) {
      const ib = gl.createBuffer();
      gl.bindBuffer(gl.ELEMENT_ARRAY_BUFFER, ib);
      gl.bufferData(gl.ELEMENT_ARRAY_BUFFER, bytes(own.indices), gl.STATIC_DRAW);
    }
    gl.bindVertexArray(null);
    return { vao, indexed: !!own.indices, count: own.count };
  }
  const meshes = spec.meshes.map((m) => {
    const full = vertexArray(m, m);
    // the coarse copy: for drafts drawn smaller than the exact frame (far fewer vertices and
    // triangles, where one would cover less than a pixel)
    const coarse = m.coarse ? vertexArray(m, m.coarse) : full;
    const draw = bytes(m.draw).slice();
    const ubo = gl.createBuffer();
    gl.bindBuffer(gl.UNIFORM_BUFFER, ubo);
    gl.bufferData(gl.UNIFORM_BUFFER, draw, gl.DYNAMIC_DRAW);
    let texture = null;
    if (m.texture) {
      const t = m.texture;
      texture = gl.createTexture();
      gl.bindTexture(gl.TEXTURE_2D, texture);
      gl.pixelStorei(gl.UNPACK_ALIGNMENT, 1);
      gl.texImage2D(gl.TEXTURE_2D, 0, gl.SRGB8_ALPHA8, t.width, t.height, 0, gl.RGBA, gl.UNSIGNED_BYTE, bytes(t.texels));
      const linear = t.filter === "linear";
      if (linear) gl.generateMipmap(gl.TEXTURE_2D);
      gl.texParameteri(gl.TEXTURE_2D, gl.TEXTURE_MIN_FILTER, linear ? gl.LINEAR_MIPMAP_LINEAR : gl.NEAREST);
      gl.texParameteri(gl.TEXTURE_2D, gl.TEXTURE_MAG_FILTER, linear ? gl.LINEAR : gl.NEAREST);
      gl.texParameteri(gl.TEXTURE_2D, gl.TEXTURE_WRAP_S, wraps[t.wrap]);
      gl.texParameteri(gl.TEXTURE_2D, gl.TEXTURE_WRAP_T, wraps[t.wrap]);
    }
    const f32 = new Float32Array(draw.buffer);
    const lengths = spec.draw_pixel_lengths.map((offset) => [offset / 4, f32[offset / 4]]);  // the dither's cell...
    // the mesh-space lines (line records, faces for smooth contours): each record a strip of 4
    // vertices, given to all 4 (the vertex stages take the corner from the vertex index's low
    // bits) and drawn as two triangles, not as instances: a browser drawing on the CPU pays for
    // every instance as for a draw
    const strips = (records, n, layout) => {
      const s = layout.stride;
      const data = new Uint8Array(n * 4 * s), index = new Uint32Array(n * 6);
      for (let i = 0; i < n; i++) {
        const r = records.subarray(i * s, (i + 1) * s);
        for (let c = 0; c < 4; c++) data.set(r, (4 * i + c) * s);
        const k = 6 * i, v = 4 * i;
        index[k] = v; index[k + 1] = v + 1; index[k + 2] = v + 2;
        index[k + 3] = v + 2; index[k + 4] = v + 1; index[k + 5] = v + 3;
      }
      const vao = gl.createVertexArray();
      gl.bindVertexArray(vao);
      attributes(layout, data);
      gl.bindBuffer(gl.ELEMENT_ARRAY_BUFFER, gl.createBuffer());
      gl.bufferData(gl.ELEMENT_ARRAY_BUFFER, index, gl.STATIC_DRAW);
      gl.bindVertexArray(null);
      return { vao, count: 6 * n };
    };
    // smooth contours: each face's record (its corners' positions and normals, where
    // `contour_buffer` puts them) gathered from a mesh's vertices (in `contour_vertices`' layout)
    const contourStrips = (vertices, faces, n) => {
      const from = spec.contour_vertices, to = spec.contour_buffer;
      const at = (layout, location) => layout.attributes.find((a) => a.location === location).offset / 4;
      const [p, nrm] = [at(from, 0), at(from, 1)], slots = [0, 1, 2, 3, 4, 5].map((l) => at(to, l));
      const v = new Float32Array(blob, vertices.offset, vertices.length / 4), f = new Uint32Array(blob, faces.offset, 3 * n);
      const [vs, rs] = [from.stride / 4, to.stride / 4];
      const records = new Float32Array(n * rs);
      for (let i = 0; i < n; i++) for (let c = 0; c < 3; c++) {
        const k = f[3 * i + c] * vs;
        records.set(v.subarray(k + p, k + p + 3), i * rs + slots[c]);
        records.set(v.subarray(k + nrm, k + nrm + 3), i * rs + slots[3 + c]);
      }
      return strips(new Uint8Array(records.buffer), n, to);
    };
    const lines = {
      lines: m.lines ? strips(bytes(m.lines.instances), m.lines.count, spec.line_buffer) : null,
      contours: m.contours ? contourStrips(m.contours.vertices, m.contours.faces, m.contours.count) : null,
    };
    // the smooth contours drawn with the coarse copy (a coarser copy's)
    const coarseLines = { lines: lines.lines, contours: m.coarse && m.coarse.contours
      ? contourStrips(m.coarse.contours.vertices, m.coarse.contours.faces, m.coarse.contours.count) : lines.contours };
    return { spec: m, full, coarse, ubo, draw, f32, lengths, texture, lines, coarseLines, program: programs[m.program] };
  });
  const emptyVao = gl.createVertexArray();
  // the opaque meshes, then the glass in the order given
  const drawOrder = meshes.filter((m) => m.spec.opacity === null).concat(meshes.filter((m) => m.spec.opacity !== null));
  const coarseFaces = meshes.reduce((n, m) => n + m.coarse.count / 3, 0);
  let lastFaces = 0;  // the faces the last draft drew

  // the targets, made at the size drawn
  let size = null, targets = null;
  function texture(internal, format, type, w, h) {
    const t = gl.createTexture();
    gl.bindTexture(gl.TEXTURE_2D, t);
    gl.texStorage2D(gl.TEXTURE_2D, 1, internal, w, h);
    gl.texParameteri(gl.TEXTURE_2D, gl.TEXTURE_MIN_FILTER, gl.NEAREST);
    gl.texParameteri(gl.TEXTURE_2D, gl.TEXTURE_MAG_FILTER, gl.NEAREST);
    return t;
  }
  function fbo(attachments, depth) {
    const f = gl.createFramebuffer();
    gl.bindFramebuffer(gl.FRAMEBUFFER, f);
    attachments.forEach((t, i) => gl.framebufferTexture2D(gl.FRAMEBUFFER, gl.COLOR_ATTACHMENT0 + i, gl.TEXTURE_2D, t, 0));
    if (depth) gl.framebufferRenderbuffer(gl.FRAMEBUFFER, gl.DEPTH_ATTACHMENT, gl.RENDERBUFFER, depth);
    gl.drawBuffers(attachments.map((_, i) => gl.COLOR_ATTACHMENT0 + i));
    if (gl.checkFramebufferStatus(gl.FRAMEBUFFER) !== gl.FRAMEBUFFER_COMPLETE) throw new Error("an incomplete framebuffer");
    return f;
  }
  function free() {
    if (!targets) return;
    // unbound first: Chromium, deleting the framebuffer still bound for reading (the last
    // draft's blit source), loses track of the canvas's own, and shows it blank from then on
    gl.bindFramebuffer(gl.FRAMEBUFFER, null);
    for (const t of [targets.color, targets.geometry, targets.edgeBits, targets.present]) if (t) gl.deleteTexture(t);
    for (const f of [targets.shade, targets.edgeBitsFbo, targets.ink, targets.presentFbo]) if (f) gl.deleteFramebuffer(f);
    gl.deleteRenderbuffer(targets.depth);
    if (targets.pbo) gl.deleteBuffer(targets.pbo);
    targets = null;
  }
  function resize(w, h) {
    if (size && size[0] === w && size[1] === h) return;
    free();
    size = [w, h];
    const color = texture(gl.SRGB8_ALPHA8, gl.RGBA, gl.UNSIGNED_BYTE, w, h);
    const geometry = spec.geometry_format ? texture(gl[spec.geometry_format], null, null, w, h) : null;
    const edgeBits = spec.edge_bits !== null ? texture(gl.R8UI, gl.RED_INTEGER, gl.UNSIGNED_BYTE, w, h) : null;
    const depth = gl.createRenderbuffer();
    gl.bindRenderbuffer(gl.RENDERBUFFER, depth);
    gl.renderbufferStorage(gl.RENDERBUFFER, gl.DEPTH_COMPONENT32F, w, h);
    const present = srgbCanvas ? null : texture(gl.RGBA8, gl.RGBA, gl.UNSIGNED_BYTE, w, h);
    let pbo = null;
    if (!srgbCanvas) {
      pbo = gl.createBuffer();
      gl.bindBuffer(gl.PIXEL_PACK_BUFFER, pbo);
      gl.bufferData(gl.PIXEL_PACK_BUFFER, w * h * 4, gl.STREAM_COPY);
      gl.bindBuffer(gl.PIXEL_PACK_BUFFER, null);
    }
    targets = {
      color, geometry, edgeBits, present, pbo, depth,
      shade: fbo(geometry ? [color, geometry] : [color], depth),
      edgeBitsFbo: edgeBits ? fbo([edgeBits]) : null,
      ink: fbo([color]),
      presentFbo: present ? fbo([present]) : null,
    };
  }

  // Draws the view `cam` at w x h pixels into the canvas, whose drawing buffer takes that size
  // (the page stretches it to the size it shows); `ratio`: its pixels per layout pixel (the
  // lengths the settings give in pixels are drawn that many pixels long; by default as the
  // kernel's frame of the same height would draw them).
  function draw(cam, w, h, ratio) {
    resize(w, h);
    const c = spec.camera;
    // the camera's matrices, in the core's normalised view space (view space / scale)
    const view = lookAt(cam);
    const scale = c.scale;
    const vn = view.map((x, i) => i % 4 === 3 ? x : x / scale);  // rows 0-2 divided
    // clip planes that enclose the scene's sphere
    const [f] = draftBasis(cam);
    const d = v3.dot(v3.sub(c.center, cam.eye), f);
    const far = Math.max(d + 2 * c.radius, c.radius * 1e-3);
    const near = cam.orthographic ? d - 2 * c.radius : Math.max(d - 2 * c.radius, far * 1e-3);
    frameF32.set(projection(cam, w / h, near, far, scale), F.proj);
    frameF32[F.size] = w; frameF32[F.size + 1] = h;
    const zoom = (c.height / h) * (cam.orthographic ? cam.height / c.fov_or_height : 1);
    frameF32[F.footprint] = footprint[0] * zoom; frameF32[F.footprint + 1] = footprint[1] * zoom;
    frameF32[F.near] = near / scale;
    const perWidth = ratio === undefined ? h / c.height : ratio / c.pixel_ratio;
    // a smaller draft keeps its lines: the ink at least the core's least width, in its pixels
    const least = spec.least_ink_width;
    for (const [i, width] of widths) frameF32[i] = Math.max(width * perWidth, Math.min(width, least));
    lights.forEach((l) => {
      let p = l.q.slice(0, 3);
      if (l.world) {
        const r = [0, 1, 2].map((row) => view[row] * p[0] + view[4 + row] * p[1] + view[8 + row] * p[2]);
        p = l.q[3] === 1 ? r.map((x, i) => x + vn[12 + i]) : r;
      }
      frameF32.set(p, l.at);
    });
    gl.bindBuffer(gl.UNIFORM_BUFFER, frameUbo);
    gl.bufferSubData(gl.UNIFORM_BUFFER, 0, frameBytes);
    gl.bindBufferBase(gl.UNIFORM_BUFFER, 0, frameUbo);

    // the shading pass: colour and, for the ink, the geometry target
    gl.bindFramebuffer(gl.FRAMEBUFFER, targets.shade);
    gl.viewport(0, 0, w, h);
    gl.disable(gl.BLEND);
    gl.enable(gl.DEPTH_TEST);
    gl.depthFunc(gl[spec.depth_compare]);
    gl.depthMask(true);
    gl.disable(gl.CULL_FACE);
    gl.frontFace(gl[spec.front_face]);
    gl.clearBufferfv(gl.COLOR, 0, spec.background);
    if (targets.geometry) gl.clearBufferuiv(gl.COLOR, 1, spec.geometry_clear);
    gl.clearBufferfv(gl.DEPTH, 0, [1]);
    // the coarse copies while they still have a face for every few pixels of this draft (one
    // drawn smaller than the frame they were made for: while the view moves)
    const smaller = coarseFaces * spec.pixels_per_coarse_face > w * h;
    lastFaces = 0;
    // opaque meshes first, then glass blended over them by its opacity (drawOrder), writing
    // neither depth nor the geometry target (the exact frame composites its layers in depth order)
    let blending = false;
    for (const m of drawOrder) {
      if (m.spec.opacity !== null && !blending) {
        blending = true;
        gl.enable(gl.BLEND);
        gl.blendFunc(gl.CONSTANT_ALPHA, gl.ONE_MINUS_CONSTANT_ALPHA);
        gl.depthMask(false);
        if (targets.geometry) gl.drawBuffers([gl.COLOR_ATTACHMENT0, gl.NONE]);
      }
      if (blending) gl.blendColor(0, 0, 0, m.spec.opacity);
      const mv = mat4Mul(vn, m.spec.model);
      m.f32.set(mv, D.modelView);
      m.f32.set(normalMatrix(mv), D.normal);
      for (const [i, length] of m.lengths) m.f32[i] = length * perWidth;
      gl.bindBuffer(gl.UNIFORM_BUFFER, m.ubo);
      gl.bufferSubData(gl.UNIFORM_BUFFER, 0, m.draw);
      gl.bindBufferBase(gl.UNIFORM_BUFFER, 1, m.ubo);
      gl.useProgram(m.program);
      if (m.texture) { gl.activeTexture(gl.TEXTURE3); gl.bindTexture(gl.TEXTURE_2D, m.texture); }
      const v = smaller ? m.coarse : m.full;
      lastFaces += v.count / 3;
      gl.bindVertexArray(v.vao);
      if (v.indexed) gl.drawElements(gl.TRIANGLES, v.count, gl.UNSIGNED_INT, 0);
      else gl.drawArrays(gl.TRIANGLES, 0, v.count);
    }
    if (blending) {
      gl.disable(gl.BLEND);
      gl.depthMask(true);
      if (targets.geometry) gl.drawBuffers([gl.COLOR_ATTACHMENT0, gl.COLOR_ATTACHMENT1]);
    }
    gl.disable(gl.DEPTH_TEST);
    gl.bindVertexArray(emptyVao);
    // the image-space ink: the edges between pixels, then the ink over the colour
    if (spec.edges !== null) {
      if (spec.edge_bits !== null) {
        gl.bindFramebuffer(gl.FRAMEBUFFER, targets.edgeBitsFbo);
        gl.clearBufferuiv(gl.COLOR, 0, [0, 0, 0, 0]);
        gl.useProgram(programs[spec.edge_bits]);
        gl.activeTexture(gl.TEXTURE1);
        gl.bindTexture(gl.TEXTURE_2D, targets.geometry);
        gl.drawArrays(gl.TRIANGLES, 0, 3);
      }
      gl.bindFramebuffer(gl.FRAMEBUFFER, targets.ink);
      gl.enable(gl.BLEND);
      gl.blendFunc(gl[spec.ink_blend[0]], gl[spec.ink_blend[1]]);  // the core's ink blending
      gl.useProgram(programs[spec.edges]);
      gl.activeTexture(gl.TEXTURE1);
      gl.bindTexture(gl.TEXTURE_2D, spec.edge_bits !== null ? targets.edgeBits : targets.geometry);
      gl.drawArrays(gl.TRIANGLES, 0, 3);
      gl.disable(gl.BLEND);
    }
    // the mesh-space lines over the colour, hidden against the geometry target's depth: the
    // lines, then the smooth contours
    for (const set of ["lines", "contours"]) {
      if (spec[set] === null) continue;
      gl.bindFramebuffer(gl.FRAMEBUFFER, targets.ink);
      gl.enable(gl.BLEND);
      gl.blendFunc(gl[spec.ink_blend[0]], gl[spec.ink_blend[1]]);
      gl.useProgram(programs[spec[set]]);
      gl.activeTexture(gl.TEXTURE2);
      gl.bindTexture(gl.TEXTURE_2D, targets.geometry);
      for (const m of meshes) {
        const drawn = (smaller ? m.coarseLines : m.lines)[set];
        if (!drawn) continue;
        gl.bindBufferBase(gl.UNIFORM_BUFFER, 1, m.ubo);  // its draw block, as the shading wrote it
        gl.bindVertexArray(drawn.vao);
        gl.drawElements(gl.TRIANGLES, drawn.count, gl.UNSIGNED_INT, 0);
      }
      gl.bindVertexArray(emptyVao);
      gl.disable(gl.BLEND);
    }
    if (!canvasSize || canvasSize[0] !== w || canvasSize[1] !== h) {
      canvasSize = [w, h];
      canvas.width = w;
      canvas.height = h;
      if (srgbCanvas) gl.drawingBufferStorage(gl.SRGB8_ALPHA8, w, h);
    }
    // the targets hold the rows top first (the translated stages flip y), the canvas bottom first
    const blit = () => gl.blitFramebuffer(0, 0, w, h, 0, h, w, 0, gl.COLOR_BUFFER_BIT, gl.NEAREST);
    gl.bindFramebuffer(gl.DRAW_FRAMEBUFFER, null);
    if (srgbCanvas) {  // sRGB to sRGB: the bytes as they are
      gl.bindFramebuffer(gl.READ_FRAMEBUFFER, targets.ink);
      blit();
      return;
    }
    // onto a plain canvas: the sRGB bytes as they are (read, copied into a plain texture, blitted)
    gl.bindFramebuffer(gl.READ_FRAMEBUFFER, targets.ink);
    gl.bindBuffer(gl.PIXEL_PACK_BUFFER, targets.pbo);
    gl.readPixels(0, 0, w, h, gl.RGBA, gl.UNSIGNED_BYTE, 0);
    gl.bindBuffer(gl.PIXEL_PACK_BUFFER, null);
    gl.bindBuffer(gl.PIXEL_UNPACK_BUFFER, targets.pbo);
    gl.bindTexture(gl.TEXTURE_2D, targets.present);
    gl.texSubImage2D(gl.TEXTURE_2D, 0, 0, 0, w, h, gl.RGBA, gl.UNSIGNED_BYTE, 0);
    gl.bindBuffer(gl.PIXEL_UNPACK_BUFFER, null);
    gl.bindFramebuffer(gl.READ_FRAMEBUFFER, targets.presentFbo);
    gl.bindFramebuffer(gl.DRAW_FRAMEBUFFER, null);
    blit();
  }

  // The last draft's pixels: RGBA8 (sRGB), rows top first.
  function pixels() {
    const [w, h] = size;
    const out = new Uint8Array(w * h * 4);
    gl.bindFramebuffer(gl.READ_FRAMEBUFFER, targets.ink);
    gl.readPixels(0, 0, w, h, gl.RGBA, gl.UNSIGNED_BYTE, out);
    return { width: w, height: h, data: out };
  }

  return { draw, pixels, leftToExact: spec.left_to_exact, gl, drawnFaces: () => lastFaces };
}

// Watches `canvas`'s WebGL context: `lost()` when the browser takes it away (the draft renderer
// on it is gone: draw as when WebGL2 fails), `restored()` when it gives it back (make the
// renderer again, on the same canvas).
function draftContextWatch(canvas, lost, restored) {
  canvas.addEventListener("webglcontextlost", (e) => { e.preventDefault(); lost(); });  // else never restored
  canvas.addEventListener("webglcontextrestored", () => restored());
}

// The size drafts are drawn at while the view moves, as a share of the full size: at most
// `most` (the viewer's drag_scale), less while drafts come slower than every TARGET_MS (40 a
// second; the browser may draw on the CPU: SwiftShader), so that the view keeps up with the
// pointer.
const DRAFT_TARGET_MS = 25, DRAFT_LEAST_SCALE = 0.25;
function draftPacer(most) {
  let scale = most, last = 0;
  return {
    scale: () => Math.min(most, Math.max(DRAFT_LEAST_SCALE, Math.round(scale * 16) / 16)),  // few sizes
    // a draft was shown at `now` (ms); `moving`: the one before was shown during the same move
    shown(now, moving) {
      if (moving && last) {
        const wanted = scale * Math.sqrt(DRAFT_TARGET_MS / Math.max(now - last, 1));
        scale = Math.min(most, Math.max(DRAFT_LEAST_SCALE, 0.5 * scale + 0.5 * wanted));
      }
      last = now;
    },
  };
}

// The tooltip's words for what the exact frame adds to a draft.
function draftNote(left) {
  return left.length ? "left to the exact frame: " + left.join(", ") : "the draft draws everything the exact frame does";
}

// The WebGL 2.0 side of shadowcheck's webgl:chromium backend. Evaluated once in about:blank; the
// worker (shadowcheck-webgl, job.rs) then calls shadowcheck.run(job) per batch. Everything a case
// needs is decided on the Rust side by the GL worker's own code (texture bytes, TexParameter list,
// es300 shader text, uniform values); this page only makes the WebGL calls, one pixel of an
// RGBA32F framebuffer per (case, path), and reads the pixels back once per job.
//
// A lost context (WebGL 1.0 §5.15.2, "The Context Lost Event", and §5.14.13, "Detecting context
// lost events", which WebGL 2.0 keeps: the calls then do nothing and getError reports
// CONTEXT_LOST_WEBGL once) draws nothing and reads nothing back, so run() and state() then answer
// {lost: why} instead of values: the worker never sends them.
globalThis.shadowcheck = (() => {
  const FB = 256;
  let gl = null;
  let fbo = null;
  let vao = null;
  const programs = new Map();
  // Why the context is lost, once seen: the webglcontextlost event, isContextLost(), or
  // CONTEXT_LOST_WEBGL from getError.
  let lost = null;
  const CONTEXT_LOST_WEBGL = 0x9242;

  // getError, noting a lost context.
  function err() {
    const e = gl.getError();
    if (e === CONTEXT_LOST_WEBGL && !lost) lost = "getError() returned CONTEXT_LOST_WEBGL";
    return e;
  }

  // Why the context is lost, or null.
  function lostNow() {
    if (!lost && gl && gl.isContextLost()) lost = "isContextLost() is true";
    return lost;
  }

  // Clears pending errors (none are left once the context is lost).
  function drain() {
    while (err() !== gl.NO_ERROR && !gl.isContextLost()) {}
  }

  // Test fault (SHADOWCHECK_WEBGL_TEST_FAULT=lose-context): WEBGL_lose_context's loseContext().
  function loseForTest() {
    const ext = gl.getExtension("WEBGL_lose_context");
    if (!ext) throw new Error("test fault lose-context: no WEBGL_lose_context");
    ext.loseContext();
  }

  const ERRORS = {
    0x0500: "GL_INVALID_ENUM",
    0x0501: "GL_INVALID_VALUE",
    0x0502: "GL_INVALID_OPERATION",
    0x0505: "GL_OUT_OF_MEMORY",
    0x0506: "GL_INVALID_FRAMEBUFFER_OPERATION",
    0x9242: "GL_CONTEXT_LOST_WEBGL",
  };
  const errorName = (e) => ERRORS[e] || "GL error 0x" + e.toString(16).toUpperCase();

  // Throws "<what> raised <error>" for a pending error, as the GL worker's texture::check does.
  function check(what) {
    const e = err();
    if (e !== gl.NO_ERROR) {
      drain();
      throw new Error(what + " raised " + errorName(e));
    }
  }

  function bytes(b64) {
    const s = atob(b64);
    const u8 = new Uint8Array(s.length);
    for (let i = 0; i < s.length; i++) u8[i] = s.charCodeAt(i);
    return u8;
  }

  function base64(u8) {
    let s = "";
    for (let i = 0; i < u8.length; i += 0x8000) {
      s += String.fromCharCode.apply(null, u8.subarray(i, i + 0x8000));
    }
    return btoa(s);
  }

  // The typed array WebGL 2.0 requires for a pixel type (WebGL 2.0 §3.7.6 table).
  function view(u8, type) {
    const buf = u8.buffer.slice(u8.byteOffset, u8.byteOffset + u8.byteLength);
    switch (type) {
      case gl.UNSIGNED_BYTE: return new Uint8Array(buf);
      case gl.UNSIGNED_SHORT:
      case gl.UNSIGNED_SHORT_4_4_4_4: return new Uint16Array(buf);
      case gl.UNSIGNED_INT:
      case gl.UNSIGNED_INT_24_8: return new Uint32Array(buf);
      case gl.FLOAT: return new Float32Array(buf);
      default: throw new Error("no typed array for pixel type 0x" + type.toString(16));
    }
  }

  function init() {
    const canvas = document.createElement("canvas");
    canvas.width = 1;
    canvas.height = 1;
    gl = canvas.getContext("webgl2", { antialias: false, depth: false, stencil: false });
    if (!gl) return { error: "no WebGL 2.0 context" };
    canvas.addEventListener("webglcontextlost", (ev) => {
      if (!lost) lost = "webglcontextlost event" + (ev.statusMessage ? ": " + ev.statusMessage : "");
    });
    const enabled = [];
    for (const e of ["EXT_color_buffer_float", "WEBGL_stencil_texturing", "WEBGL_debug_renderer_info"]) {
      if (gl.getExtension(e)) enabled.push(e);
    }
    if (!enabled.includes("EXT_color_buffer_float")) {
      return { error: "EXT_color_buffer_float not exposed: no RGBA32F render target to read results from" };
    }
    const color = gl.createTexture();
    gl.bindTexture(gl.TEXTURE_2D, color);
    gl.texImage2D(gl.TEXTURE_2D, 0, gl.RGBA32F, FB, FB, 0, gl.RGBA, gl.FLOAT, null);
    gl.texParameteri(gl.TEXTURE_2D, gl.TEXTURE_MIN_FILTER, gl.NEAREST);
    gl.texParameteri(gl.TEXTURE_2D, gl.TEXTURE_MAG_FILTER, gl.NEAREST);
    fbo = gl.createFramebuffer();
    gl.bindFramebuffer(gl.FRAMEBUFFER, fbo);
    gl.framebufferTexture2D(gl.FRAMEBUFFER, gl.COLOR_ATTACHMENT0, gl.TEXTURE_2D, color, 0);
    const status = gl.checkFramebufferStatus(gl.FRAMEBUFFER);
    if (status !== gl.FRAMEBUFFER_COMPLETE) {
      return { error: "RGBA32F framebuffer incomplete (status 0x" + status.toString(16) + ")" };
    }
    gl.bindTexture(gl.TEXTURE_2D, null);
    vao = gl.createVertexArray();
    gl.bindVertexArray(vao);
    const vbo = gl.createBuffer();
    gl.bindBuffer(gl.ARRAY_BUFFER, vbo);
    gl.bufferData(gl.ARRAY_BUFFER, new Float32Array([-1, -1, 3, -1, -1, 3]), gl.STATIC_DRAW);
    gl.vertexAttribPointer(0, 2, gl.FLOAT, false, 8, 0);
    gl.enableVertexAttribArray(0);
    gl.pixelStorei(gl.UNPACK_ALIGNMENT, 1);
    gl.pixelStorei(gl.PACK_ALIGNMENT, 1);
    gl.disable(gl.DITHER);
    check("framebuffer setup");
    if (lostNow()) return { error: "the WebGL context was lost at start (" + lost + ")" };
    const dbg = enabled.includes("WEBGL_debug_renderer_info") ? gl.getExtension("WEBGL_debug_renderer_info") : null;
    return {
      version: gl.getParameter(gl.VERSION),
      glsl: gl.getParameter(gl.SHADING_LANGUAGE_VERSION),
      renderer: dbg ? gl.getParameter(dbg.UNMASKED_RENDERER_WEBGL) : gl.getParameter(gl.RENDERER),
      vendor: dbg ? gl.getParameter(dbg.UNMASKED_VENDOR_WEBGL) : gl.getParameter(gl.VENDOR),
      extensions: gl.getSupportedExtensions(),
      enabled: enabled,
    };
  }

  function program(src) {
    const key = src[0] + "\u0000" + src[1];
    let p = programs.get(key);
    if (p) return p;
    const shader = (type, text) => {
      const s = gl.createShader(type);
      gl.shaderSource(s, text);
      gl.compileShader(s);
      if (!gl.getShaderParameter(s, gl.COMPILE_STATUS)) {
        throw new Error("shader compilation failed: " + gl.getShaderInfoLog(s));
      }
      return s;
    };
    const prog = gl.createProgram();
    gl.attachShader(prog, shader(gl.VERTEX_SHADER, src[0]));
    gl.attachShader(prog, shader(gl.FRAGMENT_SHADER, src[1]));
    gl.bindAttribLocation(prog, 0, "a_pos");
    // The case's unit in a program of several samplers (shaders/mod.rs, UNIT_ATTRIB).
    gl.bindAttribLocation(prog, 5, "a_unit");
    gl.linkProgram(prog);
    if (!gl.getProgramParameter(prog, gl.LINK_STATUS)) {
      throw new Error("program link failed: " + gl.getProgramInfoLog(prog));
    }
    const u = (n) => gl.getUniformLocation(prog, n);
    p = {
      prog,
      u_p: u("u_p"),
      u_x: u("u_x"),
      u_dx: u("u_dx"),
      u_dy: u("u_dy"),
      u_c: u("u_c"),
      u_o: u("u_o"),
    };
    gl.useProgram(prog);
    // One sampler `u_tex` on unit 0, or `u_tex0`, `u_tex1`, ... on units 0, 1, ... (units.rs).
    const t = u("u_tex");
    if (t !== null) gl.uniform1i(t, 0);
    for (let i = 0; ; i++) {
      const ti = u("u_tex" + i);
      if (ti === null) break;
      gl.uniform1i(ti, i);
    }
    programs.set(key, p);
    return p;
  }

  // Creates, uploads and parameterizes the texture of a group (texture.rs: create + set_state),
  // left bound to unit 0 (runJob unbinds it).
  function texture(t) {
    const tex = gl.createTexture();
    gl.activeTexture(gl.TEXTURE0);
    gl.bindTexture(t.target, tex);
    for (const l of t.levels) {
      const data = bytes(l.data);
      if (t.upload === "cube") {
        const face = l.width * l.height * l.bpt;
        for (let f = 0; f < 6; f++) {
          const part = data.subarray(f * face, (f + 1) * face);
          if (part.length !== face) throw new Error("cube level has fewer than 6 faces");
          gl.texImage2D(gl.TEXTURE_CUBE_MAP_POSITIVE_X + f, l.level, l.ifmt, l.width, l.height, 0, l.fmt, l.type, view(part, l.type));
        }
      } else if (t.upload === "3d") {
        gl.texImage3D(t.target, l.level, l.ifmt, l.width, l.height, l.layers, 0, l.fmt, l.type, view(data, l.type));
      } else {
        gl.texImage2D(t.target, l.level, l.ifmt, l.width, l.height, 0, l.fmt, l.type, view(data, l.type));
      }
    }
    check("texture upload (glTexImage*)");
    // getError is a synchronous round trip to the GPU process: one check for all the calls, and
    // only when that finds an error, the calls again one by one to name the one that raised it
    // (setting a parameter twice to the same value changes nothing).
    const setParams = (each) => {
      for (const p of t.params) {
        if (p.int !== undefined) gl.texParameteri(t.target, p.pname, p.int);
        else if (p.float !== undefined) gl.texParameterf(t.target, p.pname, Number(p.float));
        else throw new Error(p.call + ": WebGL 2.0 has no vector TexParameter");
        if (each) check(p.call);
      }
    };
    setParams(false);
    const e = err();
    if (e !== gl.NO_ERROR) {
      drain();
      setParams(true);
      throw new Error("glTexParameter* raised " + errorName(e));
    }
    return tex;
  }

  // A sampler object with the group's SamplerParameter calls (unitstate.rs: its state is used
  // instead of the texture's, ES 3.0 §3.8.2; bound to the group's unit by each bundle), or null
  // when the group has none.
  function sampler(t) {
    if (!t.sampler || t.sampler.length === 0) return null;
    const s = gl.createSampler();
    for (const p of t.sampler) {
      if (p.int !== undefined) gl.samplerParameteri(s, p.pname, p.int);
      else if (p.float !== undefined) gl.samplerParameterf(s, p.pname, Number(p.float));
      else throw new Error("sampler " + p.call + ": WebGL 2.0 has no vector SamplerParameter");
      check("glSamplerParameter for " + p.call);
    }
    return s;
  }

  // Binds (or, with `on` false, unbinds) the states of bundle `b`: group b.states[i]'s texture
  // and sampler object on unit i (units.rs); a group without objects leaves its unit empty.
  function bindBundle(b, objects, on) {
    b.states.forEach((g, unit) => {
      const o = objects[g];
      if (!o) return;
      gl.activeTexture(gl.TEXTURE0 + unit);
      gl.bindTexture(o.target, on ? o.tex : null);
      if (o.so) gl.bindSampler(unit, on ? o.so : null);
    });
    gl.activeTexture(gl.TEXTURE0);
  }

  function draw(d, src) {
    const p = program(src);
    const x = d.slot % FB;
    const y = Math.floor(d.slot / FB);
    // The slot's pixel, or the 2x2 quad holding it (per-fragment values, job.rs).
    gl.viewport(d.viewport[0], d.viewport[1], d.viewport[2], d.viewport[3]);
    gl.useProgram(p.prog);
    gl.vertexAttrib1f(5, d.unit);
    // Numbers, or "Infinity" / "-Infinity" / "NaN" (job.rs, Js).
    gl.uniform4fv(p.u_p, d.p.map(Number));
    gl.uniform1f(p.u_x, Number(d.x));
    gl.uniform4fv(p.u_dx, d.dx.map(Number));
    gl.uniform4fv(p.u_dy, d.dy.map(Number));
    gl.uniform2f(p.u_c, x + 0.5, y + 0.5);
    if (d.o) gl.uniform2i(p.u_o, d.o[0], d.o[1]);
    gl.bindVertexArray(vao);
    gl.drawArrays(gl.TRIANGLES, 0, 3);
  }

  // job: {programs: [[vs, fs]], slots, groups: [{cases: [i], texture: {...}}], bundles: [{states:
  // [group], draws: [{case, api, slot, program, unit, p, x, dx, dy, o?, viewport}]}]}. Answer: {pixels: base64
  // of slots x RGBA32F, errors: {case: message}}; a pixel no draw wrote stays -1. With a lost
  // context (before, during or after the job, an exception it caused included): {lost: why}.
  // opts.lose: the test fault, the context lost once the first bundle is drawn.
  // A promise: the answer once the GPU has carried the job out. A GPU process that dies while
  // drawing (ANGLE's Vulkan back end on lavapipe, sampling a colour texture with the compare mode
  // on: reports/README.md) leaves readPixels returning zeros and isContextLost() false; the loss
  // arrives later, as an event. So a fence is polled between tasks until it signals (the draws
  // ran) or the context is lost (the answer is then {lost}, never the zeros), for at most
  // SETTLE_MS. A signalled fence means the GPU process ran the job's commands; a loss that still
  // arrives later is the next job's answer ({lost}: the worker ends, naming that batch). Waiting a
  // fixed grace after every fence as well changed no verdict of the grid on the three back ends
  // and made each run about ten times longer.
  function run(job, opts) {
    let answer;
    try {
      answer = runJob(job, opts || {});
    } catch (e) {
      if (lostNow()) return Promise.resolve({ lost });
      throw e;
    }
    return settle(answer);
  }

  const SETTLE_MS = 5000;

  async function settle(answer) {
    if (lostNow() || answer.lost) return { lost: lost || answer.lost };
    const sync = gl.fenceSync(gl.SYNC_GPU_COMMANDS_COMPLETE, 0);
    gl.flush();
    const t0 = performance.now();
    while (sync && performance.now() - t0 < SETTLE_MS) {
      await new Promise((r) => setTimeout(r, 2));
      if (lostNow()) return { lost };
      const status = gl.getSyncParameter(sync, gl.SYNC_STATUS);
      if (status === gl.SIGNALED) break;
    }
    if (sync && !lostNow()) gl.deleteSync(sync);
    return lostNow() ? { lost } : answer;
  }

  function runJob(job, opts) {
    if (lostNow()) return { lost };
    const errors = {};
    gl.bindFramebuffer(gl.FRAMEBUFFER, fbo);
    gl.viewport(0, 0, FB, FB);
    gl.clearColor(-1, -1, -1, -1);
    gl.clear(gl.COLOR_BUFFER_BIT);
    // Every group's texture and sampler object first; each bundle then binds its own.
    const objects = job.groups.map((g) => {
      if (!g.texture) return null;
      drain();
      let tex;
      try {
        tex = texture(g.texture);
        gl.bindTexture(g.texture.target, null);
        return { tex, so: sampler(g.texture), target: g.texture.target };
      } catch (e) {
        for (const c of g.cases) errors[c] = e.message;
        if (tex) gl.deleteTexture(tex);
        return null;
      }
    });
    for (const b of job.bundles) {
      drain();
      bindBundle(b, objects, true);
      for (const d of b.draws) {
        if (errors[d.case] !== undefined) continue;
        try {
          draw(d, job.programs[d.program]);
        } catch (e) {
          errors[d.case] = d.api + ": " + e.message;
        }
      }
      try {
        check("drawing");
      } catch (e) {
        for (const d of b.draws) if (errors[d.case] === undefined) errors[d.case] = e.message;
      }
      bindBundle(b, objects, false);
      if (opts.lose) {
        opts.lose = false;
        loseForTest();
      }
    }
    for (const o of objects) {
      if (!o) continue;
      gl.deleteTexture(o.tex);
      if (o.so) gl.deleteSampler(o.so);
    }
    const rows = Math.max(1, Math.ceil(job.slots / FB));
    const px = new Float32Array(FB * rows * 4);
    gl.readPixels(0, 0, FB, rows, gl.RGBA, gl.FLOAT, px);
    check("glReadPixels");
    return { pixels: base64(new Uint8Array(px.buffer, 0, job.slots * 16)), errors };
  }

  // A state case (state.rs): the call on a fresh texture bound to unit 0, glGetError after it, and
  // (read_back) getTexParameter and glGetError after that; the GL worker's state.rs, in WebGL.
  function state(s, opts) {
    if (opts && opts.lose) loseForTest();
    if (lostNow()) return { lost };
    drain();
    const tex = gl.createTexture();
    gl.activeTexture(gl.TEXTURE0);
    gl.bindTexture(s.target, tex);
    const get = () => {
      const v = gl.getTexParameter(s.target, s.pname);
      if (typeof v === "boolean") return v ? 1 : 0;
      return typeof v === "number" ? v : null;
    };
    let error = 0;
    let value = null;
    let readError = 0;
    if (s.call === "initial") {
      value = get();
      error = err();
    } else {
      if (s.call === "int") gl.texParameteri(s.target, s.pname, Number(s.value));
      else gl.texParameterf(s.target, s.pname, Number(s.value));
      error = err();
      if (s.read_back) {
        drain();
        value = get();
        readError = err();
      }
    }
    gl.bindTexture(s.target, null);
    gl.deleteTexture(tex);
    drain();
    if (lostNow()) return { lost };
    return { error, value, read_error: readError };
  }

  return { init, run, state };
})();
"loaded";

// The WebGL 2.0 page's own part: the context (checked to be the instance's renderer), an RGBA32F
// colour target cleared to -1, the texture and its TexParameter calls, a sampler object where the
// case has one, the program, one draw into a 1x1 viewport, the read-back and the verdict. A GL
// error in setup is printed and no verdict is given.
const ERRORS = { 0x0500: "GL_INVALID_ENUM", 0x0501: "GL_INVALID_VALUE", 0x0502: "GL_INVALID_OPERATION",
  0x0505: "GL_OUT_OF_MEMORY", 0x0506: "GL_INVALID_FRAMEBUFFER_OPERATION", 0x9242: "GL_CONTEXT_LOST_WEBGL" };

function main() {
  const canvas = document.createElement("canvas");
  canvas.width = 1;
  canvas.height = 1;
  const gl = canvas.getContext("webgl2", { antialias: false, depth: false, stencil: false });
  if (!gl) throw new Error("no WebGL 2.0 context");
  const check = (what) => {
    const e = gl.getError();
    if (e !== gl.NO_ERROR) throw new Error(what + " raised " + (ERRORS[e] || "GL error 0x" + e.toString(16)));
  };
  // The extensions the worker's page enables.
  const colorFloat = gl.getExtension("EXT_color_buffer_float");
  gl.getExtension("WEBGL_stencil_texturing");
  const dbg = gl.getExtension("WEBGL_debug_renderer_info");
  const renderer = dbg ? gl.getParameter(dbg.UNMASKED_RENDERER_WEBGL) : gl.getParameter(gl.RENDERER);
  print("WEBGL_RENDERER: " + renderer);
  print("WEBGL_VERSION: " + gl.getParameter(gl.VERSION) + "; " + gl.getParameter(gl.SHADING_LANGUAGE_VERSION));
  print("BROWSER: " + navigator.userAgent);
  const lacking = RENDERER_WORDS.filter((w) => !renderer.toLowerCase().includes(w.toLowerCase()));
  if (lacking.length > 0) {
    throw new Error("the renderer is not " + INSTANCE + " (it lacks " + lacking.join(", ") + "): the browser fell back to another implementation");
  }
  if (!colorFloat) throw new Error("EXT_color_buffer_float not exposed: no RGBA32F render target to read the result from");

  // The colour target: RGBA32F (results are not quantized), cleared to -1, which no lookup returns.
  const color = gl.createTexture();
  gl.bindTexture(gl.TEXTURE_2D, color);
  gl.texImage2D(gl.TEXTURE_2D, 0, gl.RGBA32F, 1, 1, 0, gl.RGBA, gl.FLOAT, null);
  gl.texParameteri(gl.TEXTURE_2D, gl.TEXTURE_MIN_FILTER, gl.NEAREST);
  gl.texParameteri(gl.TEXTURE_2D, gl.TEXTURE_MAG_FILTER, gl.NEAREST);
  const fbo = gl.createFramebuffer();
  gl.bindFramebuffer(gl.FRAMEBUFFER, fbo);
  gl.framebufferTexture2D(gl.FRAMEBUFFER, gl.COLOR_ATTACHMENT0, gl.TEXTURE_2D, color, 0);
  if (gl.checkFramebufferStatus(gl.FRAMEBUFFER) !== gl.FRAMEBUFFER_COMPLETE) throw new Error("RGBA32F framebuffer incomplete");
  gl.bindTexture(gl.TEXTURE_2D, null);
  const vao = gl.createVertexArray();
  gl.bindVertexArray(vao);
  gl.bindBuffer(gl.ARRAY_BUFFER, gl.createBuffer());
  gl.bufferData(gl.ARRAY_BUFFER, new Float32Array([-1, -1, 3, -1, -1, 3]), gl.STATIC_DRAW);
  gl.vertexAttribPointer(0, 2, gl.FLOAT, false, 8, 0);
  gl.enableVertexAttribArray(0);
  gl.pixelStorei(gl.UNPACK_ALIGNMENT, 1);
  gl.pixelStorei(gl.PACK_ALIGNMENT, 1);
  gl.disable(gl.DITHER);
  gl.clearColor(-1, -1, -1, -1);
  gl.clear(gl.COLOR_BUFFER_BIT);
  check("framebuffer setup");

  // The texture, every level uploaded, then the TexParameter calls in the worker's order.
  const tex = gl.createTexture();
  gl.activeTexture(gl.TEXTURE0);
  gl.bindTexture(TEXTURE.target, tex);
  for (const l of LEVELS) {
    if (TEXTURE.upload === "cube") {
      const face = l.width * l.height * TEXTURE.bpt / l.data.BYTES_PER_ELEMENT;
      for (let f = 0; f < 6; f++) {
        gl.texImage2D(gl.TEXTURE_CUBE_MAP_POSITIVE_X + f, l.level, TEXTURE.ifmt, l.width, l.height, 0, TEXTURE.fmt, TEXTURE.type,
          l.data.subarray(f * face, (f + 1) * face));
      }
    } else if (TEXTURE.upload === "3d") {
      gl.texImage3D(TEXTURE.target, l.level, TEXTURE.ifmt, l.width, l.height, l.layers, 0, TEXTURE.fmt, TEXTURE.type, l.data);
    } else {
      gl.texImage2D(TEXTURE.target, l.level, TEXTURE.ifmt, l.width, l.height, 0, TEXTURE.fmt, TEXTURE.type, l.data);
    }
  }
  check("texture upload (texImage*)");
  for (const p of TEXTURE.params) {
    if (p.int !== undefined) gl.texParameteri(TEXTURE.target, p.pname, p.int);
    else gl.texParameterf(TEXTURE.target, p.pname, p.float);
    check(p.call);
  }
  if (TEXTURE.sampler.length > 0) {
    // A sampler object bound to unit 0: its state is used instead of the texture's (ES 3.0 §3.8.2).
    const so = gl.createSampler();
    for (const p of TEXTURE.sampler) {
      if (p.int !== undefined) gl.samplerParameteri(so, p.pname, p.int);
      else gl.samplerParameterf(so, p.pname, p.float);
      check("samplerParameter for " + p.call);
    }
    gl.bindSampler(0, so);
  }

  // The program and the draw.
  const shader = (type, text) => {
    const s = gl.createShader(type);
    gl.shaderSource(s, text);
    gl.compileShader(s);
    if (!gl.getShaderParameter(s, gl.COMPILE_STATUS)) throw new Error("shader compilation failed: " + gl.getShaderInfoLog(s));
    return s;
  };
  const prog = gl.createProgram();
  gl.attachShader(prog, shader(gl.VERTEX_SHADER, VS));
  gl.attachShader(prog, shader(gl.FRAGMENT_SHADER, FS));
  gl.bindAttribLocation(prog, 0, "a_pos");
  gl.linkProgram(prog);
  if (!gl.getProgramParameter(prog, gl.LINK_STATUS)) throw new Error("program link failed: " + gl.getProgramInfoLog(prog));
  gl.useProgram(prog);
  const u = (n) => gl.getUniformLocation(prog, n);
  gl.uniform1i(u("u_tex"), 0);
  gl.uniform4fv(u("u_p"), LOOKUP.p);
  gl.uniform1f(u("u_x"), LOOKUP.x);
  gl.uniform4fv(u("u_dx"), LOOKUP.dx);
  gl.uniform4fv(u("u_dy"), LOOKUP.dy);
  gl.uniform2f(u("u_c"), 0.5, 0.5);
  // One pixel, or the 2x2 pixel quad whose lower-left pixel is read where the values differ
  // between the fragments of the quad (the other three are discarded after their lookups).
  gl.viewport(LOOKUP.viewport[0], LOOKUP.viewport[1], LOOKUP.viewport[2], LOOKUP.viewport[3]);
  gl.drawArrays(gl.TRIANGLES, 0, 3);
  check("drawing");
  const px = new Float32Array(4);
  gl.readPixels(0, 0, 1, 1, gl.RGBA, gl.FLOAT, px);
  check("readPixels");
  judge([...px]);
}

try {
  main();
} catch (e) {
  print("setup failed: " + e.message);
} finally {
  console.log(END);
}

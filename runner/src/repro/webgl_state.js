// The fixed part of the WebGL state page: the context (checked to be the instance's renderer), the
// case's call on a fresh texture, getError, the read-back, and the verdict. Each line goes to the
// page and to the console (build.sh reads the browser's console log); END is the last line.
const out = document.getElementById("out");
const END = "shadowcheck-repro: end";
function print(s) {
  out.textContent += s + "\n";
  for (const line of s.split("\n")) console.log(line);
}

const ERRORS = { 0x0500: "GL_INVALID_ENUM", 0x0501: "GL_INVALID_VALUE", 0x0502: "GL_INVALID_OPERATION" };
// An error in the harness's words.
const errorText = (e) => (e === 0 ? "no error" : ERRORS[e] || "GL error 0x" + e.toString(16).toUpperCase().padStart(4, "0"));
// A value in the harness's words (a boolean TRUE/FALSE, an enum 0xNNNN, a float as JavaScript writes it).
function valueText(v) {
  if (STATE.kind === "b") return v ? "TRUE" : "FALSE";
  if (STATE.kind === "e") return "0x" + v.toString(16).toUpperCase().padStart(4, "0");
  return String(v);
}

function main() {
  const canvas = document.createElement("canvas");
  const gl = canvas.getContext("webgl2", { antialias: false, depth: false, stencil: false });
  if (!gl) throw new Error("no WebGL 2.0 context");
  // The extensions the worker's page enables.
  gl.getExtension("EXT_color_buffer_float");
  gl.getExtension("WEBGL_stencil_texturing");
  const dbg = gl.getExtension("WEBGL_debug_renderer_info");
  const renderer = dbg ? gl.getParameter(dbg.UNMASKED_RENDERER_WEBGL) : gl.getParameter(gl.RENDERER);
  print("WEBGL_RENDERER: " + renderer);
  print("WEBGL_VERSION: " + gl.getParameter(gl.VERSION));
  print("BROWSER: " + navigator.userAgent);
  const lacking = RENDERER_WORDS.filter((w) => !renderer.toLowerCase().includes(w.toLowerCase()));
  if (lacking.length > 0) {
    throw new Error("the renderer is not " + INSTANCE + " (it lacks " + lacking.join(", ") + "): the browser fell back to another implementation");
  }
  const listed = gl.getSupportedExtensions() || [];
  const exposed = EXPECT.filter((r) => r.extension !== null && listed.includes(r.extension)).map((r) => r.extension);
  print("extensions:" + exposed.map((x) => " " + x).join(""));
  const want = EXPECT.find((r) => r.extension !== null && exposed.includes(r.extension)) || EXPECT[EXPECT.length - 1];
  while (gl.getError() !== gl.NO_ERROR) {}

  const tex = gl.createTexture();
  gl.activeTexture(gl.TEXTURE0);
  gl.bindTexture(STATE.target, tex);
  if (gl.getError() !== gl.NO_ERROR) throw new Error("binding a fresh texture to the target");
  // getTexParameter: a boolean as 1 / 0, a number as it is, anything else (null) as no value.
  const get = () => {
    const v = gl.getTexParameter(STATE.target, STATE.pname);
    if (typeof v === "boolean") return v ? 1 : 0;
    return typeof v === "number" ? v : null;
  };
  let error = 0;
  let value = null;
  let readOk = false;
  if (STATE.call === "initial") {
    value = get();
    error = gl.getError();
    readOk = error === 0;
  } else {
    if (STATE.call === "int") gl.texParameteri(STATE.target, STATE.pname, STATE.value);
    else gl.texParameterf(STATE.target, STATE.pname, STATE.value);
    error = gl.getError();
    while (gl.getError() !== gl.NO_ERROR) {}
    if (STATE.read_back) {
      value = get();
      readOk = gl.getError() === 0;
    }
  }
  const hasValue = STATE.read_back && readOk && value !== null;
  if (STATE.kind === "f" && hasValue) value = Math.fround(value);
  print("test:      " + TEST);
  print("call:      " + (STATE.call === "initial" ? "GetTexParameter" : "TexParameter" + (STATE.call === "int" ? "i" : "f") + "(" + STATE.value + ")") + " on GL_" + STATE.name);
  print("expected:  " + want.text);
  print("observed:  " + errorText(error) + (hasValue ? ", value " + valueText(value) : ""));
  const ok = error === want.error && (want.value === null || (hasValue && value === want.value));
  print("verdict:   " + (ok ? "pass" : 'FAIL (not the error and value the spec requires: a "shall" is violated)'));
}

try {
  main();
} catch (e) {
  print("setup failed: " + e.message);
} finally {
  console.log(END);
}

"""A stand-in for Chromium on --remote-debugging-pipe (fd 3 in, fd 4 out, NUL-terminated JSON),
for the tests of the WebGL worker's browser handling (webgl/tests/browser.rs, runner/tests/webgl.rs).

Usage: python3 fake_chromium.py MODE [chromium flags...]
  ok              answers what the worker asks: its start commands, the page script, a page
                  init with no usable context (so a full worker stops at start), Browser.close
  page            as ok, but init answers a WebGL 2.0 page (a worker then says hello)
  hang-close      as page, but ignores Browser.close and SIGTERM (only SIGKILL ends it)
  renderer-crash  as page, but answers a shadowcheck.run evaluation with the page's
                  Inspector.targetCrashed event and never with its result
It prints "fake-chromium: profile DIR" on stderr.
"""
import json
import os
import signal
import sys

mode = sys.argv[1]
profile = next((a.split("=", 1)[1] for a in sys.argv if a.startswith("--user-data-dir=")), "")
print(f"fake-chromium: profile {profile}", file=sys.stderr, flush=True)
if mode == "hang-close":
    signal.signal(signal.SIGTERM, signal.SIG_IGN)

SESSION = "FAKESESSION"
PAGE = {
    "version": "WebGL 2.0 (OpenGL ES 3.0 fake)",
    "glsl": "WebGL GLSL ES 3.00 (fake)",
    # The worker checks the renderer names webgl:chromium's back end and driver.
    "renderer": "ANGLE (fake, Vulkan 1.3.0 (SwiftShader Device (fake)), SwiftShader driver)",
    "vendor": "fake",
    "extensions": ["EXT_color_buffer_float"],
    "enabled": ["EXT_color_buffer_float"],
}


def send(msg):
    os.write(4, json.dumps(msg).encode() + b"\0")


def answer(m):
    method = m.get("method", "")
    if method == "Browser.getVersion":
        return {"product": "FakeChromium/1.0"}
    if method == "Target.createTarget":
        return {"targetId": "FAKETARGET"}
    if method == "Target.attachToTarget":
        return {"sessionId": SESSION}
    if method == "Runtime.evaluate":
        expr = m.get("params", {}).get("expression", "")
        if expr == "shadowcheck.init()":
            value = {"error": "fake: no WebGL 2.0 context"} if mode == "ok" else PAGE
        elif expr.startswith("shadowcheck.run(") and mode == "renderer-crash":
            send({"method": "Inspector.targetCrashed", "params": {}, "sessionId": SESSION})
            return None
        else:
            value = "loaded"
        return {"result": {"type": "object", "value": value}}
    if method == "Browser.close":
        if mode == "hang-close":
            return None
        send({"id": m["id"], "result": {}})
        sys.exit(0)
    return {}


buf = b""
while True:
    chunk = os.read(3, 1 << 16)
    if not chunk:
        sys.exit(0)
    buf += chunk
    while b"\0" in buf:
        raw, buf = buf.split(b"\0", 1)
        m = json.loads(raw)
        result = answer(m)
        if result is not None:
            reply = {"id": m["id"], "result": result}
            if "sessionId" in m:
                reply["sessionId"] = m["sessionId"]
            send(reply)

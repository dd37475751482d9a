#!/usr/bin/env python3
"""A minimal external implementation for `shadowcheck run --backend 'exec:python3 runner/examples/nearest_2d.py'`.

OpenGL 4.6 core, GLSL `texture(sampler2DShadow, ...)`: 2D depth textures (d16, d24, d32, d32f),
NEAREST and LINEAR filtering of the base level, REPEAT / CLAMP_TO_EDGE / MIRRORED_REPEAT wrapping,
texel offsets (`textureOffset`: u = w*s + du before wrapping, GL 4.6 (8.10)), depth comparison per GL 4.6 §8.23.1 (compare each texel, then filter). It declares these
capabilities in its hello, so the runner skips every other case; anything else it meets is answered
with a skip message. It speaks runner/PROTOCOL.md (version 2): it also answers `state` requests
(TexParameteri / GetTexParameter on a GL 4.6 core context) from its own small table of the
depth-comparison texture parameters (GL 4.6 Table 8.17: TEXTURE_COMPARE_MODE NONE or
COMPARE_REF_TO_TEXTURE, TEXTURE_COMPARE_FUNC the eight functions, DEPTH_STENCIL_TEXTURE_MODE
DEPTH_COMPONENT or STENCIL_INDEX; any other value or pname INVALID_ENUM, the state unchanged).

`--swap-lequal-gequal` (or SHADOWCHECK_SWAP_LEQUAL_GEQUAL=1) swaps LEQUAL and GEQUAL: the bug the
runner must catch. `--lie-stored` answers r = 1 everywhere and claims every texel was stored as the
format's maximum (`stored`): the trust hole the runner must close ("stored texel outside the upload
allowance").
"""
import json, math, os, struct, sys

SWAP = "--swap-lequal-gequal" in sys.argv[1:] or os.environ.get("SHADOWCHECK_SWAP_LEQUAL_GEQUAL") == "1"
LIE = "--lie-stored" in sys.argv[1:]
BITS = {"d16": 16, "d24": 24, "d32": 32}

def f32(x):
    return struct.unpack("f", struct.pack("f", float(x)))[0]

def wrap(i, size, mode):  # GL 4.6 §8.14.2, Table 8.20 (applied to integer texel coordinates)
    if mode == "repeat":
        return i % size
    if mode == "edge":
        return min(max(i, 0), size - 1)
    if mode == "mirror":
        m = i % (2 * size)
        return m if m < size else 2 * size - 1 - m
    raise ValueError("wrap mode %s not implemented" % mode)

def compare(func, dref, dt):  # GL 4.6 Table 8.23
    if SWAP and func in ("lequal", "gequal"):
        func = "gequal" if func == "lequal" else "lequal"
    return float({"lequal": dref <= dt, "gequal": dref >= dt, "less": dref < dt, "greater": dref > dt,
                  "equal": dref == dt, "notequal": dref != dt, "always": True, "never": False}[func])

def sample(case):
    tex, smp, lk = case["texture"], case["sampler"], case["lookup"]
    if smp["compare_mode"] != "compare" or smp.get("depth_stencil_mode", "depth") != "depth":
        return None, "only depth comparison is implemented"
    for key in ("swizzle", "seamless", "sampler_object"):  # the unit state: not implemented
        if key in smp:
            return None, f"sampler.{key} is not implemented"
    if smp["min_filter"] not in ("nearest", "linear"):  # mipmaps bring completeness rules (§8.17)
        return None, "mipmap filters are not implemented"
    if "gather" in lk:  # a hello without `features` claims them all: refuse what is not done
        return None, "textureGather is not implemented"
    lam = f32(lk.get("lod", 0)) + f32(smp.get("lod_bias", 0)) + f32(lk.get("bias", 0))
    lam = min(max(lam, smp.get("min_lod", -1000.0)), smp.get("max_lod", 1000.0))
    flt = smp["min_filter"] if lam > 0 else smp["mag_filter"]  # §8.14: c = 0 without mipmaps
    lvl = tex["levels"][0]
    w, h = lvl["width"], lvl["height"]
    fmt = tex["format"]
    raw = lvl["depth"].get("unorm") or lvl["depth"].get("float")
    depth = [c / (2 ** BITS[fmt] - 1) for c in raw] if fmt in BITS else [min(max(f32(v), 0.0), 1.0) for v in raw]
    s, t, q = (f32(float(x)) for x in (lk["coord"][0], lk["coord"][1], lk["coord"][3]))
    dref = f32(float(lk["dref"]))
    if lk.get("projective"):
        s, t, dref = f32(s / q), f32(t / q), f32(dref / q)
    if fmt in BITS:  # fixed-point formats clamp Dref (GL 4.6 §8.23.1)
        dref = min(max(dref, 0.0), 1.0)
    du, dv = (lk.get("offset") or [0, 0, 0])[:2]
    u, v = s * w + du, t * h + dv
    try:
        if flt == "nearest":
            taps = [(wrap(math.floor(u), w, smp["wrap_s"]), wrap(math.floor(v), h, smp["wrap_t"]), 1.0)]
        else:
            i0, j0 = math.floor(u - 0.5), math.floor(v - 0.5)
            a, b = (u - 0.5) - i0, (v - 0.5) - j0
            taps = [(wrap(i0 + di, w, smp["wrap_s"]), wrap(j0 + dj, h, smp["wrap_t"]),
                     (a if di else 1 - a) * (b if dj else 1 - b)) for dj in (0, 1) for di in (0, 1)]
    except (ValueError, OverflowError) as e:
        return None, str(e)
    return sum(wt * compare(smp["compare_func"], dref, depth[j * w + i]) for i, j, wt in taps), None

def send(msg):
    sys.stdout.write(json.dumps(msg) + "\n")

# GL 4.6 core: pname key -> (initial value, legal values), Table 8.17 / Table 23.15.
STATE = {
    "compare_mode": (0x0000, {0x0000, 0x884E}),
    "compare_func": (0x0203, set(range(0x0200, 0x0208))),
    "depth_stencil_mode": (0x1902, {0x1902, 0x1901}),
}


def state_answer(case):
    """One TexParameteri / GetTexParameter call on a fresh texture: the error and the value read back."""
    known = STATE.get(case["pname"])
    call = case["call"]
    if known is None:
        return {"error": "invalid_enum"}
    initial, legal = known
    error, value = None, initial
    if isinstance(call, dict) and "set_int" in call:
        v = call["set_int"]
        if v in legal:
            value = v
        else:
            error = "invalid_enum"
    elif isinstance(call, dict):
        return None  # TexParameterf: not implemented here
    out = {"value": {"enum": value}} if case.get("read_back") else {}
    if error:
        out["error"] = error
    return out


for line in sys.stdin:
    msg = json.loads(line)
    kind = msg.get("type")
    if kind == "hello":
        send({"type": "hello", "protocol": 2, "name": "nearest_2d.py" + (" (LEQUAL/GEQUAL swapped)" if SWAP else ""),
              "capabilities": {"specs": ["gl46"], "api": ["core"], "targets": ["2d"],
                               "formats": ["d16", "d24", "d32", "d32f"], "extensions": []}})
        sys.stdout.flush()
    elif kind == "case":
        case = msg["case"]
        r, why = sample(case)
        if why:
            send({"type": "skip", "case_id": case["id"], "reason": why})
        elif LIE:
            lvl = case["texture"]["levels"][0]
            n = lvl["width"] * lvl["height"]
            fmt = case["texture"]["format"]
            stored = {"float": [1.0] * n} if fmt == "d32f" else {"unorm": [(1 << BITS[fmt]) - 1] * n}
            send({"type": "observation", "case_id": case["id"],
                  "results": [{"api": "core", "rgba": [1.0, 0.0, 0.0, 1.0], "stored": stored}]})
        else:
            send({"type": "observation", "case_id": case["id"],
                  "results": [{"api": "core", "rgba": [r, 0.0, 0.0, 1.0]}]})
    elif kind == "state":
        case = msg["state"]
        got = state_answer(case) if case["spec"] == "gl46" and case["api"] == ["core"] else None
        if got is None:
            send({"type": "skip", "case_id": case["id"], "reason": "only TexParameteri on GL 4.6 core"})
        else:
            got["api"] = "core"
            send({"type": "state_observation", "case_id": case["id"], "results": [got]})
    elif kind == "flush":
        sys.stdout.flush()
    elif kind == "bye":
        break

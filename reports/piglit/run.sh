#!/bin/sh
# piglit's shadow / depth-texture subset on every Mesa driver of this machine: the second opinion of
# reports/README.md, "piglit cross-check". Debian 12 packages: piglit (0~git20220119-124bca3c9-1), xvfb.
# Run from the repository root:  sh reports/piglit/run.sh [OUTROOT]
# Window system: Xvfb + x11_egl (under surfaceless_egl piglit's window-system tests crash without output).
# Writes OUTROOT/<driver>/results.json.bz2 and reports/piglit/<driver>.txt (one `status test` line each).
set -e
OUT=${1:-out/piglit}
mkdir -p "$OUT"
# The subset: every test whose name speaks of shadow or depth textures, seamless cubes, sampler
# objects, stencil texturing or ext_texture_swizzle (1121 tests of the `quick` profile). Serial (-1): with
# -j 2 under one Xvfb, 33 tests fail to connect to the X server and report "fail" without running
# (reports/piglit/README.md). About 22 minutes for the three drivers.
FILTER='shadow|depth|seamless|sampler_objects|stencil_texturing|ext_texture_swizzle@'
for drv in llvmpipe softpipe zink; do
  case $drv in
    zink) export LIBGL_ALWAYS_SOFTWARE=1 GALLIUM_DRIVER=zink ;;
    *) export LIBGL_ALWAYS_SOFTWARE=1 GALLIUM_DRIVER=$drv ;;
  esac
  rm -rf "$OUT/$drv"
  xvfb-run -a -s '-screen 0 1024x768x24' \
    piglit run -p x11_egl -t "$FILTER" -1 --timeout 120 -l dummy quick "$OUT/$drv" || true
  python3 - "$OUT/$drv/results.json.bz2" > "reports/piglit/$drv.txt" <<'PY'
import bz2, json, sys
d = json.load(bz2.open(sys.argv[1]))
for name, t in sorted(d["tests"].items()):
    print(t["result"], name)
PY
  echo "$drv: $(cut -d' ' -f1 "reports/piglit/$drv.txt" | sort | uniq -c | tr '\n' ' ')"
done

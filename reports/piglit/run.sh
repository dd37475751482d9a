#!/bin/sh
# piglit's shadow / depth-texture subset on every implementation of this machine that piglit can
# drive: the second opinion of reports/README.md, "piglit cross-check". Debian 12 packages: piglit
# (0~git20220119-124bca3c9-1), xvfb; chromium-common for SwiftShader's Vulkan ICD; SwiftShader's
# GLES from `sh gl/fetch-swiftshader.sh`.
# Run from the repository root:  sh reports/piglit/run.sh [OUTROOT [IMPL...]]
# IMPL (default: all): llvmpipe softpipe zink zink-swiftshader swiftshader-es angle-vulkan-lavapipe
#   angle-vulkan-swiftshader
#   llvmpipe, softpipe   Mesa's gallium drivers (LIBGL_ALWAYS_SOFTWARE=1 GALLIUM_DRIVER=...)
#   zink                 zink on lavapipe (Mesa's Vulkan driver, the default ICD here)
#   zink-swiftshader     zink on SwiftShader's Vulkan driver (VK_ICD_FILENAMES at chromium-common's
#                        ICD), no version override: GL 2.1 / GLSL 1.20 and ES 2.0, as
#                        shadowcheck's egl:zink+swiftshader:compat
#   swiftshader-es       SwiftShader 4.0's own EGL 1.4 / GLES 3.0 (egl:swiftshader:es3): its libEGL.so
#                        and libGLESv2.so first on LD_LIBRARY_PATH, behind a libEGL.so.1 shim without
#                        which waffle cannot open a window on it (swiftshader-es-window/, README.md).
#                        OpenGL (not ES) tests skip: its EGL_CLIENT_APIS is "OpenGL_ES".
#   angle-vulkan-lavapipe, angle-vulkan-swiftshader
#                        ANGLE's GLES on its Vulkan back end (ANGLE_DEFAULT_PLATFORM=vulkan) over
#                        lavapipe or chromium-common's SwiftShader ICD (VK_ICD_FILENAMES), the layers
#                        under webgl:chromium-lavapipe and webgl:chromium. Debian's chromium links
#                        ANGLE statically, so this is the ANGLE of CEF 131 (sh reports/piglit/fetch-angle.sh,
#                        PyPI cef-capi-py 131.3.5). OpenGL (not ES) tests skip.
# Window system: Xvfb + x11_egl (under surfaceless_egl piglit's window-system tests crash without output).
# Writes OUTROOT/<impl>/results.json.bz2 and reports/piglit/<impl>.txt (one `status test` line each).
set -e
OUT=${1:-out/piglit}
[ $# -gt 0 ] && shift
IMPLS=${*:-llvmpipe softpipe zink zink-swiftshader swiftshader-es angle-vulkan-lavapipe angle-vulkan-swiftshader}
mkdir -p "$OUT"
OUT=$(cd "$OUT" && pwd)
# The subset: every test whose name speaks of shadow or depth textures, seamless cubes, sampler
# objects, stencil texturing or ext_texture_swizzle (1121 tests of the `quick` profile). Serial (-1): with
# -j 2 under one Xvfb, 33 tests fail to connect to the X server and report "fail" without running
# (reports/piglit/README.md). About 5-10 minutes per implementation on 2 shared cores, 28 for
# zink-swiftshader (its tex-miplevel-selection variants take up to 90 s each).
FILTER='shadow|depth|seamless|sampler_objects|stencil_texturing|ext_texture_swizzle@'
SS_DIR=${SHADOWCHECK_SWIFTSHADER_DIR:-${XDG_CACHE_HOME:-$HOME/.cache}/shadowcheck/swiftshader-4.0.0.3}
VK_SS_ICD=${SHADOWCHECK_VK_SWIFTSHADER_ICD:-/usr/lib/chromium/vk_swiftshader_icd.json}
VK_LVP_ICD=/usr/share/vulkan/icd.d/lvp_icd.x86_64.json
ANGLE_DIR=${SHADOWCHECK_ANGLE_DIR:-${XDG_CACHE_HOME:-$HOME/.cache}/shadowcheck/angle-cef_capi_py-131.3.5}
for impl in $IMPLS; do
  # Each implementation in a subshell, so that its environment does not leak into the next one.
  (
  case $impl in
    llvmpipe|softpipe|zink) export LIBGL_ALWAYS_SOFTWARE=1 GALLIUM_DRIVER=$impl ;;
    zink-swiftshader)
      [ -f "$VK_SS_ICD" ] || { echo "missing $VK_SS_ICD: apt-get install -y chromium-common" >&2; exit 1; }
      export LIBGL_ALWAYS_SOFTWARE=1 GALLIUM_DRIVER=zink VK_ICD_FILENAMES="$VK_SS_ICD" ;;
    swiftshader-es)
      [ -f "$SS_DIR/libEGL.so" ] || { echo "missing $SS_DIR/libEGL.so: sh gl/fetch-swiftshader.sh" >&2; exit 1; }
      # A libEGL.so.1 shim over SwiftShader's libEGL.so that lets waffle open an X window
      # (swiftshader-es-window/visual-shim.c says which three answers it changes and why).
      LIBS="$OUT/$impl-lib"
      sh reports/piglit/swiftshader-es-window/build-shim.sh "$SS_DIR" "$LIBS"
      export LD_LIBRARY_PATH="$LIBS${LD_LIBRARY_PATH:+:$LD_LIBRARY_PATH}" ;;
    angle-vulkan-lavapipe|angle-vulkan-swiftshader)
      [ -f "$ANGLE_DIR/libGLESv2.so" ] || { echo "missing $ANGLE_DIR/libGLESv2.so: sh reports/piglit/fetch-angle.sh" >&2; exit 1; }
      # piglit's binaries link libEGL.so.1; waffle dlopens libEGL.so.1 and libGLESv2.so.2.
      LIBS="$OUT/$impl-lib"
      mkdir -p "$LIBS"
      for l in libEGL.so libGLESv2.so libvulkan.so.1; do ln -sf "$ANGLE_DIR/$l" "$LIBS/$l"; done
      ln -sf "$ANGLE_DIR/libEGL.so" "$LIBS/libEGL.so.1"
      ln -sf "$ANGLE_DIR/libGLESv2.so" "$LIBS/libGLESv2.so.2"
      case $impl in
        *-lavapipe) ICD=$VK_LVP_ICD ;;
        *) ICD=$VK_SS_ICD ;;
      esac
      export ANGLE_DEFAULT_PLATFORM=vulkan VK_ICD_FILENAMES="$ICD" \
        LD_LIBRARY_PATH="$LIBS${LD_LIBRARY_PATH:+:$LD_LIBRARY_PATH}" ;;
    *) echo "unknown implementation $impl" >&2; exit 1 ;;
  esac
  rm -rf "${OUT:?}/$impl"
  xvfb-run -a -s '-screen 0 1024x768x24' \
    piglit run -p x11_egl -t "$FILTER" -1 --timeout 120 -l dummy quick "$OUT/$impl" || true
  python3 - "$OUT/$impl/results.json.bz2" > "reports/piglit/$impl.txt" <<'PY'
import bz2, json, sys
d = json.load(bz2.open(sys.argv[1]))
for name, t in sorted(d["tests"].items()):
    print(t["result"], name)
PY
  echo "$impl: $(cut -d' ' -f1 "reports/piglit/$impl.txt" | sort | uniq -c | tr '\n' ' ')"
  )
done

#!/usr/bin/env bash
# Runs repro.html (standalone WebGL 2.0, no shadowcheck code) on the three ANGLE back ends of
# shadowcheck's webgl:* instances, one fresh headless Chromium per query (--dump-dom prints the
# page after its 1.5 s wait), and prints one RESULT line per (back end, query).
# usage: run.sh [CONFIG...]   (default: swiftshader gles-llvmpipe vulkan-lavapipe); env CHROMIUM.
set -uo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
configs=("$@")
[ ${#configs[@]} -gt 0 ] || configs=(swiftshader gles-llvmpipe vulkan-lavapipe)
common=(--headless --no-sandbox --disable-gpu-sandbox --no-first-run --disable-extensions
        --allow-file-access-from-files --virtual-time-budget=5000)
queries=()
for f in RGBA8 RGB8 RGBA4 RG8 R8; do
  for flt in NEAREST LINEAR; do
    for c in 0 1; do queries+=("case=colour&fmt=$f&cmp=$c&filter=$flt"); done
  done
done
queries+=("case=clamp&fmt=DEPTH24_STENCIL8&ref=1.5" "case=clamp&fmt=DEPTH_COMPONENT24&ref=1.5"
          "case=clamp&fmt=DEPTH24_STENCIL8&ref=1.0" "case=clamp&fmt=DEPTH24_STENCIL8&ref=-0.5")
for cfg in "${configs[@]}"; do
  envs=(); flags=()
  case "$cfg" in
    swiftshader) flags=(--use-angle=swiftshader --enable-unsafe-swiftshader) ;;
    gles-llvmpipe) flags=(--use-angle=gles-egl --ignore-gpu-blocklist --enable-unsafe-swiftshader)
                   envs=(LIBGL_ALWAYS_SOFTWARE=1 GALLIUM_DRIVER=llvmpipe EGL_PLATFORM=surfaceless) ;;
    vulkan-lavapipe) flags=(--use-angle=vulkan --ignore-gpu-blocklist --disable-gpu-driver-bug-workarounds)
                     envs=(VK_ICD_FILENAMES=/usr/share/vulkan/icd.d/lvp_icd.x86_64.json) ;;
    *) echo "unknown config $cfg" >&2; exit 2 ;;
  esac
  for qs in "${queries[@]}"; do
    line="$(env "${envs[@]}" timeout 60 "${CHROMIUM:-chromium}" "${common[@]}" "${flags[@]}" \
      --dump-dom "file://$here/repro.html?$qs" 2>/dev/null | grep -o 'RESULT [^<]*' | head -1)"
    echo "$cfg ${line:-RESULT ?$qs no result (page did not finish: browser or GPU process gone)}"
  done
done

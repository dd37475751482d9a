#!/bin/sh
# Runs page.html in headless Chromium (Debian's chromium package) and prints what the page wrote,
# with the flags and environment of one of shadowcheck's WebGL backends (webgl/src/instance.rs):
#   sh run.sh                   webgl:chromium: ANGLE's Vulkan back end over SwiftShader
#   ANGLE=gles-egl sh run.sh    webgl:chromium-gles: ANGLE's OpenGL ES back end over Mesa's llvmpipe (EGL)
#   ANGLE=lavapipe sh run.sh    webgl:chromium-lavapipe: ANGLE's Vulkan back end over Mesa's lavapipe
#                               (Chromium's GPU bug list turns texture storage, hence WebGL 2.0, off
#                               on lavapipe; --disable-gpu-driver-bug-workarounds keeps it)
# Output: output.txt (the three runs, committed).
dir=$(cd "$(dirname "$0")" && pwd)
profile=$(mktemp -d)
case "${ANGLE:-swiftshader}" in
  swiftshader) flags="--use-angle=swiftshader --enable-unsafe-swiftshader --disable-gpu" ;;
  gles-egl)
    flags="--use-angle=gles-egl --ignore-gpu-blocklist"
    export LIBGL_ALWAYS_SOFTWARE=1 GALLIUM_DRIVER=llvmpipe EGL_PLATFORM=surfaceless ;;
  lavapipe)
    flags="--use-angle=vulkan --ignore-gpu-blocklist --disable-gpu-driver-bug-workarounds"
    export VK_ICD_FILENAMES=/usr/share/vulkan/icd.d/lvp_icd.x86_64.json ;;
  *) echo "ANGLE=swiftshader|gles-egl|lavapipe" >&2; exit 2 ;;
esac
# shellcheck disable=SC2086
chromium --headless --no-sandbox $flags \
  --no-first-run --disable-background-networking --disable-component-update --disable-sync \
  --user-data-dir="$profile" --dump-dom "file://$dir/page.html" 2>/dev/null |
  sed -n '/<pre id="out">/,/<\/pre>/p' | sed -e 's/.*<pre id="out">//' -e 's/<\/pre>.*//' \
  -e 's/&lt;/</g' -e 's/&gt;/>/g' -e 's/&amp;/\&/g'
rm -rf "$profile"

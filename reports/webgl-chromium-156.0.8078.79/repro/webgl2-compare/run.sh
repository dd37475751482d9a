#!/bin/sh
# Runs page.html in headless Chromium (Debian's chromium package) and prints what the page wrote.
#   sh run.sh                      WebGL 2.0 on ANGLE's Vulkan back end over SwiftShader (the backend's setup)
#   ANGLE=gles-egl sh run.sh        ANGLE's OpenGL ES back end over Mesa's llvmpipe (EGL) instead: another
#                                  ANGLE back end on another driver (ANGLE=vulkan finds no Vulkan device
#                                  here outside SwiftShader, so lavapipe could not be put under ANGLE Vulkan)
# Output: output.txt (both runs, committed).
dir=$(cd "$(dirname "$0")" && pwd)
profile=$(mktemp -d)
angle=${ANGLE:-swiftshader}
gpu="--disable-gpu"; [ "$angle" = swiftshader ] || gpu="--ignore-gpu-blocklist"
chromium --headless --no-sandbox --use-angle="$angle" --enable-unsafe-swiftshader $gpu \
  --no-first-run --disable-background-networking --disable-component-update --disable-sync \
  --user-data-dir="$profile" --dump-dom "file://$dir/page.html" 2>/dev/null |
  sed -n '/<pre id="out">/,/<\/pre>/p' | sed -e 's/.*<pre id="out">//' -e 's/<\/pre>.*//' \
  -e 's/&lt;/</g' -e 's/&gt;/>/g' -e 's/&amp;/\&/g'
rm -rf "$profile"

#!/bin/sh
# Builds and runs the reproducer on four implementations; writes output.txt beside this file.
# Needs gcc and libegl-dev (headers only); SwiftShader's GLES from gl/fetch-swiftshader.sh.
set -e
cd "$(dirname "$0")"
gcc -O1 -o ./dref-clamp repro.c -ldl
SS=${SHADOWCHECK_SWIFTSHADER_DIR:-${XDG_CACHE_HOME:-$HOME/.cache}/shadowcheck/swiftshader-4.0.0.3}
ICD=/usr/lib/chromium/vk_swiftshader_icd.json
{
  echo "== Mesa llvmpipe";  EGL_PLATFORM=surfaceless LIBGL_ALWAYS_SOFTWARE=1 GALLIUM_DRIVER=llvmpipe ./dref-clamp
  echo "== Mesa zink on lavapipe"; EGL_PLATFORM=surfaceless LIBGL_ALWAYS_SOFTWARE=1 GALLIUM_DRIVER=zink ./dref-clamp
  echo "== Mesa zink on SwiftShader Vulkan (chromium-common)"; VK_ICD_FILENAMES=$ICD MESA_GLES_VERSION_OVERRIDE=3.1 EGL_PLATFORM=surfaceless LIBGL_ALWAYS_SOFTWARE=1 GALLIUM_DRIVER=zink ./dref-clamp
  echo "== SwiftShader 4.0.0.3 GLES (cefpython3 66.0)"; LD_LIBRARY_PATH=$SS REPRO_LIBEGL=$SS/libEGL.so ./dref-clamp
} 2>/dev/null > output.txt
cat output.txt

#!/bin/sh
# Builds and runs the reproducer on Mesa llvmpipe (control) and SwiftShader 4.0.0.3's GLES; writes
# output.txt beside this file. Needs gcc and libegl-dev (headers only); SwiftShader's GLES from
# gl/fetch-swiftshader.sh.
set -e
cd "$(dirname "$0")"
gcc -O1 -o ./texparam-invalid-value repro.c -ldl
SS=${SHADOWCHECK_SWIFTSHADER_DIR:-${XDG_CACHE_HOME:-$HOME/.cache}/shadowcheck/swiftshader-4.0.0.3}
{
  echo "== Mesa llvmpipe";  EGL_PLATFORM=surfaceless LIBGL_ALWAYS_SOFTWARE=1 GALLIUM_DRIVER=llvmpipe ./texparam-invalid-value
  echo "== SwiftShader 4.0.0.3 GLES (cefpython3 66.0)"; LD_LIBRARY_PATH=$SS REPRO_LIBEGL=$SS/libEGL.so ./texparam-invalid-value
} 2>/dev/null > output.txt
cat output.txt

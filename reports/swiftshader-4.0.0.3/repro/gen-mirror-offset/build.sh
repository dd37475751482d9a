#!/bin/sh
# shadowcheck reproducer for gles32/2d/d24/nearest/lequal/offset/wrap=mirror/texel=1_2/offset=-8_7/ref=0.5@es300 on egl:swiftshader:es3.
# Debian 12: apt-get install -y gcc libegl-dev libgles-dev
cd "$(dirname "$0")" || exit 2
dir=${SHADOWCHECK_SWIFTSHADER_DIR:-${XDG_CACHE_HOME:-$HOME/.cache}/shadowcheck/swiftshader-4.0.0.3}
[ -f "$dir/libEGL.so" ] || [ -f "$dir/libEGL.so.1" ] || { echo "setup failed: no libEGL.so in $dir: run 'sh gl/fetch-swiftshader.sh' in shadowcheck's source tree" >&2; exit 2; }
cc -std=c99 -O1 -Wall -o repro repro.c -L"$dir" -Wl,-rpath,"$dir" -lEGL -lGLESv2 -lm || exit 2
exec env LD_LIBRARY_PATH="$dir${LD_LIBRARY_PATH:+:$LD_LIBRARY_PATH}" ./repro

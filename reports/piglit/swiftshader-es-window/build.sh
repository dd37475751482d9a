#!/bin/sh
# Build probe.c against SwiftShader 4.0's libEGL.so / libGLESv2.so (sh gl/fetch-swiftshader.sh) and
# run it under Xvfb, as piglit's run.sh does; writes output.txt. Needs libx11-dev libegl-dev libgles-dev.
set -e
cd "$(dirname "$0")"
SS=${SHADOWCHECK_SWIFTSHADER_DIR:-${XDG_CACHE_HOME:-$HOME/.cache}/shadowcheck/swiftshader-4.0.0.3}
T=$(mktemp -d)
cc -std=c99 -O1 -Wall -o "$T/probe" probe.c -L"$SS" -lEGL -lGLESv2 -lX11 -Wl,-rpath,"$SS"
set +e
LD_LIBRARY_PATH="$SS" xvfb-run -a -s '-screen 0 1024x768x24' "$T/probe" > output.txt 2>&1
rc=$?
echo "exit $rc" >> output.txt
cat output.txt
rm -rf "$T"
exit $rc

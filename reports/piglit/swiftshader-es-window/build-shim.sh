#!/bin/sh
# Build visual-shim.c as DIR/libEGL.so.1 (linked to SwiftShader's libEGL.so) and put SwiftShader's
# libEGL.so, libGLESv2.so and libGLESv2.so.2 beside it: DIR goes first on LD_LIBRARY_PATH for piglit
# (run.sh, implementation swiftshader-es). Usage: sh build-shim.sh SWIFTSHADER_DIR DIR
set -e
SS=$1
DIR=$2
mkdir -p "$DIR"
cc -shared -fPIC -O1 -Wall -Wl,-soname,libEGL.so.1 -o "$DIR/libEGL.so.1" \
  "$(dirname "$0")/visual-shim.c" -Wl,--no-as-needed -L"$SS" -lEGL -Wl,--as-needed -lX11 -ldl
ln -sf "$SS/libEGL.so" "$DIR/libEGL.so"
ln -sf "$SS/libGLESv2.so" "$DIR/libGLESv2.so"
ln -sf "$SS/libGLESv2.so" "$DIR/libGLESv2.so.2"

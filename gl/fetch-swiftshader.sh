#!/bin/sh
# Fetches SwiftShader's own OpenGL ES 3.0 implementation (libEGL.so + libGLESv2.so, "OpenGL ES 3.0
# SwiftShader 4.0.0.3", 2018) for the egl:swiftshader:* backends: they ship in the manylinux wheel of
# cefpython3 66.0 on PyPI, directory cefpython3/swiftshader/. Downloads the wheel with pip (no
# dependencies, nothing installed), checks its SHA-256 and unpacks the two libraries into
#   $1, else $SHADOWCHECK_SWIFTSHADER_DIR, else ${XDG_CACHE_HOME:-$HOME/.cache}/shadowcheck/swiftshader-4.0.0.3
# (where the backend looks; see gl/src/libdir.rs). Needs python3 with pip, and unzip or python3.
# Usage: sh gl/fetch-swiftshader.sh [DIR]
set -eu
WHEEL=cefpython3-66.0-py2.py3-none-manylinux1_x86_64.whl
SHA256=9b8018c3b5aee260c755e0e0691be04f60ed10389e7eeea44f40ba9a3b0b410e
DIR=${1:-${SHADOWCHECK_SWIFTSHADER_DIR:-${XDG_CACHE_HOME:-$HOME/.cache}/shadowcheck/swiftshader-4.0.0.3}}
if [ -f "$DIR/libEGL.so" ] && [ -f "$DIR/libGLESv2.so" ]; then
  echo "SwiftShader GLES already in $DIR"
  exit 0
fi
TMP=$(mktemp -d)
trap 'rm -rf "$TMP"' EXIT
python3 -m pip download --quiet --no-deps --only-binary=:all: --platform manylinux1_x86_64 \
  --python-version 3.7 cefpython3==66.0 -d "$TMP"
echo "$SHA256  $TMP/$WHEEL" | sha256sum -c - >/dev/null
mkdir -p "$DIR"
python3 - "$TMP/$WHEEL" "$DIR" <<'PY'
import sys, zipfile, os
wheel, out = sys.argv[1], sys.argv[2]
with zipfile.ZipFile(wheel) as z:
    for lib in ("libEGL.so", "libGLESv2.so"):
        dest = os.path.join(out, lib)
        with z.open("cefpython3/swiftshader/" + lib) as src, open(dest, "wb") as f:
            f.write(src.read())
        os.chmod(dest, 0o755)
PY
echo "SwiftShader GLES 4.0.0.3 in $DIR"

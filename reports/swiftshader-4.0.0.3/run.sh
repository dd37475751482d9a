#!/bin/sh
# How the reference results of SwiftShader's own OpenGL ES 3.0 were made (Debian 12, 2 CPUs, no GPU):
# libEGL.so + libGLESv2.so "OpenGL ES 3.0 SwiftShader 4.0.0.3" (renderer "Google SwiftShader"; its
# own GLES front end, GLSL ES compiler and sampler) from the PyPI wheel cefpython3==66.0
# (cefpython3-66.0-py2.py3-none-manylinux1_x86_64.whl, SHA-256 9b8018c3...b410e), fetched by
# gl/fetch-swiftshader.sh. EGL 1.4 only: the worker runs it on a pbuffer context.
# Run from the repository root:  sh reports/swiftshader-4.0.0.3/run.sh [OUTROOT]
# Timing: es3 24 s (SwiftShader compiles each shader variant; it has no on-disk cache).
set -e
cargo build --release -p shadowcheck-runner
sh gl/fetch-swiftshader.sh
OUT=${1:-out/swiftshader-4.0.0.3}
HERE=reports/swiftshader-4.0.0.3
b=egl:swiftshader:es3
# exit code 100 (failures) is expected: this run makes the baseline
/usr/bin/time -f "$b %e s" target/release/shadowcheck run --backend "$b" --out "$OUT/r-egl-swiftshader-es3" || true
target/release/shadowcheck summarize -o "$HERE" "$OUT"/r-* --platform "SwiftShader 4.0.0.3 GLES 3.0 (cefpython3 66.0 wheel, 2018-08-20 libraries)" --update-readme README.md
# Check: the backend passes with its own baseline (exit 0).
target/release/shadowcheck run --backend "$b" --baseline "$HERE/egl-swiftshader-es3/failures.csv" --out "$OUT/check"

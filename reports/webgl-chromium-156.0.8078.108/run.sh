#!/bin/sh
# How the WebGL 2.0 reference results in this folder were made: Debian 12's chromium package
# (first committed with 156.0.8078.79; SUMMARY.md names the packages of the last run), 2 CPUs, no
# GPU, no network, three ANGLE back ends (webgl/src/instance.rs has the flags and environment):
#   webgl:chromium           ANGLE's Vulkan back end over SwiftShader: "ANGLE (Google, Vulkan 1.3.0
#                            (SwiftShader Device (Subzero) (0x0000C0DE)), SwiftShader driver)"
#   webgl:chromium-gles      ANGLE's OpenGL ES back end over Mesa 22.3.6 llvmpipe (EGL): "ANGLE
#                            (Mesa/X.org, llvmpipe (LLVM 15.0.6 256 bits), OpenGL ES 3.2)"
#   webgl:chromium-lavapipe  ANGLE's Vulkan back end over Mesa 22.3.6 lavapipe: "ANGLE (Mesa, Vulkan
#                            1.3.230 (llvmpipe (LLVM 15.0.6 256 bits) (0x00000000)), llvmpipe)"
# Then the drivers under them on the same fixtures (egl:llvmpipe:es3, vk:lavapipe, vk:swiftshader)
# and `shadowcheck attribute` over all of it: ATTRIBUTION.md.
# Run from the repository root:  sh reports/webgl-chromium-156.0.8078.108/run.sh [OUTROOT]
#
# Binary: the commit that last changed this folder. Fixtures: the committed default set; only the
# GLES 3.2 cases (es300 path) are tests of these backends, the rest are not applicable.
# Timing (2026-11-29, 2 shared CPUs, other jobs running), the whole backend in wall clock:
# webgl:chromium 5.1 s (13.6 s the first time); webgl:chromium-gles 5.3 s and webgl:chromium-lavapipe
# 6.2 s with Mesa's shader cache filled, 59 s and 71 s with it cold (llvmpipe and lavapipe compile a
# shader variant per program and sampler state; the cache is the user's, not the browser profile's).
set -e
cargo build --release -p shadowcheck-runner
OUT=${1:-out/webgl-chromium-156.0.8078.108}
HERE=reports/webgl-chromium-156.0.8078.108
BACKENDS="webgl:chromium webgl:chromium-gles webgl:chromium-lavapipe"
for b in $BACKENDS; do
  slug=$(echo "$b" | tr ':' '-')
  # exit code 100 (failures) is expected: these runs make the baselines
  /usr/bin/time -f "$b %e s" target/release/shadowcheck run --backend "$b" --out "$OUT/r-$slug" || true
done
PKGS=$(dpkg-query -W -f '${Package} ${Version}, ' chromium chromium-common libegl-mesa0 libgl1-mesa-dri mesa-vulkan-drivers 2>/dev/null | sed 's/, $//')
target/release/shadowcheck summarize -o "$HERE" "$OUT"/r-webgl-chromium "$OUT"/r-webgl-chromium-gles "$OUT"/r-webgl-chromium-lavapipe --platform "Chromium 156 (results first committed with 156.0.8078.79; the packages below are those of the last run), WebGL 2.0 on ANGLE: Vulkan / SwiftShader, OpenGL ES / Mesa llvmpipe, Vulkan / Mesa lavapipe (Debian 12: ${PKGS:-package versions unknown})" --update-readme README.md
# Check: each backend passes with its own baseline (exit 0).
for b in $BACKENDS; do
  slug=$(echo "$b" | tr ':' '-')
  target/release/shadowcheck run --backend "$b" --baseline "$HERE/$slug/failures.csv" --out "$OUT/check-$slug"
done
# The layers: the drivers under ANGLE on the same fixtures, then the attribution (exit 100 of the
# llvmpipe run is expected: Mesa's committed failures).
for b in egl:llvmpipe:es3 vk:lavapipe vk:swiftshader; do
  target/release/shadowcheck run --backend "$b" --out "$OUT/r-$(echo "$b" | tr ':' '-')" || true
done
target/release/shadowcheck attribute "$OUT"/r-webgl-chromium "$OUT"/r-webgl-chromium-gles "$OUT"/r-webgl-chromium-lavapipe \
  "$OUT"/r-egl-llvmpipe-es3 "$OUT"/r-vk-lavapipe "$OUT"/r-vk-swiftshader --markdown "$HERE/ATTRIBUTION.md" > /dev/null

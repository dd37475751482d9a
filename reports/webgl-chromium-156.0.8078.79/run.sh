#!/bin/sh
# How the WebGL 2.0 reference results in this folder were made: Debian 12's chromium package
# 156.0.8078.79 (WebGL 2.0 on ANGLE's Vulkan back end over SwiftShader: "ANGLE (Google, Vulkan 1.3.0
# (SwiftShader Device (Subzero) (0x0000C0DE)), SwiftShader driver)"), 2 CPUs, no GPU, no network.
# Run from the repository root:  sh reports/webgl-chromium-156.0.8078.79/run.sh [OUTROOT]
#
# Binary: the commit that last changed this folder. Fixtures: the committed default set; only the
# GLES 3.2 cases (es300 path) are tests of this backend, the rest are not applicable.
# Timing (2026-11-23, 2 shared CPUs): the whole backend in 3.6-4.1 s wall clock (flake re-runs
# included), browser start and page 1.2-1.9 s of it (`shadowcheck webgl-worker --probe`).
set -e
cargo build --release -p shadowcheck-runner
OUT=${1:-out/webgl-chromium-156.0.8078.79}
HERE=reports/webgl-chromium-156.0.8078.79
# exit code 100 (failures) is expected: this run makes the baseline
/usr/bin/time -f "webgl:chromium %e s" target/release/shadowcheck run --backend webgl:chromium --out "$OUT/r-webgl-chromium" || true
PKGS=$(dpkg-query -W -f '${Package} ${Version}, ' chromium chromium-common 2>/dev/null | sed 's/, $//')
target/release/shadowcheck summarize -o "$HERE" "$OUT"/r-webgl-chromium --platform "Chromium 156 (results first committed with 156.0.8078.79; the packages below are those of the last run), WebGL 2.0 on ANGLE Vulkan / SwiftShader (Debian 12: ${PKGS:-package versions unknown})" --update-readme README.md
# Check: the backend passes with its own baseline (exit 0).
target/release/shadowcheck run --backend webgl:chromium --baseline "$HERE/webgl-chromium/failures.csv" --out "$OUT/check-webgl-chromium"

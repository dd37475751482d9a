#!/bin/sh
# How the WebGPU reference results in this folder were made: Debian 12's chromium package
# 156.0.8078.108 headless, 2 CPUs, no GPU, no network. webgpu:chromium is Dawn's Vulkan backend on
# SwiftShader (adapter "google swiftshader", "SwiftShader Device (Subzero)", a fallback adapter);
# webgpu:chromium-compat is Dawn's OpenGL ES backend on ANGLE's Vulkan back end on SwiftShader, in
# WebGPU's compatibility mode (no cube-map arrays, no depth32float-stencil8).
# Run from the repository root:  sh reports/webgpu-chromium-156.0.8078.108/run.sh [OUTROOT]
#
# Binary: the commit that last changed this folder. Fixtures: the committed default set; only the
# `webgpu/` cases (wgsl path) are tests of these backends, the rest are not applicable.
# Timing (2026-11-29, 2 shared CPUs): webgpu:chromium about 4 s wall clock for its 3242 tests,
# browser start and device included; webgpu:chromium-compat about 8 s. Then the layer attribution
# of webgpu:chromium's Warns and Fails against SwiftShader's Vulkan driver (`vk:swiftshader`, the
# driver under Dawn): ATTRIBUTION.md.
set -e
cargo build --release -p shadowcheck-runner
OUT=${1:-out/webgpu-chromium-156.0.8078.108}
HERE=reports/webgpu-chromium-156.0.8078.108
for b in webgpu:chromium webgpu:chromium-compat; do
  slug=$(echo "$b" | tr ':' '-')
  # exit code 100 (failures) would be expected if there were any: these runs make the baselines
  /usr/bin/time -f "$b %e s" target/release/shadowcheck run --backend "$b" --out "$OUT/r-$slug" || true
done
PKGS=$(dpkg-query -W -f '${Package} ${Version}, ' chromium chromium-common 2>/dev/null | sed 's/, $//')
target/release/shadowcheck summarize -o "$HERE" "$OUT"/r-webgpu-* --platform "WebGPU in headless Chromium 156: Dawn on SwiftShader, and Dawn's OpenGL ES backend on ANGLE on SwiftShader in compatibility mode (Debian 12: ${PKGS:-package versions unknown})" --update-readme README.md
# Compute-stage cube lookups at face edges vary from run to run (flakes.txt in each backend's
# folder, committed by hand; ../README.md "Lookups outside the fragment stage"): kept out of the
# baselines, excused in the checks.
for d in "$HERE"/*/; do
  [ -f "$d/flakes.txt" ] || continue
  grep -v '^#' "$d/flakes.txt" | sed 's/\$$/,/' > "$OUT/flakes.re"
  grep -vEf "$OUT/flakes.re" "$d/failures.csv" > "$OUT/f.csv" || true
  cp "$OUT/f.csv" "$d/failures.csv"
done
# Check: every backend passes with its own baseline (exit 0).
for d in "$HERE"/*/; do
  [ -f "$d/failures.csv" ] || continue
  b=$(basename "$d" | sed 's/^webgpu-/webgpu:/')
  fl=""; [ -f "$d/flakes.txt" ] && fl="--flakes $d/flakes.txt"
  target/release/shadowcheck run --backend "$b" --baseline "$d/failures.csv" $fl --out "$OUT/check-$(basename "$d")"
done
# Layer attribution: the same lookups recast as Vulkan cases on SwiftShader's Vulkan driver.
[ -f "$OUT/r-vk-swiftshader/results.jsonl" ] || target/release/shadowcheck run -b vk:swiftshader --out "$OUT/r-vk-swiftshader" || true
target/release/shadowcheck attribute "$OUT/r-webgpu-chromium" "$OUT/r-vk-swiftshader" --markdown "$HERE/ATTRIBUTION.md" > /dev/null

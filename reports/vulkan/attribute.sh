#!/bin/sh
# How reports/vulkan/ATTRIBUTION.md was made: the layered backends (zink on lavapipe, zink on
# SwiftShader's Vulkan driver, WebGL on ANGLE's Vulkan back end on SwiftShader) and the Vulkan
# drivers under them, run on the default fixtures, then `shadowcheck attribute` over both.
# Run from the repository root:  sh reports/vulkan/attribute.sh [OUTROOT]
set -e
cargo build --release -p shadowcheck-runner
OUT=${1:-out/vulkan}
[ -f "$OUT/r-vk-lavapipe/results.jsonl" ] || sh reports/vulkan/run.sh "$OUT"
# exit code 100 (the committed failures) is expected
target/release/shadowcheck run -b egl:zink:core -b egl:zink:compat -b egl:zink:es3 \
  -b egl:zink+swiftshader:core -b egl:zink+swiftshader:compat -b egl:zink+swiftshader:es3 \
  -b webgl:chromium --out "$OUT/layered" || true
# The Vulkan counterparts the vulkan/ grid lacks (the seeded random family draws other cases per
# spec), written with their expectations, run on both drivers, then the attribution with them.
target/release/shadowcheck attribute "$OUT/layered" "$OUT/r-vk-lavapipe" "$OUT/r-vk-swiftshader" \
  --counterparts "$OUT/counterparts.json" > /dev/null
for b in vk:lavapipe vk:swiftshader; do
  target/release/shadowcheck run -b "$b" --fixtures "$OUT/counterparts.json" --out "$OUT/cp-$(echo "$b" | tr ':' '-')" || true
done
target/release/shadowcheck attribute "$OUT/layered" "$OUT/r-vk-lavapipe" "$OUT/r-vk-swiftshader" \
  "$OUT/cp-vk-lavapipe" "$OUT/cp-vk-swiftshader" --fixtures cases/fixtures --fixtures "$OUT/counterparts.json" \
  --markdown reports/vulkan/ATTRIBUTION.md > /dev/null

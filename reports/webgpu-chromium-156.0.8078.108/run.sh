#!/bin/sh
# How the reference results of WebGPU in headless Chromium were made (Debian 12's chromium, 2
# CPUs, no GPU): `webgpu:chromium` (Dawn's Vulkan back end on its SwiftShader adapter, the only
# adapter Chromium gives here), through shadowcheck's webgpu-worker (the DevTools pipe, WGSL from
# the plan). Only the `webgpu/` fixtures apply. Then the attribution of its failures against
# SwiftShader's Vulkan driver (`vk:swiftshader`, the driver under Dawn).
# Run from the repository root:  sh reports/webgpu-chromium-156.0.8078.108/run.sh [OUTROOT]
set -e
cargo build --release -p shadowcheck-runner
OUT=${1:-out/webgpu}
HERE=reports/webgpu-chromium-156.0.8078.108
for b in webgpu:chromium; do
  slug=$(echo "$b" | tr ':' '-')
  # exit code 100 (failures) is expected: these runs make the baselines
  /usr/bin/time -f "$b %e s" target/release/shadowcheck run --backend "$b" --out "$OUT/r-$slug" || true
done
VER=$(dpkg-query -W -f '${Version}' chromium 2>/dev/null || echo unknown)
target/release/shadowcheck summarize -o "$HERE" "$OUT"/r-webgpu-* --platform "WebGPU in headless Chromium (Debian 12: chromium $VER)" --update-readme README.md
# Check: every backend passes with its own baseline (exit 0).
for d in "$HERE"/*/; do
  [ -f "$d/failures.csv" ] || continue
  b=$(basename "$d" | sed 's/-/:/')
  target/release/shadowcheck run --backend "$b" --baseline "$d/failures.csv" --out "$OUT/check-$(basename "$d")"
done
# Layer attribution: the same lookups on SwiftShader's Vulkan driver.
[ -f "$OUT/r-vk-swiftshader/results.jsonl" ] || target/release/shadowcheck run -b vk:swiftshader --out "$OUT/r-vk-swiftshader" || true
target/release/shadowcheck attribute "$OUT"/r-webgpu-* "$OUT/r-vk-swiftshader" --markdown "$HERE/ATTRIBUTION.md" > /dev/null

#!/bin/sh
# How the reference results of zink (Mesa 22.3.6) on SwiftShader's Vulkan driver in this folder were
# made (Debian 12, 2 CPUs, no GPU): the ICD is the one Debian's chromium-common ships
# (/usr/lib/chromium/libvk_swiftshader.so with its vk_swiftshader_icd.json); the GL worker points
# VK_ICD_FILENAMES at it (`egl:zink+swiftshader:*`, gl/src/names.rs).
# Run from the repository root:  sh reports/zink-swiftshader-chromium-156/run.sh [OUTROOT]
#
# Binary: the commit that last changed this folder (run.sh is re-run whenever the fixtures change).
# Fixtures: the committed default set (cases/fixtures).
set -e
cargo build --release -p shadowcheck-runner
OUT=${1:-out/zink-swiftshader-chromium-156}
HERE=reports/zink-swiftshader-chromium-156
for b in egl:zink+swiftshader:core egl:zink+swiftshader:compat egl:zink+swiftshader:es3; do
  slug=$(echo "$b" | tr ':' '-')
  # exit code 100 (failures) is expected: these runs make the baselines
  /usr/bin/time -f "$b %e s" target/release/shadowcheck run --backend "$b" --out "$OUT/r-$slug" || true
done
PKGS=$(dpkg-query -W -f '${Package} ${Version}, ' chromium-common libegl-mesa0 libgl1-mesa-dri libvulkan1 2>/dev/null | sed 's/, $//')
target/release/shadowcheck summarize -o "$HERE" "$OUT"/r-* --platform "zink (Mesa 22.3.6) on SwiftShader Vulkan (Debian 12: ${PKGS:-package versions unknown})"
# Check: every backend passes with its own baseline (exit 0).
for d in "$HERE"/egl-*/; do
  b=$(basename "$d" | sed 's/-/:/g')
  target/release/shadowcheck run --backend "$b" --baseline "$d/failures.csv" --out "$OUT/check-$(basename "$d")"
done

#!/bin/sh
# How the reference results of the Vulkan drivers were made (Debian 12, 2 CPUs, no GPU): Mesa
# 22.3.6's lavapipe (mesa-vulkan-drivers, /usr/share/vulkan/icd.d/lvp_icd.x86_64.json) and
# SwiftShader's Vulkan driver as Debian's chromium-common ships it
# (/usr/lib/chromium/vk_swiftshader_icd.json), both through shadowcheck's vk-worker (ash, SPIR-V
# from glslang-tools), under VK_LAYER_KHRONOS_validation (vulkan-validationlayers): a validation
# message would make the batch's answers Errors. Only the `vulkan/` fixtures apply to them.
# Run from the repository root:  sh reports/vulkan/run.sh [OUTROOT]
set -e
cargo build --release -p shadowcheck-runner
OUT=${1:-out/vulkan}
HERE=reports/vulkan
export SHADOWCHECK_VK_VALIDATION=1
for b in vk:lavapipe vk:swiftshader; do
  slug=$(echo "$b" | tr ':' '-')
  # exit code 100 (failures) would be expected if there were any: these runs make the baselines
  /usr/bin/time -f "$b %e s" target/release/shadowcheck run --backend "$b" --out "$OUT/r-$slug" || true
done
PKGS=$(dpkg-query -W -f '${Package} ${Version}, ' mesa-vulkan-drivers chromium-common libvulkan1 glslang-tools vulkan-validationlayers 2>/dev/null | sed 's/, $//')
target/release/shadowcheck summarize -o "$HERE" "$OUT"/r-* --platform "Vulkan drivers through ash (Debian 12: ${PKGS:-package versions unknown})" --update-readme README.md
# Check: every backend passes with its own baseline (exit 0).
for d in "$HERE"/*/; do
  [ -f "$d/failures.csv" ] || continue
  b=$(basename "$d" | sed 's/-/:/g')
  target/release/shadowcheck run --backend "$b" --baseline "$d/failures.csv" --out "$OUT/check-$(basename "$d")"
done

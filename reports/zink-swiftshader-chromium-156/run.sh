#!/bin/sh
# How the reference results of zink on SwiftShader's Vulkan driver were made (Debian 12, 2 CPUs, no
# GPU): Mesa 22.3.6's zink (GL front end, state tracker, zink's NIR-to-SPIR-V) on the SwiftShader
# Vulkan ICD that Debian's chromium-common ships (/usr/lib/chromium/vk_swiftshader_icd.json;
# "SwiftShader Device (Subzero)"). Backends egl:zink+swiftshader:{core,compat,es3}; the version
# overrides each uses, and why they are honest, are in runner/README.md ("Contexts by capability").
# Run from the repository root:  sh reports/zink-swiftshader-chromium-156/run.sh [OUTROOT]
# Timings (warm Mesa shader cache, 2 shared CPUs): core 3.1 s, compat 5.4 s, es3 2.3 s.
set -e
cargo build --release -p shadowcheck-runner
OUT=${1:-out/zink-swiftshader}
HERE=reports/zink-swiftshader-chromium-156
for b in egl:zink+swiftshader:core egl:zink+swiftshader:compat egl:zink+swiftshader:es3; do
  slug=$(echo "$b" | tr ':' '-')
  # exit code 100 (failures) is expected: these runs make the baselines
  /usr/bin/time -f "$b %e s" target/release/shadowcheck run --backend "$b" --out "$OUT/r-$slug" || true
done
PKGS=$(dpkg-query -W -f '${Package} ${Version}, ' chromium-common libvulkan1 libegl-mesa0 libgl1-mesa-dri 2>/dev/null | sed 's/, $//')
target/release/shadowcheck summarize -o "$HERE" "$OUT"/r-* --platform "zink (Mesa 22.3.6) on SwiftShader Vulkan (Debian 12: ${PKGS:-package versions unknown})" --update-readme README.md
# Check: every backend passes with its own baseline (exit 0).
for d in "$HERE"/*/; do
  [ -f "$d/failures.csv" ] || continue   # repro/ is not a backend
  b=$(basename "$d" | sed 's/-/:/g')
  fl=""; [ -f "$d/flakes.txt" ] && fl="--flakes $d/flakes.txt"
  target/release/shadowcheck run --backend "$b" --baseline "$d/failures.csv" $fl --out "$OUT/check-$(basename "$d")"
done

#!/usr/bin/env bash
# Run repro-color-compare-mode.html (a colour texture sampled through sampler2D while
# TEXTURE_COMPARE_MODE = COMPARE_REF_TO_TEXTURE) for several formats and compare-mode sources,
# one fresh browser per case (a GPU-process crash must not affect the next case).
#
# usage: run_repro.sh OUT_DIR [CONFIG...]   (default: swiftshader gles-llvmpipe vulkan-lavapipe)
# env: CHROMIUM, PLAYWRIGHT_DIR (as for run.sh; PLAYWRIGHT_DIR defaults to OUT_DIR/.playwright
#      as installed by run.sh)
# Writes OUT_DIR/repro/<config>/<case>/... and prints one line per case; OUT_DIR/repro/summary.md.
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
[ $# -ge 1 ] || { sed -n 2,9p "$0"; exit 2; }
mkdir -p "$1/repro"
out="$(cd "$1" && pwd)/repro"
shift
configs=("$@")
[ ${#configs[@]} -gt 0 ] || configs=(swiftshader gles-llvmpipe vulkan-lavapipe)
pw="${PLAYWRIGHT_DIR:-$out/../.playwright}"
[ -d "$pw/node_modules/playwright-core" ] || { echo "no playwright-core under $pw (run run.sh first or set PLAYWRIGHT_DIR)" >&2; exit 2; }
# shellcheck source=backends.sh
. "$here/backends.sh"
cases=(
  "fmt=RGBA8&tex=0&sampler=none"      # control: no compare mode anywhere
  "fmt=RGBA8&tex=1&sampler=nocmp"     # control: texture compare mode overridden by a sampler with NONE
  "fmt=RGBA8&tex=1&sampler=none" "fmt=RGBA8&tex=0&sampler=cmp"
  "fmt=R8&tex=1&sampler=none" "fmt=R8&tex=0&sampler=cmp"
  "fmt=RG8&tex=1&sampler=none" "fmt=RGB8&tex=1&sampler=none"
  "fmt=SRGB8_ALPHA8&tex=1&sampler=none" "fmt=RGBA8_SNORM&tex=1&sampler=none"
  "fmt=RGBA4&tex=1&sampler=none" "fmt=RGB10_A2&tex=1&sampler=none"
  "fmt=RGBA16F&tex=1&sampler=none" "fmt=R16F&tex=1&sampler=none"
  "fmt=R32F&tex=1&sampler=none" "fmt=RGBA32F&tex=1&sampler=none"
)
hdr="| case |"; sep="| --- |"
for c in "${configs[@]}"; do hdr+=" \`$c\` |"; sep+=" --- |"; done
printf '%s\n%s\n' "$hdr" "$sep" > "$out/summary.md"
declare -A res
for c in "${configs[@]}"; do
  backend_setup "$c"
  for k in "${cases[@]}"; do
    d="$out/$c/${k//[&=]/_}"
    mkdir -p "$d"
    echo "repro-color-compare-mode.html?$k" > "$d/pages.txt"
    line="$(env "${envs[@]}" node "$here/run_webgl_cts.js" --playwright "$pw" --tests "$here" --out "$d" \
      --config "$c" --pages "$d/pages.txt" --chromium "${CHROMIUM:-chromium}" --page-timeout 60 \
      --idle-timeout 30 "${flags[@]}" 2>&1 | tee "$d/run.log" | grep 'repro-color' | tail -1 || true)"
    echo "$line"
    r="$(node -e '
      const r = require(process.argv[1]).pages[0] || {};
      const d = r.dom || { pass: [], fail: [] };
      console.log(d.fail.length ? "**context lost**" + ((r.browserEvents || []).some(e => /GPU process exited/.test(e)) ? " (GPU process crashed)" : "") :
                  d.pass.length ? "ok" : "no result");' "$d/$c/results.json" 2>/dev/null || echo "no result")"
    res["$k|$c"]="$r"
  done
done
for k in "${cases[@]}"; do
  row="| \`$k\` |"
  for c in "${configs[@]}"; do row+=" ${res["$k|$c"]} |"; done
  echo "$row" >> "$out/summary.md"
done
cat "$out/summary.md"

#!/usr/bin/env bash
# Run the Khronos WebGL conformance pages listed in pages.txt (depth textures, shadow samplers,
# sampler objects, depth/stencil texture formats) in headless Chromium on three ANGLE back ends,
# one browser launch each, and summarise the results.
#
# usage: run.sh WEBGL_DIR OUT_DIR [CONFIG...]
#   WEBGL_DIR  a checkout (or exported tree) of https://github.com/KhronosGroup/WebGL; its
#              sdk/tests/ folder is served as is on 127.0.0.1 (see README.md for the commit used)
#   OUT_DIR    where the raw results go: OUT_DIR/<config>/results.json (renderer probe, every
#              page's PASS/FAIL/WARNING lines and harness counts), console.log, run.log; and
#              OUT_DIR/summary.md (made by summarize.js)
#   CONFIG     swiftshader, gles-llvmpipe and/or vulkan-lavapipe (default: all three)
# env: CHROMIUM (default: chromium on PATH), PAGES (default: pages.txt next to this script),
#      PLAYWRIGHT_DIR (a folder with node_modules/playwright-core; default: installed into
#      OUT_DIR/.playwright from the npm registry, no browser download),
#      WEBGL_COMMIT (recorded commit when WEBGL_DIR is not a git checkout),
#      PAGE_TIMEOUT_S (default 300, per page), IDLE_TIMEOUT_S (default 120, no new result),
#      WEBGL_CTS_HARD_LIMIT_S (default 3600, per configuration).
# Needs: chromium, node, npm; Mesa llvmpipe (EGL) and lavapipe (Vulkan ICD) for the last two.
# The flags and environment of each configuration are in backends.sh.
set -euo pipefail

here="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
[ $# -ge 2 ] || { sed -n 2,22p "$0"; exit 2; }
webgl="$(cd "$1" && pwd)"
tests="$webgl/sdk/tests"
[ -f "$tests/js/js-test-pre.js" ] || { echo "$tests/js/js-test-pre.js not found" >&2; exit 2; }
mkdir -p "$2"
out="$(cd "$2" && pwd)"
shift 2
configs=("$@")
[ ${#configs[@]} -gt 0 ] || configs=(swiftshader gles-llvmpipe vulkan-lavapipe)
chromium_bin="${CHROMIUM:-chromium}"
pages="${PAGES:-$here/pages.txt}"

commit="${WEBGL_COMMIT:-}"
if [ -z "$commit" ] && git -C "$webgl" rev-parse --git-dir >/dev/null 2>&1; then
  commit="$(git -C "$webgl" rev-parse HEAD)"
fi
echo "${commit:-unknown}" > "$out/webgl-commit.txt"
"$chromium_bin" --version 2>/dev/null | tee "$out/chromium-version.txt"
node --version

pw="${PLAYWRIGHT_DIR:-}"
if [ -z "$pw" ]; then
  pw="$out/.playwright"
  if [ ! -d "$pw/node_modules/playwright-core" ]; then
    mkdir -p "$pw"
    PLAYWRIGHT_SKIP_BROWSER_DOWNLOAD=1 npm install --prefix "$pw" --no-audit --no-fund --no-save \
      playwright-core@1.65.1
  fi
fi

# shellcheck source=backends.sh
. "$here/backends.sh"
for c in "${configs[@]}"; do
  backend_setup "$c" || exit 2
  start=$(date +%s)
  mkdir -p "$out/$c"
  env "${envs[@]}" node "$here/run_webgl_cts.js" --playwright "$pw" --tests "$tests" --out "$out" \
    --config "$c" --pages "$pages" --chromium "$chromium_bin" \
    --page-timeout "${PAGE_TIMEOUT_S:-300}" --idle-timeout "${IDLE_TIMEOUT_S:-120}" \
    "${flags[@]}" 2>&1 | tee "$out/$c/run.log" ||
    echo "run_webgl_cts.js for $c failed" >&2
  echo "$c took $(( $(date +%s) - start )) s" | tee -a "$out/$c/run.log"
done

node "$here/summarize.js" "$out" "${configs[@]}" > "$out/summary.md"
echo "summary: $out/summary.md"

#!/usr/bin/env bash
# Run the WebGPU CTS comparison-sampler tests (textureSampleCompare, textureSampleCompareLevel,
# textureGatherCompare) in headless Chromium, in two configurations, and summarise the results.
#
# usage: run.sh CTS_DIR OUT_DIR [CONFIG...]
#   CTS_DIR  a checkout of https://github.com/gpuweb/cts (the one manual step; see README.md
#            for the commit used). It is built in place: npm ci + npm run standalone.
#   OUT_DIR  where the raw results go: OUT_DIR/<config>/*.json (the CTS's own results JSON,
#            one file per test), meta.json (adapter info, timings), console.log; and
#            OUT_DIR/summary.md (made by summarize.js).
#   CONFIG   swiftshader-core and/or opengles-compat (default: both).
# env: CHROMIUM (default: chromium on PATH), SKIP_BUILD=1 (reuse an existing build),
#      CTS_VERSION (version string for a CTS_DIR that is not a git checkout),
#      QUERY_TIMEOUT_S (default 1800, per test query), CTS_HARD_LIMIT_S (default 14400, per config).
# Needs: chromium, node, npm (reaches the npm registry for `npm ci`). No browser is downloaded.
set -euo pipefail

here="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
[ $# -ge 2 ] || { sed -n 2,20p "$0"; exit 2; }
cts="$(cd "$1" && pwd)"
mkdir -p "$2"
out="$(cd "$2" && pwd)"
shift 2
configs=("$@")
[ ${#configs[@]} -gt 0 ] || configs=(swiftshader-core opengles-compat)
chromium_bin="${CHROMIUM:-chromium}"

"$chromium_bin" --version
node --version

cd "$cts"
if [ "${SKIP_BUILD:-0}" != 1 ]; then
  # playwright-core (a CTS devDependency) downloads nothing at install; skip any browser download.
  PUPPETEER_SKIP_DOWNLOAD=1 PLAYWRIGHT_SKIP_BROWSER_DOWNLOAD=1 npm ci --no-audit --no-fund
  if git -C "$cts" rev-parse --git-dir >/dev/null 2>&1; then
    npm run standalone
  else
    # tools/gen_version runs `git describe`; for an exported (non-git) tree answer it with
    # $CTS_VERSION through a shim, everything else goes to the real git.
    shim="$(mktemp -d)"
    real_git="$(command -v git || echo false)"
    printf '#!/bin/sh\ncase "$1" in describe) echo "${CTS_VERSION:-unknown}"; exit 0;; esac\nexec %s "$@"\n' \
      "$real_git" > "$shim/git"
    chmod +x "$shim/git"
    PATH="$shim:$PATH" npm run standalone
    rm -rf "$shim"
  fi
fi

# One query per test (file:test:*), listed by the CTS's own command-line tool.
queries=()
for t in textureSampleCompare textureSampleCompareLevel textureGatherCompare; do
  while IFS= read -r q; do queries+=("$q"); done < <(
    node tools/run_node --list "webgpu:shader,execution,expression,call,builtin,$t:*" |
      awk -F: '{print $1":"$2":"$3":*"}' | sort -u)
done
printf '%s\n' "${queries[@]}" > "$out/queries.txt"
echo "queries: ${#queries[@]}"
qargs=()
for q in "${queries[@]}"; do qargs+=(--query "$q"); done

common_flags=(--flag=--use-angle=swiftshader --flag=--enable-unsafe-swiftshader)
for c in "${configs[@]}"; do
  case "$c" in
    swiftshader-core) extra=() ;;
    opengles-compat) extra=(--compat --flag=--use-webgpu-adapter=opengles) ;;
    *) echo "unknown config $c" >&2; exit 2 ;;
  esac
  start=$(date +%s)
  node "$here/run_cts.js" --cts "$cts" --out "$out" --config "$c" --chromium "$chromium_bin" \
    --query-timeout "${QUERY_TIMEOUT_S:-1800}" "${common_flags[@]}" "${extra[@]}" "${qargs[@]}" ||
    echo "run_cts.js for $c exited with $?" >&2
  echo "$c took $(( $(date +%s) - start )) s"
done

node "$here/summarize.js" "$out" > "$out/summary.md"
echo "summary: $out/summary.md"

#!/bin/sh
# How the Mesa 22.3.6 reference results in this folder were made (Debian 12, 2 CPUs, no GPU;
# Mesa from the distribution: libegl-mesa0 libgl1-mesa-dri libosmesa6 mesa-vulkan-drivers).
# Run from the repository root:  sh reports/mesa-22.3.6/run.sh [OUTROOT]
#
# Binary: the commit that last changed this folder (run.sh is re-run whenever the fixtures change).
# Fixtures: the committed default set (cases/fixtures).
#
# Shader cache: Mesa's on-disk cache is left ON (default: ~/.cache/mesa_shader_cache; the GL worker
# does not disable it). Timings for one backend each (wall clock, 2 shared CPUs):
#   warm cache (what produced the committed files, 2026-11-21): 1-3 s per core/es3 backend,
#     5-7 s per compat backend, all 13 backends in about 40 s;
#   cold cache (first run after the GL worker changed, same day): egl llvmpipe core 62 s,
#     zink core 48 s, zink es3 38 s, llvmpipe compat 144 s, zink compat 129 s, osmesa llvmpipe
#     compat 115 s, osmesa llvmpipe core 60 s; softpipe backends 1-2 s either way (no JIT).
#   To time a cold run: MESA_SHADER_CACHE_DIR=$(mktemp -d) before the command (or
#   MESA_SHADER_CACHE_DISABLE=true to keep the cache out altogether: every run is then cold).
set -e
cargo build --release -p shadowcheck-runner
OUT=${1:-out/mesa-22.3.6}
for b in egl:llvmpipe:core egl:llvmpipe:compat egl:llvmpipe:es3 \
         egl:softpipe:core egl:softpipe:compat egl:softpipe:es3 \
         egl:zink:core egl:zink:compat egl:zink:es3 \
         osmesa:llvmpipe:core osmesa:llvmpipe:compat osmesa:softpipe:core osmesa:softpipe:compat; do
  slug=$(echo "$b" | tr ':' '-')
  # exit code 100 (failures) is expected for most backends: these runs make the baselines
  /usr/bin/time -f "$b %e s" target/release/shadowcheck run --backend "$b" --out "$OUT/r-$slug" || true
done
# Condense into this folder: failures.csv (baseline), warnings.csv, summary.md, report.md (capped),
# and SUMMARY.md over all backends x API paths (`shadowcheck summarize --help`).
# The exact Debian package versions go into every summary (the folder name says only 22.3.6).
PKGS=$(dpkg-query -W -f '${Package} ${Version}, ' libegl-mesa0 libgl1-mesa-dri libosmesa6 mesa-vulkan-drivers 2>/dev/null | sed 's/, $//')
target/release/shadowcheck summarize -o reports/mesa-22.3.6 "$OUT"/r-* --platform "Mesa 22.3.6 (Debian 12: ${PKGS:-package versions unknown})" --update-readme README.md
# The ARB fp DEPTH_TEXTURE_MODE=ALPHA results flip between runs on llvmpipe/softpipe: those tests
# are kept out of the baselines and listed in flakes.txt (committed by hand, see ../README.md).
for b in egl-llvmpipe-compat osmesa-llvmpipe-compat egl-softpipe-compat osmesa-softpipe-compat; do
  grep -v 'dtm=alpha\(/.*\)\?@arbfp"\?,' "reports/mesa-22.3.6/$b/failures.csv" > "$OUT/f.csv"
  cp "$OUT/f.csv" "reports/mesa-22.3.6/$b/failures.csv"
done
# zink compat: the tests of egl-zink-compat/flakes.txt flip between r = 0 and 1; kept out of its baseline.
grep -v '^#' reports/mesa-22.3.6/egl-zink-compat/flakes.txt | sed 's/\$$/,/' > "$OUT/flakes.re"
grep -vEf "$OUT/flakes.re" reports/mesa-22.3.6/egl-zink-compat/failures.csv > "$OUT/f.csv"
cp "$OUT/f.csv" reports/mesa-22.3.6/egl-zink-compat/failures.csv
# Check: every backend passes with its own baseline (exit 0).
for d in reports/mesa-22.3.6/*/; do
  [ -f "$d/failures.csv" ] || continue   # repro/ and other folders that are not a backend's
  b=$(basename "$d" | sed 's/-/:/g')
  fl=""; [ -f "$d/flakes.txt" ] && fl="--flakes $d/flakes.txt"
  target/release/shadowcheck run --backend "$b" --baseline "$d/failures.csv" $fl --out "$OUT/check-$(basename "$d")"
done
# The HTML report (reports/index.html): every backend of this machine in one run (the main job),
# then `shadowcheck report` over its results.
/usr/bin/time -f "all backends %e s" target/release/shadowcheck run --out "$OUT/all" || true
target/release/shadowcheck report "$OUT/all" -o reports

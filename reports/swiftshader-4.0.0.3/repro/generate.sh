#!/bin/sh
# Regenerates the reproducers written by `shadowcheck repro` (the gen-* directories: repro.c,
# build.sh, output.txt, REPORT.md), one per failure class of egl:swiftshader:es3 (`shadowcheck repro
# --all-failures` over its results gives these classes), beside the hand-written ones of the same
# causes (depth-completeness/, dref-clamp/, ...). Each repro.c opens SwiftShader's EGL 1.4 library
# as the GL worker does (a pbuffer context); build.sh links and runs it against the library's
# directory, ${SHADOWCHECK_SWIFTSHADER_DIR:-${XDG_CACHE_HOME:-$HOME/.cache}/shadowcheck/swiftshader-4.0.0.3}.
# Run from the repository root after `cargo build --release` and `sh gl/fetch-swiftshader.sh`; needs
# gcc libegl-dev libgles-dev.
set -e
S=${SHADOWCHECK:-target/release/shadowcheck}
D=reports/swiftshader-4.0.0.3/repro
gen() { # dir test
  "$S" repro --backend egl:swiftshader:es3 --case "$2" -o "$D/$1"
  rm -f "$D/$1/repro"
}
gen gen-depth-completeness 'gles32/2d/d16/lml/none/lod=1/read/levels=0.2_0.8_0.4@es300'
gen gen-dref-clamp 'gles32/2d/d24/nearest/less/clamp/dt=0/ref=0@es300'
gen gen-linear-layer-tie 'gles32/2darray/d24/linear/lequal/layer/layer=0.5/ref=0.3/layers=0.2_0.8_0.4@es300'
gen gen-mirror-offset 'gles32/2d/d24/nearest/lequal/offset/wrap=mirror/texel=1_2/offset=-8_7/ref=0.5@es300'
gen gen-sampler-object-completeness 'gles32/2d/d24/linear/lequal/sampler_object/so_none_linear/s=0.5/ref=0.5@es300'
gen gen-texparam-invalid-value 'state/gles32/es/2d/compare_func/set=-1@es300'

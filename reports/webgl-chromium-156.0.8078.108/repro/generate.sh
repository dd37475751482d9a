#!/bin/sh
# Regenerates the reproducers written by `shadowcheck repro` (the w<N>-* directories: repro.html,
# build.sh, output.txt, REPORT.md), one per failure class of the WebGL 2.0 runs in this folder
# (`shadowcheck repro --all-failures` over the three backends' results gives these classes; causes
# W1-W3 of reports/README.md). Each repro.html is a plain WebGL 2.0 page; build.sh runs it in headless
# Chromium with the instance's flags and environment (webgl/src/instance.rs).
# Run from the repository root after `cargo build --release`; needs chromium (and, for the gles and
# lavapipe instances, libegl-mesa0 libgl1-mesa-dri / mesa-vulkan-drivers). The hand-written
# reproducer webgl2-compare/ is not touched.
set -e
S=${SHADOWCHECK:-target/release/shadowcheck}
D=reports/webgl-chromium-156.0.8078.108/repro
gen() { # dir backend test
  "$S" repro --backend "$2" --case "$3" -o "$D/$1"
}
# W1: a comparison applied to an R8 colour texture (compare mode is ignored for a non-depth format).
gen w1-r8-compare-chromium webgl:chromium 'gles32/2d/r8/lml/less/lod=1/ref=0.5/levels=0.2_0.8_0.4@es300'
gen w1-r8-compare-lavapipe webgl:chromium-lavapipe 'gles32/2d/r8/lml/less/lod=1/ref=0.5/levels=0.2_0.8_0.4@es300'
# W2: DEPTH_COMPONENT24 compared as a floating-point texture (the reference is not clamped to [0, 1]).
gen w2-d24-reference-clamp-chromium webgl:chromium 'gles32/2d/d24/nearest/less/clamp/dt=0/ref=0@es300'
# W3: the LINEAR array-layer tie, on all three ANGLE back ends.
gen w3-layer-tie-chromium webgl:chromium 'gles32/2darray/d24/linear/lequal/layer/layer=0.5/ref=0.3/layers=0.2_0.8_0.4@es300'
gen w3-layer-tie-chromium-gles webgl:chromium-gles 'gles32/2darray/d24/linear/lequal/layer/layer=0.5/ref=0.3/layers=0.2_0.8_0.4@es300'
gen w3-layer-tie-chromium-lavapipe webgl:chromium-lavapipe 'gles32/2darray/d24/linear/lequal/layer/layer=0.5/ref=0.3/layers=0.2_0.8_0.4@es300'

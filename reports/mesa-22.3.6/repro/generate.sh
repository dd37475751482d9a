#!/bin/sh
# Regenerates the reproducers written by `shadowcheck repro` (the cause<N>-* directories: repro.c,
# build.sh, output.txt, REPORT.md), one known Fail per "shall"-level Mesa cause of reports/README.md.
# Run from the repository root after `cargo build --release`; needs gcc and the GL dev packages
# (apt-get install -y gcc libegl-dev libgles-dev libgl-dev libosmesa6-dev). The hand-written
# reproducers (linear-layer-tie/, compat-layouts/, gather-softpipe-cube-array/,
# interact-softpipe-gather-swizzle-sampler-object/) are not touched.
set -e
S=${SHADOWCHECK:-target/release/shadowcheck}
D=reports/mesa-22.3.6/repro
gen() { # dir backend test
  "$S" repro --backend "$2" --case "$3" -o "$D/$1"
  rm -f "$D/$1/repro"
}
gen cause2-es-depth-completeness egl:llvmpipe:es3 'gles32/2d/d24/linear/none/a=0.25_0.5/read/dt=0.2_0.4_0.6_0.8@es300'
gen cause3-softpipe-compare-after-filtering egl:softpipe:core 'gl46/2d/d24/linear/equal/pcf/a=0.5_0.5/ref=0.5/dt=0.2_0.4_0.6_0.8@core'
gen cause5-ff-1d-compares-t egl:llvmpipe:compat 'arb/1d/d16/nearest/lequal/texel1/ref=0.5/dt=0.2_0.4_0.6_0.8@ff'
gen cause6-zink-depth-texture-mode egl:zink:compat 'arb/2d/d24/linear/lequal/wrap/wrap=clamp/st=-0.25_0.25/border=1/ref=0.5@glsl120'
gen cause7-glsl130-alpha-intensity egl:llvmpipe:compat 'gl46/2d/d24/nearest/none/dtm/dtm=alpha/texel1/ref=0.3@glsl130'
gen cause8-softpipe-grad-lod-bias egl:softpipe:core:grad 'gl46/2d/d24/nmn/lequal/mip/lod_bias=1/lod=0/ref=0.5/levels=0.2_0.8_0.4@core'
gen cause9-linear-layer-tie-core egl:llvmpipe:core 'gl46/2darray/d24/linear/lequal/layer/layer=0.5/ref=0.6/layers=0.2_0.8_0.4@core'
# Issue 16 (unit state): the same causes reached through the swizzle and a sampler object.
gen i16-cause7-swizzle-alpha egl:llvmpipe:compat 'gl46/2d/d24/nearest/none/swizzle/swizzle=zero_green_blue_alpha/dtm=alpha/texel1/ref=0.5@glsl130'
gen i16-cause2-sampler-object-none egl:llvmpipe:es3 'gles32/2d/d24/linear/lequal/sampler_object/so_none_linear/s=0.5/ref=0.5@es300'
gen i16-cause6-zink-sampler-object egl:zink:compat 'gl46/2d/d24/nearest/lequal/sampler_object/so_func/s=0.75/ref=0.5@glsl120'
# The second audit (oracle round two): a sampler object's rectangle-illegal state (GL 4.6 §8.2), and
# cause 6 reached through the swizzle on zink's compatibility paths.
gen cause11-rect-sampler-object-incomplete egl:llvmpipe:core 'gl46/rect/d24/nearest/lequal/sampler_object/so_rect_wrap=repeat/u=2.5/ref=0.5@core'
gen r2-cause6-zink-swizzle egl:zink:compat 'gl46/2d/d24/nearest/lequal/swizzle/swizzle=zero_green_blue_alpha/texel1/ref=0.5@glsl120'
# The `interact` covering array: cause 7 reached through a swizzled *shadow* lookup (the
# hand-written interact-softpipe-gather-swizzle-sampler-object/ is not touched).
gen interact-cause7-shadow-swizzle-alpha egl:llvmpipe:compat 'gl46/cube/d24/linear/lequal/interact/swizzle=gbar+seamless=off+dtm=alpha@glsl130'

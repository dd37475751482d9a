#!/bin/sh
# shadowcheck reproducer for gl46/rect/d24/nearest/lequal/sampler_object/so_rect_wrap=repeat/u=2.5/ref=0.5@core on egl:llvmpipe:core.
# Debian 12: apt-get install -y gcc libegl-dev libgl-dev libegl-mesa0 libgl1-mesa-dri
cd "$(dirname "$0")" || exit 2
cc -std=c99 -O1 -Wall -o repro repro.c -lEGL -lGL -lm || exit 2
exec env LIBGL_ALWAYS_SOFTWARE=1 GALLIUM_DRIVER=llvmpipe EGL_PLATFORM=surfaceless ./repro

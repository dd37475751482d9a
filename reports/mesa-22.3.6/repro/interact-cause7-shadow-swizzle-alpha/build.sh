#!/bin/sh
# shadowcheck reproducer for gl46/cube/d24/linear/lequal/interact/swizzle=gbar+seamless=off+dtm=alpha@glsl130 on egl:llvmpipe:compat.
# Debian 12: apt-get install -y gcc libegl-dev libgl-dev libegl-mesa0 libgl1-mesa-dri
cd "$(dirname "$0")" || exit 2
cc -std=c99 -O1 -Wall -o repro repro.c -lEGL -lGL -lm || exit 2
exec env LIBGL_ALWAYS_SOFTWARE=1 GALLIUM_DRIVER=llvmpipe EGL_PLATFORM=surfaceless ./repro

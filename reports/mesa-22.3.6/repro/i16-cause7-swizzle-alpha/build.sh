#!/bin/sh
# shadowcheck reproducer for gl46/2d/d24/nearest/none/swizzle/swizzle=zero_green_blue_alpha/dtm=alpha/texel1/ref=0.5@glsl130 on egl:llvmpipe:compat.
# Debian 12: apt-get install -y gcc libegl-dev libgl-dev libegl-mesa0 libgl1-mesa-dri
cd "$(dirname "$0")" || exit 2
cc -std=c99 -O1 -Wall -o repro repro.c -lEGL -lGL -lm || exit 2
exec env LIBGL_ALWAYS_SOFTWARE=1 GALLIUM_DRIVER=llvmpipe EGL_PLATFORM=surfaceless ./repro

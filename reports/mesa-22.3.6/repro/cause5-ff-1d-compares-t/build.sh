#!/bin/sh
# shadowcheck reproducer for arb/1d/d16/nearest/lequal/texel1/ref=0.5/dt=0.2_0.4_0.6_0.8@ff on egl:llvmpipe:compat.
# Debian 12: apt-get install -y gcc libegl-dev libgl-dev libegl-mesa0 libgl1-mesa-dri
cd "$(dirname "$0")" || exit 2
cc -std=c99 -O1 -Wall -o repro repro.c -lEGL -lGL -lm || exit 2
exec env LIBGL_ALWAYS_SOFTWARE=1 GALLIUM_DRIVER=llvmpipe EGL_PLATFORM=surfaceless ./repro

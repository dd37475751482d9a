#!/bin/sh
# shadowcheck reproducer for gl46/2d/d24/linear/equal/pcf/a=0.5_0.5/ref=0.5/dt=0.2_0.4_0.6_0.8@core on egl:softpipe:core.
# Debian 12: apt-get install -y gcc libegl-dev libgl-dev libegl-mesa0 libgl1-mesa-dri
cd "$(dirname "$0")" || exit 2
cc -std=c99 -O1 -Wall -o repro repro.c -lEGL -lGL -lm || exit 2
exec env LIBGL_ALWAYS_SOFTWARE=1 GALLIUM_DRIVER=softpipe EGL_PLATFORM=surfaceless ./repro

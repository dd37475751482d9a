#!/bin/sh
# shadowcheck reproducer for arb/2d/d24/linear/lequal/wrap/wrap=clamp/st=-0.25_0.25/border=1/ref=0.5@glsl120 on egl:zink:compat.
# Debian 12: apt-get install -y gcc libegl-dev libgl-dev libegl-mesa0 libgl1-mesa-dri mesa-vulkan-drivers
cd "$(dirname "$0")" || exit 2
cc -std=c99 -O1 -Wall -o repro repro.c -lEGL -lGL -lm || exit 2
exec env LIBGL_ALWAYS_SOFTWARE=1 GALLIUM_DRIVER=zink EGL_PLATFORM=surfaceless ./repro

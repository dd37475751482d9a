#!/bin/sh
# shadowcheck reproducer for gl46/2d/d24/nearest/lequal/swizzle/swizzle=zero_green_blue_alpha/texel1/ref=0.5@glsl120 on egl:zink:compat.
# Debian 12: apt-get install -y gcc libegl-dev libgl-dev libegl-mesa0 libgl1-mesa-dri mesa-vulkan-drivers
cd "$(dirname "$0")" || exit 2
cc -std=c99 -O1 -Wall -o repro repro.c -lEGL -lGL -lm || exit 2
exec env LIBGL_ALWAYS_SOFTWARE=1 GALLIUM_DRIVER=zink EGL_PLATFORM=surfaceless ./repro

#!/bin/sh
# shadowcheck reproducer for gles32/2d/d24/linear/none/a=0.25_0.5/read/dt=0.2_0.4_0.6_0.8@es300 on egl:llvmpipe:es3.
# Debian 12: apt-get install -y gcc libegl-dev libgles-dev libegl-mesa0 libgl1-mesa-dri
cd "$(dirname "$0")" || exit 2
cc -std=c99 -O1 -Wall -o repro repro.c -lEGL -lGLESv2 -lm || exit 2
exec env LIBGL_ALWAYS_SOFTWARE=1 GALLIUM_DRIVER=llvmpipe EGL_PLATFORM=surfaceless ./repro

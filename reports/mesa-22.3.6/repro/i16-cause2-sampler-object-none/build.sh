#!/bin/sh
# shadowcheck reproducer for gles32/2d/d24/linear/lequal/sampler_object/so_none_linear/s=0.5/ref=0.5@es300 on egl:llvmpipe:es3.
# Debian 12: apt-get install -y gcc libegl-dev libgles-dev libegl-mesa0 libgl1-mesa-dri
cd "$(dirname "$0")" || exit 2
cc -std=c99 -O1 -Wall -o repro repro.c -lEGL -lGLESv2 -lm || exit 2
exec env LIBGL_ALWAYS_SOFTWARE=1 GALLIUM_DRIVER=llvmpipe EGL_PLATFORM=surfaceless ./repro

#!/bin/sh
# Shadow textureGather with a texture swizzle and a bound sampler object (interact covering array). Debian 12: apt-get install -y gcc libegl-dev libgles-dev libegl-mesa0 libgl1-mesa-dri
# sh build.sh            softpipe (exits 1 on Mesa 22.3.6)
# DRIVER=llvmpipe sh build.sh   llvmpipe (exits 0)
cd "$(dirname "$0")" || exit 2
cc -std=c99 -O1 -Wall -o repro repro.c -lEGL -lGLESv2 -lm || exit 2
exec env LIBGL_ALWAYS_SOFTWARE=1 GALLIUM_DRIVER=${DRIVER:-softpipe} EGL_PLATFORM=surfaceless ./repro

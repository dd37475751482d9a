#!/bin/sh
# Compute-shader image store vs. the framebuffer read-back. Debian 12: apt-get install -y gcc libegl-dev libgles-dev libegl-mesa0 libgl1-mesa-dri
# sh build.sh                    softpipe (exits 1 on Mesa 22.3.6)
# ARGS=unbind sh build.sh        softpipe, framebuffer unbound around the dispatch (exits 0)
# DRIVER=llvmpipe sh build.sh    llvmpipe (exits 0)
cd "$(dirname "$0")" || exit 2
cc -std=c99 -O1 -Wall -o repro repro.c -lEGL -lGLESv2 || exit 2
exec env LIBGL_ALWAYS_SOFTWARE=1 GALLIUM_DRIVER=${DRIVER:-softpipe} EGL_PLATFORM=surfaceless ./repro $ARGS

#!/bin/sh
# shadowcheck reproducer for gl46/cubearray/d24/nml/gequal/lod=1/ref=0.5/levels=0.2_0.8_0.4@core on egl:zink+swiftshader:core.
# Debian 12: apt-get install -y gcc libegl-dev libgl-dev libegl-mesa0 libgl1-mesa-dri chromium-common
cd "$(dirname "$0")" || exit 2
cc -std=c99 -O1 -Wall -o repro repro.c -lEGL -lGL -lm || exit 2
exec env LIBGL_ALWAYS_SOFTWARE=1 GALLIUM_DRIVER=zink EGL_PLATFORM=surfaceless VK_ICD_FILENAMES=/usr/lib/chromium/vk_swiftshader_icd.json MESA_GL_VERSION_OVERRIDE=4.6 MESA_GLSL_VERSION_OVERRIDE=460 ./repro

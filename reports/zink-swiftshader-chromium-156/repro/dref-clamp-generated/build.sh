#!/bin/sh
# shadowcheck reproducer for gl46/2d/d24/nearest/less/clamp/dt=0/ref=-0.1@core on egl:zink+swiftshader:core.
# Debian 12: apt-get install -y gcc libegl-dev libgl-dev libegl-mesa0 libgl1-mesa-dri chromium-common
cd "$(dirname "$0")" || exit 2
cc -std=c99 -O1 -Wall -o repro repro.c -lEGL -lGL -lm || exit 2
exec env LIBGL_ALWAYS_SOFTWARE=1 GALLIUM_DRIVER=zink EGL_PLATFORM=surfaceless VK_ICD_FILENAMES=/usr/lib/chromium/vk_swiftshader_icd.json MESA_GL_VERSION_OVERRIDE=4.6 MESA_GLSL_VERSION_OVERRIDE=460 ./repro

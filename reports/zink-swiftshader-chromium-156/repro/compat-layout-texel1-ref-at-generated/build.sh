#!/bin/sh
# shadowcheck reproducer for ext_funcs/1d/d24/nearest/less/texel1/ref=at/dt=0.2_0.4_0.6_0.8@arbfp on egl:zink+swiftshader:compat.
# Debian 12: apt-get install -y gcc libegl-dev libgl-dev libegl-mesa0 libgl1-mesa-dri chromium-common
cd "$(dirname "$0")" || exit 2
cc -std=c99 -O1 -Wall -o repro repro.c -lEGL -lGL -lm || exit 2
exec env LIBGL_ALWAYS_SOFTWARE=1 GALLIUM_DRIVER=zink EGL_PLATFORM=surfaceless VK_ICD_FILENAMES=/usr/lib/chromium/vk_swiftshader_icd.json ./repro

#!/bin/sh
# Debian 12: apt-get install -y gcc libegl-dev libgl-dev libegl-mesa0 libgl1-mesa-dri mesa-vulkan-drivers chromium-common
# Runs repro.c on zink over SwiftShader Vulkan (chromium-common's ICD), zink over lavapipe, llvmpipe
# and softpipe; output.txt is this script's output. Exit status of each run: 1 = a grad-x probe (dPdy = 0,
# where the spec fixes lambda) read another level than lambda = F gives, 0 = none did.
cd "$(dirname "$0")"
cc -O1 -Wall -o repro repro.c -lEGL -lGL || exit 2
run() { echo "== $1"; shift; env "$@" ./repro 2>&1 | grep -v -e XDG_RUNTIME_DIR -e 'base Zink requirements'; echo "exit $(env "$@" ./repro >/dev/null 2>&1; echo $?)"; }
run "zink on SwiftShader Vulkan" LIBGL_ALWAYS_SOFTWARE=1 GALLIUM_DRIVER=zink VK_ICD_FILENAMES=/usr/lib/chromium/vk_swiftshader_icd.json
run "zink on lavapipe" LIBGL_ALWAYS_SOFTWARE=1 GALLIUM_DRIVER=zink
run "llvmpipe" LIBGL_ALWAYS_SOFTWARE=1 GALLIUM_DRIVER=llvmpipe
run "softpipe" LIBGL_ALWAYS_SOFTWARE=1 GALLIUM_DRIVER=softpipe
rm -f repro

#!/bin/sh
# Debian 12: apt-get install -y gcc libegl-dev libgl-dev libegl-mesa0 libgl1-mesa-dri mesa-vulkan-drivers
cd "$(dirname "$0")"
cc -O1 -Wall -o repro repro.c -lEGL -lGL || exit 2
for d in llvmpipe softpipe; do echo "== GALLIUM_DRIVER=$d"; GALLIUM_DRIVER=$d ./repro && echo "exit 0" || echo "exit $?"; done
echo "== zink (lavapipe)"; LIBGL_ALWAYS_SOFTWARE=1 GALLIUM_DRIVER=zink ./repro 2>&1 | grep -v XDG_RUNTIME_DIR; echo "exit $(LIBGL_ALWAYS_SOFTWARE=1 GALLIUM_DRIVER=zink ./repro >/dev/null 2>&1; echo $?)"

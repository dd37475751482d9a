#!/bin/sh
# Debian 12: apt-get install -y gcc libegl-dev libgles-dev libegl-mesa0 libgl1-mesa-dri chromium-common;
# SwiftShader's GLES from gl/fetch-swiftshader.sh. Writes output.txt beside this file.
cd "$(dirname "$0")"
cc -O1 -Wall -o ./depth-completeness repro.c -lEGL -lGLESv2 || exit 2
SS=${SHADOWCHECK_SWIFTSHADER_DIR:-${XDG_CACHE_HOME:-$HOME/.cache}/shadowcheck/swiftshader-4.0.0.3}
LINKS=$(mktemp -d); ln -s "$SS/libEGL.so" "$LINKS/libEGL.so.1"; ln -s "$SS/libGLESv2.so" "$LINKS/libGLESv2.so.2"
{
echo "== Mesa llvmpipe"; EGL_PLATFORM=surfaceless LIBGL_ALWAYS_SOFTWARE=1 GALLIUM_DRIVER=llvmpipe ./depth-completeness; echo "exit $?"
echo "== zink on SwiftShader Vulkan (chromium-common), ES 3.1 override as egl:zink+swiftshader:es3"
VK_ICD_FILENAMES=/usr/lib/chromium/vk_swiftshader_icd.json MESA_GLES_VERSION_OVERRIDE=3.1 EGL_PLATFORM=surfaceless LIBGL_ALWAYS_SOFTWARE=1 GALLIUM_DRIVER=zink ./depth-completeness; echo "exit $?"
echo "== SwiftShader 4.0.0.3 GLES (cefpython3 66.0)"; LD_LIBRARY_PATH=$LINKS:$SS ./depth-completeness; echo "exit $?"
} 2>/dev/null > output.txt
rm -rf "$LINKS"
cat output.txt

#!/bin/sh
# Builds and runs the reproducer on llvmpipe, zink on lavapipe and zink on SwiftShader Vulkan;
# writes output.txt beside this file. Needs gcc and libegl-dev (headers); chromium-common's ICD.
set -e
cd "$(dirname "$0")"
gcc -O1 -o ./cube-array-lod repro.c -lEGL
ICD=/usr/lib/chromium/vk_swiftshader_icd.json
{
  echo "== Mesa llvmpipe"; LIBGL_ALWAYS_SOFTWARE=1 GALLIUM_DRIVER=llvmpipe ./cube-array-lod
  echo "== Mesa zink on lavapipe"; LIBGL_ALWAYS_SOFTWARE=1 GALLIUM_DRIVER=zink ./cube-array-lod
  echo "== Mesa zink on SwiftShader Vulkan (chromium-common), GL 4.6 override as egl:zink+swiftshader:core"
  VK_ICD_FILENAMES=$ICD MESA_GL_VERSION_OVERRIDE=4.6 MESA_GLSL_VERSION_OVERRIDE=460 LIBGL_ALWAYS_SOFTWARE=1 GALLIUM_DRIVER=zink ./cube-array-lod
} 2>/dev/null > output.txt
cat output.txt

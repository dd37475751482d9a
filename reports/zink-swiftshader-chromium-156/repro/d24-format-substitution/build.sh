#!/bin/sh
# Why GL's fixed-point depth textures are compared without the [0, 1] clamp on zink over SwiftShader
# Vulkan (cause S1 in reports/README.md): SwiftShader's Vulkan driver cannot sample
# VK_FORMAT_X8_D24_UNORM_PACK32 or VK_FORMAT_D24_UNORM_S8_UINT (vkformats.c), so zink stores GL's
# 24-bit depth (and GL's DEPTH_COMPONENT32, which Mesa keeps as 24-bit: depthfmt.c) in
# VK_FORMAT_D32_SFLOAT, while GL still reports a 24-bit unsigned-normalized texture (depthfmt.c).
# Vulkan clamps Dref only for UNORM formats, so SwiftShader's unclamped compare is Vulkan's rule
# for the format it was given.
# Debian 12: apt-get install -y gcc libegl-dev libgl-dev libegl-mesa0 libgl1-mesa-dri libvulkan1 mesa-vulkan-drivers chromium-common
cd "$(dirname "$0")" || exit 2
cc -std=c99 -O1 -Wall -o vkformats vkformats.c -ldl || exit 2
cc -std=c99 -O1 -Wall -o depthfmt depthfmt.c -lEGL -lGL || exit 2
echo "== Vulkan formats: SwiftShader (/usr/lib/chromium/vk_swiftshader_icd.json)"
VK_ICD_FILENAMES=/usr/lib/chromium/vk_swiftshader_icd.json ./vkformats
echo "== Vulkan formats: lavapipe"
VK_ICD_FILENAMES=$(ls /usr/share/vulkan/icd.d/lvp_icd*.json | head -1) ./vkformats
echo "== GL level-0 state: zink on SwiftShader Vulkan (its native GL is 2.1: the core context needs the backend's overrides)"
LIBGL_ALWAYS_SOFTWARE=1 GALLIUM_DRIVER=zink EGL_PLATFORM=surfaceless VK_ICD_FILENAMES=/usr/lib/chromium/vk_swiftshader_icd.json MESA_GL_VERSION_OVERRIDE=4.6 MESA_GLSL_VERSION_OVERRIDE=460 ./depthfmt 2>/dev/null
for d in zink llvmpipe; do
  echo "== GL level-0 state: GALLIUM_DRIVER=$d"
  LIBGL_ALWAYS_SOFTWARE=1 GALLIUM_DRIVER=$d EGL_PLATFORM=surfaceless ./depthfmt 2>/dev/null
done
rm -f vkformats depthfmt

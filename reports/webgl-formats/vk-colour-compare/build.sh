#!/bin/sh
# Plain Vulkan: an RGBA8 colour image sampled through sampler2D with a compare-enabled VkSampler,
# on lavapipe (the layer under webgl:chromium-lavapipe). Three runs: compare on NEAREST, compare on
# LINEAR, compare off (control). Debian 12: apt-get install -y gcc libvulkan-dev glslang-tools libvulkan1 mesa-vulkan-drivers
cd "$(dirname "$0")" || exit 2
glslangValidator --quiet -V -S vert -o vert.spv vert.glsl && glslangValidator --quiet -V -S frag -o frag.spv frag.glsl || exit 2
for v in "VK_TRUE 0" "VK_TRUE 1" "VK_FALSE 0"; do
  set -- $v
  gcc -std=c99 -O1 -Wall -DCOMPARE_ENABLE="$1" -DFILTER="$2" -o repro repro.c -lvulkan -lm || exit 2
  echo "== compareEnable=$1 filter=$2 (0 NEAREST, 1 LINEAR)"
  env VK_ICD_FILENAMES=/usr/share/vulkan/icd.d/lvp_icd.x86_64.json VK_INSTANCE_LAYERS=VK_LAYER_KHRONOS_validation ./repro 2>&1 | grep -v '^verdict\|^expected\|^layout\|^test'
  echo "exit status $?"
done

#!/bin/sh
# shadowcheck reproducer for vulkan/cube/d32f/linear/lequal/seamless/stage=compute/seamless=always/wrap=edge/x0=0.9/edge_s/ref=0.5@vk on vk:swiftshader.
# Debian 12: apt-get install -y gcc libvulkan-dev glslang-tools libvulkan1 chromium-common
cd "$(dirname "$0")" || exit 2
glslangValidator --quiet -V -S comp -o comp.spv comp.glsl && gcc -std=c99 -O1 -Wall -o repro repro.c -lvulkan -lm || exit 2
exec env VK_ICD_FILENAMES=/usr/lib/chromium/vk_swiftshader_icd.json ./repro

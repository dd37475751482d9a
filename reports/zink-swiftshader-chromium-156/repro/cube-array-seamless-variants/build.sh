#!/bin/sh
# Hand-edited variants of the generated cube-array reproducers (each file's first comment says what
# was changed). Each program is built and run on zink over SwiftShader Vulkan and over lavapipe; the
# generated originals are run beside them for comparison. Then the SPIR-V that zink hands to each
# Vulkan driver for the original layer program (ZINK_DEBUG=spirv; needs spirv-tools for spirv-dis):
# on SwiftShader, which lacks VK_EXT_non_seamless_cube_map, zink samples a 2D array image (its
# non-seamless cube-map emulation); on lavapipe a Cube arrayed image.
# Debian 12: apt-get install -y gcc libegl-dev libgl-dev libegl-mesa0 libgl1-mesa-dri mesa-vulkan-drivers chromium-common spirv-tools
cd "$(dirname "$0")" || exit 2
SS="VK_ICD_FILENAMES=/usr/lib/chromium/vk_swiftshader_icd.json MESA_GL_VERSION_OVERRIDE=4.6 MESA_GLSL_VERSION_OVERRIDE=460"
T=$(mktemp -d) || exit 2
cp ../cube-array-layer-generated/repro.c "$T/layer.c"
cp ../cube-array-lod-generated/repro.c "$T/lod.c"
for p in layer layer-seamless lod lod-uniform lod-uniform-seamless; do
  src=$p.c; [ -f "$src" ] || src=$T/$p.c
  cc -std=c99 -O1 -w -o "$T/$p" "$src" -lEGL -lGL -lm || exit 2
  for drv in swiftshader lavapipe; do
    env=""; [ $drv = swiftshader ] && env=$SS
    printf '%-22s zink/%-11s ' "$p" "$drv"
    env LIBGL_ALWAYS_SOFTWARE=1 GALLIUM_DRIVER=zink EGL_PLATFORM=surfaceless $env "$T/$p" 2>/dev/null | grep -E '^(observed|verdict)' | tr -s ' ' | tr '\n' ' '
    echo
  done
done
if command -v spirv-dis >/dev/null; then
  for drv in swiftshader lavapipe; do
    env=""; [ $drv = swiftshader ] && env=$SS
    mkdir -p "$T/spv-$drv" && (cd "$T/spv-$drv" && env ZINK_DEBUG=spirv LIBGL_ALWAYS_SOFTWARE=1 GALLIUM_DRIVER=zink EGL_PLATFORM=surfaceless $env "$T/layer" >/dev/null 2>&1)
    echo "== SPIR-V of the fragment shader of layer.c, zink on $drv (image type, sampling instruction, the layer arithmetic)"
    for f in "$T/spv-$drv"/*.spv; do spirv-dis "$f"; done | grep -E 'OpCapability ImageCubeArray|OpTypeImage|OpImageSample|%float_6|1086324736'
  done
fi
rm -rf "$T"
